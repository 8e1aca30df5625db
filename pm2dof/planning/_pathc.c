/* pm2dof.planning._pathc: a TaskPath's p(s), p'(s), p''(s) at many arc lengths in one C call. */

/*
 * evaluate(table, s, right, p, dp, ddp)
 *   table  the path packed by pm2dof.planning.pathtable.pack (float64, layout there)
 *   s      arc lengths (k,), float64, finite and within [0, length] up to rounding (the caller
 *          checks; here they are clipped to [0, length] as TaskPath.evaluate documents)
 *   right  nonzero: at a junction the following piece, else the preceding one
 *   p, dp, ddp  outputs (k, dim) float64, C-contiguous, written in place
 *
 * Every formula is the NumPy one of pm2dof/planning/paths.py and spline.py, operation for
 * operation (compiled without contraction into fused multiply-adds), so the result equals it
 * bit for bit (tests/planning/test_pathc.py): the planner's plans do not move.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>

#include "_buffers.h"

enum { LINE = 0, ARC = 1, SPLINE = 2, ORIENTED = 3 };

/* NumPy's clip and searchsorted, as they treat finite numbers (np.clip: min(max(x, lo), hi)
   with the first argument kept on ties only when it compares greater / smaller) */
static inline double vmax(double a, double b) { return a > b ? a : b; }
static inline double vmin(double a, double b) { return a < b ? a : b; }
static inline double clip(double x, double lo, double hi) { return vmin(vmax(x, lo), hi); }

/* the number of a[0..n) <= x (right) or < x (left); a sorted */
static Py_ssize_t search(const double *a, Py_ssize_t n, double x, int right)
{
    Py_ssize_t lo = 0, hi = n;
    while (lo < hi) {
        Py_ssize_t mid = lo + (hi - lo) / 2;
        if (right ? a[mid] <= x : a[mid] < x)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

static inline Py_ssize_t iclip(Py_ssize_t i, Py_ssize_t lo, Py_ssize_t hi)
{
    return i < lo ? lo : i > hi ? hi : i;
}

/* one planar piece at its own arc length s: p, dp, ddp (2 each) */
static void planar(const double *d, double s, double *p, double *dp, double *ddp)
{
    int kind = (int)d[0];
    if (kind == LINE) {          /* length, p0 (2), p1 (2), u (2) */
        double lam = s / d[1];
        for (int i = 0; i < 2; i++) {
            p[i] = (1.0 - lam) * d[2 + i] + lam * d[4 + i];
            dp[i] = d[6 + i];
            ddp[i] = 0.0;
        }
    } else if (kind == ARC) {    /* c (2), r, a0, d */
        double r = d[3], dir = d[5];
        double phi = d[4] + dir * s / r;
        double e0 = cos(phi), e1 = sin(phi);
        dp[0] = dir * -e1;
        dp[1] = dir * e0;
        p[0] = d[1] + r * e0;
        p[1] = d[2] + r * e1;
        ddp[0] = -e0 / r;
        ddp[1] = -e1 / r;
    } else {                     /* SPLINE: m, nodes; u (m), P (m, 2), k1, k2, k3 (m-1, 2),
                                    nodes, s_nodes, du_ds (N each) */
        Py_ssize_t m = (Py_ssize_t)d[1], N = (Py_ssize_t)d[2];
        const double *u = d + 3, *P = u + m, *k1 = P + 2 * m, *k2 = k1 + 2 * (m - 1),
                     *k3 = k2 + 2 * (m - 1), *nodes = k3 + 2 * (m - 1), *sn = nodes + N,
                     *du = sn + N;
        /* u(s): the cubic Hermite interpolant of the arc-length table */
        Py_ssize_t k = iclip(search(sn, N, s, 1) - 1, 0, N - 2);
        double s0 = sn[k], s1 = sn[k + 1], u0 = nodes[k], u1 = nodes[k + 1];
        double h = s1 - s0;
        double t = (s - s0) / h;
        double t2 = t * t, t3 = t * t * t;
        double uu = (2 * t3 - 3 * t2 + 1) * u0 + (t3 - 2 * t2 + t) * h * du[k]
                    + (-2 * t3 + 3 * t2) * u1 + (t3 - t2) * h * du[k + 1];
        /* c, c', c'' on the span (Horner in B = u - u_j) */
        Py_ssize_t j = iclip(search(u, m, uu, 1) - 1, 0, m - 2);
        double B = uu - u[j], d1[2], d2[2];
        for (int i = 0; i < 2; i++) {
            double a1 = k1[2 * j + i], a2 = k2[2 * j + i], a3 = k3[2 * j + i];
            d1[i] = (3 * a3 * B + 2 * a2) * B + a1;
            p[i] = ((a3 * B + a2) * B + a1) * B + P[2 * j + i];
            d2[i] = 6 * a3 * B + 2 * a2;
        }
        double speed = hypot(d1[0], d1[1]);
        double t0 = d1[0] / speed, t1 = d1[1] / speed;
        double dot = d2[0] * t0 + d2[1] * t1;
        double sq = speed * speed;
        dp[0] = t0;
        dp[1] = t1;
        ddp[0] = (d2[0] - dot * t0) / sq;
        ddp[1] = (d2[1] - dot * t1) / sq;
    }
}

/* a piece with phi linear along it (a platform's path): has_planar, point (2), phi0, dphi,
   length, c, then the planar piece */
static void oriented(const double *d, double s, double *p, double *dp, double *ddp)
{
    double c = d[7];
    if (d[1] == 0.0) {
        p[0] = d[2];
        p[1] = d[3];
        dp[0] = dp[1] = ddp[0] = ddp[1] = 0.0;
    } else {
        planar(d + 8, c * s, p, dp, ddp);
        double cc = c * c;
        dp[0] *= c;
        dp[1] *= c;
        ddp[0] *= cc;
        ddp[1] *= cc;
    }
    p[2] = d[4] + d[5] * (s / d[6]);
    dp[2] = d[5] / d[6];
    ddp[2] = 0.0;
}

static PyObject *evaluate(PyObject *self, PyObject *args)
{
    PyObject *ot, *os, *op, *odp, *oddp;
    int right;
    if (!PyArg_ParseTuple(args, "OOpOOO", &ot, &os, &right, &op, &odp, &oddp))
        return NULL;
    Py_buffer b[5];
    PyObject *objs[5] = {ot, os, op, odp, oddp};
    const char *names[5] = {"table", "s", "p", "dp", "ddp"};
    int got = 0;
    PyObject *result = NULL;
    for (; got < 5; got++)
        if (take_buffer(objs[got], &b[got], names[got], got >= 2, -1, 0) < 0)
            goto done;
    const double *tab = b[0].buf, *s = b[1].buf;
    Py_ssize_t ntab = b[0].len / 8, k = b[1].len / 8;
    if (ntab < 2) {
        PyErr_SetString(PyExc_ValueError, "table: too short");
        goto done;
    }
    Py_ssize_t n = (Py_ssize_t)tab[0], dim = (Py_ssize_t)tab[1];
    if (n < 1 || (dim != 2 && dim != 3) || ntab < 2 + 3 * n + 1) {
        PyErr_SetString(PyExc_ValueError, "table: bad header");
        goto done;
    }
    for (int i = 2; i < 5; i++)
        if (b[i].len / 8 != k * dim) {
            PyErr_Format(PyExc_ValueError, "%s must hold %zd x %zd entries", names[i], k, dim);
            goto done;
        }
    const double *ends = tab + 2, *offset = ends + n + 1, *lengths = offset + n;
    double L = ends[n];
    double *p = b[2].buf, *dp = b[3].buf, *ddp = b[4].buf;
    for (Py_ssize_t i = 0; i < k; i++) {
        double si = clip(s[i], 0.0, L);
        Py_ssize_t j = n == 1 ? 0 : iclip(search(ends, n + 1, si, right) - 1, 0, n - 1);
        double local = clip(si - ends[j], 0.0, lengths[j]);
        const double *d = tab + (Py_ssize_t)offset[j];
        if (dim == 3)
            oriented(d, local, p + 3 * i, dp + 3 * i, ddp + 3 * i);
        else
            planar(d, local, p + 2 * i, dp + 2 * i, ddp + 2 * i);
    }
    result = Py_None;
    Py_INCREF(result);
done:
    for (int i = 0; i < got; i++)
        PyBuffer_Release(&b[i]);
    return result;
}

static PyMethodDef methods[] = {
    {"evaluate", evaluate, METH_VARARGS,
     "evaluate(table, s, right, p, dp, ddp): p(s), p'(s), p''(s) of a packed TaskPath into "
     "p, dp, ddp (k, dim), in place."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_pathc",
    "A TaskPath's p, p', p'' at many arc lengths in one C call (pm2dof.planning.pathtable).",
    -1, methods,
};

PyMODINIT_FUNC PyInit__pathc(void) { return PyModule_Create(&module); }
