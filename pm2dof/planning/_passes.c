/* pm2dof.planning._passes: the time-optimal planner's rows and passes on one grid, in C. */

/*
 * solve(mvc, backward, forward, params, s, base, v1, x_cap, left, junctions, offsets,
 *       stage, x, sdd, x_mvc, arrival_ok, cap, hi, y, x_raw, prev) -> int
 *
 * What pm2dof.planning.stages.link then pm2dof.planning.grid.passes (the whole
 * computation) give, with the generated functions path_mvc, path_backward and
 * path_forward called per row through _cbind's C API (_cbind_api.h): the same inputs, row
 * for row, so the same results bit for bit (tests/planning/test_planning_passes_c.py).
 *
 *   mvc, backward, forward  the model's path_mvc, path_backward, path_forward (Functions)
 *   params      path_params (np,)
 *   s           the grid (K,), K >= 2; base its points' own path_stage rows (K, S) (rho,
 *               delta, x_cap unset); v1 (K, n); x_cap (K,) (0 at the stops)
 *   left        the preceding piece's rows at the interior breakpoints (J, S), base-like;
 *   junctions   their arc lengths (J,), increasing (J may be 0)
 *   offsets     int64: S, rho, n, delta, x_cap, h, F, then path_pair's size, stage, next,
 *               next_cap, path_backward_input's size and pair, path_forward_input's size,
 *               pair and x_next_max, path_forward_output's size, x, sdd, L, U, Z,
 *               arrival_ok (the inputs' memo entries are left zero: see run())
 *   outputs     stage (K, S) the linked rows; x (K,) s_d^2 >= 0 (0 at the stops); sdd (K,)
 *               (the last repeats the one before); x_mvc (K,); arrival_ok (K - 1,); and what
 *               a next solve reuses: cap (K,), hi (K,), y (K - 1, path_forward's y), x_raw (K,)
 *   prev        None, or (s, stage, x_mvc, cap, hi, y, x_raw) of a previous solve on a grid
 *               of which s is a refinement (its points among s): what cannot have changed is
 *               taken from it (run()), the result the same bit for bit
 *
 * Returns 0, or 1 where the Python passes raise (a point with no feasible speed, the end not
 * reachable at rest, the forward pass breaking its own conditions, a generated function's
 * error code): the caller then runs them for their message. The arrays are then undefined.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <string.h>

#include "../core/_cbind_api.h"
#include "_buffers.h"

static const Pm2dofCbindAPI *api;

enum { S_, RHO, NL, DELTA, XCAP, H, NF, P_, P_STAGE, P_NEXT, P_CAP, B_, B_PAIR, FI_, F_PAIR,
       F_XNM, Y_, Y_X, Y_SDD, Y_L, Y_U, Y_Z, Y_OK, N_OFFSETS };

static const double TOL = 1e-9; /* grid.py's _TOL */

/* every field of a path_stage row but rho, delta and x_cap (the ones link sets) */
static int linked(const Py_ssize_t *o, Py_ssize_t c)
{
    return (c >= o[RHO] && c < o[RHO] + o[NL]) || c == o[DELTA] || c == o[XCAP];
}

/* arrive row k: the facets at point k for the interval that ends there (stages.link) */
static void arrive_row(const Py_ssize_t *o, const double *stage, Py_ssize_t k,
                       const double *left_row, double *out)
{
    const Py_ssize_t S = o[S_];
    const double *row = stage + k * S;
    if (left_row != NULL) {
        for (Py_ssize_t c = 0; c < S; c++)
            out[c] = linked(o, c) ? row[c] : left_row[c];
    } else {
        memcpy(out, row, (size_t)S * sizeof(double));
    }
    if (k > 0)
        memcpy(out + o[RHO], stage + (k - 1) * S + o[RHO], (size_t)o[NL] * sizeof(double));
}

/* index of s in junctions (exact), or -1 */
static Py_ssize_t junction(const double *bp, Py_ssize_t J, double s)
{
    Py_ssize_t lo = 0, hi = J;
    while (lo < hi) {
        Py_ssize_t mid = lo + (hi - lo) / 2;
        if (bp[mid] < s)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < J && bp[lo] == s ? lo : -1;
}

typedef struct {
    Pm2dofCall *mvc, *back, *fwd;
} Calls;

/* the previous solve on a grid of which this one is a refinement (its points a subset) */
typedef struct {
    Py_ssize_t K;
    const double *s, *stage, *x_mvc, *cap, *hi, *y, *x_raw;
} Prev;

static int rows_equal(const double *a, const double *b, Py_ssize_t S)
{
    for (Py_ssize_t c = 0; c < S; c++)
        if (!(a[c] == b[c]))
            return 0;
    return 1;
}

/* The passes: the outputs x, sdd, x_mvc, ok (arrival_ok), and what the next solve reuses:
 * cap, hi, y (K - 1, Y), x_raw. With a previous solve, what cannot have changed is taken from
 * it (grid.py before the passes moved to C): a row's maximum-velocity curve where its stage
 * row is the same, the backward pass's bounds above the last interval whose input changed,
 * the forward pass's steps before the first one whose input or bound changed, and the
 * previous steps where the pass meets the previous one again (the same interval, arrived at
 * with the same bound or speed), neither built nor evaluated: what the generated steps' own
 * memo (same, x_in, x_out, left zero here) would hand back. The result is the whole
 * computation's, bit for bit. */
static int run(const Calls *f, const Py_ssize_t *o, const double *prm, const double *s,
               const double *base, const double *v1, const double *x_cap, const double *left,
               const double *bp, Py_ssize_t J, Py_ssize_t K, const Prev *pv, double *stage,
               double *x, double *sdd, double *x_mvc, double *ok, double *cap, double *hi,
               double *yall, double *x_raw, double *scratch, Py_ssize_t *src,
               unsigned char *flags)
{
    const Py_ssize_t S = o[S_], n = o[NL], Y = o[Y_];
    double *arr = scratch, *arr2 = arr + S, *in = arr2 + S;
    unsigned char *kept = flags, *same_st = kept + K, *same_ar = same_st + K,
                  *same_int = same_ar + K;
    double xs[2];
    /* link: rho (a joint reverses on the interval), delta, x_cap */
    memcpy(stage, base, (size_t)(K * S) * sizeof(double));
    for (Py_ssize_t k = 0; k < K; k++) {
        double *row = stage + k * S;
        for (Py_ssize_t i = 0; i < n; i++) {
            double a = v1[k * n + i] >= 0 ? 1.0 : -1.0;
            double b = k + 1 < K ? (v1[(k + 1) * n + i] >= 0 ? 1.0 : -1.0) : a;
            row[o[RHO] + i] = k + 1 < K ? (double)(a != b) : 0.0;
        }
        row[o[DELTA]] = k + 1 < K ? s[k + 1] - s[k] : s[K - 1] - s[K - 2];
        row[o[XCAP]] = x_cap[k];
    }
    /* which rows and intervals are the previous solve's: src (the point's index there, -1),
       kept (the interval is one of its intervals), the stage and arrive rows the same */
    for (Py_ssize_t k = 0, j = 0; k < K; k++) {
        if (pv == NULL) {
            src[k] = -1;
            continue;
        }
        while (j < pv->K - 1 && pv->s[j] < s[k])
            j++;
        src[k] = pv->s[j] == s[k] ? j : -1;
    }
    for (Py_ssize_t k = 0; k + 1 < K; k++)
        kept[k] = src[k] >= 0 && src[k + 1] == src[k] + 1;
    kept[K - 1] = 0;
    for (Py_ssize_t k = 0; k < K; k++) {
        same_st[k] = k + 1 < K ? kept[k] : kept[K - 2] && src[K - 1] >= 0;
        same_ar[k] = same_st[k] && (k == 0 || kept[k - 1]);
    }
    for (Py_ssize_t k = 0; k < K; k++) {
        if (src[k] < 0)
            continue;
        Py_ssize_t jk = junction(bp, J, s[k]);
        const double *lr = jk >= 0 ? left + jk * S : NULL;
        if (!same_st[k])
            same_st[k] = rows_equal(stage + k * S, pv->stage + src[k] * S, S);
        if (!same_ar[k]) {
            arrive_row(o, stage, k, lr, arr);
            arrive_row(o, pv->stage, src[k], lr, arr2);
            same_ar[k] = rows_equal(arr, arr2, S);
        }
    }
#define JS(k) (src[k] >= 0 ? src[k] : 0)
    /* the maximum-velocity curve; the arrival facets' own where they differ */
    for (Py_ssize_t k = 0; k < K; k++) {
        if (same_st[k]) {
            x_mvc[k] = pv->x_mvc[src[k]];
        } else {
            const double *a[2] = {stage + k * S, prm};
            double *r[1] = {x_mvc + k};
            if (api->eval(f->mvc, a, r) != 0)
                return 1;
        }
        if (x_mvc[k] < 0 || (x_mvc[k] <= 0 && x_cap[k] > 0))
            return 1;
    }
    for (Py_ssize_t k = 0; k < K; k++) {
        if (same_ar[k] && same_st[k]) {     /* its rows and so its cap are the previous */
            cap[k] = pv->cap[src[k]];
            continue;
        }
        Py_ssize_t j = junction(bp, J, s[k]);
        arrive_row(o, stage, k, j >= 0 ? left + j * S : NULL, arr);
        int other = !rows_equal(arr, stage + k * S, S);
        cap[k] = x_mvc[k];
        if (other) {
            const double *a[2] = {arr, prm};
            double *r[1] = {cap + k};
            if (api->eval(f->mvc, a, r) != 0)
                return 1;
        }
    }
    /* intervals with the previous solve's input (pair) */
    Py_ssize_t top = -1;
    for (Py_ssize_t k = 0; k + 1 < K; k++) {
        same_int[k] = kept[k] && same_st[k] && same_ar[k + 1] && same_st[k + 1];
        if (!same_int[k])
            top = k;
    }
    /* one pair per interval: stage k, arrive k + 1, cap k + 1 */
#define PAIR(dst, k)                                                                          \
    do {                                                                                      \
        Py_ssize_t jj = junction(bp, J, s[(k) + 1]);                                          \
        memcpy((dst) + o[P_STAGE], stage + (k) * S, (size_t)S * sizeof(double));              \
        arrive_row(o, stage, (k) + 1, jj >= 0 ? left + jj * S : NULL, (dst) + o[P_NEXT]);     \
        (dst)[o[P_CAP]] = cap[(k) + 1];                                                       \
    } while (0)
    /* backward from rest at the end: the controllable bounds hi; above the last changed
       interval the previous ones */
    for (Py_ssize_t k = top + 1; k < K; k++)
        hi[k] = pv != NULL ? pv->hi[JS(k)] : 0.0;
    hi[K - 1] = 0.0;
    if (top >= 0) {
        memset(in, 0, (size_t)o[B_] * sizeof(double));
        xs[0] = hi[top + 1];
        for (Py_ssize_t k = top; k >= 0; k--) {
            if (pv != NULL && same_int[k] && xs[0] == pv->hi[JS(k + 1)]) {
                /* the same interval from the same bound: the previous step's result */
                hi[k] = xs[0] = pv->hi[JS(k)];
                continue;
            }
            PAIR(in + o[B_PAIR], k);
            const double *a[3] = {xs, in, prm};
            double *r[2] = {xs + 1, hi + k};
            if (api->eval(f->back, a, r) != 0)
                return 1;
            xs[0] = xs[1];
        }
    }
    if (hi[0] < 0)
        return 1;
    /* forward from rest at the start; before the first interval whose input or bound changed
       the previous steps */
    Py_ssize_t first = K - 1;
    for (Py_ssize_t k = 0; k + 1 < K; k++) {
        same_int[k] = pv != NULL && same_int[k] && hi[k + 1] == pv->hi[JS(k + 1)];
        if (!same_int[k] && first == K - 1)
            first = k;
    }
    for (Py_ssize_t k = 0; k < first; k++)
        memcpy(yall + k * Y, pv->y + JS(k) * Y, (size_t)Y * sizeof(double));
    if (first > 0) {
        for (Py_ssize_t k = 0; k <= first; k++)
            x_raw[k] = pv->x_raw[JS(k)];
    } else {
        x_raw[0] = 0.0;
    }
    if (first < K - 1) {
        memset(in, 0, (size_t)o[FI_] * sizeof(double));
        xs[0] = x_raw[first];
        for (Py_ssize_t k = first; k + 1 < K; k++) {
            if (pv != NULL && same_int[k] && xs[0] == pv->x_raw[JS(k)]) {
                /* met the previous pass: the same interval from the same speed */
                memcpy(yall + k * Y, pv->y + JS(k) * Y, (size_t)Y * sizeof(double));
                x_raw[k] = pv->x_raw[JS(k)];
                xs[0] = pv->x_raw[JS(k + 1)];
                continue;
            }
            PAIR(in + o[F_PAIR], k);
            in[o[F_XNM]] = hi[k + 1];
            double *yk = yall + k * Y;
            const double *a[3] = {xs, in, prm};
            double *r[2] = {xs + 1, yk};
            if (api->eval(f->fwd, a, r) != 0)
                return 1;
            x_raw[k] = yk[o[Y_X]];
            xs[0] = xs[1];
        }
        x_raw[K - 1] = xs[0];
    }
#undef PAIR
#undef JS
    /* grid.py's _check_forward: s_dd within [L, U], the free facets held, landed at or above
       rest */
    for (Py_ssize_t k = 0; k + 1 < K; k++) {
        const double *yk = yall + k * Y;
        double u = yk[o[Y_SDD]], scale = 1.0 > fabs(u) ? 1.0 : fabs(u), h = stage[k * S + o[H]];
        for (Py_ssize_t c = 1; c < o[NF]; c++)
            h = stage[k * S + o[H] + c] > h ? stage[k * S + o[H] + c] : h;
        if (u < yk[o[Y_L]] - TOL * scale || u > yk[o[Y_U]] + TOL * scale ||
            yk[o[Y_Z]] < -TOL * h)
            return 1;
        double m = x_mvc[k + 1] > 1e-12 ? x_mvc[k + 1] : 1e-12;
        if (x_raw[k + 1] < -TOL * m)
            return 1;
        sdd[k] = u;
        ok[k] = yk[o[Y_OK]];
    }
    sdd[K - 1] = sdd[K - 2];
    for (Py_ssize_t k = 0; k < K; k++) {
        x[k] = x_raw[k] >= 0.0 || isnan(x_raw[k]) ? x_raw[k] : 0.0;   /* np.maximum(x, 0) */
        if (x_cap[k] == 0)
            x[k] = 0.0;
    }
    return 0;
}

static PyObject *solve(PyObject *self, PyObject *args)
{
    PyObject *fo[3], *a[17], *prev;
    if (!PyArg_ParseTuple(args, "OOOOOOOOOOOOOOOOOOOOO", &fo[0], &fo[1], &fo[2], &a[0], &a[1],
                          &a[2], &a[3], &a[4], &a[5], &a[6], &a[7], &a[8], &a[9], &a[10],
                          &a[11], &a[12], &a[13], &a[14], &a[15], &a[16], &prev))
        return NULL;
    Py_buffer b[24];
    int got = 0;
    PyObject *result = NULL;
    Calls f = {NULL, NULL, NULL};
    double *scratch = NULL;
    Py_ssize_t *src = NULL;
    unsigned char *flags = NULL;
    Prev pv, *pvp = NULL;
    /* offsets first: they give the sizes */
    if (take_buffer(a[7], &b[got], "offsets", 0, N_OFFSETS, 1) < 0)
        goto done;
    got++;
    const long long *off = b[0].buf;
    Py_ssize_t o[N_OFFSETS];
    for (int i = 0; i < N_OFFSETS; i++)
        o[i] = (Py_ssize_t)off[i];
    Py_ssize_t K, J, S = o[S_], n = o[NL], Y = o[Y_];
    if (take_buffer(a[1], &b[got], "s", 0, -1, 0) < 0)
        goto done;
    K = b[got++].len / 8;
    if (take_buffer(a[6], &b[got], "junctions", 0, -1, 0) < 0)
        goto done;
    J = b[got++].len / 8;
    if (K < 2) {
        PyErr_SetString(PyExc_ValueError, "s: at least 2 grid points");
        goto done;
    }
    struct { int i; const char *name; int w; Py_ssize_t n; } spec[] = {
        {0, "params", 0, -1}, {2, "base", 0, K * S}, {3, "v1", 0, K * n}, {4, "x_cap", 0, K},
        {5, "left", 0, J * S}, {8, "stage", 1, K * S}, {9, "x", 1, K}, {10, "sdd", 1, K},
        {11, "x_mvc", 1, K}, {12, "arrival_ok", 1, K - 1}, {13, "cap", 1, K},
        {14, "hi", 1, K}, {15, "y", 1, (K - 1) * Y}, {16, "x_raw", 1, K}};
    const double *ptr[17];
    for (size_t i = 0; i < sizeof(spec) / sizeof(spec[0]); i++) {
        if (take_buffer(a[spec[i].i], &b[got], spec[i].name, spec[i].w, spec[i].n, 0) < 0)
            goto done;
        ptr[spec[i].i] = b[got++].buf;
    }
    ptr[1] = b[1].buf;
    ptr[6] = b[2].buf;
    Py_ssize_t np_ = b[3].len / 8;
    /* prev: None, or (s, stage, x_mvc, cap, hi, y, x_raw) of the previous solve */
    if (prev != Py_None) {
        if (!PyTuple_Check(prev) || PyTuple_GET_SIZE(prev) != 7) {
            PyErr_SetString(PyExc_TypeError, "prev must be None or (s, stage, x_mvc, cap, hi, "
                            "y, x_raw) of the previous solve");
            goto done;
        }
        static const char *pn[7] = {"prev s", "prev stage", "prev x_mvc", "prev cap",
                                    "prev hi", "prev y", "prev x_raw"};
        const double *pp[7];
        for (int i = 0; i < 7; i++) {
            if (take_buffer(PyTuple_GET_ITEM(prev, i), &b[got], pn[i], 0, -1, 0) < 0)
                goto done;
            pp[i] = b[got++].buf;
        }
        pv.K = b[got - 7].len / 8;
        Py_ssize_t want[7] = {pv.K, pv.K * S, pv.K, pv.K, pv.K, (pv.K - 1) * Y, pv.K};
        for (int i = 0; i < 7; i++)
            if (pv.K < 2 || b[got - 7 + i].len / 8 != want[i]) {
                PyErr_Format(PyExc_ValueError, "%s does not fit the previous grid", pn[i]);
                goto done;
            }
        pv.s = pp[0], pv.stage = pp[1], pv.x_mvc = pp[2], pv.cap = pp[3], pv.hi = pp[4];
        pv.y = pp[5], pv.x_raw = pp[6];
        pvp = &pv;
    }
    if ((f.mvc = api->begin(fo[0], 2, 1)) == NULL || (f.back = api->begin(fo[1], 3, 2)) == NULL ||
        (f.fwd = api->begin(fo[2], 3, 2)) == NULL)
        goto done;
    if (api->nnz(f.mvc, 0) != S || api->nnz(f.mvc, 1) != np_ || api->nnz(f.mvc, 2) != 1 ||
        api->nnz(f.back, 0) != 1 || api->nnz(f.back, 1) != o[B_] || api->nnz(f.back, 2) != np_ ||
        api->nnz(f.back, 3) != 1 || api->nnz(f.back, 4) != 1 || api->nnz(f.fwd, 0) != 1 ||
        api->nnz(f.fwd, 1) != o[FI_] || api->nnz(f.fwd, 2) != np_ || api->nnz(f.fwd, 3) != 1 ||
        api->nnz(f.fwd, 4) != Y) {
        PyErr_SetString(PyExc_ValueError, "the generated functions do not fit the offsets");
        goto done;
    }
    Py_ssize_t nb = o[B_] > o[FI_] ? o[B_] : o[FI_];
    scratch = PyMem_Malloc((size_t)(2 * S + nb) * sizeof(double));
    src = PyMem_Malloc((size_t)K * sizeof(Py_ssize_t));
    flags = PyMem_Malloc((size_t)(4 * K));
    if (scratch == NULL || src == NULL || flags == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    int status;
    Py_BEGIN_ALLOW_THREADS
    status = run(&f, o, ptr[0], ptr[1], ptr[2], ptr[3], ptr[4], ptr[5], ptr[6], J, K, pvp,
                 (double *)ptr[8], (double *)ptr[9], (double *)ptr[10], (double *)ptr[11],
                 (double *)ptr[12], (double *)ptr[13], (double *)ptr[14], (double *)ptr[15],
                 (double *)ptr[16], scratch, src, flags);
    Py_END_ALLOW_THREADS
    result = PyLong_FromLong(status);
done:
    PyMem_Free(scratch);
    PyMem_Free(src);
    PyMem_Free(flags);
    api->end(f.mvc);
    api->end(f.back);
    api->end(f.fwd);
    for (int i = 0; i < got; i++)
        PyBuffer_Release(&b[i]);
    return result;
}

/* rows(coefficients, p, dp, ddp, theta, tau_max, outmap, rows, v1, sing) -> None
 *
 * Each point's own path_stage row (stages.point_stages): path_coefficients at (p, dp, ddp)
 * (K, m) each, its outputs written straight into the row: outmap (n_out + 2,) int64 gives each
 * output's offset in the row, -1 (not computed: the other split's polygon) or -2 (the
 * singularity measures, into sing (K, 2)), then v1's offset and length, copied into v1 (K, n)
 * too. The rest of each row (rho, delta, x_cap) is zero. */
static PyObject *rows(PyObject *self, PyObject *args)
{
    PyObject *fo, *a[9];
    if (!PyArg_ParseTuple(args, "OOOOOOOOOO", &fo, &a[0], &a[1], &a[2], &a[3], &a[4], &a[5],
                          &a[6], &a[7], &a[8]))
        return NULL;
    Py_buffer b[9];
    int got = 0;
    PyObject *result = NULL;
    Pm2dofCall *f = NULL;
    if (take_buffer(a[5], &b[got], "outmap", 0, -1, 1) < 0)
        goto done;
    got++;
    const long long *map = b[0].buf;
    Py_ssize_t n_map = b[0].len / 8;
    if ((f = api->begin(fo, 5, n_map - 2)) == NULL)
        goto done;
    Py_ssize_t n_out = n_map - 2, m = api->nnz(f, 0), K;
    if (take_buffer(a[0], &b[got], "p", 0, -1, 0) < 0)
        goto done;
    K = b[got++].len / 8 / (m ? m : 1);
    Py_ssize_t S = 0, n = (Py_ssize_t)map[n_map - 1], v1_off = (Py_ssize_t)map[n_map - 2];
    if (take_buffer(a[6], &b[got], "rows", 1, -1, 0) < 0)
        goto done;
    S = K ? b[got].len / 8 / K : 0;
    got++;
    struct { int i; const char *name; Py_ssize_t n; } spec[] = {
        {1, "dp", K * m}, {2, "ddp", K * m}, {3, "theta", api->nnz(f, 3)},
        {4, "tau_max", api->nnz(f, 4)}, {7, "v1", K * n}, {8, "sing", 2 * K}};
    double *ptr[9];
    ptr[0] = b[1].buf;
    ptr[6] = b[2].buf;
    for (size_t i = 0; i < sizeof(spec) / sizeof(spec[0]); i++) {
        if (take_buffer(a[spec[i].i], &b[got], spec[i].name, spec[i].i >= 7, spec[i].n, 0) < 0)
            goto done;
        ptr[spec[i].i] = b[got++].buf;
    }
    if (K == 0) {                     /* no point: nothing to write */
        result = Py_None;
        Py_INCREF(result);
        goto done;
    }
    if (b[1].len / 8 != K * m || b[2].len / 8 != K * S || api->nnz(f, 1) != m ||
        api->nnz(f, 2) != m || v1_off < 0 || v1_off + n > S) {
        PyErr_SetString(PyExc_ValueError, "rows: p, rows or outmap do not fit the function");
        goto done;
    }
    for (Py_ssize_t i = 0; i < n_out; i++) {
        Py_ssize_t d = (Py_ssize_t)map[i], nz = api->nnz(f, 5 + i);
        if ((d >= 0 && d + nz > S) || (d == -2 && nz != 2) || d < -2) {
            PyErr_Format(PyExc_ValueError, "rows: output %zd does not fit its place", i);
            goto done;
        }
    }
    double *res[64];
    if (n_out > 64) {
        PyErr_SetString(PyExc_ValueError, "rows: too many outputs");
        goto done;
    }
    int rc = 0;
    Py_ssize_t k;
    Py_BEGIN_ALLOW_THREADS
    for (k = 0; k < K && rc == 0; k++) {
        double *row = ptr[6] + k * S;
        memset(row, 0, (size_t)S * sizeof(double));
        for (Py_ssize_t i = 0; i < n_out; i++)
            res[i] = map[i] >= 0 ? row + map[i] : map[i] == -2 ? ptr[8] + 2 * k : NULL;
        const double *in[5] = {ptr[0] + k * m, ptr[1] + k * m, ptr[2] + k * m, ptr[3], ptr[4]};
        rc = api->eval(f, in, res);
        memcpy(ptr[7] + k * n, row + v1_off, (size_t)n * sizeof(double));
    }
    Py_END_ALLOW_THREADS
    if (rc != 0) {
        PyErr_Format(PyExc_RuntimeError, "path_coefficients returned error code %d at point "
                     "%zd", rc, k - 1);
        goto done;
    }
    result = Py_None;
    Py_INCREF(result);
done:
    api->end(f);
    for (int i = 0; i < got; i++)
        PyBuffer_Release(&b[i]);
    return result;
}

static PyMethodDef methods[] = {
    {"rows", rows, METH_VARARGS,
     "rows(coefficients, p, dp, ddp, theta, tau_max, outmap, rows, v1, sing): each point's "
     "own path_stage row, in place."},
    {"solve", solve, METH_VARARGS,
     "solve(mvc, backward, forward, params, s, base, v1, x_cap, left, junctions, offsets, "
     "stage, x, sdd, x_mvc, arrival_ok, cap, hi, y, x_raw, prev) -> 0, or 1 where the Python "
     "passes raise."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_passes",
    "The time-optimal planner's rows and passes on one grid in C (pm2dof.planning.cpasses).",
    -1, methods,
};

PyMODINIT_FUNC PyInit__passes(void)
{
    api = PyCapsule_Import(PM2DOF_CBIND_API, 0);
    if (api == NULL)
        return NULL;
    return PyModule_Create(&module);
}
