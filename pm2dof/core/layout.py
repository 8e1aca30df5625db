# Pack and unpack the flat vectors of the generated controllers and plant, by field name.
import numpy as np

__all__ = ["Layout"]


class Layout:
    """A named layout from ``manifest.json`` (written by derive/layouts.py): fields and sizes.

    Examples
    --------
    >>> lay = Layout("demo", [["Kd", 2], ["T", 1]])
    >>> lay.pack(Kd=[1.0, 2.0], T=0.002)
    array([1.   , 2.   , 0.002])
    """

    def __init__(self, name, fields):
        self.name = name
        self.fields = tuple((str(f), int(k)) for f, k in fields)
        self.slices, k = {}, 0
        for f, size in self.fields:
            self.slices[f] = slice(k, k + size)
            k += size
        self.size = k

    def __repr__(self):
        return f"Layout({self.name!r}, {', '.join(f'{f}[{k}]' for f, k in self.fields)})"

    def pack(self, out=None, **values):
        """Return (or fill ``out`` with) the flat vector; every field must be given, no others."""
        names = [f for f, _ in self.fields]
        unknown = sorted(set(values) - set(names))
        missing = [f for f in names if f not in values]
        if unknown or missing:
            raise TypeError(f"{self.name}: unknown field(s) {unknown}, missing {missing}; "
                            f"fields are {names}")
        vec = np.empty(self.size) if out is None else out
        for f, size in self.fields:
            v = np.asarray(values[f], dtype=float).ravel()
            if v.size == 1 and size > 1:
                v = np.full(size, v[0])
            if v.size != size:
                raise ValueError(f"{self.name}.{f} needs {size} values, got {v.size}")
            vec[self.slices[f]] = v
        if not np.isfinite(vec).all():   # one check; name the first offending field
            f = next(f for f, sl in self.slices.items() if not np.isfinite(vec[sl]).all())
            raise ValueError(f"{self.name}.{f} has non-finite values: {vec[self.slices[f]].tolist()}")
        return vec

    def unpack(self, vec):
        """Dict of views into ``vec`` (its last axis is the layout)."""
        return {f: vec[..., sl] for f, sl in self.slices.items()}
