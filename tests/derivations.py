# One SymPy derivation per model file per test process, shared by the modules that need one.
"""The SymPy derivation of a shipped model (:class:`pm2dof.derive.model_functions.Derivation`)
takes 0.1-0.6 s (rrr4_platform the most), and its lambdified matrices seconds more; six test
modules build the same ones: tests/derive/test_generated.py (regeneration and the 30-digit
check), test_derive_task_dimension.py (the paper's robot), test_factored_platform.py (the
shipped platforms), test_derive_path_mvc.py (the paper's robot),
tests/mechanisms/test_independent.py (the shipped mechanisms against an independent
formulation) and tests/derivatives/test_derivatives_mpmath.py (the paper's robot and the
five-bar). A derivation is a pure function of its model file, so it is built once per process
and shared; conftest.py's scheduler runs these modules (test_derive_path_mvc.py aside: one
cheap derivation) in one pytest-xdist worker, so the sharing holds under ``make test`` too.
tests/core/test_install_paths.py derives the same user model files several times in its own
module (its own worker is enough). The CasADi functions of the generated C are shared the
same way (:func:`functions`): by the regeneration, test_derive_task_dimension.py (the paper's
robot) and test_install_paths.py.

Keyed by the SHA-256 of the model file's bytes: the same file content, the same derivation
(wherever the file lies: a derivation does not depend on the file's path; a spec changed in
memory, e.g. by ``dataclasses.replace``, is never looked up here).
"""
from __future__ import annotations

import contextlib

_CACHE: dict = {}


def derivation(spec):
    """``Derivation(spec)`` of a model file as read (``read_model_file``), built once per
    process."""
    from pm2dof.derive.model_functions import Derivation
    key = spec.file_sha256
    if key not in _CACHE:
        _CACHE[key] = Derivation(spec)
    return _CACHE[key]


_FUNCTIONS: dict = {}


def functions(d, spec, derive_functions=None):
    """``pm2dof.derive.run.derive_functions(d, spec)`` (the CasADi functions of the generated
    C, 0.6 s for the paper's robot, 2.5 s for rrr4_platform), built once per process for a
    derivation of :func:`derivation` and a model file of the same content (they are a pure
    function of it); any other derivation's are built on every call. A new list each time.
    ``derive_functions``: the builder (default pm2dof.derive.run's)."""
    if derive_functions is None:
        from pm2dof.derive.run import derive_functions
    key = getattr(spec, "file_sha256", None)    # pm2dof.derive reads no path, only content
    if key is None or _CACHE.get(key) is not d or d.spec.file_sha256 != key:
        return derive_functions(d, spec)
    if key not in _FUNCTIONS:
        _FUNCTIONS[key] = tuple(derive_functions(d, spec))
    return list(_FUNCTIONS[key])


@contextlib.contextmanager
def shared_in_derive():
    """Within the block, :func:`pm2dof.derive.run.derive` takes its SymPy derivation from
    :func:`derivation` and its CasADi functions from :func:`functions` (each built there if
    not yet): everything else of the pipeline (the checks of the output folder, the C, the
    header and the manifest) runs as it does for ``pm2dof derive``."""
    from pm2dof.derive import run
    built = run.Derivation, run.derive_functions
    run.Derivation = derivation
    run.derive_functions = lambda d, spec: functions(d, spec, built[1])
    try:
        yield
    finally:
        run.Derivation, run.derive_functions = built


def cse(exprs):
    """SymPy's common-subexpression elimination for ``lambdify(..., cse=cse)`` without its
    canonical ordering of the terms (``order="none"``): the same subexpressions, a third less
    time on the platforms' big matrices (rrr4_platform's xedd 1.5 -> 1.0 s)."""
    import sympy
    return sympy.cse(exprs, order="none", list=False)   # list=False: as lambdify(cse=True)


def lambdify(args, expr, modules):
    """``sympy.lambdify(args, expr, modules, cse=cse)``, the same function, built faster:
    ``expr`` is handed over inside a list, which has no ``atoms``, so lambdify skips walking
    the whole tree for its symbols' names (a walk that does not share repeated subtrees: a
    third of the time on a platform's xedd); its value is unwrapped here. No search for
    ``implemented_function`` (:func:`plain_lambdify`)."""
    fn = plain_lambdify(args, [expr], modules, cse=cse)

    def call(*a):
        return fn(*a)[0]
    return call


def plain_lambdify(args, expr, modules, **kw):
    """``sympy.lambdify(args, expr, modules, **kw)`` with ``use_imps=False``: the same code.
    By default lambdify walks the whole tree for functions made by ``implemented_function``
    (their ``_imp_``), a walk that does not share repeated subtrees (a third of lambdify's time
    on a platform's matrices); pm2dof.derive makes none (``sgn`` comes from ``modules``), so
    the walk finds nothing and the generated function is the same."""
    import sympy
    return sympy.lambdify(args, expr, modules=modules, use_imps=False, **kw)
