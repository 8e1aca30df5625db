/* pm2dof.planning._passes: the time-optimal planner's rows and passes on one grid, in C. */

/*
 * solve(mvc, backward, forward, params, s, base, v1, x_cap, left, junctions, offsets,
 *       stage, x, sdd, x_mvc, arrival_ok) -> int
 *
 * What pm2dof.planning.grid.passes computes with no previous solve (prev=None), after
 * pm2dof.planning.stages.link, with the generated functions path_mvc, path_backward and
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
 *               pair and x_next_max, path_forward_output's size, x, sdd, L, U, Z, arrival_ok
 *   outputs     stage (K, S) the linked rows; x (K,) s_d^2 >= 0 (0 at the stops); sdd (K,)
 *               (the last repeats the one before); x_mvc (K,); arrival_ok (K - 1,)
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

static const Pm2dofCbindAPI *api;

enum { S_, RHO, NL, DELTA, XCAP, H, NF, P_, P_STAGE, P_NEXT, P_CAP, B_, B_PAIR, FI_, F_PAIR,
       F_XNM, Y_, Y_X, Y_SDD, Y_L, Y_U, Y_Z, Y_OK, N_OFFSETS };

static const double TOL = 1e-9; /* grid.py's _TOL */

typedef struct {
    Py_buffer v;
    const char *name;
} Buf;

static int get(PyObject *o, Buf *b, const char *name, int writable, Py_ssize_t n, int integer)
{
    b->name = name;
    if (PyObject_GetBuffer(o, &b->v, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT |
                                        (writable ? PyBUF_WRITABLE : 0)) < 0)
        return -1;
    const char *fmt = b->v.format ? b->v.format : "";
    int fits = integer ? strcmp(fmt, "l") == 0 || strcmp(fmt, "q") == 0 : strcmp(fmt, "d") == 0;
    if (b->v.itemsize != 8 || !fits || (n >= 0 && b->v.len / 8 != n)) {
        PyErr_Format(PyExc_ValueError, "%s must be a contiguous %s array of %zd entries", name,
                     integer ? "int64" : "float64", n);
        PyBuffer_Release(&b->v);
        return -1;
    }
    return 0;
}

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

static int run(const Calls *f, const Py_ssize_t *o, const double *prm, const double *s,
               const double *base, const double *v1, const double *x_cap, const double *left,
               const double *bp, Py_ssize_t J, Py_ssize_t K, double *stage, double *x,
               double *sdd, double *x_mvc, double *ok, double *scratch)
{
    const Py_ssize_t S = o[S_], n = o[NL];
    double *arr = scratch, *in = arr + S, *y = in + (o[B_] > o[FI_] ? o[B_] : o[FI_]),
           *hi = y + o[Y_] + 2, *cap = hi + K;   /* hi, cap: K each */
    double xs[2];
    int rc;
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
    /* the maximum-velocity curve; the arrival facets' own where they differ */
    for (Py_ssize_t k = 0; k < K; k++) {
        const double *a[2] = {stage + k * S, prm};
        double *r[1] = {x_mvc + k};
        if ((rc = api->eval(f->mvc, a, r)) != 0)
            return 1;
        if (x_mvc[k] < 0 || (x_mvc[k] <= 0 && x_cap[k] > 0))
            return 1;
    }
    for (Py_ssize_t k = 0; k < K; k++) {
        Py_ssize_t j = junction(bp, J, s[k]);
        arrive_row(o, stage, k, j >= 0 ? left + j * S : NULL, arr);
        int other = 0;
        for (Py_ssize_t c = 0; c < S && !other; c++)
            other = arr[c] != stage[k * S + c];
        cap[k] = x_mvc[k];
        if (other) {
            const double *a[2] = {arr, prm};
            double *r[1] = {cap + k};
            if ((rc = api->eval(f->mvc, a, r)) != 0)
                return 1;
        }
    }
    /* one pair per interval: stage k, arrive k + 1, cap k + 1 */
#define PAIR(dst, k)                                                                          \
    do {                                                                                      \
        Py_ssize_t jj = junction(bp, J, s[(k) + 1]);                                          \
        memcpy((dst) + o[P_STAGE], stage + (k) * S, (size_t)S * sizeof(double));              \
        arrive_row(o, stage, (k) + 1, jj >= 0 ? left + jj * S : NULL, (dst) + o[P_NEXT]);     \
        (dst)[o[P_CAP]] = cap[(k) + 1];                                                       \
    } while (0)
    /* backward from rest at the end: the controllable bounds hi */
    memset(in, 0, (size_t)o[B_] * sizeof(double));
    xs[0] = 0.0;
    hi[K - 1] = 0.0;
    for (Py_ssize_t k = K - 2; k >= 0; k--) {
        PAIR(in + o[B_PAIR], k);
        const double *a[3] = {xs, in, prm};
        double *r[2] = {xs + 1, hi + k};
        if ((rc = api->eval(f->back, a, r)) != 0)
            return 1;
        xs[0] = xs[1];
    }
    if (hi[0] < 0)
        return 1;
    /* forward from rest at the start */
    memset(in, 0, (size_t)o[FI_] * sizeof(double));
    xs[0] = 0.0;
    for (Py_ssize_t k = 0; k + 1 < K; k++) {
        PAIR(in + o[F_PAIR], k);
        in[o[F_XNM]] = hi[k + 1];
        const double *a[3] = {xs, in, prm};
        double *r[2] = {xs + 1, y};
        if ((rc = api->eval(f->fwd, a, r)) != 0)
            return 1;
        x[k] = y[o[Y_X]];
        sdd[k] = y[o[Y_SDD]];
        ok[k] = y[o[Y_OK]];
        /* grid.py's _check_forward: s_dd within [L, U], the free facets held */
        double u = y[o[Y_SDD]], scale = 1.0 > fabs(u) ? 1.0 : fabs(u), h = stage[k * S + o[H]];
        for (Py_ssize_t c = 1; c < o[NF]; c++)
            h = stage[k * S + o[H] + c] > h ? stage[k * S + o[H] + c] : h;
        if (u < y[o[Y_L]] - TOL * scale || u > y[o[Y_U]] + TOL * scale ||
            y[o[Y_Z]] < -TOL * h)
            return 1;
        xs[0] = xs[1];
    }
#undef PAIR
    x[K - 1] = xs[0];
    sdd[K - 1] = sdd[K - 2];
    for (Py_ssize_t k = 1; k < K; k++) {   /* landed at or above rest */
        double m = x_mvc[k] > 1e-12 ? x_mvc[k] : 1e-12;
        if (x[k] < -TOL * m)
            return 1;
    }
    for (Py_ssize_t k = 0; k < K; k++) {
        x[k] = x[k] >= 0.0 || isnan(x[k]) ? x[k] : 0.0;   /* np.maximum(x_raw, 0.0) */
        if (x_cap[k] == 0)
            x[k] = 0.0;
    }
    return 0;
}

static PyObject *solve(PyObject *self, PyObject *args)
{
    PyObject *fo[3], *a[13];
    if (!PyArg_ParseTuple(args, "OOOOOOOOOOOOOOOO", &fo[0], &fo[1], &fo[2], &a[0], &a[1],
                          &a[2], &a[3], &a[4], &a[5], &a[6], &a[7], &a[8], &a[9], &a[10],
                          &a[11], &a[12]))
        return NULL;
    Buf b[13];
    int got = 0;
    PyObject *result = NULL;
    Calls f = {NULL, NULL, NULL};
    double *scratch = NULL;
    /* offsets first: they give the sizes */
    if (get(a[7], &b[got], "offsets", 0, N_OFFSETS, 1) < 0)
        goto done;
    got++;
    const long long *off = b[0].v.buf;
    Py_ssize_t o[N_OFFSETS];
    for (int i = 0; i < N_OFFSETS; i++)
        o[i] = (Py_ssize_t)off[i];
    Py_ssize_t K, J, S = o[S_], n = o[NL];
    if (get(a[1], &b[got], "s", 0, -1, 0) < 0)
        goto done;
    K = b[got++].v.len / 8;
    if (get(a[6], &b[got], "junctions", 0, -1, 0) < 0)
        goto done;
    J = b[got++].v.len / 8;
    if (K < 2) {
        PyErr_SetString(PyExc_ValueError, "s: at least 2 grid points");
        goto done;
    }
    struct { int i; const char *name; int w; Py_ssize_t n; } spec[] = {
        {0, "params", 0, -1}, {2, "base", 0, K * S}, {3, "v1", 0, K * n}, {4, "x_cap", 0, K},
        {5, "left", 0, J * S}, {8, "stage", 1, K * S}, {9, "x", 1, K}, {10, "sdd", 1, K},
        {11, "x_mvc", 1, K}, {12, "arrival_ok", 1, K - 1}};
    const double *ptr[13];
    for (size_t i = 0; i < sizeof(spec) / sizeof(spec[0]); i++) {
        if (get(a[spec[i].i], &b[got], spec[i].name, spec[i].w, spec[i].n, 0) < 0)
            goto done;
        ptr[spec[i].i] = b[got++].v.buf;
    }
    ptr[1] = b[1].v.buf;
    ptr[6] = b[2].v.buf;
    Py_ssize_t np_ = b[3].v.len / 8;
    if ((f.mvc = api->begin(fo[0], 2, 1)) == NULL || (f.back = api->begin(fo[1], 3, 2)) == NULL ||
        (f.fwd = api->begin(fo[2], 3, 2)) == NULL)
        goto done;
    if (api->nnz(f.mvc, 0) != S || api->nnz(f.mvc, 1) != np_ || api->nnz(f.mvc, 2) != 1 ||
        api->nnz(f.back, 0) != 1 || api->nnz(f.back, 1) != o[B_] || api->nnz(f.back, 2) != np_ ||
        api->nnz(f.back, 3) != 1 || api->nnz(f.back, 4) != 1 || api->nnz(f.fwd, 0) != 1 ||
        api->nnz(f.fwd, 1) != o[FI_] || api->nnz(f.fwd, 2) != np_ || api->nnz(f.fwd, 3) != 1 ||
        api->nnz(f.fwd, 4) != o[Y_]) {
        PyErr_SetString(PyExc_ValueError, "the generated functions do not fit the offsets");
        goto done;
    }
    Py_ssize_t nb = o[B_] > o[FI_] ? o[B_] : o[FI_];
    scratch = PyMem_Malloc((size_t)(S + nb + o[Y_] + 2 + 2 * K) * sizeof(double));
    if (scratch == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    int status;
    Py_BEGIN_ALLOW_THREADS
    status = run(&f, o, ptr[0], ptr[1], ptr[2], ptr[3], ptr[4], ptr[5], ptr[6], J, K,
                 (double *)ptr[8], (double *)ptr[9], (double *)ptr[10], (double *)ptr[11],
                 (double *)ptr[12], scratch);
    Py_END_ALLOW_THREADS
    result = PyLong_FromLong(status);
done:
    PyMem_Free(scratch);
    api->end(f.mvc);
    api->end(f.back);
    api->end(f.fwd);
    for (int i = 0; i < got; i++)
        PyBuffer_Release(&b[i].v);
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
    Buf b[9];
    int got = 0;
    PyObject *result = NULL;
    Pm2dofCall *f = NULL;
    if (get(a[5], &b[got], "outmap", 0, -1, 1) < 0)
        goto done;
    got++;
    const long long *map = b[0].v.buf;
    Py_ssize_t n_map = b[0].v.len / 8;
    if ((f = api->begin(fo, 5, n_map - 2)) == NULL)
        goto done;
    Py_ssize_t n_out = n_map - 2, m = api->nnz(f, 0), K;
    if (get(a[0], &b[got], "p", 0, -1, 0) < 0)
        goto done;
    K = b[got++].v.len / 8 / (m ? m : 1);
    Py_ssize_t S = 0, n = (Py_ssize_t)map[n_map - 1], v1_off = (Py_ssize_t)map[n_map - 2];
    if (get(a[6], &b[got], "rows", 1, -1, 0) < 0)
        goto done;
    S = K ? b[got].v.len / 8 / K : 0;
    got++;
    struct { int i; const char *name; Py_ssize_t n; } spec[] = {
        {1, "dp", K * m}, {2, "ddp", K * m}, {3, "theta", api->nnz(f, 3)},
        {4, "tau_max", api->nnz(f, 4)}, {7, "v1", K * n}, {8, "sing", 2 * K}};
    double *ptr[9];
    ptr[0] = b[1].v.buf;
    ptr[6] = b[2].v.buf;
    for (size_t i = 0; i < sizeof(spec) / sizeof(spec[0]); i++) {
        if (get(a[spec[i].i], &b[got], spec[i].name, spec[i].i >= 7, spec[i].n, 0) < 0)
            goto done;
        ptr[spec[i].i] = b[got++].v.buf;
    }
    if (b[1].v.len / 8 != K * m || b[2].v.len / 8 != K * S || api->nnz(f, 1) != m ||
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
        PyBuffer_Release(&b[i].v);
    return result;
}

static PyMethodDef methods[] = {
    {"rows", rows, METH_VARARGS,
     "rows(coefficients, p, dp, ddp, theta, tau_max, outmap, rows, v1, sing): each point's "
     "own path_stage row, in place."},
    {"solve", solve, METH_VARARGS,
     "solve(mvc, backward, forward, params, s, base, v1, x_cap, left, junctions, offsets, "
     "stage, x, sdd, x_mvc, arrival_ok) -> 0, or 1 where the Python passes raise."},
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
