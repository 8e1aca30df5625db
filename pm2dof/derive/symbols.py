# The symbols of the derivation: joint angles, task-space quantities, parameters, and sgn().
import sympy as sp

__all__ = ["Symbols", "sgn", "solve2"]


def solve2(A, b):
    """A^-1 b for a 2x2 A by Cramer's rule (SymPy's generic det/adjugate simplify and crawl)."""
    det = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]
    return sp.Matrix([A[1, 1] * b[0] - A[0, 1] * b[1], A[0, 0] * b[1] - A[1, 0] * b[0]]) / det


class sgn(sp.Function):
    """The mathematical sign, sgn(0) = 0, of eq. 2's Coulomb term (a joint at rest has no
    Coulomb force); exported as CasADi's sign (NaN in, NaN out). The paper prints U_ij (eq. 13)
    with sign(0) = +1, which pushes a robot at rest; eq. 2 means the sign."""

    @classmethod
    def eval(cls, v):
        if v.is_extended_real and v.is_number:
            return sp.Integer(int(v > 0) - int(v < 0))
        return None

    def _eval_derivative(self, x):  # piecewise constant: zero almost everywhere
        return sp.Integer(0)


class Symbols:
    """All symbols for an n-leg model; names follow the paper (q = [qa; qb], theta, ...)."""

    def __init__(self, n_legs, param_names):
        n = n_legs
        self.n = n
        self.qa = sp.Matrix(sp.symbols(f"qa1:{n + 1}", real=True))
        self.qb = sp.Matrix(sp.symbols(f"qb1:{n + 1}", real=True))
        self.q = self.qa.col_join(self.qb)                      # eq. 3 ordering
        self.xe = sp.Matrix(sp.symbols("x y", real=True))       # task coordinates q_e
        self.xed = sp.Matrix(sp.symbols("xd yd", real=True))    # measured qd_e
        self.xrd = sp.Matrix(sp.symbols("xrd yrd", real=True))  # reference velocity qd_e^r
        self.xrdd = sp.Matrix(sp.symbols("xrdd yrdd", real=True))  # reference acceleration
        self.tau_a = sp.Matrix(sp.symbols(f"tau_a1:{n + 1}", real=True))
        # joint-space velocities: measured qd, reference qd^r = W xrd, qdd^r = W xrdd + Wdot xrd
        self.qd = sp.Matrix(sp.symbols(f"qda1:{n + 1}", real=True) + sp.symbols(f"qdb1:{n + 1}", real=True))
        self.qdr = sp.Matrix(sp.symbols(f"qdra1:{n + 1}", real=True) + sp.symbols(f"qdrb1:{n + 1}", real=True))
        self.qddr = sp.Matrix(sp.symbols(f"qddra1:{n + 1}", real=True) + sp.symbols(f"qddrb1:{n + 1}", real=True))
        self.theta = sp.Matrix(sp.symbols(" ".join(param_names), real=True))
        self.param = dict(zip(param_names, self.theta))

    def leg_params(self, i, names):
        """Parameters of leg i (0-based) for the given base names, e.g. ("alpha", "beta")."""
        return [self.param[f"{name}{i + 1}"] for name in names]
