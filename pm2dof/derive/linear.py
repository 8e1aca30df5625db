# The Jacobian of an expression linear in the parameters, by substitution instead of differentiation.
"""``linear_jacobian(F, theta)``: dF/dtheta of a matrix F linear in theta (eq. 13's
Y = d tau / d theta, tau = Y theta).

SymPy's ``jacobian`` differentiates every entry once per parameter, and each ``diff`` walks
the whole expression tree (recomputing ``free_symbols`` at every node): on a platform's
task-space tau, whose entries hold W^T M W, that is most of the derivation (7.4 of 8.1 s for
``rrr4_platform``). When F is homogeneous of degree one in theta, F = sum_k theta_k c_k, so
column k is F at theta = e_k (an ``xreplace``, one walk per parameter), exactly. This module
checks the degree first, structurally, and otherwise falls back to ``jacobian``; on every
shipped model the result is the same SymPy expression as ``jacobian``'s (so the same C). The
substitution walks only the subtrees that hold a parameter, each shared one once.
"""
import sympy as sp

__all__ = ["linear_jacobian"]

_NONLINEAR = (2, 2)   # (least, greatest) degree standing for "not a polynomial of degree <= 1"


def _degree(expr, theta, memo):
    """(least, greatest) degree in ``theta`` of the terms of ``expr``'s tree as written (no
    expansion), capped at 2: (2, 2) for anything nonlinear (a product of two parameters, a
    parameter in a function, a power or a denominator)."""
    got = memo.get(expr)
    if got is not None:
        return got
    if expr in theta:
        out = (1, 1)
    elif not expr.args:
        out = (0, 0)
    elif isinstance(expr, sp.Add):
        ds = [_degree(a, theta, memo) for a in expr.args]
        out = (min(d[0] for d in ds), max(d[1] for d in ds))
    elif isinstance(expr, sp.Mul):
        ds = [_degree(a, theta, memo) for a in expr.args]
        out = (min(2, sum(d[0] for d in ds)), min(2, sum(d[1] for d in ds)))
    else:   # Pow, functions: linear only where theta does not occur inside
        ds = [_degree(a, theta, memo) for a in expr.args]
        out = (0, 0) if all(d == (0, 0) for d in ds) else _NONLINEAR
    memo[expr] = out
    return out


def _substituted(expr, rule, degree, memo):
    """``expr.xreplace(rule)`` (rule: every parameter to a number), the same expression, built
    by the same ``func(*args)`` calls, but walking only the subtrees that hold a parameter
    (``degree`` of :func:`_degree` not (0, 0)) and each shared subtree once (``memo``)."""
    got = memo.get(expr)
    if got is not None:
        return got
    if expr in rule:
        out = rule[expr]
    elif degree[expr] == (0, 0):
        out = expr
    else:
        out = expr.func(*[_substituted(a, rule, degree, memo) for a in expr.args])
    memo[expr] = out
    return out


def linear_jacobian(F, theta):
    """dF/dtheta (rows: F's entries in order, columns: ``theta``), F a SymPy matrix.

    Where every entry of F is a polynomial of degree <= 1 in ``theta`` as written and F is 0 at
    theta = 0, column k is F at theta = e_k (exact); otherwise ``F.jacobian(theta)``."""
    theta = list(theta)
    flat = list(sp.Matrix(F))
    degree, tset = {}, set(theta)
    zero = {t: sp.Integer(0) for t in theta}
    at_zero = {}
    linear = (all(_degree(e, tset, degree)[1] <= 1 for e in flat)
              and all(_substituted(e, zero, degree, at_zero) == 0 for e in flat))
    if not linear:
        return sp.Matrix(flat).jacobian(theta)
    cols = []
    for t in theta:
        unit, memo = dict(zero), {}
        unit[t] = sp.Integer(1)
        cols.append([_substituted(e, unit, degree, memo) for e in flat])
    return sp.Matrix(len(flat), len(theta), lambda i, k: cols[k][i])
