/* pm2dof.core._cbind's C API: other extensions call a bound generated function through it. */

/*
 * One plan pass calls a generated function thousands of times; through this table each call
 * is a function pointer, as inside _cbind (pm2dof/planning/_passes.c). Import it with
 *
 *     const Pm2dofCbindAPI *api = PyCapsule_Import(PM2DOF_CBIND_API, 0);
 *
 * begin(function) checks that ``function`` is a pm2dof.core._cbind.Function with n_in
 * inputs and n_out outputs and takes its work area (NULL with a Python error set otherwise);
 * nnz(handle, i) is argument i's element count (inputs first, then outputs); eval(handle,
 * arg, res) evaluates with arg[0 .. n_in) and res[0 .. n_out) (a NULL output is not
 * computed) and returns CasADi's code (0: success); end(handle) gives the work area back.
 * A Function bound to a design keeps it: arg holds only the visible inputs. The GIL may be
 * released between begin and end (the work area is the handle's until end).
 */
#ifndef PM2DOF_CBIND_API_H
#define PM2DOF_CBIND_API_H

#define PM2DOF_CBIND_API "pm2dof.core._cbind._C_API"

typedef struct Pm2dofCall Pm2dofCall;

typedef struct {
    Pm2dofCall *(*begin)(PyObject *function, Py_ssize_t n_in, Py_ssize_t n_out);
    Py_ssize_t (*nnz)(const Pm2dofCall *call, Py_ssize_t i);
    int (*eval)(Pm2dofCall *call, const double *const *arg, double *const *res);
    void (*end)(Pm2dofCall *call);
} Pm2dofCbindAPI;

#endif
