/* na_loop.c: the NA controller of Shang & Cong (2010) in a 2 ms loop, plain C99, no Python.
 *
 * Uses only the generated code pm2dof/generated/shang2010/shang2010.{c,h}:
 *   shang2010_na_step     the controller (fk, velocity estimate, NA law eqs. 14-29,
 *                         minimum-norm torque split eq. 21, parameter update eq. 28)
 *   shang2010_measure     the simulated encoders (true pose -> quantised active angles)
 *   shang2010_plant_step  the simulated robot (one RK4 step of its truth dynamics)
 *   shang2010_fk          forward kinematics (initial controller state only)
 * Each sample k: read qa (measure), compute tau_a (na_step), apply tau_a for one period
 * (4 RK4 plant substeps, zero-order hold): the order of shang2010_na_closed_loop and of
 * pm2dof.simulate.simulate, so the tracking error printed here is the one Python reports.
 *
 * Usage: na_loop [--no-sleep] [--repeat N] [--settle SECONDS] [--rt]
 *   --no-sleep   run as fast as possible (no pacing); default: paced at the 2 ms period
 *                with clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME)
 *   --repeat N   run the whole move N times (fresh state each time) for timing statistics
 *   --settle S   rest at the end point for S seconds after the move (default 0.2)
 *   --rt         try SCHED_FIFO priority 80 and mlockall (needs CAP_SYS_NICE / root)
 */
#define _POSIX_C_SOURCE 200809L /* clock_nanosleep, sched_setscheduler, mlockall */

#include <errno.h>
#include <math.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>

#include "shang2010.h"

#define N_LEGS 3
#define N_THETA (5 * N_LEGS)
#define PI 3.14159265358979323846

/* ---------------------------------------------------------------------------------------
 * Model data, hard-coded from pm2dof/models/shang2010.toml (keep in sync with that file).
 * The flat-vector layouts are those of pm2dof/generated/shang2010/manifest.json ("layouts");
 * main() checks the vector sizes against the generated code before running.
 * theta order: alpha1..3, beta1..3, gamma1..3, fv1..3, fc1..3 (header of shang2010.h).
 * ------------------------------------------------------------------------------------- */

/* [[legs]]: link lengths, m (for the payload below) */
static const double LA[N_LEGS] = {0.244, 0.244, 0.244};
static const double LB[N_LEGS] = {0.244, 0.244, 0.244};

/* [nominal], Tables 1-2 of the paper: the controller's initial theta_hat */
static const double THETA_NOMINAL[N_THETA] = {
    0.0932, 0.0427, 0.0427,    /* alpha, kg m^2 */
    0.0381, 0.0085, 0.0085,    /* beta, kg m^2 */
    0.0426, 0.0111, 0.0111,    /* gamma, kg m^2 */
    2.9936, 2.7617, 2.8771,    /* fv, N m s/rad */
    0.4976, 0.4570, 0.3006};   /* fc, N m */

/* [gains.na], Sect. 5 of the paper */
static const double KD[2] = {195.0, 195.0};  /* N s/m */
static const double Q[2] = {280.0, 280.0};   /* 1/s */
static const double GAMMA[N_THETA] = {5e-4, 5e-4, 5e-4, 5e-4, 5e-4, 5e-4, 5e-4, 5e-4, 5e-4,
                                      0.02, 0.02, 0.02, 0.005, 0.005, 0.005};

/* [sensing] and [limits] */
static const double SAMPLE_PERIOD = 0.002;          /* s */
static const double VELOCITY_FILTER_HZ = 0.0;       /* 0: plain backward difference */
static const double ENCODER_COUNTS_PER_REV = 131072.0;
static const double SING_THRESHOLD = 0.1;           /* type I (legs) */
static const double PARALLEL_SING_THRESHOLD = 0.1;  /* type II (actuation) */
/* largest closure residual |O - B_i| - lb_i accepted from the encoders, m: the model file's
   default, 5 encoder steps at the longest active link ([sensing] closure_tolerance) */
static const double CLOSURE_TOL = 5 * 0.244 * 2 * PI / 131072.0;
static const double TAU_MAX[N_LEGS] = {30.0, 30.0, 30.0}; /* N m */
static const int RK4_SUBSTEPS = 3;                  /* manifest.json "rk4_substeps" */

/* [plant]: the simulated robot's truth (differs from [nominal] on purpose) */
static const double PLANT_ALPHA[N_LEGS] = {0.0932, 0.0427, 0.0427};
static const double PLANT_BETA[N_LEGS] = {0.0381, 0.0085, 0.0085};
static const double PLANT_GAMMA[N_LEGS] = {0.0426, 0.0111, 0.0111};
static const double PAYLOAD_MASS = 0.3; /* kg, at the tip of leg PAYLOAD_LEG's distal link */
static const int PAYLOAD_LEG = 0;       /* 0-based (the model file says 1) */
static const double PLANT_FV[N_LEGS] = {2.5446, 2.3474, 2.4455};
static const double PLANT_FC[N_LEGS] = {0.5971, 0.5484, 0.3607};
static const double PLANT_FS[N_LEGS] = {0.25, 0.25, 0.15};
static const double STRIBECK_VELOCITY = 0.05;
static const double COULOMB_SMOOTHING_VELOCITY = 0.005;

/* [trajectories.high]: straight line, time-optimal jerk-limited S-curve, rest to rest */
static const double MOVE_START[2] = {0.22, 0.29}, MOVE_END[2] = {0.27, 0.24}; /* m */
static const double MOVE_V = 0.5, MOVE_A = 10.0, MOVE_J = 400.0; /* m/s, m/s^2, m/s^3 */

/* Layout sizes (manifest.json "layouts") */
enum {
    STATE_SIZE = 2 + 2 + N_THETA,              /* ctrl_state: xe_prev, v, theta_hat */
    NA_PARAMS_SIZE = 2 + 2 + N_THETA + 1 + 4 + 3 * N_LEGS + 1, /* Kd, Q, Gamma,
                                                      freeze_saturated, T, vel_alpha,
                                                      sing_threshold, parallel_sing_threshold,
                                                      tau_max, preload_sign, preload,
                                                      closure_tol */
    DIAG_SIZE = 10,                            /* diag: xe, v, e, edot, sing (type I, II) */
    PLANT_SIZE = 6 * N_LEGS + 3                /* alpha beta gamma fv fc fs, vs, eps, step */
};

/* ---------------------------------------------------------------------------------------
 * Calling a generated function: arg/res pointer arrays and work vectors from <f>_work(),
 * allocated once before the loop; a call in the loop does not allocate.
 * ------------------------------------------------------------------------------------- */

typedef int (*eval_fn)(const casadi_real **arg, casadi_real **res, casadi_int *iw,
                       casadi_real *w, int mem);
typedef int (*work_fn)(casadi_int *sz_arg, casadi_int *sz_res, casadi_int *sz_iw,
                       casadi_int *sz_w);

typedef struct {
    const char *name;
    eval_fn eval;
    const casadi_real **arg;
    casadi_real **res;
    casadi_int *iw;
    casadi_real *w;
    int mem;
} Call;

static void *xcalloc(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size);
    if (p == NULL) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    return p;
}

static void call_init(Call *c, const char *name, eval_fn eval, work_fn work, int mem)
{
    casadi_int sz_arg, sz_res, sz_iw, sz_w;
    if (work(&sz_arg, &sz_res, &sz_iw, &sz_w) != 0) {
        fprintf(stderr, "%s_work failed\n", name);
        exit(1);
    }
    c->name = name;
    c->eval = eval;
    c->arg = xcalloc((size_t)sz_arg, sizeof(*c->arg));
    c->res = xcalloc((size_t)sz_res, sizeof(*c->res));
    c->iw = xcalloc((size_t)sz_iw, sizeof(*c->iw));
    c->w = xcalloc((size_t)sz_w, sizeof(*c->w));
    c->mem = mem;
}

static void call_free(Call *c)
{
    free((void *)c->arg);
    free(c->res);
    free(c->iw);
    free(c->w);
}

static inline void call_eval(const Call *c)
{
    if (c->eval(c->arg, c->res, c->iw, c->w, c->mem) != 0) {
        fprintf(stderr, "%s failed\n", c->name);
        exit(1);
    }
}

/* Number of stored entries of a CasADi sparsity pattern (dense: nrow * ncol). */
static long nnz_of(const casadi_int *sp)
{
    long nrow = (long)sp[0], ncol = (long)sp[1];
    if (sp[2] == 1) /* compact form of a dense pattern */
        return nrow * ncol;
    return (long)sp[2 + ncol];
}

/* Exit unless input/output i of a generated function has the size this program assumes. */
static void expect_size(const char *fname, const char *what, const casadi_int *sp, long n)
{
    if (sp == NULL || nnz_of(sp) != n) {
        fprintf(stderr, "%s: %s has %ld entries, this program assumes %ld: the generated code "
                "changed, update examples/c/na_loop.c to manifest.json\n",
                fname, what, sp ? nnz_of(sp) : -1L, n);
        exit(1);
    }
}

/* ---------------------------------------------------------------------------------------
 * Desired motion: the time-optimal rest-to-rest S-curve along a straight line, the same
 * closed form as pm2dof.trajectory.SCurve (jerk +j, 0, -j, 0, -j, 0, +j).
 * ------------------------------------------------------------------------------------- */

typedef struct {
    double L, j, t_j, t_a, t_v, v_peak, a_peak;
} SCurve;

static SCurve scurve_plan(double L, double v, double a, double j)
{
    SCurve p = {L, j, 0.0, 0.0, 0.0, v, a};
    double a_p;
    if (v * j >= a * a) { /* a_max is reached while accelerating to v_max */
        p.t_j = a / j;
        p.t_a = fmax(v / a - a / j, 0.0);
        a_p = a;
    } else {
        p.t_j = sqrt(v / j);
        p.t_a = 0.0;
        a_p = j * p.t_j;
    }
    if (L >= v * (2.0 * p.t_j + p.t_a)) { /* v_max is reached: cruise */
        p.t_v = L / v - (2.0 * p.t_j + p.t_a);
        p.v_peak = v;
        p.a_peak = a_p;
    } else if (L >= 2.0 * a * a * a / (j * j)) { /* no cruise, a_max still reached */
        p.t_j = a / j;
        p.v_peak = 2.0 * L / (p.t_j + sqrt(p.t_j * p.t_j + 4.0 * L / a));
        p.t_a = fmax(p.v_peak / a - p.t_j, 0.0);
        p.a_peak = a;
    } else { /* no limit reached: L = 2 j t_j^3 */
        p.t_j = cbrt(L / (2.0 * j));
        p.v_peak = j * p.t_j * p.t_j;
        p.a_peak = j * p.t_j;
    }
    return p;
}

static double scurve_duration(const SCurve *p)
{
    return 4.0 * p->t_j + 2.0 * p->t_a + p->t_v;
}

/* Path parameter s (m), its rate sd (m/s) and sdd (m/s^2) at time t. */
static void scurve_eval(const SCurve *p, double t, double *s, double *sd, double *sdd)
{
    const double T = scurve_duration(p), j = p->j, a_p = p->a_peak, v_p = p->v_peak;
    const double t1 = p->t_j, t3 = 2.0 * p->t_j + p->t_a;
    const double v1 = 0.5 * j * t1 * t1, s3 = 0.5 * v_p * t3;
    const double tc = t < 0.0 ? 0.0 : (t > T ? T : t);
    const int second = tc > 0.5 * T; /* the second half mirrors the first */
    const double m = second ? T - tc : tc, r = t3 - m, u = m - t1;
    if (m < t1) {
        *s = j * pow(m, 3) / 6.0;
        *sd = 0.5 * j * m * m;
        *sdd = j * m;
    } else if (m < t1 + p->t_a) {
        *s = j * pow(t1, 3) / 6.0 + v1 * u + 0.5 * a_p * u * u;
        *sd = v1 + a_p * u;
        *sdd = a_p;
    } else if (m < t3) {
        *s = s3 - v_p * r + j * pow(r, 3) / 6.0;
        *sd = v_p - 0.5 * j * r * r;
        *sdd = j * r;
    } else {
        *s = s3 + v_p * (m - t3);
        *sd = v_p;
        *sdd = 0.0;
    }
    if (second) {
        *s = p->L - *s;
        *sdd = -*sdd;
    }
}

typedef struct {
    double xd[2], xd_dot[2], xd_ddot[2];
} Desired;

/* Sample k of the move (samples past its end rest at MOVE_END). */
static Desired desired(const SCurve *p, long k, double period)
{
    const double dx = MOVE_END[0] - MOVE_START[0], dy = MOVE_END[1] - MOVE_START[1];
    double s, sd, sdd;
    Desired d;
    scurve_eval(p, (double)k * period, &s, &sd, &sdd);
    const double lam = s / p->L, ux = dx / p->L, uy = dy / p->L;
    d.xd[0] = (1.0 - lam) * MOVE_START[0] + lam * MOVE_END[0];
    d.xd[1] = (1.0 - lam) * MOVE_START[1] + lam * MOVE_END[1];
    d.xd_dot[0] = sd * ux + 0.0;
    d.xd_dot[1] = sd * uy + 0.0;
    d.xd_ddot[0] = sdd * ux + 0.0;
    d.xd_ddot[1] = sdd * uy + 0.0;
    return d;
}

/* ---------------------------------------------------------------------------------------
 * Timing
 * ------------------------------------------------------------------------------------- */

static inline long long now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

static void timespec_add_ns(struct timespec *t, long long ns)
{
    long long total = (long long)t->tv_nsec + ns;
    t->tv_sec += (time_t)(total / 1000000000LL);
    t->tv_nsec = (long)(total % 1000000000LL);
}

typedef struct {
    long long n, sum, worst;
} Stat;

static inline void stat_add(Stat *s, long long v)
{
    s->n++;
    s->sum += v;
    if (v > s->worst)
        s->worst = v;
}

static double stat_mean(const Stat *s)
{
    return s->n ? (double)s->sum / (double)s->n : 0.0;
}

/* ---------------------------------------------------------------------------------------
 * main
 * ------------------------------------------------------------------------------------- */

static void usage(const char *prog)
{
    fprintf(stderr, "usage: %s [--no-sleep] [--repeat N] [--settle SECONDS] [--rt]\n", prog);
}

int main(int argc, char **argv)
{
    int sleep_mode = 1, realtime = 0;
    long repeat = 1;
    double settle = 0.2;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--no-sleep") == 0) {
            sleep_mode = 0;
        } else if (strcmp(argv[i], "--rt") == 0) {
            realtime = 1;
        } else if (strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
            repeat = strtol(argv[++i], NULL, 10);
        } else if (strcmp(argv[i], "--settle") == 0 && i + 1 < argc) {
            settle = strtod(argv[++i], NULL);
        } else {
            usage(argv[0]);
            return 2;
        }
    }
    if (repeat < 1 || !(settle >= 0.0)) {
        usage(argv[0]);
        return 2;
    }

    /* --- the generated code must match the layouts hard-coded above ------------------ */
    expect_size("shang2010_na_step", "input state", shang2010_na_step_sparsity_in(0), STATE_SIZE);
    expect_size("shang2010_na_step", "input qa", shang2010_na_step_sparsity_in(1), N_LEGS);
    expect_size("shang2010_na_step", "input params", shang2010_na_step_sparsity_in(5),
                NA_PARAMS_SIZE);
    expect_size("shang2010_na_step", "output tau_a", shang2010_na_step_sparsity_out(0), N_LEGS);
    expect_size("shang2010_na_step", "output diag", shang2010_na_step_sparsity_out(3),
                DIAG_SIZE);
    expect_size("shang2010_plant_step", "input plant", shang2010_plant_step_sparsity_in(2),
                PLANT_SIZE);
    expect_size("shang2010_plant_step", "input x", shang2010_plant_step_sparsity_in(0), 4);
    expect_size("shang2010_measure", "input plant", shang2010_measure_sparsity_in(1),
                PLANT_SIZE);

    /* --- controller parameters: na_params layout ------------------------------------- */
    const double T = SAMPLE_PERIOD;
    double params[NA_PARAMS_SIZE], *pp = params;
    for (int i = 0; i < 2; i++) *pp++ = KD[i];
    for (int i = 0; i < 2; i++) *pp++ = Q[i];
    for (int i = 0; i < N_THETA; i++) *pp++ = GAMMA[i];
    *pp++ = 0.0;                /* freeze_saturated: 0, adapt on every good sample (eq. 28) */
    *pp++ = T;
    /* velocity estimate v += a ((xe - xe_prev) / T - v): first-order low-pass, a = 1: none */
    *pp++ = VELOCITY_FILTER_HZ > 0.0 ? T / (T + 1.0 / (2.0 * PI * VELOCITY_FILTER_HZ)) : 1.0;
    *pp++ = SING_THRESHOLD;
    *pp++ = PARALLEL_SING_THRESHOLD;
    for (int i = 0; i < N_LEGS; i++) *pp++ = TAU_MAX[i];
    for (int i = 0; i < N_LEGS; i++) *pp++ = 1.0;   /* preload_sign: unused by the min_norm step */
    for (int i = 0; i < N_LEGS; i++) *pp++ = 0.0;   /* preload, N m: likewise */
    *pp++ = CLOSURE_TOL;                            /* status 5 beyond it */

    /* --- plant truth: plant layout, payload booked into leg PAYLOAD_LEG --------------- */
    double plant[PLANT_SIZE];
    for (int i = 0; i < N_LEGS; i++) {
        const double m = i == PAYLOAD_LEG ? PAYLOAD_MASS : 0.0;
        plant[i] = PLANT_ALPHA[i] + m * LA[i] * LA[i];
        plant[N_LEGS + i] = PLANT_BETA[i] + m * LA[i] * LB[i];
        plant[2 * N_LEGS + i] = PLANT_GAMMA[i] + m * LB[i] * LB[i];
        plant[3 * N_LEGS + i] = PLANT_FV[i];
        plant[4 * N_LEGS + i] = PLANT_FC[i];
        plant[5 * N_LEGS + i] = PLANT_FS[i];
    }
    plant[6 * N_LEGS] = STRIBECK_VELOCITY;
    plant[6 * N_LEGS + 1] = COULOMB_SMOOTHING_VELOCITY;
    plant[6 * N_LEGS + 2] = 2.0 * PI / ENCODER_COUNTS_PER_REV; /* encoder quantum, rad */

    /* --- the move -------------------------------------------------------------------- */
    const double L = hypot(MOVE_END[0] - MOVE_START[0], MOVE_END[1] - MOVE_START[1]);
    const SCurve prof = scurve_plan(L, MOVE_V, MOVE_A, MOVE_J);
    long n_move = (long)ceil(scurve_duration(&prof) / T);
    n_move += (double)n_move * T < scurve_duration(&prof);
    n_move += 1; /* samples k = 0 .. n_move - 1, the last one at rest at the end */
    const long n_settle = (long)ceil(settle / T - 1e-9);
    const long n_total = n_move + n_settle;

    /* --- generated functions, work vectors allocated once ---------------------------- */
    Call step, meas, plant_step, fk;
    call_init(&step, "shang2010_na_step", shang2010_na_step, shang2010_na_step_work,
              shang2010_na_step_checkout());
    call_init(&meas, "shang2010_measure", shang2010_measure, shang2010_measure_work,
              shang2010_measure_checkout());
    call_init(&plant_step, "shang2010_plant_step", shang2010_plant_step,
              shang2010_plant_step_work, shang2010_plant_step_checkout());
    call_init(&fk, "shang2010_fk", shang2010_fk, shang2010_fk_work, shang2010_fk_checkout());

    /* buffers: controller state ping-pong, plant state ping-pong, outputs */
    double state[2][STATE_SIZE], z[2][4], qa[N_LEGS], tau[N_LEGS], status, diag[DIAG_SIZE];
    double h = T / (double)RK4_SUBSTEPS; /* zero-order hold over RK4_SUBSTEPS RK4 steps */
    Desired d;

    meas.arg[0] = z[0];            /* xe: the first two entries of the plant state */
    meas.arg[1] = plant;
    meas.res[0] = qa;
    step.arg[1] = qa;
    step.arg[2] = d.xd;
    step.arg[3] = d.xd_dot;
    step.arg[4] = d.xd_ddot;
    step.arg[5] = params;
    step.res[0] = tau;
    step.res[2] = &status;
    step.res[3] = diag;
    plant_step.arg[1] = tau;
    plant_step.arg[2] = plant;
    plant_step.arg[3] = &h;

    int fifo = 0, locked = 0;
    if (realtime) {
        struct sched_param sp;
        memset(&sp, 0, sizeof(sp));
        sp.sched_priority = 80;
        fifo = sched_setscheduler(0, SCHED_FIFO, &sp) == 0;
        if (!fifo)
            fprintf(stderr, "warning: SCHED_FIFO refused (%s); running with normal priority\n",
                    strerror(errno));
        locked = mlockall(MCL_CURRENT | MCL_FUTURE) == 0;
        if (!locked)
            fprintf(stderr, "warning: mlockall failed (%s)\n", strerror(errno));
    }

    Stat t_step = {0, 0, 0}, t_plant = {0, 0, 0}, wake = {0, 0, 0};
    long overruns = 0, n_singular = 0, n_saturated = 0;
    double sum_e2 = 0.0, final_err = 0.0, tau_peak = 0.0;

    for (long run = 0; run < repeat; run++) {
        /* start at rest at the first desired point, as pm2dof.simulate.simulate */
        int cur = 0, pcur = 0;
        d = desired(&prof, 0, T);
        z[0][0] = d.xd[0];
        z[0][1] = d.xd[1];
        z[0][2] = z[0][3] = 0.0;
        meas.arg[0] = z[0];
        call_eval(&meas);                       /* qa0 = encoders at the start pose */
        fk.arg[0] = qa;
        fk.res[0] = state[0];                   /* xe_prev = fk(qa0) */
        call_eval(&fk);
        state[0][2] = state[0][3] = 0.0;        /* v = 0 */
        memcpy(&state[0][4], THETA_NOMINAL, sizeof(THETA_NOMINAL));
        sum_e2 = 0.0;

        struct timespec next;
        clock_gettime(CLOCK_MONOTONIC, &next);
        for (long k = 0; k < n_total; k++) {
            if (sleep_mode) { /* wait for the start of period k */
                timespec_add_ns(&next, (long long)(T * 1e9 + 0.5));
                while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL) == EINTR) {
                }
                stat_add(&wake, now_ns() - ((long long)next.tv_sec * 1000000000LL +
                                            next.tv_nsec));
            }
            d = desired(&prof, k, T);

            /* sensor: encoders read the true pose */
            meas.arg[0] = z[pcur];
            call_eval(&meas);

            /* the controller step, timed */
            step.arg[0] = state[cur];
            step.res[1] = state[1 - cur];
            long long t0 = now_ns();
            call_eval(&step);
            long long t1 = now_ns();
            stat_add(&t_step, t1 - t0);
            cur = 1 - cur;

            /* bookkeeping: eq. 41 over the move, status, peak torque */
            const double ex = d.xd[0] - z[pcur][0], ey = d.xd[1] - z[pcur][1];
            if (k < n_move)
                sum_e2 += ex * ex + ey * ey;
            n_singular += status == 1.0;
            n_saturated += status == 2.0;
            for (int i = 0; i < N_LEGS; i++)
                tau_peak = fmax(tau_peak, fabs(tau[i]));

            /* actuators: hold tau_a for one period; the simulated robot moves */
            for (int s = 0; s < RK4_SUBSTEPS; s++) {
                plant_step.arg[0] = z[pcur];
                plant_step.res[0] = z[1 - pcur];
                call_eval(&plant_step);
                pcur = 1 - pcur;
            }
            stat_add(&t_plant, now_ns() - t1);
            if (sleep_mode) { /* did this period's work finish before the next one? */
                struct timespec deadline = next;
                timespec_add_ns(&deadline, (long long)(T * 1e9 + 0.5));
                if (now_ns() > (long long)deadline.tv_sec * 1000000000LL + deadline.tv_nsec)
                    overruns++;
            }
        }
        final_err = hypot(d.xd[0] - z[pcur][0], d.xd[1] - z[pcur][1]);
    }

    printf("NA controller (shang2010_na_step), high-speed move: %ld + %ld settle samples at "
           "%.3f ms, %s, %ld run%s\n", n_move, n_settle, T * 1e3,
           sleep_mode ? "paced by clock_nanosleep(TIMER_ABSTIME)" : "not paced (--no-sleep)",
           repeat, repeat == 1 ? "" : "s");
    printf("scheduling: %s, memory %s\n", fifo ? "SCHED_FIFO priority 80" : "default policy",
           locked ? "locked (mlockall)" : "not locked");
    printf("NA step time:    mean %8.1f ns, worst %8lld ns  (%lld steps)\n", stat_mean(&t_step),
           t_step.worst, t_step.n);
    printf("plant (%d RK4):   mean %8.1f ns, worst %8lld ns  per sample (the simulated robot)\n",
           RK4_SUBSTEPS, stat_mean(&t_plant), t_plant.worst);
    if (sleep_mode)
        printf("wake-up latency: mean %8.1f ns, worst %8lld ns; overruns: %ld\n",
               stat_mean(&wake), wake.worst, overruns);
    printf("tracking (last run): RMSE over the move %.6e m (eq. 41), error at the end %.3e m\n",
           sqrt(sum_e2 / (double)n_move), final_err);
    printf("peak |tau_a| %.3f N m; samples singular %ld, saturated %ld\n", tau_peak,
           n_singular, n_saturated);

    call_free(&step);
    call_free(&meas);
    call_free(&plant_step);
    call_free(&fk);
    shang2010_na_step_release(step.mem);
    shang2010_measure_release(meas.mem);
    shang2010_plant_step_release(plant_step.mem);
    shang2010_fk_release(fk.mem);
    return 0;
}
