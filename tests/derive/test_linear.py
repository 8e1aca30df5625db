# linear_jacobian: the substitution equals SymPy's jacobian, and falls back where F is not linear.
import sympy as sp

from pm2dof.derive.linear import linear_jacobian

t1, t2, t3 = sp.symbols("t1 t2 t3")
x, y = sp.symbols("x y", real=True)
THETA = [t1, t2, t3]


def _same(F):
    F = sp.Matrix(F)
    got, want = linear_jacobian(F, THETA), F.jacobian(THETA)
    assert got.shape == want.shape
    assert all(sp.simplify(a - b) == 0 for a, b in zip(got, want)), (got, want)
    return got


def test_linear_entries_give_the_jacobian_expression_for_expression():
    F = sp.Matrix([t1 * sp.cos(x) + t2 * x * y ** 2 - t3 / (1 + x ** 2),
                   sp.sin(x - y) * (t1 * x + t3 * sp.exp(y)) + 2 * t2])
    got = _same(F)
    assert got == F.jacobian(THETA)          # the same expressions, not just equal values


def test_nonlinear_or_affine_entries_fall_back_to_the_jacobian():
    # each is a case where F(e_k) is not the coefficient of t_k (a product of parameters, a
    # power, a function or a denominator of one, a part without any)
    for F in ([t1 * t2 + x], [t1 ** 2], [sp.cos(t1) * x], [x / t1], [t1 + 1],
              [t1 * x + y], [sp.sign(t2 * x)]):
        assert _same(F) == sp.Matrix(F).jacobian(THETA)


def test_cancelling_constant_part_is_still_exact():
    F = sp.Matrix([x * (t1 + 1) - x])      # = t1 x, written with a constant that cancels
    assert sp.simplify(_same(F)[0, 0] - x) == 0
