/* The array arguments of the planner's C modules (_pathc.c, _passes.c): one check for all. */
#ifndef PM2DOF_PLANNING_BUFFERS_H
#define PM2DOF_PLANNING_BUFFERS_H

#include <string.h>

/* A C-contiguous array of float64 (integer: int64) held as the buffer view v, writable if
 * asked, of exactly n entries when n >= 0. 0, or -1 with the view released and an error
 * naming the argument: TypeError for the wrong kind of array, ValueError for the wrong size. */
static int
take_buffer(PyObject *o, Py_buffer *v, const char *name, int writable, Py_ssize_t n,
            int integer)
{
    if (PyObject_GetBuffer(o, v, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT |
                                     (writable ? PyBUF_WRITABLE : 0)) < 0)
        return -1;
    const char *fmt = v->format ? v->format : "";
    int fits = integer ? strcmp(fmt, "l") == 0 || strcmp(fmt, "q") == 0 : strcmp(fmt, "d") == 0;
    if (v->itemsize != 8 || !fits) {
        PyErr_Format(PyExc_TypeError, "%s must be a contiguous %s array", name,
                     integer ? "int64" : "float64");
        PyBuffer_Release(v);
        return -1;
    }
    if (n >= 0 && v->len / 8 != n) {
        PyErr_Format(PyExc_ValueError, "%s must hold %zd entries, got %zd", name, n,
                     v->len / 8);
        PyBuffer_Release(v);
        return -1;
    }
    return 0;
}

#endif
