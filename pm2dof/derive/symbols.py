# The symbols of the derivation: joint angles, task-space quantities, parameters, and sgn().
import sympy as sp

__all__ = ["Symbols", "sgn", "solve2", "solve_small"]


def solve2(A, b):
    """A^-1 b for a 2x2 A by Cramer's rule (SymPy's generic det/adjugate simplify and crawl)."""
    det = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]
    return sp.Matrix([A[1, 1] * b[0] - A[0, 1] * b[1], A[0, 0] * b[1] - A[1, 0] * b[0]]) / det


def solve_small(A, b):
    """A^-1 b for a 2x2 or 3x3 A by Cramer's rule, unsimplified (2x2: exactly solve2's
    expressions, so today's models derive to the same code)."""
    if A.shape == (2, 2):
        return solve2(A, b)
    if A.shape != (3, 3):
        raise ValueError(f"solve_small takes a 2x2 or 3x3 matrix, got {A.shape}")

    def det3(c0, c1, c2):  # det [c0 c1 c2] by columns
        return (c0[0] * (c1[1] * c2[2] - c1[2] * c2[1]) - c1[0] * (c0[1] * c2[2] - c0[2] * c2[1])
                + c2[0] * (c0[1] * c1[2] - c0[2] * c1[1]))
    cols = [A[:, k] for k in range(3)]
    det = det3(*cols)
    return sp.Matrix([det3(*[b if k == j else cols[k] for k in range(3)]) for j in range(3)]) / det


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

    def __init__(self, n_legs, param_names, task_names=("x", "y"), design=None):
        n = n_legs
        self.n, self.m = n, len(task_names)       # legs, task-space dimension
        self.qa = sp.Matrix(sp.symbols(f"qa1:{n + 1}", real=True))
        self.qb = sp.Matrix(sp.symbols(f"qb1:{n + 1}", real=True))
        self.q = self.qa.col_join(self.qb)                      # eq. 3 ordering

        def task(suffix):
            return sp.Matrix(sp.symbols(" ".join(f"{t}{suffix}" for t in task_names), real=True))
        self.xe = task("")          # task coordinates q_e: x, y (and phi for a platform)
        self.xed = task("d")        # measured qd_e
        self.xrd = task("rd")       # reference velocity qd_e^r
        self.xrdd = task("rdd")     # reference acceleration
        self.tau_a = sp.Matrix(sp.symbols(f"tau_a1:{n + 1}", real=True))
        # joint-space velocities: measured qd, reference qd^r = W xrd, qdd^r = W xrdd + Wdot xrd
        self.qd = sp.Matrix(sp.symbols(f"qda1:{n + 1}", real=True) + sp.symbols(f"qdb1:{n + 1}", real=True))
        self.qdr = sp.Matrix(sp.symbols(f"qdra1:{n + 1}", real=True) + sp.symbols(f"qdrb1:{n + 1}", real=True))
        self.qddr = sp.Matrix(sp.symbols(f"qddra1:{n + 1}", real=True) + sp.symbols(f"qddrb1:{n + 1}", real=True))
        self.theta = sp.Matrix(sp.symbols(" ".join(param_names), real=True))
        self.param = dict(zip(param_names, self.theta))
        # a model file's [design] variables (core/design.py): symbols that stay in the generated
        # C as its input ``design``; their signs over the bounds are SymPy assumptions
        # (Model.at_design keeps values inside the bounds), so sqrt(la**2) folds to la
        signs = {1: {"positive": True}, -1: {"negative": True}, 0: {}}
        self.design = sp.Matrix([sp.Symbol(f"design_{name}", real=True, **signs[sign])
                                 for name, sign in zip(design.names, design.signs)]
                                if design is not None else [])
        #: {(leg, field, component): its design symbol}
        self.design_of = ({key: self.design[j] for j, keys in enumerate(design.keys)
                           for key in keys} if design is not None else {})

    def leg_params(self, i, names):
        """Parameters of leg i (0-based) for the given base names, e.g. ("alpha", "beta")."""
        return [self.param[f"{name}{i + 1}"] for name in names]
