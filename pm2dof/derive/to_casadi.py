# SymPy expression trees -> CasADi SX, memoised, with trig of joint angles taken from a table.
import casadi as ca
import sympy as sp

from .symbols import sgn

__all__ = ["Converter"]

_UNARY = {sp.exp: ca.exp, sp.tanh: ca.tanh, sp.acos: ca.acos, sp.asin: ca.asin,
          sp.atan: ca.atan, sp.Abs: ca.fabs, sp.log: ca.log}


class Converter:
    """Convert SymPy expressions to CasADi SX.

    Parameters
    ----------
    symbols : dict {sympy.Symbol: casadi.SX}
        What each free symbol stands for.
    trig : dict {sympy.Symbol: (casadi.SX, casadi.SX)}, optional
        (cos, sin) of joint angles. sin/cos of a sum or difference of such angles is expanded
        by the angle-sum identities, so a whole model costs one sin/cos per angle (or none,
        when the table comes from geometry as unit vectors).
    """

    def __init__(self, symbols, trig=None):
        self.symbols = dict(symbols)
        self.trig = dict(trig or {})
        self.cache = {}

    def extended(self, pairs):
        """A converter with more symbols bound ((sympy symbols, SX vector) pairs). It shares the
        trig table and starts from a copy of this cache, so common pieces convert once."""
        out = Converter(self.symbols, self.trig)
        out.cache = dict(self.cache)
        for syms, value in pairs:
            out.symbols.update(zip(syms, ca.vertsplit(value)))
        return out

    def __call__(self, expr):
        if isinstance(expr, sp.MatrixBase):  # row-major flattening, the layout of every output
            return ca.vertcat(*[self(e) for e in expr]) if expr.shape[0] * expr.shape[1] else ca.SX(0, 1)
        expr = sp.sympify(expr)
        hit = self.cache.get(expr)
        if hit is None:
            hit = self.cache[expr] = self._convert(expr)
        return hit

    def _angle_trig(self, arg):
        """(cos, sin) of arg if it is a sum of +-1 multiples of table angles, else None."""
        terms = arg.as_coefficients_dict()
        if not all(t in self.trig and c in (1, -1) for t, c in terms.items()):
            return None
        cos_sum, sin_sum = ca.SX(1), ca.SX(0)
        for t, c in sorted(terms.items(), key=lambda tc: str(tc[0])):
            ct, st = self.trig[t]
            st = st if c == 1 else -st
            cos_sum, sin_sum = cos_sum * ct - sin_sum * st, sin_sum * ct + cos_sum * st
        return cos_sum, sin_sum

    def _convert(self, e):
        if e.is_Symbol:
            if e not in self.symbols:
                raise KeyError(f"no CasADi value for symbol {e}")
            return self.symbols[e]
        if e.is_Integer or e.is_Rational or e.is_Float:
            return ca.SX(float(e))
        if e is sp.pi:
            return ca.SX(float(sp.pi))
        if e.is_Add:
            out = self(e.args[0])
            for a in e.args[1:]:
                out = out + self(a)
            return out
        if e.is_Mul:
            out = self(e.args[0])
            for a in e.args[1:]:
                out = out * self(a)
            return out
        if e.is_Pow:
            base, p = e.args
            if p == sp.Rational(1, 2):
                return ca.sqrt(self(base))
            if p == -sp.Rational(1, 2):
                return 1 / ca.sqrt(self(base))
            if p.is_Integer:
                b = self(base)
                k = int(p)
                powered = b
                for _ in range(abs(k) - 1):  # small integer powers as products, not pow()
                    powered = powered * b
                return powered if k > 0 else 1 / powered
            return self(base) ** self(p)
        if isinstance(e, (sp.sin, sp.cos)):
            pair = self._angle_trig(e.args[0])
            if pair is not None:
                return pair[0] if isinstance(e, sp.cos) else pair[1]
            return (ca.cos if isinstance(e, sp.cos) else ca.sin)(self(e.args[0]))
        if isinstance(e, sp.atan2):
            return ca.atan2(self(e.args[0]), self(e.args[1]))
        if isinstance(e, sgn):  # sgn(0) = 0 (eq. 2); its derivative is 0
            return ca.sign(self(e.args[0]))
        for fn, cfn in _UNARY.items():
            if isinstance(e, fn):
                return cfn(self(e.args[0]))
        raise NotImplementedError(f"cannot convert {type(e).__name__}: {e}")
