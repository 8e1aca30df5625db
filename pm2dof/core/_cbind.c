/* pm2dof.core._cbind: near-zero-overhead calls from Python into CasADi-generated C functions loaded with dlopen. */

/*
 * Overview
 * --------
 * Library(path)          dlopen()s a shared library built from CasADi-generated C code.
 * Function(lib, name)    resolves the CasADi external C API of one function
 *                        (name, name_n_in, name_sparsity_in, name_work, ...), checks that
 *                        every input/output is dense, and allocates the work arrays once.
 * f(*inputs, *outputs)   binds flat float64 buffers to arg/res and calls the function.
 *                        Outputs are written in place; None as an output means "don't
 *                        compute it" (NULL res pointer).
 * f.accumulate(...)      runs a whole x_{k+1}, y_k = f(x_k, u_k, p) rollout in C.
 * f.time_calls(...)      times back-to-back calls inside a C loop.
 * Function(lib, name, fixed=d)  binds the last input, "design", to a copy of d once for
 *                        all: the Function then has one input fewer, and every call path
 *                        (plain calls, map, accumulate, time_calls, Method) runs with d.
 * f.clone(fixed=d2)      the same function at another design from what f resolved (no
 *                        dlsym): a Model at another design rebinds its functions this way.
 *
 * The binding is layout-agnostic: it passes the buffers' memory as the flat nonzero
 * vectors CasADi expects. CasADi stores matrices column-major, so a 2x3 matrix argument
 * must be given as its 6 column-major entries (e.g. numpy order='F' flattened, or the
 * transpose of a C-ordered array); the binding only checks the element count.
 *
 * Per-call cost: no heap allocation and no Python object creation on the success path.
 * Buffer views are stored in an array owned by the Function (allocated once) and are
 * released before returning, on every path. If the Function is already in use (another
 * thread while accumulate/time_calls run without the GIL, or re-entrancy from a buffer
 * exporter), the call transparently uses a temporary work area instead.
 */

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include "structmember.h"
#include "_cbind_api.h"

#include <dlfcn.h>
#include <math.h>
#include <float.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <time.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* CasADi's defaults (see the generated header): casadi_real = double, casadi_int = long long. */
typedef double casadi_real;
typedef long long int casadi_int;

_Static_assert(sizeof(double) == 8, "float64 buffers require an 8-byte double");

typedef int (*eval_fn)(const casadi_real **arg, casadi_real **res, casadi_int *iw,
                       casadi_real *w, int mem);
typedef int (*work_fn)(casadi_int *sz_arg, casadi_int *sz_res, casadi_int *sz_iw,
                       casadi_int *sz_w);
typedef casadi_int (*count_fn)(void);
typedef const casadi_int *(*sparsity_fn)(casadi_int i);
typedef const char *(*name_fn)(casadi_int i);
typedef int (*checkout_fn)(void);
typedef void (*release_fn)(int mem);
typedef void (*void_fn)(void);
typedef int (*int_fn)(void);

/* Sanity limit on the number of inputs/outputs reported by a library. */
#define MAX_ARGS 4096
/* Longest accepted function name (bytes); symbol names add a short suffix. */
#define MAX_NAME 400

static PyObject *EvalError;
static PyObject *NonFiniteOutputError;

/* ------------------------------------------------------------------------------------ */
/* Library                                                                              */
/* ------------------------------------------------------------------------------------ */

typedef struct {
    PyObject_HEAD
    void *handle;   /* from dlopen, closed on dealloc */
    PyObject *path; /* str */
} LibraryObject;

static PyObject *
Library_new(PyTypeObject *type, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {"path", NULL};
    PyObject *path_bytes = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "O&:Library", kwlist,
                                     PyUnicode_FSConverter, &path_bytes))
        return NULL;
    const char *cpath = PyBytes_AS_STRING(path_bytes);

    (void)dlerror(); /* clear any stale error */
    void *handle = dlopen(cpath, RTLD_NOW | RTLD_LOCAL);
    if (handle == NULL) {
        const char *msg = dlerror();
        PyErr_Format(PyExc_OSError, "cannot load shared library '%s': %s", cpath,
                     msg ? msg : "unknown dlopen error");
        Py_DECREF(path_bytes);
        return NULL;
    }
    LibraryObject *self = (LibraryObject *)type->tp_alloc(type, 0);
    if (self == NULL) {
        dlclose(handle);
        Py_DECREF(path_bytes);
        return NULL;
    }
    self->handle = handle;
    self->path = PyUnicode_DecodeFSDefaultAndSize(PyBytes_AS_STRING(path_bytes),
                                                  PyBytes_GET_SIZE(path_bytes));
    Py_DECREF(path_bytes);
    if (self->path == NULL) {
        Py_DECREF(self);
        return NULL;
    }
    return (PyObject *)self;
}

static void
Library_dealloc(LibraryObject *self)
{
    if (self->handle)
        dlclose(self->handle);
    Py_XDECREF(self->path);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyObject *
Library_repr(LibraryObject *self)
{
    return PyUnicode_FromFormat("<Library %R>", self->path);
}

static PyMemberDef Library_members[] = {
    {"path", T_OBJECT_EX, offsetof(LibraryObject, path), READONLY,
     "Path the library was loaded from (str)."},
    {NULL, 0, 0, 0, NULL},
};

PyDoc_STRVAR(Library_doc,
"Library(path)\n"
"--\n\n"
"A shared library loaded with dlopen(path, RTLD_NOW | RTLD_LOCAL).\n\n"
"Raises OSError (with the dlerror() text) if it cannot be loaded. The library is\n"
"dlclose()d when the object is garbage-collected; Function objects keep a reference\n"
"to their Library. Note that dlopen() returns the already-loaded library for a path\n"
"that is still open in this process, so a library rebuilt in place is only reloaded\n"
"once every Library for that path (and every Function using it) is gone.");

static PyTypeObject LibraryType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "pm2dof.core._cbind.Library",
    .tp_basicsize = sizeof(LibraryObject),
    .tp_dealloc = (destructor)Library_dealloc,
    .tp_repr = (reprfunc)Library_repr,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = Library_doc,
    .tp_members = Library_members,
    .tp_new = Library_new,
};

/* ------------------------------------------------------------------------------------ */
/* Function                                                                             */
/* ------------------------------------------------------------------------------------ */

/* Everything one evaluation needs; a Function owns one, busy callers get a temporary. */
typedef struct {
    const casadi_real **arg; /* max(sz_arg, n_in) entries */
    casadi_real **res;       /* max(sz_res, n_out) entries */
    casadi_int *iw;          /* sz_iw */
    casadi_real *w;          /* sz_w */
    casadi_real *scalars;    /* n_in: Python numbers passed for 1-element inputs */
    casadi_real *xbuf;       /* nx: accumulate ping-pong state (NULL if not applicable) */
    Py_buffer *views;        /* n_in + n_out held buffer views */
    unsigned char *how;      /* n_in + n_out: how each argument was bound (BOUND_*) */
    int mem;                 /* from checkout() */
    int checked_out;
} Work;

typedef struct {
    PyObject_HEAD
    vectorcallfunc vectorcall;
    LibraryObject *lib;
    PyObject *name;      /* str */
    PyObject *signature; /* str, e.g. "f(x[3], p[1]) -> (y[2])" */
    PyObject *names_in, *names_out;   /* tuple of str */
    PyObject *sizes_in, *sizes_out;   /* tuple of int */
    PyObject *shapes_in, *shapes_out; /* tuple of (nrow, ncol) */
    Py_ssize_t n_in, n_out;
    Py_ssize_t *nnz; /* n_in + n_out element counts (outputs start at nnz + n_in) */
    unsigned char *vec; /* per argument: 1 if a vector (k x 1 or 1 x k): must be 1-D */
    double *fixed;      /* owned copy of the bound "design" input (arg[n_in]), or NULL */
    Py_ssize_t n_fixed; /* its element count */
    casadi_int sz_arg, sz_res, sz_iw, sz_w;
    eval_fn eval;
    checkout_fn checkout;
    release_fn release;
    void_fn incref; /* kept for clone() */
    void_fn decref;
    int increfed;
    int acc_ok; /* signature fits accumulate: 3 inputs, 2 outputs, nnz_out[0] == nnz_in[0] */
    int busy;   /* primary work area in use */
    char check_outputs; /* raise ValueError when a call leaves a non-finite output */
    Work work;
} FunctionObject;

/* ---- work areas ---- */

static void
work_free(FunctionObject *f, Work *w)
{
    if (w->checked_out && f->release)
        f->release(w->mem);
    w->checked_out = 0;
    PyMem_Free((void *)w->arg);
    PyMem_Free(w->res);
    PyMem_Free(w->iw);
    PyMem_Free(w->w);
    PyMem_Free(w->scalars);
    PyMem_Free(w->xbuf);
    PyMem_Free(w->views);
    PyMem_Free(w->how);
    memset(w, 0, sizeof(*w));
}

static int
work_init(FunctionObject *f, Work *w)
{
    memset(w, 0, sizeof(*w));
    /* with a bound design the function's real inputs are n_in + 1 (CasADi's sz_arg
       covers them; the max is a guard) */
    const Py_ssize_t n_in_all = f->n_in + (f->fixed != NULL);
    size_t n_arg = (size_t)(f->sz_arg > n_in_all ? f->sz_arg : n_in_all);
    size_t n_res = (size_t)(f->sz_res > f->n_out ? f->sz_res : f->n_out);
    /* +1 everywhere: never ask for zero bytes */
    w->arg = PyMem_Calloc(n_arg + 1, sizeof(*w->arg));
    w->res = PyMem_Calloc(n_res + 1, sizeof(*w->res));
    w->iw = PyMem_Calloc((size_t)f->sz_iw + 1, sizeof(*w->iw));
    w->w = PyMem_Calloc((size_t)f->sz_w + 1, sizeof(*w->w));
    w->scalars = PyMem_Calloc((size_t)f->n_in + 1, sizeof(*w->scalars));
    w->views = PyMem_Calloc((size_t)(f->n_in + f->n_out) + 1, sizeof(*w->views));
    w->how = PyMem_Calloc((size_t)(f->n_in + f->n_out) + 1, sizeof(*w->how));
    if (f->acc_ok)
        w->xbuf = PyMem_Calloc((size_t)f->nnz[0] + 1, sizeof(*w->xbuf));
    if (!w->arg || !w->res || !w->iw || !w->w || !w->scalars || !w->views || !w->how ||
        (f->acc_ok && !w->xbuf)) {
        work_free(f, w);
        PyErr_NoMemory();
        return -1;
    }
    if (f->checkout) {
        int mem = f->checkout();
        if (mem < 0) {
            work_free(f, w);
            PyErr_Format(EvalError, "%U: checkout() failed (returned %d)", f->name, mem);
            return -1;
        }
        w->mem = mem;
        w->checked_out = 1;
    }
    /* The bound design: set once per work area. The binding writes arg[] only at the
       visible inputs (0..n_in-1) and generated code only at its own n_in and beyond (the
       arguments of nested calls), so the slot keeps this pointer: no cost per call. */
    if (f->fixed)
        w->arg[f->n_in] = f->fixed;
    return 0;
}

/* Primary work area if free, else a freshly initialised temporary in *tmp. */
static Work *
work_acquire(FunctionObject *f, Work *tmp)
{
    if (!f->busy) {
        f->busy = 1;
        return &f->work;
    }
    if (work_init(f, tmp) < 0)
        return NULL;
    return tmp;
}

static void
work_done(FunctionObject *f, Work *w, Py_ssize_t held)
{
    for (Py_ssize_t k = 0; k < held; k++)
        PyBuffer_Release(&w->views[k]);
    if (w == &f->work)
        f->busy = 0;
    else
        work_free(f, w);
}

/* ---- error messages ---- */

/* Which argument an error is about; only formatted into text on error paths. */
typedef struct {
    const char *method; /* NULL for a plain call, else "time_calls" / "accumulate" */
    const char *accarg; /* accumulate's own argument name, or NULL */
    int is_out;
    Py_ssize_t idx;
} ArgCtx;

static void
arg_error(FunctionObject *f, PyObject *exc, const ArgCtx *c, const char *fmt, ...)
{
    PyObject *nm = PyTuple_GET_ITEM(c->is_out ? f->names_out : f->names_in, c->idx);
    const char *kind = c->is_out ? "output" : "input";
    PyObject *label;
    if (c->accarg)
        label = PyUnicode_FromFormat("%U.%s: argument '%s' (%s '%U' #%zd)", f->name,
                                     c->method, c->accarg, kind, nm, c->idx);
    else if (c->method)
        label = PyUnicode_FromFormat("%U.%s: %s '%U' (#%zd)", f->name, c->method, kind, nm,
                                     c->idx);
    else
        label = PyUnicode_FromFormat("%U: %s '%U' (#%zd)", f->name, kind, nm, c->idx);
    if (label == NULL)
        return;
    va_list va;
    va_start(va, fmt);
    PyObject *detail = PyUnicode_FromFormatV(fmt, va);
    va_end(va);
    if (detail != NULL)
        PyErr_Format(exc, "%U %U", label, detail);
    Py_DECREF(label);
    Py_XDECREF(detail);
}

/* ---- argument checks ---- */

/* True for a struct-module format describing one native float64. */
static int
format_is_f64(const char *fmt)
{
    if (fmt == NULL) /* NULL means unsigned bytes */
        return 0;
    if (fmt[0] == '@' || fmt[0] == '=')
        fmt++;
#if PY_LITTLE_ENDIAN
    else if (fmt[0] == '<')
        fmt++;
#else
    else if (fmt[0] == '>' || fmt[0] == '!')
        fmt++;
#endif
    return fmt[0] == 'd' && fmt[1] == '\0';
}

/*
 * numpy fast path
 * ---------------
 * numpy's buffer export builds and compares a format string on every request (~60 ns
 * here), which would dominate a call with several small arrays. For an exact
 * numpy.ndarray, a plain call (GIL held from binding to the end of the evaluation, so
 * the array cannot be resized or freed meanwhile) reads the array's public C struct
 * instead (the documented PyArrayObject_fields / PyArray_Descr layout, unchanged in
 * numpy 1.x and 2.x) and takes the pointer if the array is exactly what is needed:
 * float64 in native byte order, C-contiguous, aligned, writable for outputs, with the
 * right element count. Anything else goes through the buffer protocol, which produces
 * the precise error messages. The struct layout is checked once against a real buffer
 * export of the first ndarray seen; on any mismatch the fast path is disabled for good.
 * numpy headers are not needed at build time.
 */
typedef struct {
    PyObject_HEAD
    PyTypeObject *typeobj;
    char kind, type, byteorder, former_flags;
    int type_num;
} NpDescr;

typedef struct {
    PyObject_HEAD
    char *data;
    int nd;
    Py_ssize_t *dimensions;
    Py_ssize_t *strides;
    PyObject *base;
    NpDescr *descr;
    int flags;
} NpArray;

#define NP_C_CONTIGUOUS 0x0001
#define NP_ALIGNED 0x0100
#define NP_WRITEABLE 0x0400
#define NP_WARN_ON_WRITE ((int)(1u << 31))
#define NP_DOUBLE 12
#if PY_LITTLE_ENDIAN
#define NP_NATIVE_ORDER '<'
#else
#define NP_NATIVE_ORDER '>'
#endif

static PyTypeObject *np_type; /* numpy.ndarray once its layout was verified */
static int np_disabled;       /* layout check failed: never use the fast path */

static const NpDescr *np_f64_descr; /* a float64 descriptor seen before (a reference held) */

static inline int
np_descr_is_f64(const NpDescr *d)
{
    if (d == np_f64_descr) /* numpy's float64 is one object: one comparison */
        return 1;
    if (d->type_num == NP_DOUBLE && d->type == 'd' && d->kind == 'f' &&
        (d->byteorder == '=' || d->byteorder == NP_NATIVE_ORDER)) {
        if (np_f64_descr == NULL) { /* kept alive, so its address is never another's */
            Py_INCREF((PyObject *)d);
            np_f64_descr = d;
        }
        return 1;
    }
    return 0;
}

/* Verify our view of the struct against a buffer export of one array. */
static void
np_probe(PyObject *o)
{
    Py_buffer v;
    if (PyObject_GetBuffer(o, &v, PyBUF_RECORDS_RO) < 0) {
        PyErr_Clear(); /* e.g. object arrays: try again with another array */
        return;
    }
    const NpArray *a = (const NpArray *)o;
    int ok = Py_TYPE(o)->tp_basicsize >= (Py_ssize_t)sizeof(NpArray) && v.buf == a->data &&
             v.ndim == a->nd && v.shape != NULL && v.strides != NULL;
    for (int k = 0; ok && k < v.ndim; k++)
        ok = v.shape[k] == a->dimensions[k] && v.strides[k] == a->strides[k];
    /* Only now is a->descr known to be at the assumed offset. */
    ok = ok && a->descr != NULL &&
         (np_descr_is_f64(a->descr) == (v.itemsize == 8 && format_is_f64(v.format)));
    if (ok && !(a->flags & NP_WARN_ON_WRITE))
        ok = v.readonly == !(a->flags & NP_WRITEABLE);
    PyBuffer_Release(&v);
    if (ok) {
        Py_INCREF(Py_TYPE(o));
        np_type = Py_TYPE(o);
    }
    else {
        np_disabled = 1;
    }
}

static inline int
np_is_ndarray(PyObject *o)
{
    PyTypeObject *t = Py_TYPE(o);
    if (t == np_type)
        return 1;
    if (np_type == NULL && !np_disabled && strcmp(t->tp_name, "numpy.ndarray") == 0) {
        np_probe(o);
        return t == np_type;
    }
    return 0;
}

/* A vector argument takes a 1-D buffer (a 0-d one too when it has one element). */
static inline int
ndim_ok(int is_vec, int ndim, Py_ssize_t expect)
{
    return !is_vec || ndim == 1 || (ndim == 0 && expect == 1);
}

/* Data pointer of an ndarray that is exactly right for the argument, else NULL. */
static inline double *
np_fast(PyObject *o, int writable, Py_ssize_t expect, int is_vec)
{
    const NpArray *a = (const NpArray *)o;
    int need = NP_C_CONTIGUOUS | NP_ALIGNED | (writable ? NP_WRITEABLE : 0);
    if ((a->flags & need) != need || (writable && (a->flags & NP_WARN_ON_WRITE)) ||
        !np_descr_is_f64(a->descr) || !ndim_ok(is_vec, a->nd, expect))
        return NULL;
    /* a vector: its length (written so: 12 instructions fewer per call than if/else) */
    Py_ssize_t n = a->nd == 1 ? a->dimensions[0] : 1;
    if (a->nd != 1)
        for (int k = 0; k < a->nd; k++)
            n *= a->dimensions[k];
    return n == expect ? (double *)a->data : NULL;
}

/* The usual argument, a vector of exactly n float64 elements with the flags `need` (and not
   warning on write): its data pointer in one test, else NULL (then np_fast decides). */
static inline double *
np_vector(PyObject *o, Py_ssize_t n, int need)
{
    const NpArray *a = (const NpArray *)o;
    return a->nd == 1 && a->dimensions[0] == n && a->descr == np_f64_descr &&
                   (a->flags & (need | NP_WARN_ON_WRITE)) == need
               ? (double *)a->data
               : NULL;
}

/*
 * Get a C-contiguous, aligned float64 buffer from obj into *view. On failure sets an
 * exception and holds no view. The element count is checked by the caller.
 */
static int
get_f64_buffer(FunctionObject *f, PyObject *obj, Py_buffer *view, int writable,
               int scalar_ok, const ArgCtx *c)
{
    int flags = PyBUF_STRIDES | PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0);
    if (PyObject_GetBuffer(obj, view, flags) < 0) {
        if (!PyObject_CheckBuffer(obj)) {
            PyErr_Clear();
            arg_error(f, PyExc_TypeError, c,
                      "must be a C-contiguous float64 buffer%s, got %s",
                      scalar_ok ? " or a Python float" : "", Py_TYPE(obj)->tp_name);
            return -1;
        }
        if (writable) {
            /* Distinguish "read-only" from other export failures. */
            PyObject *et, *ev, *tb;
            PyErr_Fetch(&et, &ev, &tb);
            if (PyObject_GetBuffer(obj, view, PyBUF_STRIDES | PyBUF_FORMAT) == 0) {
                PyBuffer_Release(view);
                Py_XDECREF(et);
                Py_XDECREF(ev);
                Py_XDECREF(tb);
                arg_error(f, PyExc_ValueError, c, "must be writable, got a read-only %s",
                          Py_TYPE(obj)->tp_name);
                return -1;
            }
            PyErr_Clear();
            PyErr_Restore(et, ev, tb);
        }
        /* Keep the exporter's message, prefixed with the argument. */
        PyObject *et, *ev, *tb;
        PyErr_Fetch(&et, &ev, &tb);
        PyErr_NormalizeException(&et, &ev, &tb);
        arg_error(f, PyExc_TypeError, c, "cannot export a float64 buffer from %s: %S",
                  Py_TYPE(obj)->tp_name, ev ? ev : Py_None);
        Py_XDECREF(et);
        Py_XDECREF(ev);
        Py_XDECREF(tb);
        return -1;
    }
    if (view->itemsize != 8 || !format_is_f64(view->format)) {
        arg_error(f, PyExc_TypeError, c,
                  "must have dtype float64 (buffer format 'd'), got format '%s' "
                  "(itemsize %zd) from %s",
                  view->format ? view->format : "B", view->itemsize, Py_TYPE(obj)->tp_name);
        PyBuffer_Release(view);
        return -1;
    }
    if (!PyBuffer_IsContiguous(view, 'C')) {
        arg_error(f, PyExc_ValueError, c, "must be C-contiguous, got a strided %s",
                  Py_TYPE(obj)->tp_name);
        PyBuffer_Release(view);
        return -1;
    }
    if (((uintptr_t)view->buf & 7u) != 0 && view->len > 0) {
        arg_error(f, PyExc_ValueError, c, "must be 8-byte aligned, got a misaligned %s",
                  Py_TYPE(obj)->tp_name);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

/* Whether p[0..n) is all finite (|x| <= DBL_MAX: false for inf and NaN). With SSE2 (every
   x86-64) two elements per comparison, four in two chains on long arrays, and no branch but
   the loop's; elsewhere an exponent field of all ones (inf or NaN) is looked for branch-free
   in four chains. The error paths find the index. */
#if defined(__SSE2__)
static inline int
all_finite(const double *p, Py_ssize_t n)
{
    const __m128d mag = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
    const __m128d big = _mm_set1_pd(DBL_MAX);
    __m128d ok0 = _mm_castsi128_pd(_mm_set1_epi64x(-1)), ok1 = ok0;
    Py_ssize_t k = 0;
    for (; k + 4 <= n; k += 4) {
        ok0 = _mm_and_pd(ok0, _mm_cmple_pd(_mm_and_pd(_mm_loadu_pd(p + k), mag), big));
        ok1 = _mm_and_pd(ok1, _mm_cmple_pd(_mm_and_pd(_mm_loadu_pd(p + k + 2), mag), big));
    }
    if (k + 2 <= n) {
        ok0 = _mm_and_pd(ok0, _mm_cmple_pd(_mm_and_pd(_mm_loadu_pd(p + k), mag), big));
        k += 2;
    }
    if (k < n)
        ok1 = _mm_and_pd(ok1, _mm_cmple_pd(_mm_and_pd(_mm_load_sd(p + k), mag), big));
    return _mm_movemask_pd(_mm_and_pd(ok0, ok1)) == 3;
}
#else
static inline int
all_finite(const double *p, Py_ssize_t n)
{
    /* (b & exponent) + one exponent step carries into the sign bit only from all ones */
    uint64_t bad0 = 0, bad1 = 0, bad2 = 0, bad3 = 0, b0, b1, b2, b3;
    Py_ssize_t k = 0;
    for (; k + 4 <= n; k += 4) {
        memcpy(&b0, p + k, sizeof b0);
        memcpy(&b1, p + k + 1, sizeof b1);
        memcpy(&b2, p + k + 2, sizeof b2);
        memcpy(&b3, p + k + 3, sizeof b3);
        bad0 |= (b0 & 0x7ff0000000000000ull) + 0x0010000000000000ull;
        bad1 |= (b1 & 0x7ff0000000000000ull) + 0x0010000000000000ull;
        bad2 |= (b2 & 0x7ff0000000000000ull) + 0x0010000000000000ull;
        bad3 |= (b3 & 0x7ff0000000000000ull) + 0x0010000000000000ull;
    }
    for (; k < n; k++) {
        memcpy(&b0, p + k, sizeof b0);
        bad0 |= (b0 & 0x7ff0000000000000ull) + 0x0010000000000000ull;
    }
    return ((bad0 | bad1 | bad2 | bad3) >> 63) == 0;
}
#endif

/* Index of the first non-finite value in p[0..n), or -1: a long array is tested whole
   first, branch-free (all_finite), and searched only when something is not finite. */
static inline Py_ssize_t
first_nonfinite(const double *p, Py_ssize_t n)
{
    if (n >= 8 && all_finite(p, n))
        return -1;
    for (Py_ssize_t k = 0; k < n; k++)
        if (!isfinite(p[k]))
            return k;
    return -1;
}

static int
check_finite(FunctionObject *f, const double *p, Py_ssize_t n, const ArgCtx *c)
{
    Py_ssize_t k = first_nonfinite(p, n);
    if (k < 0)
        return 0;
    const char *v = isnan(p[k]) ? "nan" : (p[k] > 0 ? "inf" : "-inf");
    arg_error(f, PyExc_ValueError, c, "has a non-finite value at index %zd (%s)", k, v);
    return -1;
}

/* Refuse a vector argument given as a 2-D (or higher) buffer: name it and both shapes. */
static int
check_ndim(FunctionObject *f, const Py_buffer *v, Py_ssize_t expect, int is_vec,
           const ArgCtx *c)
{
    if (ndim_ok(is_vec, v->ndim, expect))
        return 0;
    PyObject *shape = PyTuple_New(v->ndim);
    if (shape == NULL)
        return -1;
    for (int k = 0; k < v->ndim; k++) {
        PyObject *d = PyLong_FromSsize_t(v->shape ? v->shape[k] : 0);
        if (d == NULL) {
            Py_DECREF(shape);
            return -1;
        }
        PyTuple_SET_ITEM(shape, k, d);
    }
    arg_error(f, PyExc_ValueError, c, "must have shape (%zd,), got shape %R", expect, shape);
    Py_DECREF(shape);
    return -1;
}

/* How an argument was bound. */
enum { BOUND_NONE, BOUND_SCALAR, BOUND_FAST, BOUND_NUMPY_EXPORT, BOUND_FOREIGN_EXPORT };

/*
 * Bind one input through the buffer protocol, or as a Python float/int when expect == 1
 * (copied to w->scalars[c->idx]). A view is appended to w->views[*held]. expect < 0
 * accepts any element count. Finiteness is checked by the caller, after all arguments
 * are bound (a foreign exporter could run Python code that changes earlier arguments).
 */
static int
bind_input(FunctionObject *f, Work *w, PyObject *o, Py_ssize_t *held, const ArgCtx *c,
           Py_ssize_t expect, int is_vec, const double **data, Py_ssize_t *count)
{
    Py_ssize_t i = c->idx;
    if (expect == 1 && PyFloat_Check(o)) {
        w->scalars[i] = PyFloat_AS_DOUBLE(o);
    }
    else if (expect == 1 && PyLong_Check(o)) {
        double v = PyLong_AsDouble(o); /* never runs Python code */
        if (v == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            arg_error(f, PyExc_OverflowError, c, "is an int too large for a float64");
            return -1;
        }
        w->scalars[i] = v;
    }
    else if (o == Py_None) {
        arg_error(f, PyExc_TypeError, c,
                  "cannot be None (only outputs may be None), expected a float64 buffer");
        return -1;
    }
    else {
        Py_buffer *v = &w->views[*held];
        if (get_f64_buffer(f, o, v, 0, expect == 1, c) < 0)
            return -1;
        (*held)++;
        *data = (const double *)v->buf;
        *count = v->len / 8;
        if (expect >= 0 && *count != expect) {
            arg_error(f, PyExc_ValueError, c, "must have %zd float64 element%s, got %zd",
                      expect, expect == 1 ? "" : "s", *count);
            return -1;
        }
        if (check_ndim(f, v, expect, is_vec, c) < 0)
            return -1;
        return Py_TYPE(o) == np_type ? BOUND_NUMPY_EXPORT : BOUND_FOREIGN_EXPORT;
    }
    *data = &w->scalars[i];
    *count = 1;
    return BOUND_SCALAR;
}

/* Bind one output: a writable float64 buffer, or None (-> NULL). */
static int
bind_output(FunctionObject *f, Work *w, PyObject *o, Py_ssize_t *held, const ArgCtx *c,
            Py_ssize_t expect, int is_vec, double **data, Py_ssize_t *count)
{
    if (o == Py_None) {
        *data = NULL;
        *count = 0;
        return BOUND_NONE;
    }
    Py_buffer *v = &w->views[*held];
    if (get_f64_buffer(f, o, v, 1, 0, c) < 0)
        return -1;
    (*held)++;
    *data = (double *)v->buf;
    *count = v->len / 8;
    if (expect >= 0 && *count != expect) {
        arg_error(f, PyExc_ValueError, c, "must have %zd float64 element%s, got %zd", expect,
                  expect == 1 ? "" : "s", *count);
        return -1;
    }
    if (check_ndim(f, v, expect, is_vec, c) < 0)
        return -1;
    return Py_TYPE(o) == np_type ? BOUND_NUMPY_EXPORT : BOUND_FOREIGN_EXPORT;
}

static inline int
overlaps(const void *a, Py_ssize_t na, const void *b, Py_ssize_t nb)
{
    const char *pa = (const char *)a, *pb = (const char *)b;
    return na > 0 && nb > 0 && pa < pb + nb * 8 && pb < pa + na * 8;
}

/* Bind argument k (inputs first, then outputs), trying the numpy fast path if allowed. */
static int
bind_one(FunctionObject *f, Work *w, PyObject *const *args, Py_ssize_t k, int fast_ok,
         const char *method, Py_ssize_t *held)
{
    int is_out = k >= f->n_in;
    PyObject *o = args[k];
    Py_ssize_t expect = f->nnz[k], count;
    if (fast_ok && np_is_ndarray(o)) {
        double *p = np_fast(o, is_out, expect, f->vec[k]);
        if (p != NULL) {
            if (is_out)
                w->res[k - f->n_in] = p;
            else
                w->arg[k] = p;
            return BOUND_FAST;
        }
    }
    ArgCtx c = {method, NULL, is_out, is_out ? k - f->n_in : k};
    if (is_out)
        return bind_output(f, w, o, held, &c, expect, f->vec[k], &w->res[k - f->n_in],
                           &count);
    return bind_input(f, w, o, held, &c, expect, f->vec[k], &w->arg[k], &count);
}

/*
 * Bind all n_in + n_out arguments of a call into w->arg / w->res, then check that the
 * inputs are finite and that no output shares memory with an input or another output
 * (generated code may read an input after writing an output). The numpy fast path is
 * used only for plain calls (fast_ok), where the GIL is held until the evaluation ends.
 */
static int
bind_all(FunctionObject *f, Work *w, PyObject *const *args, int fast_ok,
         const char *method, Py_ssize_t *held)
{
    const Py_ssize_t nargs = f->n_in + f->n_out;
    int fast_seen = 0, recheck = 0;
    for (Py_ssize_t k = 0; k < nargs; k++) {
        int how = bind_one(f, w, args, k, fast_ok, method, held);
        if (how < 0)
            return -1;
        w->how[k] = (unsigned char)how;
        fast_seen |= how == BOUND_FAST;
        recheck |= fast_seen && how == BOUND_FOREIGN_EXPORT;
    }
    if (recheck) {
        /* A foreign exporter ran after pointers were taken from ndarrays without an
           export: it might have resized them, so take those pointers again. */
        for (Py_ssize_t k = 0; k < nargs; k++) {
            if (w->how[k] != BOUND_FAST)
                continue;
            int how = bind_one(f, w, args, k, fast_ok, method, held);
            if (how < 0)
                return -1;
            w->how[k] = (unsigned char)how;
        }
    }
    ArgCtx c = {method, NULL, 0, 0};
    for (Py_ssize_t i = 0; i < f->n_in; i++) {
        c.idx = i;
        if (check_finite(f, w->arg[i], f->nnz[i], &c) < 0)
            return -1;
    }
    c.is_out = 1;
    for (Py_ssize_t j = 0; j < f->n_out; j++) {
        const double *r = w->res[j];
        Py_ssize_t nr = f->nnz[f->n_in + j];
        if (r == NULL)
            continue;
        c.idx = j;
        for (Py_ssize_t i = 0; i < f->n_in; i++) {
            if (overlaps(r, nr, w->arg[i], f->nnz[i])) {
                arg_error(f, PyExc_ValueError, &c,
                          "shares memory with input '%U' (#%zd); in-place evaluation "
                          "is not supported",
                          PyTuple_GET_ITEM(f->names_in, i), i);
                return -1;
            }
        }
        for (Py_ssize_t k = 0; k < j; k++) {
            if (w->res[k] && overlaps(r, nr, w->res[k], f->nnz[f->n_in + k])) {
                arg_error(f, PyExc_ValueError, &c, "shares memory with output '%U' (#%zd)",
                          PyTuple_GET_ITEM(f->names_out, k), k);
                return -1;
            }
        }
    }
    return 0;
}

static int
check_nargs(FunctionObject *f, Py_ssize_t nargs, PyObject *kwnames, const char *method)
{
    if (kwnames != NULL && PyTuple_GET_SIZE(kwnames) > 0) {
        if (method)
            PyErr_Format(PyExc_TypeError, "%U.%s() takes no keyword arguments", f->name,
                         method);
        else
            PyErr_Format(PyExc_TypeError, "%U() takes no keyword arguments", f->name);
        return -1;
    }
    Py_ssize_t want = f->n_in + f->n_out;
    if (nargs == want)
        return 0;
    if (method)
        PyErr_Format(PyExc_TypeError,
                     "%U.%s(n_inner, n_repeat, *inputs, *outputs) for %U takes %zd "
                     "arguments (2 counts, %zd input%s, %zd output%s), got %zd",
                     f->name, method, f->signature, want + 2, f->n_in,
                     f->n_in == 1 ? "" : "s", f->n_out, f->n_out == 1 ? "" : "s",
                     nargs + 2);
    else
        PyErr_Format(PyExc_TypeError,
                     "%U takes %zd argument%s (%zd input%s, %zd output%s), got %zd",
                     f->signature, want, want == 1 ? "" : "s", f->n_in,
                     f->n_in == 1 ? "" : "s", f->n_out, f->n_out == 1 ? "" : "s", nargs);
    return -1;
}

static PyObject *
eval_error(FunctionObject *f, int rc)
{
    PyErr_Format(EvalError, "%U: CasADi function returned error code %d", f->name, rc);
    return NULL;
}

/* ---- f(*inputs, *outputs) ---- */

static PyObject *
Function_vectorcall(PyObject *self, PyObject *const *args, size_t nargsf, PyObject *kwnames)
{
    FunctionObject *f = (FunctionObject *)self;
    if (check_nargs(f, PyVectorcall_NARGS(nargsf), kwnames, NULL) < 0)
        return NULL;
    Work tmp;
    Work *w = work_acquire(f, &tmp);
    if (w == NULL)
        return NULL;
    Py_ssize_t held = 0;
    if (bind_all(f, w, args, 1, NULL, &held) < 0) {
        work_done(f, w, held);
        return NULL;
    }
    int rc = f->eval(w->arg, w->res, w->iw, w->w, w->mem);
    int bad = 0;
    if (rc == 0 && f->check_outputs) {
        /* finite inputs can still give a non-finite result (overflow, degenerate pose or
           parameters): never hand that back silently */
        for (Py_ssize_t j = 0; j < f->n_out && !bad; j++) {
            const double *r = w->res[j];
            if (r == NULL)
                continue;
            Py_ssize_t k = first_nonfinite(r, f->nnz[f->n_in + j]);
            if (k >= 0) {
                /* name the input holding the largest magnitude: the usual culprit */
                Py_ssize_t bi = 0, bk = 0;
                double big = -1.0;
                for (Py_ssize_t i = 0; i < f->n_in; i++)
                    for (Py_ssize_t e = 0; e < f->nnz[i]; e++)
                        if (fabs(w->arg[i][e]) > big) {
                            big = fabs(w->arg[i][e]);
                            bi = i;
                            bk = e;
                        }
                char num[32];
                snprintf(num, sizeof num, "%.6g", f->n_in ? w->arg[bi][bk] : 0.0);
                PyErr_Format(NonFiniteOutputError,
                             "%U: output '%U' (#%zd) is not finite at index %zd (%s) although "
                             "every input is finite: inputs too large, or a degenerate pose or "
                             "parameter set (e.g. a singular inertia); the largest input is "
                             "'%U' (#%zd) = %s at index %zd",
                             f->name, PyTuple_GET_ITEM(f->names_out, j), j, k,
                             isnan(r[k]) ? "nan" : (r[k] > 0 ? "inf" : "-inf"),
                             PyTuple_GET_ITEM(f->names_in, bi), bi, num, bk);
                bad = 1;
            }
        }
    }
    work_done(f, w, held);
    if (rc != 0)
        return eval_error(f, rc);
    if (bad)
        return NULL;
    Py_RETURN_NONE;
}

/* ---- f.time_calls(n_inner, n_repeat, *inputs, *outputs) ---- */

static int
positive_count(FunctionObject *f, PyObject *o, const char *what, Py_ssize_t *out)
{
    Py_ssize_t v = PyLong_AsSsize_t(o);
    if (v == -1 && PyErr_Occurred()) {
        PyErr_Clear();
        PyErr_Format(PyExc_TypeError, "%U.time_calls: %s must be a positive int, got %R",
                     f->name, what, o);
        return -1;
    }
    if (v < 1) {
        PyErr_Format(PyExc_ValueError, "%U.time_calls: %s must be >= 1, got %zd", f->name,
                     what, v);
        return -1;
    }
    *out = v;
    return 0;
}

static inline double
now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static PyObject *
Function_time_calls(PyObject *self, PyObject *const *args, Py_ssize_t nargs,
                    PyObject *kwnames)
{
    FunctionObject *f = (FunctionObject *)self;
    Py_ssize_t n_inner, n_repeat;
    if (nargs < 2) {
        check_nargs(f, nargs - 2, NULL, "time_calls");
        return NULL;
    }
    if (check_nargs(f, nargs - 2, kwnames, "time_calls") < 0 ||
        positive_count(f, args[0], "n_inner", &n_inner) < 0 ||
        positive_count(f, args[1], "n_repeat", &n_repeat) < 0)
        return NULL;

    PyObject *result = PyList_New(n_repeat);
    if (result == NULL)
        return NULL;
    Work tmp;
    Work *w = work_acquire(f, &tmp);
    if (w == NULL) {
        Py_DECREF(result);
        return NULL;
    }
    Py_ssize_t held = 0;
    if (bind_all(f, w, args + 2, 0, "time_calls", &held) < 0) {
        work_done(f, w, held);
        Py_DECREF(result);
        return NULL;
    }
    int rc = 0;
    /* Raw timings, boxed into floats after the GIL is reacquired. */
    double *ns = PyMem_Malloc((size_t)n_repeat * sizeof(double));
    if (ns == NULL) {
        work_done(f, w, held);
        Py_DECREF(result);
        return PyErr_NoMemory();
    }
    eval_fn eval = f->eval;
    const casadi_real **arg = w->arg;
    casadi_real **res = w->res;
    casadi_int *iw = w->iw;
    casadi_real *wk = w->w;
    int mem = w->mem;
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t r = 0; r < n_repeat && rc == 0; r++) {
        double t0 = now_ns();
        for (Py_ssize_t k = 0; k < n_inner; k++)
            rc |= eval(arg, res, iw, wk, mem);
        ns[r] = (now_ns() - t0) / (double)n_inner;
    }
    Py_END_ALLOW_THREADS
    work_done(f, w, held);
    if (rc != 0) {
        PyMem_Free(ns);
        Py_DECREF(result);
        return eval_error(f, rc);
    }
    for (Py_ssize_t r = 0; r < n_repeat; r++) {
        PyObject *v = PyFloat_FromDouble(ns[r]);
        if (v == NULL) {
            PyMem_Free(ns);
            Py_DECREF(result);
            return NULL;
        }
        PyList_SET_ITEM(result, r, v);
    }
    PyMem_Free(ns);
    return result;
}

/* ---- f.accumulate(x, u_seq, p, y_seq) ---- */

/* One rollout x_{k+1}, y_k = f(x_k, u_k, p) for k < steps, without the GIL: x holds the final
 * state on return (or, if step *k fails, the state before it); returns CasADi's code. */
static int
rollout(FunctionObject *f, Work *w, double *x, const double *u, const double *p, double *y,
        Py_ssize_t steps, Py_ssize_t *k_out)
{
    const Py_ssize_t nx = f->nnz[0], nu = f->nnz[1], ny = f->nnz[4];
    const casadi_real **arg = w->arg;
    casadi_real **res = w->res;
    double *cur = x, *nxt = w->xbuf;
    int rc = 0;
    Py_ssize_t k;
    for (k = 0; k < steps; k++) {
        arg[0] = cur;
        arg[1] = u + k * nu;
        arg[2] = p;
        res[0] = nxt;
        res[1] = y ? y + k * ny : NULL;
        rc = f->eval(arg, res, w->iw, w->w, w->mem);
        if (rc != 0)
            break; /* cur still holds x_k, the input of the failed step */
        double *t = cur;
        cur = nxt;
        nxt = t;
    }
    if (cur != x)
        memcpy(x, cur, (size_t)nx * sizeof(double));
    *k_out = k;
    return rc;
}

/* The two rollout methods share one body: accumulate is the K = 1 case of accumulate_batch,
 * with its own argument names, a single p (a Python float when np == 1) and its messages. */
typedef struct {
    const char *method, *x, *p, *y; /* the method's name and its argument names */
    int batch;                      /* 1: K rows of X and P; 0: one x and p (K = 1) */
} Rollouts;

static const Rollouts ONE = {"accumulate", "x", "p", "y_seq", 0},
                      BATCH = {"accumulate_batch", "X", "P", "Y_seq", 1};

static PyObject *
rollouts(FunctionObject *f, const Rollouts *m, PyObject *const *args, Py_ssize_t nargs,
         PyObject *kwnames)
{
    if (!f->acc_ok) {
        PyErr_Format(PyExc_TypeError,
                     "%U.%s requires a function with 3 inputs (x[nx], u[nu], "
                     "p[np]) and 2 outputs (x_next[nx], y[ny]) where x_next has as many "
                     "elements as x; %U does not fit",
                     f->name, m->method, f->signature);
        return NULL;
    }
    const int kw = kwnames != NULL && PyTuple_GET_SIZE(kwnames) > 0;
    if (m->batch && (kw || nargs != 4)) {
        PyErr_Format(PyExc_TypeError,
                     "%U.accumulate_batch(X, u_seq, P, Y_seq) takes 4 positional arguments",
                     f->name);
        return NULL;
    }
    if (kw) {
        PyErr_Format(PyExc_TypeError, "%U.accumulate() takes no keyword arguments", f->name);
        return NULL;
    }
    if (nargs != 4) {
        PyErr_Format(PyExc_TypeError,
                     "%U.accumulate(x, u_seq, p, y_seq) takes 4 arguments, got %zd", f->name,
                     nargs);
        return NULL;
    }
    const Py_ssize_t nx = f->nnz[0], nu = f->nnz[1], np_ = f->nnz[2], ny = f->nnz[4];
    if (m->batch && (nu == 0 || np_ == 0)) {
        PyErr_Format(PyExc_ValueError, "%U.accumulate_batch: needs nu > 0 and np > 0", f->name);
        return NULL;
    }
    if (nu == 0) {
        PyErr_Format(PyExc_ValueError,
                     "%U.accumulate: input 'u' has 0 elements; the number of steps is "
                     "taken from len(u_seq) / nu, so nu == 0 is not supported",
                     f->name);
        return NULL;
    }
    Work tmp;
    Work *w = work_acquire(f, &tmp);
    if (w == NULL)
        return NULL;
    Py_ssize_t held = 0, n, n_p = np_, n_u, K = 1;
    double *X, *Y;
    const double *u, *P;
    ArgCtx cx = {m->method, m->x, 0, 0}, cu = {m->method, "u_seq", 0, 1},
           cp = {m->method, m->p, 0, 2}, cy = {m->method, m->y, 1, 1};
    if (m->batch) { /* P first: its rows give K */
        if (bind_input(f, w, args[2], &held, &cp, -1, 0, &P, &n_p) < 0)
            goto fail;
        if (n_p == 0 || n_p % np_ != 0) {
            arg_error(f, PyExc_ValueError, &cp, "must have K * %zd float64 elements with K >= 1, "
                      "got %zd", np_, n_p);
            goto fail;
        }
        K = n_p / np_;
    }
    /* X: writable states, K * nx elements */
    if (bind_output(f, w, args[0], &held, &cx, K * nx, 0, &X, &n) < 0)
        goto fail;
    if (X == NULL) {
        arg_error(f, PyExc_TypeError, &cx, "must be a writable float64 buffer, got None");
        goto fail;
    }
    /* u_seq: N * nu elements, shared by every rollout */
    if (bind_input(f, w, args[1], &held, &cu, -1, 0, &u, &n_u) < 0)
        goto fail;
    if (n_u == 0 || n_u % nu != 0) {
        arg_error(f, PyExc_ValueError, &cu,
                  "must have N * %zd float64 elements with N >= 1, got %zd", nu, n_u);
        goto fail;
    }
    const Py_ssize_t steps = n_u / nu;
    /* p: np elements (or a Python float if np == 1) */
    if (!m->batch && bind_input(f, w, args[2], &held, &cp, np_, 0, &P, &n) < 0)
        goto fail;
    /* Y_seq: K * N * ny elements, or None (outputs y not computed) */
    if (bind_output(f, w, args[3], &held, &cy, K * steps * ny, 0, &Y, &n) < 0)
        goto fail;
    /* Finiteness last: binding may run an exporter's code that changes earlier buffers. */
    if (check_finite(f, X, K * nx, &cx) < 0 || check_finite(f, u, n_u, &cu) < 0 ||
        check_finite(f, P, n_p, &cp) < 0)
        goto fail;
    if (overlaps(X, K * nx, u, n_u) || overlaps(X, K * nx, P, n_p) ||
        (Y && (overlaps(Y, K * steps * ny, X, K * nx) || overlaps(Y, K * steps * ny, u, n_u) ||
               overlaps(Y, K * steps * ny, P, n_p)))) {
        PyErr_Format(PyExc_ValueError,
                     "%U.%s: %s and %s must not share memory with each other or with "
                     "u_seq / %s", f->name, m->method, m->x, m->y, m->p);
        goto fail;
    }
    int rc = 0;
    Py_ssize_t r = 0, k = 0;
    Py_BEGIN_ALLOW_THREADS
    for (r = 0; r < K && rc == 0; r++)
        rc = rollout(f, w, X + r * nx, u, P + r * np_, Y ? Y + r * steps * ny : NULL, steps, &k);
    Py_END_ALLOW_THREADS
    work_done(f, w, held);
    if (rc != 0 && m->batch) {
        PyErr_Format(EvalError,
                     "%U: CasADi function returned error code %d at step %zd of rollout %zd "
                     "(row %zd of X holds the state before that step)",
                     f->name, rc, k, r - 1, r - 1);
        return NULL;
    }
    if (rc != 0) {
        PyErr_Format(EvalError,
                     "%U: CasADi function returned error code %d at step %zd of %zd "
                     "(x holds the state before that step)",
                     f->name, rc, k, steps);
        return NULL;
    }
    Py_RETURN_NONE;

fail:
    work_done(f, w, held);
    return NULL;
}

/* f.accumulate(x, u_seq, p, y_seq): one rollout, the K = 1 case of accumulate_batch. */
static PyObject *
Function_accumulate(PyObject *self, PyObject *const *args, Py_ssize_t nargs,
                    PyObject *kwnames)
{
    return rollouts((FunctionObject *)self, &ONE, args, nargs, kwnames);
}

/* f.accumulate_batch(X, u_seq, P, Y_seq): K rollouts of the same input sequence with their
 * own initial states (rows of X) and parameters (rows of P), all in one call with the GIL
 * released. Studies run thousands of rollouts: one Python call per batch, not per rollout. */
static PyObject *
Function_accumulate_batch(PyObject *self, PyObject *const *args, Py_ssize_t nargs,
                          PyObject *kwnames)
{
    return rollouts((FunctionObject *)self, &BATCH, args, nargs, kwnames);
}

/* ---- construction ---- */

/*
 * dlsym() a symbol "<base><suffix>". Returned as a generic function pointer (converted via
 * memcpy, the POSIX-sanctioned way that keeps ISO C happy); callers cast it to the real
 * type. A missing required symbol sets LookupError.
 */
static void_fn
lookup(LibraryObject *lib, const char *base, const char *suffix, int required)
{
    char sym[MAX_NAME + 64];
    int len = snprintf(sym, sizeof(sym), "%s%s", base, suffix);
    if (len < 0 || (size_t)len >= sizeof(sym)) {
        PyErr_Format(PyExc_ValueError, "function name too long: '%s'", base);
        return NULL;
    }
    (void)dlerror();
    void *p = dlsym(lib->handle, sym);
    if (p == NULL) {
        if (required)
            PyErr_Format(PyExc_LookupError,
                         "symbol '%s' not found in %R (is '%s' a CasADi function generated "
                         "into this library?)",
                         sym, lib->path, base);
        return NULL;
    }
    void_fn fp;
    _Static_assert(sizeof(fp) == sizeof(p), "function and object pointers differ in size");
    memcpy(&fp, &p, sizeof(fp));
    return fp;
}

/* Tuple of argument names; CasADi's default i0/o0 names if name_in/out is absent. */
static PyObject *
read_names(name_fn getname, Py_ssize_t n, const char *dflt)
{
    PyObject *t = PyTuple_New(n);
    if (t == NULL)
        return NULL;
    for (Py_ssize_t i = 0; i < n; i++) {
        const char *s = getname ? getname((casadi_int)i) : NULL;
        PyObject *nm = s ? PyUnicode_FromString(s) : PyUnicode_FromFormat("%s%zd", dflt, i);
        if (nm == NULL) {
            Py_DECREF(t);
            return NULL;
        }
        PyTuple_SET_ITEM(t, i, nm);
    }
    return t;
}

/*
 * Read sparsity patterns, fill nnz[] and the sizes/shapes tuples, and reject sparse
 * arguments. Generated code abbreviates a dense pattern to [nrow, ncol, 1]; the canonical
 * form is [nrow, ncol, colind[0..ncol], row[0..nnz-1]] with colind[0] == 0.
 */
static int
read_sparsity(FunctionObject *f, sparsity_fn sp, Py_ssize_t n, Py_ssize_t *nnz,
              unsigned char *vec, PyObject *names, const char *kind, PyObject **sizes,
              PyObject **shapes)
{
    *sizes = PyTuple_New(n);
    *shapes = PyTuple_New(n);
    if (*sizes == NULL || *shapes == NULL)
        return -1;
    for (Py_ssize_t i = 0; i < n; i++) {
        const casadi_int *s = sp((casadi_int)i);
        if (s == NULL || s[0] < 0 || s[1] < 0) {
            PyErr_Format(PyExc_ValueError, "%U: invalid sparsity pattern for %s '%U' (#%zd)",
                         f->name, kind, PyTuple_GET_ITEM(names, i), i);
            return -1;
        }
        casadi_int nrow = s[0], ncol = s[1], count;
        if (s[2] == 1) { /* abbreviated dense pattern */
            count = nrow * ncol;
        }
        else {
            count = s[2 + ncol]; /* colind[ncol] */
        }
        if (count != nrow * ncol) {
            PyErr_Format(PyExc_ValueError,
                         "%U: %s '%U' (#%zd) is sparse (%lldx%lld with %lld nonzeros); "
                         "only dense inputs and outputs are supported (densify it before "
                         "code generation)",
                         f->name, kind, PyTuple_GET_ITEM(names, i), i, nrow, ncol, count);
            return -1;
        }
        if (count > PY_SSIZE_T_MAX / 8) {
            PyErr_Format(PyExc_ValueError, "%U: %s '%U' (#%zd) is too large", f->name, kind,
                         PyTuple_GET_ITEM(names, i), i);
            return -1;
        }
        nnz[i] = (Py_ssize_t)count;
        /* inputs only: generated outputs are often matrices flattened into a column */
        vec[i] = strcmp(kind, "input") == 0 && (nrow == 1 || ncol == 1);
        PyObject *sz = PyLong_FromLongLong(count);
        PyObject *shape = Py_BuildValue("(LL)", nrow, ncol);
        if (sz == NULL || shape == NULL) {
            Py_XDECREF(sz);
            Py_XDECREF(shape);
            return -1;
        }
        PyTuple_SET_ITEM(*sizes, i, sz);
        PyTuple_SET_ITEM(*shapes, i, shape);
    }
    return 0;
}

/* "name(a[3], b[1]) -> (c[2])" */
static PyObject *
make_signature(FunctionObject *f)
{
    PyObject *parts[2] = {NULL, NULL}, *result = NULL, *sep = NULL;
    for (int o = 0; o < 2; o++) {
        Py_ssize_t n = o ? f->n_out : f->n_in;
        PyObject *names = o ? f->names_out : f->names_in;
        parts[o] = PyList_New(n);
        if (parts[o] == NULL)
            goto done;
        for (Py_ssize_t i = 0; i < n; i++) {
            PyObject *s = PyUnicode_FromFormat("%U[%zd]", PyTuple_GET_ITEM(names, i),
                                               f->nnz[o ? f->n_in + i : i]);
            if (s == NULL)
                goto done;
            PyList_SET_ITEM(parts[o], i, s);
        }
    }
    sep = PyUnicode_FromString(", ");
    if (sep == NULL)
        goto done;
    PyObject *ins = PyUnicode_Join(sep, parts[0]);
    PyObject *outs = ins ? PyUnicode_Join(sep, parts[1]) : NULL;
    if (ins && outs)
        result = PyUnicode_FromFormat("%U(%U) -> (%U)", f->name, ins, outs);
    Py_XDECREF(ins);
    Py_XDECREF(outs);
done:
    Py_XDECREF(parts[0]);
    Py_XDECREF(parts[1]);
    Py_XDECREF(sep);
    return result;
}

/*
 * The values of fixed= as float64 into dst[0..n): a float64 buffer (any layout; one
 * dimension, or none for one value), a sequence of real numbers, or one Python float/int.
 * TypeError for anything else, ValueError for a wrong count or a non-finite value.
 */
static int
read_fixed(FunctionObject *f, PyObject *obj, double *dst, Py_ssize_t n)
{
    Py_ssize_t got;
    if (PyFloat_Check(obj) || PyLong_Check(obj)) { /* one value */
        double d = PyFloat_AsDouble(obj);
        if (d == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            PyErr_Format(PyExc_ValueError, "%U: fixed (the 'design' input) is an int too "
                         "large for a float64", f->name);
            return -1;
        }
        got = 1;
        if (n == 1)
            dst[0] = d;
    }
    else if (PyObject_CheckBuffer(obj)) {
        Py_buffer v;
        if (PyObject_GetBuffer(obj, &v, PyBUF_STRIDES | PyBUF_FORMAT) < 0) {
            PyObject *et, *ev, *tb;
            PyErr_Fetch(&et, &ev, &tb);
            PyErr_NormalizeException(&et, &ev, &tb);
            PyErr_Format(PyExc_TypeError, "%U: fixed (the 'design' input): cannot export a "
                         "float64 buffer from %s: %S", f->name, Py_TYPE(obj)->tp_name,
                         ev ? ev : Py_None);
            Py_XDECREF(et);
            Py_XDECREF(ev);
            Py_XDECREF(tb);
            return -1;
        }
        if (v.itemsize != 8 || !format_is_f64(v.format)) {
            PyErr_Format(PyExc_TypeError,
                         "%U: fixed (the 'design' input) must be float64 values, got a buffer "
                         "of format '%s' (itemsize %zd) from %s",
                         f->name, v.format ? v.format : "B", v.itemsize,
                         Py_TYPE(obj)->tp_name);
            PyBuffer_Release(&v);
            return -1;
        }
        got = v.len / 8;
        if (v.ndim > 1) {
            PyErr_Format(PyExc_ValueError,
                         "%U: fixed (the 'design' input) must be one-dimensional, got %d "
                         "dimensions", f->name, v.ndim);
            PyBuffer_Release(&v);
            return -1;
        }
        if (got == n && PyBuffer_ToContiguous(dst, &v, v.len, 'C') < 0) {
            PyBuffer_Release(&v);
            return -1;
        }
        PyBuffer_Release(&v);
    }
    else {
        if (PyUnicode_Check(obj)) {
            PyErr_Format(PyExc_TypeError, "%U: fixed (the 'design' input) must be real "
                         "numbers, got str", f->name);
            return -1;
        }
        /* a tuple copy: converting an item may run Python code that changes a list */
        PyObject *seq = PySequence_Check(obj) ? PySequence_Tuple(obj) : NULL;
        if (seq == NULL) {
            if (PyErr_Occurred() && !PyErr_ExceptionMatches(PyExc_TypeError))
                return -1; /* e.g. a sequence whose __getitem__ failed */
            PyErr_Clear();
            PyErr_Format(PyExc_TypeError, "%U: fixed (the 'design' input) must be a float64 "
                         "buffer or a sequence of real numbers, got %s",
                         f->name, Py_TYPE(obj)->tp_name);
            return -1;
        }
        got = PyTuple_GET_SIZE(seq);
        for (Py_ssize_t k = 0; k < got && got == n; k++) {
            PyObject *it = PyTuple_GET_ITEM(seq, k);
            double d = -1.0;
            if (PyFloat_Check(it) || PyLong_Check(it) || PyNumber_Check(it))
                d = PyFloat_AsDouble(it); /* no complex: it has no __float__ */
            else
                PyErr_SetString(PyExc_TypeError, "not a number");
            if (d == -1.0 && PyErr_Occurred()) {
                PyObject *et, *ev, *tb;
                PyErr_Fetch(&et, &ev, &tb);
                PyErr_NormalizeException(&et, &ev, &tb);
                PyErr_Format(PyErr_GivenExceptionMatches(et, PyExc_OverflowError)
                                 ? PyExc_ValueError : PyExc_TypeError,
                             "%U: fixed (the 'design' input) must be real numbers, value %zd "
                             "is %s (%S)", f->name, k, Py_TYPE(it)->tp_name,
                             ev ? ev : Py_None);
                Py_XDECREF(et);
                Py_XDECREF(ev);
                Py_XDECREF(tb);
                Py_DECREF(seq);
                return -1;
            }
            dst[k] = d;
        }
        Py_DECREF(seq);
    }
    if (got != n) {
        PyErr_Format(PyExc_ValueError,
                     "%U: fixed must have %zd value%s (the 'design' input has %zd element%s), "
                     "got %zd", f->name, n, n == 1 ? "" : "s", n, n == 1 ? "" : "s", got);
        return -1;
    }
    Py_ssize_t k = first_nonfinite(dst, n);
    if (k >= 0) {
        PyErr_Format(PyExc_ValueError,
                     "%U: fixed (the 'design' input) has a non-finite value at index %zd (%s)",
                     f->name, k, isnan(dst[k]) ? "nan" : (dst[k] > 0 ? "inf" : "-inf"));
        return -1;
    }
    return 0;
}

/*
 * Bind the last input, which must be a vector named "design", to a copy of fixed: the
 * Function then shows n_in - 1 inputs (names, sizes, shapes, nnz, vec), and work_init
 * points arg[n_in] at the copy.
 */
static int
bind_fixed(FunctionObject *f, PyObject *fixed)
{
    const Py_ssize_t last = f->n_in - 1;
    PyObject *nm = last >= 0 ? PyTuple_GET_ITEM(f->names_in, last) : NULL;
    if (nm == NULL || PyUnicode_CompareWithASCIIString(nm, "design") != 0) {
        PyErr_Format(PyExc_ValueError,
                     "%U: fixed= binds a last input named 'design', but the inputs are %R",
                     f->name, f->names_in);
        return -1;
    }
    if (!f->vec[last]) {
        PyErr_Format(PyExc_ValueError,
                     "%U: fixed= binds a vector, but input 'design' (#%zd) has shape %R",
                     f->name, last, PyTuple_GET_ITEM(f->shapes_in, last));
        return -1;
    }
    const Py_ssize_t n = f->nnz[last];
    double *copy = PyMem_Malloc(((size_t)n + 1) * sizeof(double));
    if (copy == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    if (read_fixed(f, fixed, copy, n) < 0) {
        PyMem_Free(copy);
        return -1;
    }
    PyObject *names = PyTuple_GetSlice(f->names_in, 0, last);
    PyObject *sizes = PyTuple_GetSlice(f->sizes_in, 0, last);
    PyObject *shapes = PyTuple_GetSlice(f->shapes_in, 0, last);
    if (names == NULL || sizes == NULL || shapes == NULL) {
        Py_XDECREF(names);
        Py_XDECREF(sizes);
        Py_XDECREF(shapes);
        PyMem_Free(copy);
        return -1;
    }
    Py_SETREF(f->names_in, names);
    Py_SETREF(f->sizes_in, sizes);
    Py_SETREF(f->shapes_in, shapes);
    /* outputs start at nnz + n_in, vec + n_in: move them down one slot */
    memmove(f->nnz + last, f->nnz + f->n_in, (size_t)f->n_out * sizeof(*f->nnz));
    memmove(f->vec + last, f->vec + f->n_in, (size_t)f->n_out * sizeof(*f->vec));
    f->n_in = last;
    f->fixed = copy;
    f->n_fixed = n;
    return 0;
}

static PyObject *
Function_new(PyTypeObject *type, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {"library", "name", "fixed", NULL};
    LibraryObject *lib;
    PyObject *name, *fixed = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "O!U|$O:Function", kwlist, &LibraryType, &lib,
                                     &name, &fixed))
        return NULL;
    const char *cname = PyUnicode_AsUTF8(name);
    if (cname == NULL)
        return NULL;
    if (strlen(cname) > MAX_NAME) {
        PyErr_Format(PyExc_ValueError, "function name longer than %d bytes: %R", MAX_NAME,
                     name);
        return NULL;
    }

    FunctionObject *f = (FunctionObject *)type->tp_alloc(type, 0);
    if (f == NULL)
        return NULL;
    f->vectorcall = Function_vectorcall;
    Py_INCREF(lib);
    f->lib = lib;
    Py_INCREF(name);
    f->name = name;

    /* Required symbols */
    count_fn n_in = NULL, n_out = NULL;
    sparsity_fn sp_in = NULL, sp_out = NULL;
    work_fn work = NULL;
    if (!(f->eval = (eval_fn)lookup(lib, cname, "", 1)) ||
        !(n_in = (count_fn)lookup(lib, cname, "_n_in", 1)) ||
        !(n_out = (count_fn)lookup(lib, cname, "_n_out", 1)) ||
        !(sp_in = (sparsity_fn)lookup(lib, cname, "_sparsity_in", 1)) ||
        !(sp_out = (sparsity_fn)lookup(lib, cname, "_sparsity_out", 1)) ||
        !(work = (work_fn)lookup(lib, cname, "_work", 1)))
        goto fail;
    /* Optional symbols (absent with some code-generation options) */
    name_fn name_in = (name_fn)lookup(lib, cname, "_name_in", 0);
    name_fn name_out = (name_fn)lookup(lib, cname, "_name_out", 0);
    void_fn incref = f->incref = (void_fn)lookup(lib, cname, "_incref", 0);
    f->decref = (void_fn)lookup(lib, cname, "_decref", 0);
    f->checkout = (checkout_fn)lookup(lib, cname, "_checkout", 0);
    f->release = (release_fn)lookup(lib, cname, "_release", 0);
    int_fn int_size = (int_fn)lookup(lib, cname, "_casadi_int_size", 0);
    int_fn real_size = (int_fn)lookup(lib, cname, "_casadi_real_size", 0);

    if ((int_size && int_size() != (int)sizeof(casadi_int)) ||
        (real_size && real_size() != (int)sizeof(casadi_real))) {
        PyErr_Format(PyExc_ValueError,
                     "%U in %R was generated with casadi_int of %d bytes and casadi_real of "
                     "%d bytes; this binding requires long long (8) and double (8)",
                     name, lib->path, int_size ? int_size() : 8, real_size ? real_size() : 8);
        goto fail;
    }

    casadi_int ni = n_in(), no = n_out();
    if (ni < 0 || no < 0 || ni > MAX_ARGS || no > MAX_ARGS) {
        PyErr_Format(PyExc_ValueError, "%U: implausible n_in=%lld / n_out=%lld", name, ni, no);
        goto fail;
    }
    f->n_in = (Py_ssize_t)ni;
    f->n_out = (Py_ssize_t)no;

    if (work(&f->sz_arg, &f->sz_res, &f->sz_iw, &f->sz_w) != 0 || f->sz_arg < 0 ||
        f->sz_res < 0 || f->sz_iw < 0 || f->sz_w < 0) {
        PyErr_Format(PyExc_ValueError, "%U: %s_work() failed or returned negative sizes",
                     name, cname);
        goto fail;
    }

    f->nnz = PyMem_Calloc((size_t)(f->n_in + f->n_out) + 1, sizeof(Py_ssize_t));
    f->vec = PyMem_Calloc((size_t)(f->n_in + f->n_out) + 1, 1);
    if (f->nnz == NULL || f->vec == NULL) {
        PyErr_NoMemory();
        goto fail;
    }
    f->names_in = read_names(name_in, f->n_in, "i");
    if (f->names_in == NULL)
        goto fail;
    f->names_out = read_names(name_out, f->n_out, "o");
    if (f->names_out == NULL)
        goto fail;
    if (read_sparsity(f, sp_in, f->n_in, f->nnz, f->vec, f->names_in, "input", &f->sizes_in,
                      &f->shapes_in) < 0 ||
        read_sparsity(f, sp_out, f->n_out, f->nnz + f->n_in, f->vec + f->n_in, f->names_out,
                      "output",
                      &f->sizes_out, &f->shapes_out) < 0)
        goto fail;
    if (fixed != Py_None && bind_fixed(f, fixed) < 0)
        goto fail;
    f->signature = make_signature(f);
    if (f->signature == NULL)
        goto fail;
    f->acc_ok = f->n_in == 3 && f->n_out == 2 && f->nnz[3] == f->nnz[0];

    if (incref) {
        incref();
        f->increfed = 1;
    }
    if (work_init(f, &f->work) < 0)
        goto fail;
    return (PyObject *)f;

fail:
    Py_DECREF(f);
    return NULL;
}

/*
 * f.clone(fixed=None): a new Function of the same generated function, from what f already
 * resolved (the symbols, the names and sparsity, the work sizes): no dlsym, no sparsity read.
 * It shares f's Library and immutable metadata, owns its work area and, for a Function made
 * with fixed=, its own copy of the design: f's (fixed=None) or the values given.
 */
static PyObject *
Function_clone(PyObject *self, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {"fixed", NULL};
    FunctionObject *src = (FunctionObject *)self;
    PyObject *fixed = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "|$O:clone", kwlist, &fixed))
        return NULL;
    if (fixed != Py_None && src->fixed == NULL) {
        PyErr_Format(PyExc_ValueError,
                     "%U: clone(fixed=...) rebinds the 'design' input of a Function made with "
                     "fixed=; this one was made without (inputs %R)", src->name, src->names_in);
        return NULL;
    }
    FunctionObject *f = (FunctionObject *)Py_TYPE(self)->tp_alloc(Py_TYPE(self), 0);
    if (f == NULL)
        return NULL;
    f->vectorcall = Function_vectorcall;
    f->lib = (LibraryObject *)Py_NewRef((PyObject *)src->lib);
    f->name = Py_NewRef(src->name);
    f->signature = Py_NewRef(src->signature);
    f->names_in = Py_NewRef(src->names_in);
    f->names_out = Py_NewRef(src->names_out);
    f->sizes_in = Py_NewRef(src->sizes_in);
    f->sizes_out = Py_NewRef(src->sizes_out);
    f->shapes_in = Py_NewRef(src->shapes_in);
    f->shapes_out = Py_NewRef(src->shapes_out);
    f->n_in = src->n_in;
    f->n_out = src->n_out;
    const size_t nio = (size_t)(src->n_in + src->n_out);
    f->nnz = PyMem_Calloc(nio + 1, sizeof(*f->nnz));
    f->vec = PyMem_Calloc(nio + 1, 1);
    if (f->nnz == NULL || f->vec == NULL) {
        PyErr_NoMemory();
        goto fail;
    }
    memcpy(f->nnz, src->nnz, nio * sizeof(*f->nnz));
    memcpy(f->vec, src->vec, nio);
    if (src->fixed) {
        f->fixed = PyMem_Malloc(((size_t)src->n_fixed + 1) * sizeof(double));
        if (f->fixed == NULL) {
            PyErr_NoMemory();
            goto fail;
        }
        f->n_fixed = src->n_fixed;
        if (fixed == Py_None)
            memcpy(f->fixed, src->fixed, (size_t)src->n_fixed * sizeof(double));
        else if (read_fixed(f, fixed, f->fixed, f->n_fixed) < 0)
            goto fail;
    }
    f->sz_arg = src->sz_arg;
    f->sz_res = src->sz_res;
    f->sz_iw = src->sz_iw;
    f->sz_w = src->sz_w;
    f->eval = src->eval;
    f->checkout = src->checkout;
    f->release = src->release;
    f->incref = src->incref;
    f->decref = src->decref;
    f->acc_ok = src->acc_ok;
    f->check_outputs = src->check_outputs;
    if (f->incref) {
        f->incref();
        f->increfed = 1;
    }
    if (work_init(f, &f->work) < 0)
        goto fail;
    return (PyObject *)f;

fail:
    Py_DECREF(f);
    return NULL;
}

static void
Function_dealloc(FunctionObject *f)
{
    work_free(f, &f->work); /* releases the checked-out memory */
    if (f->increfed && f->decref)
        f->decref();
    PyMem_Free(f->nnz);
    PyMem_Free(f->vec);
    PyMem_Free(f->fixed);
    Py_XDECREF(f->name);
    Py_XDECREF(f->signature);
    Py_XDECREF(f->names_in);
    Py_XDECREF(f->names_out);
    Py_XDECREF(f->sizes_in);
    Py_XDECREF(f->sizes_out);
    Py_XDECREF(f->shapes_in);
    Py_XDECREF(f->shapes_out);
    Py_XDECREF(f->lib); /* last: may dlclose the code called above */
    Py_TYPE(f)->tp_free((PyObject *)f);
}

static PyObject *
Function_repr(FunctionObject *f)
{
    if (f->fixed)
        return PyUnicode_FromFormat("<Function %U, design[%zd] fixed>", f->signature,
                                    f->n_fixed);
    return PyUnicode_FromFormat("<Function %U>", f->signature);
}

/* f.fixed: the bound design as a tuple of floats, or None. */
static PyObject *
Function_get_fixed(FunctionObject *f, void *closure)
{
    (void)closure;
    if (f->fixed == NULL)
        Py_RETURN_NONE;
    PyObject *t = PyTuple_New(f->n_fixed);
    if (t == NULL)
        return NULL;
    for (Py_ssize_t k = 0; k < f->n_fixed; k++) {
        PyObject *v = PyFloat_FromDouble(f->fixed[k]);
        if (v == NULL) {
            Py_DECREF(t);
            return NULL;
        }
        PyTuple_SET_ITEM(t, k, v);
    }
    return t;
}

static PyGetSetDef Function_getset[] = {
    {"fixed", (getter)Function_get_fixed, NULL,
     "The values bound to the last input 'design' (fixed=), a tuple of floats, or None.",
     NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

static PyMemberDef Function_members[] = {
    {"name", T_OBJECT_EX, offsetof(FunctionObject, name), READONLY, "Function name (str)."},
    {"check_outputs", T_BOOL, offsetof(FunctionObject, check_outputs), 0,
     "If true, a call whose result holds a NaN or inf raises NonFiniteOutputError "
     "(a ValueError; default false)."},
    {"library", T_OBJECT_EX, offsetof(FunctionObject, lib), READONLY,
     "The Library the function was resolved from."},
    {"signature", T_OBJECT_EX, offsetof(FunctionObject, signature), READONLY,
     "Signature with element counts, e.g. 'f(x[3], p[1]) -> (y[2])'."},
    {"n_in", T_PYSSIZET, offsetof(FunctionObject, n_in), READONLY, "Number of inputs."},
    {"n_out", T_PYSSIZET, offsetof(FunctionObject, n_out), READONLY, "Number of outputs."},
    {"names_in", T_OBJECT_EX, offsetof(FunctionObject, names_in), READONLY,
     "Input names (tuple of str)."},
    {"names_out", T_OBJECT_EX, offsetof(FunctionObject, names_out), READONLY,
     "Output names (tuple of str)."},
    {"sizes_in", T_OBJECT_EX, offsetof(FunctionObject, sizes_in), READONLY,
     "Number of float64 elements of each input (tuple of int)."},
    {"sizes_out", T_OBJECT_EX, offsetof(FunctionObject, sizes_out), READONLY,
     "Number of float64 elements of each output (tuple of int)."},
    {"shapes_in", T_OBJECT_EX, offsetof(FunctionObject, shapes_in), READONLY,
     "(nrow, ncol) of each input; data is column-major (tuple of tuples)."},
    {"shapes_out", T_OBJECT_EX, offsetof(FunctionObject, shapes_out), READONLY,
     "(nrow, ncol) of each output; data is column-major (tuple of tuples)."},
    {NULL, 0, 0, 0, NULL},
};

PyDoc_STRVAR(time_calls_doc,
"time_calls(n_inner, n_repeat, *inputs, *outputs) -> list[float]\n"
"--\n\n"
"Bind the arguments as for a call, then time n_repeat batches of n_inner\n"
"back-to-back evaluations in a C loop (clock_gettime(CLOCK_MONOTONIC), GIL\n"
"released). Returns nanoseconds per evaluation for each batch.");



/* ---- f.map(K, *inputs, *outputs) ---- */

static PyObject *
Function_map(PyObject *self, PyObject *const *args, Py_ssize_t nargs, PyObject *kwnames)
{
    FunctionObject *f = (FunctionObject *)self;
    if (kwnames != NULL && PyTuple_GET_SIZE(kwnames) > 0) {
        PyErr_Format(PyExc_TypeError, "%U.map() takes no keyword arguments", f->name);
        return NULL;
    }
    const Py_ssize_t nio = f->n_in + f->n_out;
    if (nargs != nio + 1) {
        PyErr_Format(PyExc_TypeError,
                     "%U.map(K, *inputs, *outputs) for %U takes %zd arguments (K, %zd "
                     "input%s, %zd output%s), got %zd",
                     f->name, f->signature, nio + 1, f->n_in, f->n_in == 1 ? "" : "s",
                     f->n_out, f->n_out == 1 ? "" : "s", nargs);
        return NULL;
    }
    Py_ssize_t K = PyLong_AsSsize_t(args[0]);
    if (K == -1 && PyErr_Occurred())
        return NULL;
    if (K < 1) {
        PyErr_Format(PyExc_ValueError, "%U.map: K must be >= 1, got %zd", f->name, K);
        return NULL;
    }
    Py_ssize_t *stride = PyMem_Calloc((size_t)nio + 1, sizeof(Py_ssize_t));
    const double **base = PyMem_Calloc((size_t)nio + 1, sizeof(double *));
    if (stride == NULL || base == NULL) {
        PyMem_Free(stride);
        PyMem_Free(base);
        return PyErr_NoMemory();
    }
    Work tmp;
    Work *w = work_acquire(f, &tmp);
    if (w == NULL) {
        PyMem_Free(stride);
        PyMem_Free(base);
        return NULL;
    }
    Py_ssize_t held = 0, count;
    for (Py_ssize_t i = 0; i < f->n_in; i++) {
        ArgCtx c = {"map", NULL, 0, i};
        const Py_ssize_t nz = f->nnz[i];
        const double *d;
        int scalar = nz == 1 && (PyFloat_Check(args[1 + i]) || PyLong_Check(args[1 + i]));
        if (bind_input(f, w, args[1 + i], &held, &c, scalar ? 1 : -1, 0, &d, &count) < 0)
            goto fail;
        if (count == nz && K > 1)
            stride[i] = 0; /* one value for every point */
        else if (count == K * nz)
            stride[i] = nz;
        else {
            arg_error(f, PyExc_ValueError, &c,
                      "must have %zd float64 elements (one value for all points) or K * %zd "
                      "= %zd (one row per point), got %zd", nz, nz, K * nz, count);
            goto fail;
        }
        if (check_finite(f, d, count, &c) < 0)
            goto fail;
        base[i] = d;
    }
    for (Py_ssize_t j = 0; j < f->n_out; j++) {
        ArgCtx c = {"map", NULL, 1, j};
        const Py_ssize_t nz = f->nnz[f->n_in + j];
        double *d;
        if (bind_output(f, w, args[1 + f->n_in + j], &held, &c, K * nz, 0, &d, &count) < 0)
            goto fail;
        stride[f->n_in + j] = nz;
        base[f->n_in + j] = d;
        if (d == NULL)
            continue;
        for (Py_ssize_t i = 0; i < f->n_in; i++)
            if (overlaps(d, K * nz, base[i], stride[i] ? K * f->nnz[i] : f->nnz[i])) {
                arg_error(f, PyExc_ValueError, &c, "shares memory with input '%U' (#%zd)",
                          PyTuple_GET_ITEM(f->names_in, i), i);
                goto fail;
            }
        for (Py_ssize_t k = 0; k < j; k++)
            if (base[f->n_in + k] &&
                overlaps(d, K * nz, base[f->n_in + k], K * f->nnz[f->n_in + k])) {
                arg_error(f, PyExc_ValueError, &c, "shares memory with output '%U' (#%zd)",
                          PyTuple_GET_ITEM(f->names_out, k), k);
                goto fail;
            }
    }
    int rc = 0;
    Py_ssize_t k = 0;
    Py_BEGIN_ALLOW_THREADS
    for (k = 0; k < K && rc == 0; k++) {
        for (Py_ssize_t i = 0; i < f->n_in; i++)
            w->arg[i] = base[i] + k * stride[i];
        for (Py_ssize_t j = 0; j < f->n_out; j++)
            w->res[j] = base[f->n_in + j] ? (double *)base[f->n_in + j] +
                                                k * stride[f->n_in + j] : NULL;
        rc = f->eval(w->arg, w->res, w->iw, w->w, w->mem);
    }
    Py_END_ALLOW_THREADS
    if (rc != 0) {
        work_done(f, w, held);
        PyMem_Free(stride);
        PyMem_Free(base);
        PyErr_Format(EvalError, "%U.map: CasADi function returned error code %d at point %zd "
                     "of %zd", f->name, rc, k - 1, K);
        return NULL;
    }
    if (f->check_outputs) {
        for (Py_ssize_t j = 0; j < f->n_out; j++) {
            const double *r = base[f->n_in + j];
            const Py_ssize_t nz = f->nnz[f->n_in + j];
            if (r == NULL)
                continue;
            Py_ssize_t e = first_nonfinite(r, K * nz);
            if (e >= 0) {
                PyErr_Format(NonFiniteOutputError,
                             "%U.map: output '%U' (#%zd) is not finite at point %zd, index %zd "
                             "although every input is finite (a degenerate pose or parameter "
                             "set)", f->name, PyTuple_GET_ITEM(f->names_out, j), j, e / nz,
                             e % nz);
                goto fail;
            }
        }
    }
    work_done(f, w, held);
    PyMem_Free(stride);
    PyMem_Free(base);
    Py_RETURN_NONE;

fail:
    work_done(f, w, held);
    PyMem_Free(stride);
    PyMem_Free(base);
    return NULL;
}

PyDoc_STRVAR(map_doc,
"map(K, *inputs, *outputs) -> None\n"
"--\n\n"
"Evaluate the function at K points in one call, in C (GIL released).\n\n"
"Each input is a float64 buffer of K*nnz elements (row k = its value at point k) or of\n"
"nnz elements (the same value at every point; a Python number for a 1-element input).\n"
"Each output is a writable float64 buffer of K*nnz elements (row k = point k), or None.\n"
"Inputs must be finite; with check_outputs, a non-finite output raises\n"
"NonFiniteOutputError naming the point.");

PyDoc_STRVAR(accumulate_batch_doc,
"accumulate_batch(X, u_seq, P, Y_seq) -> None\n"
"--\n\n"
"K rollouts x_{k+1}, y_k = f(x_k, u_k, p_r) of one input sequence, in C (GIL released).\n\n"
"P: float64 buffer of K*np elements, row r = the parameters of rollout r (K >= 1).\n"
"X: writable float64 buffer of K*nx: row r = initial state in, final state out.\n"
"u_seq: float64 buffer of N*nu elements (N >= 1), shared by every rollout.\n"
"Y_seq: writable float64 buffer of K*N*ny elements (rollout r's rows r*N..r*N+N-1),\n"
"or None. Each rollout is exactly accumulate() on its row. If the function fails,\n"
"EvalError names the rollout and the step.");


PyDoc_STRVAR(accumulate_doc,
"accumulate(x, u_seq, p, y_seq) -> None\n"
"--\n\n"
"Roll out x_{k+1}, y_k = f(x_k, u_k, p) for k = 0..N-1 in C (GIL released).\n\n"
"Requires 3 inputs (x[nx], u[nu], p[np]) and 2 outputs (x_next[nx], y[ny]).\n"
"x: writable float64 buffer of nx: initial state in, final state out.\n"
"u_seq: float64 buffer of N*nu elements (N >= 1), row k = u_k.\n"
"p: float64 buffer of np elements (or a Python float if np == 1).\n"
"y_seq: writable float64 buffer of N*ny elements (row k = y_k), or None.\n"
"x, u_seq and p must be finite on entry. If the function fails at step k,\n"
"EvalError is raised and x holds x_k.");

PyDoc_STRVAR(clone_doc,
"clone(*, fixed=None) -> Function\n"
"--\n\n"
"A new Function of the same generated function, made from what this one resolved\n"
"(symbols, names, sparsity, work sizes: no symbol lookup, no sparsity read). It shares\n"
"the Library and owns its work area; check_outputs is copied. fixed: for a Function\n"
"made with fixed=, the values to bind to 'design' instead (the same rules as\n"
"Function(..., fixed=)); None keeps this one's (copied). ValueError for values given\n"
"to a Function made without fixed=.");

static PyMethodDef Function_methods[] = {
    {"time_calls", (PyCFunction)(void (*)(void))Function_time_calls,
     METH_FASTCALL | METH_KEYWORDS, time_calls_doc},
    {"accumulate", (PyCFunction)(void (*)(void))Function_accumulate,
     METH_FASTCALL | METH_KEYWORDS, accumulate_doc},
    {"accumulate_batch", (PyCFunction)(void (*)(void))Function_accumulate_batch,
     METH_FASTCALL | METH_KEYWORDS, accumulate_batch_doc},
    {"map", (PyCFunction)(void (*)(void))Function_map, METH_FASTCALL | METH_KEYWORDS, map_doc},
    {"clone", (PyCFunction)(void (*)(void))Function_clone, METH_VARARGS | METH_KEYWORDS,
     clone_doc},
    {NULL, NULL, 0, NULL},
};

PyDoc_STRVAR(Function_doc,
"Function(library, name, *, fixed=None)\n"
"--\n\n"
"A CasADi-generated function resolved from a Library by name.\n\n"
"fixed: values for the function's last input, which must be a vector named\n"
"'design': a float64 buffer or a sequence of real numbers, finite, with as many\n"
"elements as 'design'. They are copied once and bound to every evaluation (calls,\n"
"map, accumulate, time_calls, Method); the Function then shows one input fewer\n"
"(n_in, names_in, sizes_in, shapes_in and signature are those of the others), at no\n"
"cost per call. TypeError for values that are not real numbers, ValueError for a\n"
"function without a last 'design' input, a wrong count or a non-finite value.\n\n"
"Call as f(*inputs, *outputs) with exactly n_in + n_out positional arguments:\n"
"each input a C-contiguous float64 buffer with sizes_in[i] elements, or a Python\n"
"float/int when sizes_in[i] == 1; each output a writable C-contiguous float64\n"
"buffer with sizes_out[i] elements, or None to skip it. A vector input (shape\n"
"k x 1 or 1 x k) must be a 1-D buffer of shape (k,) (0-d allowed when k == 1);\n"
"matrix inputs and all outputs may have any ndim: they are flat vectors of\n"
"nonzeros (generated code often flattens a matrix into a column), and only\n"
"their element count is checked. Outputs are\n"
"written in place and must not share memory with inputs or other outputs.\n"
"Inputs must be finite (ValueError otherwise). A\n"
"nonzero return code raises EvalError. Returns None.");

static PyTypeObject FunctionType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "pm2dof.core._cbind.Function",
    .tp_basicsize = sizeof(FunctionObject),
    .tp_dealloc = (destructor)Function_dealloc,
    .tp_vectorcall_offset = offsetof(FunctionObject, vectorcall),
    .tp_repr = (reprfunc)Function_repr,
    .tp_call = PyVectorcall_Call,
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_VECTORCALL,
    .tp_doc = Function_doc,
    .tp_methods = Function_methods,
    .tp_members = Function_members,
    .tp_getset = Function_getset,
    .tp_new = Function_new,
};

/* ------------------------------------------------------------------------------------ */
/* Method                                                                               */
/* ------------------------------------------------------------------------------------ */

/*
 * Method(function, inputs, outputs, *, empty, kind=None, finite=False, guard=None,
 *        feedback=None)
 *
 * The fast path of one pm2dof call (a Model method, a controller step) as a single C call:
 * preset inputs (a controller's state and parameters) are bound by the Method, the caller
 * gives the others and one `out` argument; the returned outputs are the caller's arrays,
 * checked for type and exact shape, or new ones from empty(shape); the other outputs are
 * skipped (None) or the Method's own scratch arrays; after the evaluation the outputs can be
 * checked for finiteness and one scratch output against a guard, and one output copied
 * back into a preset input (a controller's state: state <- state_next).
 *
 * Anything the fast path does not accept raises Refused with no message and no side
 * effect: a bad argument (the binding's own refusal), a non-finite output (finite=True) or
 * a failed guard. The caller then takes its checked path, which converts, re-evaluates and
 * raises the typed error with its message. With feedback, a failed guard raises
 * GuardTripped (a Refused) after the copy: the step happened, only its status is reported.
 */

#define METHOD_MAX_ARGS 64
#define METHOD_MAX_RET 8
#define METHOD_MAX_ND 4

enum { GUARD_NONE, GUARD_AT_LEAST, GUARD_ABS_AT_MOST, GUARD_NOT_EQUAL };

static PyObject *Refused;
static PyObject *GuardTripped;

typedef struct {
    PyObject_HEAD
    vectorcallfunc vectorcall;
    FunctionObject *f;
    PyObject **tmpl;     /* n_in + n_out: preset input / NULL (caller's); output: None,
                            scratch array, or NULL (returned) */
    Py_ssize_t n_given;  /* inputs the caller gives */
    Py_ssize_t n_ret;    /* returned outputs */
    Py_ssize_t ret_out[METHOD_MAX_RET];         /* their output indices */
    PyObject *ret_shape[METHOD_MAX_RET];        /* shape tuples, for empty() */
    int ret_nd[METHOD_MAX_RET];
    Py_ssize_t ret_dims[METHOD_MAX_RET][METHOD_MAX_ND];
    PyObject *empty;     /* numpy.empty */
    PyObject *kind;      /* type of the result when n_ret > 1 (a tuple subclass), or NULL */
    char finite;         /* every computed output must be finite */
    char guard_on;       /* writable: the guard is checked */
    int guard_kind;
    Py_ssize_t guard_out;
    double guard_v[2];
    Py_ssize_t fb_out, fb_in; /* feedback: output fb_out copied into input fb_in (-1: none) */
    char positive[METHOD_MAX_ARGS];  /* per input: a positive finite Python float only */
    char plain_in;       /* every input the caller's, none positive: they are bound as given */
    char plain_out;      /* every output returned: the returned arrays are the outputs */
    PyObject *scalar;    /* scalar=True: the returned 1-element output's scratch array, and
                            the result is a Python float; else NULL */
} MethodObject;

static PyObject *
refuse(void)
{
    PyErr_Clear();
    PyErr_SetNone(Refused);
    return NULL;
}

/* An exact ndarray of the returned output r's shape (dtype etc. are checked by binding). */
static inline int
ret_shape_ok(MethodObject *m, PyObject *o, Py_ssize_t r)
{
    if (!np_is_ndarray(o))
        return 0;
    const NpArray *a = (const NpArray *)o;
    if (a->nd != m->ret_nd[r])
        return 0;
    for (int k = 0; k < a->nd; k++)
        if (a->dimensions[k] != m->ret_dims[r][k])
            return 0;
    return 1;
}

static inline int
guard_passes(MethodObject *m, const double *p, Py_ssize_t n)
{
    switch (m->guard_kind) {
    case GUARD_AT_LEAST:
        for (Py_ssize_t k = 0; k < n && k < 2; k++)
            if (!(p[k] >= m->guard_v[k])) /* NaN fails */
                return 0;
        return 1;
    case GUARD_ABS_AT_MOST:
        for (Py_ssize_t k = 0; k < n; k++)
            if (!(fabs(p[k]) <= m->guard_v[0]))
                return 0;
        return 1;
    case GUARD_NOT_EQUAL:
        return !(n > 0 && p[0] == m->guard_v[0]);
    default:
        return 1;
    }
}

/*
 * The Method's binding when every argument is an ndarray the numpy fast path takes (else -1,
 * nothing bound: bind_all then does it all, with its messages). Presets were checked once,
 * when the Method was built: they are not re-checked for finiteness (a controller's
 * parameters are read-only and its state is written only by its own step, which keeps the
 * state when a result is not finite), nor for overlap (private arrays). The caller's inputs
 * must be finite, and the caller's out must not share memory with them. Any refusal (1 or -1)
 * ends in the Python body, which gives the error: the order of the tests is free.
 */
static int
method_bind_fast(MethodObject *m, Work *w, PyObject *const *ins, PyObject *const *outs,
                 int caller_out)
{
    FunctionObject *f = m->f;
    const Py_ssize_t n_in = f->n_in, n_out = f->n_out;
    for (Py_ssize_t j = 0; j < n_out; j++) {
        PyObject *o = outs[j];
        double *p = NULL;
        if (Py_TYPE(o) == np_type) {
            const Py_ssize_t nj = f->nnz[n_in + j];
            if ((p = np_vector(o, nj, NP_C_CONTIGUOUS | NP_ALIGNED | NP_WRITEABLE)) == NULL &&
                (p = np_fast(o, 1, nj, f->vec[n_in + j])) == NULL)
                return -1;
        }
        else if (o != Py_None) { /* None: an output not computed */
            return -1;
        }
        w->res[j] = p;
    }
    /* one returned array (the usual case): an input shares memory with the caller's out if
       and only if it meets its span [ob, oe) (empty without an out). Several: each returned
       array that meets the inputs' span [lo, hi) is tested against each input, after them */
    const int several = caller_out && m->n_ret > 1;
    uintptr_t ob = 0, oe = 0, lo = UINTPTR_MAX, hi = 0;
    if (caller_out && !several) {
        ob = (uintptr_t)w->res[m->ret_out[0]];
        oe = ob + (uintptr_t)f->nnz[n_in + m->ret_out[0]] * 8;
    }
    /* the inputs; the caller's: finite, and where they lie */
    int meets = 0;
    for (Py_ssize_t k = 0; k < n_in; k++) {
        PyObject *o = ins[k];
        const Py_ssize_t nk = f->nnz[k];
        double *p;
        if (Py_TYPE(o) == np_type) { /* the common case first */
            if ((p = np_vector(o, nk, NP_C_CONTIGUOUS | NP_ALIGNED)) == NULL &&
                (p = np_fast(o, 0, nk, f->vec[k])) == NULL)
                return -1;
        }
        else if (nk == 1 && PyFloat_Check(o)) { /* a number, as bind_input */
            w->scalars[k] = PyFloat_AS_DOUBLE(o);
            p = &w->scalars[k];
        }
        else {
            return -1;
        }
        w->arg[k] = p;
        if (m->tmpl[k] != NULL || nk <= 0)
            continue;
        if (!all_finite(p, nk))
            return 1;
        const uintptr_t b0 = (uintptr_t)p, b1 = b0 + (uintptr_t)nk * 8;
        meets |= (b0 < oe) & (ob < b1);
        if (several) {
            lo = b0 < lo ? b0 : lo;
            hi = b1 > hi ? b1 : hi;
        }
    }
    if (!several || hi == 0)
        return meets;
    for (Py_ssize_t r = 0; r < m->n_ret; r++) {
        const Py_ssize_t j = m->ret_out[r];
        if (!overlaps(w->res[j], f->nnz[n_in + j], (const void *)lo, (Py_ssize_t)(hi - lo) / 8))
            continue;
        for (Py_ssize_t i = 0; i < n_in; i++)
            if (m->tmpl[i] == NULL &&
                overlaps(w->res[j], f->nnz[n_in + j], w->arg[i], f->nnz[i]))
                return 1;
    }
    return 0;
}

/* The call of a Method with the caller's n_given inputs `args` and its `out`. */
static PyObject *
method_call(MethodObject *m, PyObject *const *args, PyObject *out)
{
    FunctionObject *f = m->f;
    PyObject *ret[METHOD_MAX_RET];
    PyObject *argv[METHOD_MAX_ARGS];
    const Py_ssize_t n_in = f->n_in, n_out = f->n_out;
    Py_ssize_t r;

    /* the inputs: presets and the caller's (as given when there are only the caller's) */
    PyObject *const *ins = args, *const *outs = ret;
    if (!m->plain_in) {
        for (Py_ssize_t i = 0, g = 0; i < n_in; i++) {
            PyObject *o = m->tmpl[i];
            if (o == NULL) {
                o = args[g++];
                if (m->positive[i]) { /* e.g. a sample period: a float > 0, nothing else */
                    if (!PyFloat_Check(o))
                        return refuse();
                    const double v = PyFloat_AS_DOUBLE(o);
                    if (!(v > 0.0 && v < INFINITY))
                        return refuse();
                }
            }
            argv[i] = o;
        }
        ins = argv;
    }

    /* the returned outputs: the caller's (exact type and shape), or new arrays */
    if (out == Py_None && m->scalar != NULL) {
        ret[0] = Py_NewRef(m->scalar);
    }
    else if (out == Py_None) {
        for (r = 0; r < m->n_ret; r++) {
            ret[r] = PyObject_CallOneArg(m->empty, m->ret_shape[r]);
            if (ret[r] == NULL) {
                while (r-- > 0)
                    Py_DECREF(ret[r]);
                return NULL;
            }
        }
    }
    else if (m->kind == NULL) {
        if (!ret_shape_ok(m, out, 0))
            return refuse();
        ret[0] = Py_NewRef(out);
    }
    else {
        if (Py_TYPE(out) != (PyTypeObject *)m->kind || PyTuple_GET_SIZE(out) != m->n_ret)
            return refuse();
        for (r = 0; r < m->n_ret; r++)
            if (!ret_shape_ok(m, PyTuple_GET_ITEM(out, r), r))
                return refuse();
        for (r = 0; r < m->n_ret; r++)
            ret[r] = Py_NewRef(PyTuple_GET_ITEM(out, r));
    }

    if (!m->plain_out) { /* the returned arrays among the presets */
        for (Py_ssize_t j = 0, rr = 0; j < n_out; j++)
            argv[n_in + j] = m->tmpl[n_in + j] ? m->tmpl[n_in + j] : ret[rr++];
        outs = argv + n_in;
    }

    Work tmp;
    Work *w = work_acquire(f, &tmp);
    Py_ssize_t held = 0;
    int rc = 0, bad = 0, tripped = 0;
    if (w == NULL) {
        bad = -1;
        goto done;
    }
    int fast = method_bind_fast(m, w, ins, outs, out != Py_None);
    if (fast < 0) { /* bind_all takes the inputs and outputs in one array */
        if (m->plain_in)
            memcpy(argv, ins, (size_t)n_in * sizeof(*argv));
        if (m->plain_out)
            memcpy(argv + n_in, outs, (size_t)n_out * sizeof(*argv));
    }
    if (fast > 0 || (fast < 0 && bind_all(f, w, argv, 1, NULL, &held) < 0)) {
        bad = 1;
        goto release;
    }
    rc = f->eval(w->arg, w->res, w->iw, w->w, w->mem);
    if (rc != 0) {
        bad = 1;
        goto release;
    }
    if (m->finite) {
        for (Py_ssize_t j = 0; j < n_out && !bad; j++)
            if (w->res[j] && !all_finite(w->res[j], f->nnz[n_in + j]))
                bad = 1;
        if (bad)
            goto release;
    }
    if (m->fb_out >= 0)
        memcpy((double *)w->arg[m->fb_in], w->res[m->fb_out],
               (size_t)f->nnz[m->fb_in] * sizeof(double));
    if (m->guard_on && m->guard_kind != GUARD_NONE &&
        !guard_passes(m, w->res[m->guard_out], f->nnz[n_in + m->guard_out]))
        tripped = 1;
release:
    work_done(f, w, held);
done:
    if (bad || tripped) {
        for (r = 0; r < m->n_ret; r++)
            Py_DECREF(ret[r]);
        if (bad < 0)
            return NULL;
        if (bad)
            return refuse();
        PyErr_Clear();
        PyErr_SetNone(m->fb_out >= 0 ? GuardTripped : Refused);
        return NULL;
    }
    if (out != Py_None) {
        for (r = 0; r < m->n_ret; r++)
            Py_DECREF(ret[r]);
        return Py_NewRef(out);
    }
    if (m->scalar != NULL) {
        Py_DECREF(ret[0]);
        return PyFloat_FromDouble(*(const double *)((const NpArray *)m->scalar)->data);
    }
    if (m->kind == NULL)
        return ret[0];
    PyObject *items = PyTuple_New(m->n_ret);
    if (items == NULL) {
        for (r = 0; r < m->n_ret; r++)
            Py_DECREF(ret[r]);
        return NULL;
    }
    for (r = 0; r < m->n_ret; r++)
        PyTuple_SET_ITEM(items, r, ret[r]); /* steals */
    PyObject *targs = PyTuple_Pack(1, items);
    Py_DECREF(items);
    if (targs == NULL)
        return NULL;
    /* tuple.__new__(kind, items): a NamedTuple without calling its Python __new__ */
    PyObject *res = PyTuple_Type.tp_new((PyTypeObject *)m->kind, targs, NULL);
    Py_DECREF(targs);
    return res;
}

static PyObject *
Method_vectorcall(PyObject *self, PyObject *const *args, size_t nargsf, PyObject *kwnames)
{
    MethodObject *m = (MethodObject *)self;
    const Py_ssize_t nargs = PyVectorcall_NARGS(nargsf);
    if ((kwnames != NULL && PyTuple_GET_SIZE(kwnames) > 0) || nargs != m->n_given + 1) {
        PyErr_Format(PyExc_TypeError, "Method of %U takes %zd positional arguments (%zd "
                     "inputs, out), got %zd", m->f->name, m->n_given + 1, m->n_given, nargs);
        return NULL;
    }
    return method_call(m, args, args[nargs - 1]);
}

static int
Method_traverse(MethodObject *m, visitproc visit, void *arg)
{
    Py_VISIT(m->f);
    Py_VISIT(m->empty);
    Py_VISIT(m->kind);
    Py_VISIT(m->scalar);
    if (m->f && m->tmpl)
        for (Py_ssize_t k = 0; k < m->f->n_in + m->f->n_out; k++)
            Py_VISIT(m->tmpl[k]);
    return 0;
}

static int
Method_clear(MethodObject *m)
{
    if (m->tmpl && m->f)
        for (Py_ssize_t k = 0; k < m->f->n_in + m->f->n_out; k++)
            Py_CLEAR(m->tmpl[k]);
    for (Py_ssize_t r = 0; r < METHOD_MAX_RET; r++)
        Py_CLEAR(m->ret_shape[r]);
    Py_CLEAR(m->empty);
    Py_CLEAR(m->kind);
    Py_CLEAR(m->scalar);
    return 0;
}

static void
Method_dealloc(MethodObject *m)
{
    PyObject_GC_UnTrack(m);
    Method_clear(m);
    PyMem_Free(m->tmpl);
    Py_CLEAR(m->f);
    Py_TYPE(m)->tp_free((PyObject *)m);
}

/* A preset argument: an ndarray the fast path takes (float64, C-contiguous, the element
   count; writable for an output or a feedback target). */
static int
preset_ok(FunctionObject *f, PyObject *o, Py_ssize_t k, int writable, const char *what)
{
    if (np_is_ndarray(o) && np_fast(o, writable, f->nnz[k], 0) != NULL)
        return 1;
    PyErr_Format(PyExc_ValueError, "Method of %U: %s #%zd must be a %sC-contiguous float64 "
                 "ndarray of %zd elements", f->name, what, k < f->n_in ? k : k - f->n_in,
                 writable ? "writable " : "", f->nnz[k]);
    return 0;
}

static PyObject *
Method_new(PyTypeObject *type, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {"function", "inputs", "outputs", "empty", "kind", "finite",
                             "guard", "feedback", "positive", "scalar", NULL};
    PyObject *fo, *inputs, *outputs, *empty = NULL, *kind = Py_None, *guard = Py_None,
                                             *feedback = Py_None, *positive = Py_None;
    int finite = 0, scalar = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "O!O!O!|$OOpOOOp:Method", kwlist,
                                     &FunctionType, &fo, &PyTuple_Type, &inputs, &PyTuple_Type,
                                     &outputs, &empty, &kind, &finite, &guard, &feedback,
                                     &positive, &scalar))
        return NULL;
    FunctionObject *f = (FunctionObject *)fo;
    if (PyTuple_GET_SIZE(inputs) != f->n_in || PyTuple_GET_SIZE(outputs) != f->n_out) {
        PyErr_Format(PyExc_ValueError, "Method of %U: inputs and outputs must have %zd and "
                     "%zd entries", f->name, f->n_in, f->n_out);
        return NULL;
    }
    if (f->n_in + f->n_out > METHOD_MAX_ARGS) {
        PyErr_Format(PyExc_ValueError, "Method of %U: more than %d arguments", f->name,
                     METHOD_MAX_ARGS);
        return NULL;
    }
    if (empty == NULL || !PyCallable_Check(empty) || (kind != Py_None && !(PyType_Check(kind) &&
                                                          PyType_IsSubtype((PyTypeObject *)kind,
                                                                           &PyTuple_Type)))) {
        PyErr_SetString(PyExc_TypeError, "Method: empty must be callable (numpy.empty), kind "
                        "None or a tuple subclass");
        return NULL;
    }
    MethodObject *m = (MethodObject *)type->tp_alloc(type, 0);
    if (m == NULL)
        return NULL;
    m->vectorcall = Method_vectorcall;
    m->f = (FunctionObject *)Py_NewRef(fo);
    m->empty = Py_NewRef(empty);
    m->fb_out = m->fb_in = -1;
    m->guard_on = 1;
    m->finite = (char)finite;
    const Py_ssize_t nio = f->n_in + f->n_out;
    m->tmpl = PyMem_Calloc((size_t)nio + 1, sizeof(PyObject *));
    if (m->tmpl == NULL) {
        PyErr_NoMemory();
        goto fail;
    }
    for (Py_ssize_t i = 0; i < f->n_in; i++) {
        PyObject *o = PyTuple_GET_ITEM(inputs, i);
        if (o == Py_None) {
            m->n_given++;
            continue;
        }
        if (!preset_ok(f, o, i, 0, "input"))
            goto fail;
        m->tmpl[i] = Py_NewRef(o);
    }
    for (Py_ssize_t j = 0; j < f->n_out; j++) {
        PyObject *o = PyTuple_GET_ITEM(outputs, j);
        if (PyTuple_Check(o)) { /* a returned output: its shape */
            Py_ssize_t r = m->n_ret, nd = PyTuple_GET_SIZE(o), count = 1;
            if (r >= METHOD_MAX_RET || nd > METHOD_MAX_ND) {
                PyErr_Format(PyExc_ValueError, "Method of %U: too many returned outputs or "
                             "dimensions", f->name);
                goto fail;
            }
            for (Py_ssize_t k = 0; k < nd; k++) {
                Py_ssize_t d = PyLong_AsSsize_t(PyTuple_GET_ITEM(o, k));
                if (d < 0) {
                    if (!PyErr_Occurred())
                        PyErr_SetString(PyExc_ValueError, "Method: negative dimension");
                    goto fail;
                }
                m->ret_dims[r][k] = d;
                count *= d;
            }
            if (count != f->nnz[f->n_in + j]) {
                PyErr_Format(PyExc_ValueError, "Method of %U: output #%zd has %zd elements, "
                             "shape %R has %zd", f->name, j, f->nnz[f->n_in + j], o, count);
                goto fail;
            }
            m->ret_nd[r] = (int)nd;
            m->ret_shape[r] = Py_NewRef(o);
            m->ret_out[r] = j;
            m->n_ret++;
        }
        else if (o == Py_None) {
            m->tmpl[f->n_in + j] = Py_NewRef(o);
        }
        else {
            if (!preset_ok(f, o, f->n_in + j, 1, "output"))
                goto fail;
            m->tmpl[f->n_in + j] = Py_NewRef(o);
        }
    }
    if (m->n_ret < 1 || (m->n_ret > 1) != (kind != Py_None)) {
        PyErr_Format(PyExc_ValueError, "Method of %U: at least one returned output (a shape "
                     "tuple), and kind exactly when there are several", f->name);
        goto fail;
    }
    if (kind != Py_None)
        m->kind = Py_NewRef(kind);
    if (guard != Py_None) {
        Py_ssize_t j;
        const char *how;
        PyObject *val;
        if (!PyArg_ParseTuple(guard, "nsO:guard", &j, &how, &val))
            goto fail;
        if (j < 0 || j >= f->n_out || m->tmpl[f->n_in + j] == NULL ||
            m->tmpl[f->n_in + j] == Py_None) {
            PyErr_Format(PyExc_ValueError, "Method of %U: the guard's output #%zd must be a "
                         "scratch output", f->name, j);
            goto fail;
        }
        m->guard_out = j;
        if (strcmp(how, "at_least") == 0) {
            m->guard_kind = GUARD_AT_LEAST;
            if (!PyArg_ParseTuple(val, "dd:guard", &m->guard_v[0], &m->guard_v[1]))
                goto fail;
        }
        else if (strcmp(how, "abs_at_most") == 0 || strcmp(how, "not_equal") == 0) {
            m->guard_kind = how[0] == 'a' ? GUARD_ABS_AT_MOST : GUARD_NOT_EQUAL;
            m->guard_v[0] = PyFloat_AsDouble(val);
            if (m->guard_v[0] == -1.0 && PyErr_Occurred())
                goto fail;
        }
        else {
            PyErr_Format(PyExc_ValueError, "Method: unknown guard '%s'", how);
            goto fail;
        }
    }
    if (feedback != Py_None) {
        Py_ssize_t j, i;
        if (!PyArg_ParseTuple(feedback, "nn:feedback", &j, &i))
            goto fail;
        if (j < 0 || j >= f->n_out || i < 0 || i >= f->n_in || m->tmpl[i] == NULL ||
            m->tmpl[f->n_in + j] == NULL || m->tmpl[f->n_in + j] == Py_None ||
            f->nnz[i] != f->nnz[f->n_in + j] || !preset_ok(f, m->tmpl[i], i, 1, "input")) {
            if (!PyErr_Occurred())
                PyErr_Format(PyExc_ValueError, "Method of %U: feedback needs a scratch output "
                             "and a preset writable input of the same size", f->name);
            goto fail;
        }
        m->fb_out = j;
        m->fb_in = i;
    }
    if (positive != Py_None) {
        if (!PyTuple_Check(positive)) {
            PyErr_SetString(PyExc_TypeError, "Method: positive must be a tuple of indices");
            goto fail;
        }
        for (Py_ssize_t k = 0; k < PyTuple_GET_SIZE(positive); k++) {
            Py_ssize_t gi = PyLong_AsSsize_t(PyTuple_GET_ITEM(positive, k)), i, g = -1;
            if (gi == -1 && PyErr_Occurred())
                goto fail;
            for (i = 0; i < f->n_in; i++)      /* the given input gi's index in the inputs */
                if (m->tmpl[i] == NULL && ++g == gi)
                    break;
            if (gi < 0 || i == f->n_in || f->nnz[i] != 1) {
                PyErr_Format(PyExc_ValueError, "Method of %U: positive #%zd is not a given "
                             "input of one element", f->name, gi);
                goto fail;
            }
            m->positive[i] = 1;
        }
    }
    m->plain_in = m->n_given == f->n_in;
    for (Py_ssize_t i = 0; i < f->n_in; i++)
        if (m->positive[i])
            m->plain_in = 0;
    m->plain_out = m->n_ret == f->n_out;
    if (scalar) {
        if (m->n_ret != 1 || f->nnz[f->n_in + m->ret_out[0]] != 1) {
            PyErr_Format(PyExc_ValueError, "Method of %U: scalar needs one returned output of "
                         "one element", f->name);
            goto fail;
        }
        m->scalar = PyObject_CallOneArg(empty, m->ret_shape[0]);
        if (m->scalar == NULL)
            goto fail;
        if (!preset_ok(f, m->scalar, f->n_in + m->ret_out[0], 1, "output")) {
            Py_CLEAR(m->scalar);
            goto fail;
        }
    }
    return (PyObject *)m;

fail:
    Py_DECREF(m);
    return NULL;
}

static PyMemberDef Method_members[] = {
    {"function", T_OBJECT_EX, offsetof(MethodObject, f), READONLY, "The bound Function."},
    {"guard_on", T_BOOL, offsetof(MethodObject, guard_on), 0,
     "Whether the guard is checked (default true)."},
    {"finite", T_BOOL, offsetof(MethodObject, finite), READONLY,
     "Whether every computed output must be finite."},
    {NULL, 0, 0, 0, NULL},
};

PyDoc_STRVAR(Method_doc,
"Method(function, inputs, outputs, *, empty, kind=None, finite=False, guard=None,\n"
"       feedback=None, positive=None, scalar=False)\n"
"--\n\n"
"The fast path of one call as a single C call: m(*given_inputs, out).\n\n"
"inputs: per input of function, None (the caller gives it, in order) or a preset\n"
"C-contiguous float64 ndarray bound at every call. outputs: per output, a shape tuple\n"
"(returned: the caller's out, an ndarray of exactly that shape, or a new array from\n"
"empty(shape)), None (not computed) or a preset scratch ndarray. With several returned\n"
"outputs the result is a kind instance (a tuple subclass) and out is None or one.\n"
"finite: every computed output must be finite. guard: (j, 'at_least', (a, b)),\n"
"(j, 'abs_at_most', tol) or (j, 'not_equal', v) on scratch output j. feedback: (j, i)\n"
"copies output j into preset input i after the evaluation. positive: indices of given\n"
"inputs of one element that must be a Python float > 0 and finite (e.g. a sample\n"
"period); anything else there is refused. scalar:\n"
"the one returned output has one element, written into the Method's own array when out\n"
"is None, and the result is a Python float.\n\n"
"Raises Refused (no message, nothing changed) when the fast path does not accept the\n"
"call: a bad argument, a non-finite output, a failed guard; the caller then takes its\n"
"checked path. With feedback a failed guard raises GuardTripped after the copy.");

static PyTypeObject MethodType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "pm2dof.core._cbind.Method",
    .tp_basicsize = sizeof(MethodObject),
    .tp_dealloc = (destructor)Method_dealloc,
    .tp_vectorcall_offset = offsetof(MethodObject, vectorcall),
    .tp_call = PyVectorcall_Call,
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_VECTORCALL | Py_TPFLAGS_HAVE_GC,
    .tp_doc = Method_doc,
    .tp_traverse = (traverseproc)Method_traverse,
    .tp_clear = (inquiry)Method_clear,
    .tp_members = Method_members,
    .tp_new = Method_new,
};

/* ------------------------------------------------------------------------------------ */
/* FastMethod                                                                           */
/* ------------------------------------------------------------------------------------ */

/*
 * FastMethod(func, key, params, required, *, unless=None)
 *
 * A method of a class (pm2dof.Model's per-sample methods) whose call from Python is one C
 * call: a method descriptor (no bound method is made for obj.name(...)) that maps the
 * arguments onto the instance's Method, obj._fast[key], and calls it; what that refuses, and
 * every call it does not map (an unknown or repeated keyword, a missing argument, a Method
 * missing, obj.<unless> not None), goes to func(obj, ...) with the arguments as given: the
 * Python method, its checked path, which converts and names the problem in a typed error.
 *
 * params: the names of func's parameters after self, in order; "out", if there, is the
 * Method's out, the others its given inputs in order (None: the Method's default, if any).
 * required: how many leading parameters have no default.
 */

#define FM_MAX_PARAMS 16

typedef struct {
    PyObject_HEAD
    vectorcallfunc vectorcall;
    PyObject *func;      /* the Python method: the checked path */
    PyObject *key;       /* the Method's key in obj._fast */
    PyObject *params;    /* tuple of str */
    Py_ssize_t n_params, n_req, out_pos; /* out_pos: index of "out" in params, or -1 */
    Py_ssize_t n_inputs; /* n_params without out */
    PyObject *unless;    /* attribute name, or NULL */
    PyObject *dict;      /* __dict__: __doc__, __name__, __wrapped__, ... */
    PyTypeObject *ctype; /* the last instance's type whose _fast (and unless) are slots */
    unsigned int ctag;   /* its version tag then: a changed class is looked up again */
    Py_ssize_t off_fast, off_unless; /* their offsets in an instance (-1: no unless) */
#if PY_VERSION_HEX < 0x030C0000
    /* the Method last found in an instance's _fast, with that dict and its version tag: the
       same dict, unmodified since (a dict's version tag is unique to one dict and one state,
       CPython 3.11), holds the same Method (borrowed: the dict keeps it). A model's _fast only
       ever gains keys (model._Pending), and a new one is looked up again. */
    PyObject *cdict, *cmeth;
    uint64_t cdict_tag;
#endif
} FastMethodObject;

static PyObject *str_fast; /* "_fast" */

/* The offset of the slot `name` of instances of `type` (a member descriptor holding an
   object, found on the type as attribute lookup finds it), else -1. */
static Py_ssize_t
slot_offset(PyTypeObject *type, PyObject *name)
{
    PyObject *descr = _PyType_Lookup(type, name); /* borrowed */
    if (descr == NULL || Py_TYPE(descr) != &PyMemberDescr_Type)
        return -1;
    PyMemberDef *def = ((PyMemberDescrObject *)descr)->d_member;
    return def->type == T_OBJECT_EX ? def->offset : -1;
}

/* obj's attribute `name` (a new reference; NULL without an error when it has none): read
   from its slot when obj's type is the one cached, else looked up (and the type cached when
   both attributes are slots). */
static PyObject *
fm_attr(FastMethodObject *d, PyObject *obj, PyObject *name, int which)
{
    PyTypeObject *t = Py_TYPE(obj);
    if (t != d->ctype || !(t->tp_flags & Py_TPFLAGS_VALID_VERSION_TAG) ||
        t->tp_version_tag != d->ctag) {
        Py_ssize_t of = slot_offset(t, str_fast);
        Py_ssize_t ou = d->unless ? slot_offset(t, d->unless) : -1;
        if (of >= 0 && (d->unless == NULL || ou >= 0) &&
            (t->tp_flags & Py_TPFLAGS_VALID_VERSION_TAG)) {
            Py_INCREF(t);
            Py_XSETREF(d->ctype, t);
            d->ctag = t->tp_version_tag;
            d->off_fast = of;
            d->off_unless = ou;
        }
        else {
            PyObject *v = PyObject_GetAttr(obj, name);
            if (v == NULL)
                PyErr_Clear();
            return v;
        }
    }
    PyObject *v = *(PyObject **)((char *)obj + (which ? d->off_unless : d->off_fast));
    Py_XINCREF(v);
    return v;
}

static PyObject *
FastMethod_vectorcall(PyObject *self, PyObject *const *args, size_t nargsf, PyObject *kwnames)
{
    FastMethodObject *d = (FastMethodObject *)self;
    const Py_ssize_t nargs = PyVectorcall_NARGS(nargsf);
    const Py_ssize_t nkw = kwnames ? PyTuple_GET_SIZE(kwnames) : 0;
    PyObject *slot[FM_MAX_PARAMS];
    PyObject *given_buf[FM_MAX_PARAMS];
    PyObject *const *given = given_buf;
    PyObject *out;
    Py_ssize_t g = 0;
    if (nargs < 1 || nargs - 1 > d->n_params)
        goto checked;
    /* the usual call, every input by position and out (last) by keyword or not given: the
       inputs are the caller's own array of arguments */
    if (nargs - 1 == d->n_inputs && (d->out_pos < 0 || d->out_pos == d->n_params - 1) &&
        (nkw == 0 || (nkw == 1 && d->out_pos >= 0 &&
                      PyTuple_GET_ITEM(kwnames, 0) == PyTuple_GET_ITEM(d->params, d->out_pos)))) {
        given = args + 1;
        g = d->n_inputs;
        out = nkw ? args[nargs] : Py_None;
        goto mapped;
    }
    for (Py_ssize_t j = 0; j < d->n_params; j++)
        slot[j] = NULL;
    for (Py_ssize_t j = 0; j < nargs - 1; j++)
        slot[j] = args[1 + j];
    for (Py_ssize_t i = 0; i < nkw; i++) {
        PyObject *name = PyTuple_GET_ITEM(kwnames, i);
        Py_ssize_t j = 0;
        while (j < d->n_params && PyTuple_GET_ITEM(d->params, j) != name)  /* interned */
            j++;
        if (j == d->n_params) {  /* not the same object: compare the text */
            for (j = 0; j < d->n_params; j++) {
                int eq = PyUnicode_Compare(PyTuple_GET_ITEM(d->params, j), name);
                if (eq == -1 && PyErr_Occurred())
                    PyErr_Clear();
                else if (eq == 0)
                    break;
            }
        }
        if (j == d->n_params || slot[j] != NULL)
            goto checked;
        slot[j] = args[nargs + i];
    }
    for (Py_ssize_t j = 0; j < d->n_params; j++) {
        if (slot[j] == NULL) {
            if (j < d->n_req)
                goto checked;
            slot[j] = Py_None;
        }
        if (j != d->out_pos)
            given_buf[g++] = slot[j];
    }
    out = d->out_pos >= 0 ? slot[d->out_pos] : Py_None;
mapped:;
    PyObject *obj = args[0];
    if (d->unless != NULL) {
        PyObject *u = fm_attr(d, obj, d->unless, 1);
        if (u == NULL)
            goto checked;
        Py_DECREF(u);
        if (u != Py_None)
            goto checked;
    }
    PyObject *fast = fm_attr(d, obj, str_fast, 0);
    if (fast == NULL)
        goto checked;
    PyObject *meth;
#if PY_VERSION_HEX < 0x030C0000
    if (fast == d->cdict && PyDict_Check(fast) &&
        ((PyDictObject *)fast)->ma_version_tag == d->cdict_tag) {
        meth = d->cmeth;
    }
    else {
        meth = PyDict_Check(fast) ? PyDict_GetItemWithError(fast, d->key) : NULL;
        if (meth != NULL) {
            d->cdict = fast;  /* borrowed, compared only together with the tag */
            d->cdict_tag = ((PyDictObject *)fast)->ma_version_tag;
            d->cmeth = meth;
        }
    }
#else
    meth = PyDict_Check(fast) ? PyDict_GetItemWithError(fast, d->key) : NULL;
#endif
    Py_DECREF(fast);  /* the instance holds it, and it holds meth */
    if (meth == NULL || Py_TYPE(meth) != &MethodType || ((MethodObject *)meth)->n_given != g) {
        PyErr_Clear();
        goto checked;
    }
    Py_INCREF(meth);
    PyObject *res = method_call((MethodObject *)meth, given, out);
    Py_DECREF(meth);
    if (res != NULL || !PyErr_ExceptionMatches(Refused))
        return res;
    PyErr_Clear();
checked:
    return PyObject_Vectorcall(d->func, args, nargsf, kwnames);
}

static PyObject *
FastMethod_descr_get(PyObject *self, PyObject *obj, PyObject *type)
{
    if (obj == NULL || obj == Py_None)
        return Py_NewRef(self);
    return PyMethod_New(self, obj);
}

static int
FastMethod_traverse(FastMethodObject *d, visitproc visit, void *arg)
{
    Py_VISIT(d->func);
    Py_VISIT(d->dict);
    Py_VISIT(d->ctype);
    return 0;
}

static int
FastMethod_clear(FastMethodObject *d)
{
    Py_CLEAR(d->func);
    Py_CLEAR(d->key);
    Py_CLEAR(d->params);
    Py_CLEAR(d->unless);
    Py_CLEAR(d->dict);
    Py_CLEAR(d->ctype);
    return 0;
}

static void
FastMethod_dealloc(FastMethodObject *d)
{
    PyObject_GC_UnTrack(d);
    FastMethod_clear(d);
    Py_TYPE(d)->tp_free((PyObject *)d);
}

static PyObject *
FastMethod_new(PyTypeObject *type, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {"func", "key", "params", "required", "unless", NULL};
    PyObject *func, *key, *params, *unless = Py_None;
    Py_ssize_t required;
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "OUO!n|$O:FastMethod", kwlist, &func, &key,
                                     &PyTuple_Type, &params, &required, &unless))
        return NULL;
    const Py_ssize_t n = PyTuple_GET_SIZE(params);
    if (!PyCallable_Check(func) || n > FM_MAX_PARAMS || required < 0 || required > n ||
        (unless != Py_None && !PyUnicode_Check(unless))) {
        PyErr_Format(PyExc_ValueError, "FastMethod: func must be callable, params a tuple of at "
                     "most %d names, 0 <= required <= len(params), unless None or a str",
                     FM_MAX_PARAMS);
        return NULL;
    }
    FastMethodObject *d = (FastMethodObject *)type->tp_alloc(type, 0);
    if (d == NULL)
        return NULL;
    d->vectorcall = FastMethod_vectorcall;
    d->func = Py_NewRef(func);
    d->key = Py_NewRef(key);
    PyUnicode_InternInPlace(&d->key);
    d->params = PyTuple_New(n);
    if (d->params == NULL)
        goto fail;
    d->n_params = n;
    d->n_req = required;
    d->out_pos = -1;
    for (Py_ssize_t j = 0; j < n; j++) {
        PyObject *name = PyTuple_GET_ITEM(params, j);
        if (!PyUnicode_Check(name)) {
            PyErr_SetString(PyExc_TypeError, "FastMethod: params must be str");
            goto fail;
        }
        Py_INCREF(name);
        PyUnicode_InternInPlace(&name);
        PyTuple_SET_ITEM(d->params, j, name);
        if (PyUnicode_CompareWithASCIIString(name, "out") == 0)
            d->out_pos = j;
    }
    d->n_inputs = n - (d->out_pos >= 0);
    if (unless != Py_None) {
        d->unless = Py_NewRef(unless);
        PyUnicode_InternInPlace(&d->unless);
    }
    return (PyObject *)d;
fail:
    Py_DECREF(d);
    return NULL;
}

static PyMemberDef FastMethod_members[] = {
    {"func", T_OBJECT_EX, offsetof(FastMethodObject, func), READONLY,
     "The Python method: the checked path."},
    {"key", T_OBJECT_EX, offsetof(FastMethodObject, key), READONLY,
     "The key of the instance's Method in its _fast mapping."},
    {"params", T_OBJECT_EX, offsetof(FastMethodObject, params), READONLY,
     "The parameter names after self."},
    {NULL, 0, 0, 0, NULL},
};

static PyGetSetDef FastMethod_getset[] = {
    {"__dict__", PyObject_GenericGetDict, PyObject_GenericSetDict, NULL, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

PyDoc_STRVAR(FastMethod_doc,
"FastMethod(func, key, params, required, *, unless=None)\n"
"--\n\n"
"A method whose call is one C call: obj.name(*args, out=...) maps the arguments onto\n"
"the Method obj._fast[key] and calls it. What the Method refuses, and any call it does\n"
"not map (an unknown or repeated keyword, a missing argument, no such Method,\n"
"getattr(obj, unless) not None), goes to func(obj, ...) with the arguments as given.\n\n"
"params: func's parameter names after self; 'out', if there, is the Method's out, the\n"
"others its given inputs in order. required: how many leading ones have no default.");

static PyTypeObject FastMethodType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "pm2dof.core._cbind.FastMethod",
    .tp_basicsize = sizeof(FastMethodObject),
    .tp_dealloc = (destructor)FastMethod_dealloc,
    .tp_vectorcall_offset = offsetof(FastMethodObject, vectorcall),
    .tp_call = PyVectorcall_Call,
    .tp_descr_get = FastMethod_descr_get,
    .tp_getattro = PyObject_GenericGetAttr,
    .tp_setattro = PyObject_GenericSetAttr,
    .tp_dictoffset = offsetof(FastMethodObject, dict),
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_VECTORCALL | Py_TPFLAGS_HAVE_GC |
                Py_TPFLAGS_METHOD_DESCRIPTOR,
    .tp_doc = FastMethod_doc,
    .tp_traverse = (traverseproc)FastMethod_traverse,
    .tp_clear = (inquiry)FastMethod_clear,
    .tp_members = FastMethod_members,
    .tp_getset = FastMethod_getset,
    .tp_new = FastMethod_new,
};

/* ------------------------------------------------------------------------------------ */
/* C API (_cbind_api.h): generated functions called from other extensions                 */
/* ------------------------------------------------------------------------------------ */

struct Pm2dofCall {
    FunctionObject *f;
    Work *w;
    Work tmp;
};

static Pm2dofCall *
api_begin(PyObject *o, Py_ssize_t n_in, Py_ssize_t n_out)
{
    if (!PyObject_TypeCheck(o, &FunctionType)) {
        PyErr_Format(PyExc_TypeError, "expected a pm2dof.core._cbind.Function, got %.200s",
                     Py_TYPE(o)->tp_name);
        return NULL;
    }
    FunctionObject *f = (FunctionObject *)o;
    if (f->n_in != n_in || f->n_out != n_out) {
        PyErr_Format(PyExc_TypeError, "%U: expected %zd inputs and %zd outputs, it has %zd "
                     "and %zd", f->name, n_in, n_out, f->n_in, f->n_out);
        return NULL;
    }
    Pm2dofCall *c = PyMem_Calloc(1, sizeof(*c));
    if (c == NULL)
        return (Pm2dofCall *)PyErr_NoMemory();
    c->w = work_acquire(f, &c->tmp);
    if (c->w == NULL) {
        PyMem_Free(c);
        return NULL;
    }
    /* the temporary was initialised in place: it stays where it is (c is not moved) */
    Py_INCREF(o);
    c->f = f;
    return c;
}

static Py_ssize_t
api_nnz(const Pm2dofCall *c, Py_ssize_t i)
{
    return c->f->nnz[i];
}

static int
api_eval(Pm2dofCall *c, const double *const *arg, double *const *res)
{
    Work *w = c->w;
    for (Py_ssize_t i = 0; i < c->f->n_in; i++)
        w->arg[i] = arg[i];
    for (Py_ssize_t i = 0; i < c->f->n_out; i++)
        w->res[i] = res[i];
    return c->f->eval(w->arg, w->res, w->iw, w->w, w->mem);
}

static void
api_end(Pm2dofCall *c)
{
    if (c == NULL)
        return;
    work_done(c->f, c->w, 0);
    Py_DECREF((PyObject *)c->f);
    PyMem_Free(c);
}

static const Pm2dofCbindAPI cbind_api = {api_begin, api_nnz, api_eval, api_end};

/* ------------------------------------------------------------------------------------ */
/* Module                                                                               */
/* ------------------------------------------------------------------------------------ */

PyDoc_STRVAR(module_doc,
"Near-zero-overhead calls into CasADi-generated C functions loaded with dlopen.\n\n"
"Library(path) loads a shared library; Function(library, name) resolves one\n"
"generated function; EvalError is raised when the function returns nonzero.");

static struct PyModuleDef cbind_module = {
    PyModuleDef_HEAD_INIT,
    .m_name = "pm2dof.core._cbind",
    .m_doc = module_doc,
    .m_size = -1,
};

PyMODINIT_FUNC
PyInit__cbind(void)
{
    if (PyType_Ready(&LibraryType) < 0 || PyType_Ready(&FunctionType) < 0 ||
        PyType_Ready(&MethodType) < 0 || PyType_Ready(&FastMethodType) < 0)
        return NULL;
    str_fast = PyUnicode_InternFromString("_fast");
    if (str_fast == NULL)
        return NULL;
    PyObject *m = PyModule_Create(&cbind_module);
    if (m == NULL)
        return NULL;
    EvalError = PyErr_NewExceptionWithDoc(
        "pm2dof.core._cbind.EvalError",
        "A CasADi-generated function returned a nonzero error code.", PyExc_RuntimeError,
        NULL);
    NonFiniteOutputError = PyErr_NewExceptionWithDoc(
        "pm2dof.core._cbind.NonFiniteOutputError",
        "A call with finite inputs left a NaN or inf in an output (check_outputs).",
        PyExc_ValueError, NULL);
    Refused = PyErr_NewExceptionWithDoc(
        "pm2dof.core._cbind.Refused",
        "A Method's fast path did not accept the call (no message, nothing changed): take "
        "the checked path.", PyExc_Exception, NULL);
    GuardTripped = Refused == NULL ? NULL : PyErr_NewExceptionWithDoc(
        "pm2dof.core._cbind.GuardTripped",
        "A Method with feedback ran and copied its state, and its guard failed.", Refused,
        NULL);
    if (Refused == NULL || PyModule_AddObjectRef(m, "Refused", Refused) < 0 ||
        GuardTripped == NULL || PyModule_AddObjectRef(m, "GuardTripped", GuardTripped) < 0 ||
        PyModule_AddObjectRef(m, "Method", (PyObject *)&MethodType) < 0 ||
        PyModule_AddObjectRef(m, "FastMethod", (PyObject *)&FastMethodType) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    if (EvalError == NULL || PyModule_AddObjectRef(m, "EvalError", EvalError) < 0 ||
        NonFiniteOutputError == NULL ||
        PyModule_AddObjectRef(m, "NonFiniteOutputError", NonFiniteOutputError) < 0 ||
        PyModule_AddObjectRef(m, "Library", (PyObject *)&LibraryType) < 0 ||
        PyModule_AddObjectRef(m, "Function", (PyObject *)&FunctionType) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    PyObject *api = PyCapsule_New((void *)&cbind_api, PM2DOF_CBIND_API, NULL);
    if (api == NULL || PyModule_AddObjectRef(m, "_C_API", api) < 0) {
        Py_XDECREF(api);
        Py_DECREF(m);
        return NULL;
    }
    Py_DECREF(api);
    return m;
}
