# Named layouts of the flat vectors the generated controllers and plant take (state, params, ...).
import casadi as ca

__all__ = ["Layout"]


class Layout:
    """An ordered list of (name, size) fields packed into one flat vector.

    The layouts are written into the manifest, so the runtime packs vectors by field name and
    nothing outside derive/ hard-codes an offset.
    """

    def __init__(self, fields):
        self.fields = [(name, int(size)) for name, size in fields]
        self.size = sum(size for _, size in self.fields)

    def offsets(self):
        out, k = {}, 0
        for name, size in self.fields:
            out[name] = (k, size)
            k += size
        return out

    def split(self, vec):
        """Split a symbolic vector into a dict of its fields."""
        return {name: vec[k:k + size] for name, (k, size) in self.offsets().items()}

    def pack(self, **parts):
        missing = [name for name, _ in self.fields if name not in parts]
        if missing or len(parts) != len(self.fields):
            raise KeyError(f"layout needs exactly {[n for n, _ in self.fields]}, got {sorted(parts)}")
        return ca.vertcat(*[parts[name] for name, _ in self.fields])

    def to_json(self):
        return [[name, size] for name, size in self.fields]
