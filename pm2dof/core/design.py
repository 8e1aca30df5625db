# A model file's [design] table: named geometric variables of the legs, kept as a run-time
# input of the generated C (pm2dof.derive keeps them symbolic; Model.at_design rebinds them).
from dataclasses import dataclass

__all__ = ["Design", "DESIGN_FIELDS"]

#: per leg kind, the designable keys of [[legs]] and their internal (field, component):
#: component None for a length, 0/1 for a point's x/y. "rail.start" is Leg.base, "rail.end" is
#: Leg.rail_end. A stroke does not enter the generated C, so it is not designable.
DESIGN_FIELDS = {
    "RRR": {"la": ("la", None), "lb": ("lb", None),
            "base.x": ("base", 0), "base.y": ("base", 1),
            "attach.x": ("attach", 0), "attach.y": ("attach", 1)},
    "PRR": {"lb": ("lb", None),
            "rail.start.x": ("base", 0), "rail.start.y": ("base", 1),
            "rail.end.x": ("rail_end", 0), "rail.end.y": ("rail_end", 1),
            "attach.x": ("attach", 0), "attach.y": ("attach", 1)},
    "RPR": {"base.x": ("base", 0), "base.y": ("base", 1),
            "attach.x": ("attach", 0), "attach.y": ("attach", 1)},
}


@dataclass(frozen=True)
class Design:
    """The design variables of a model file, in the file's order.

    ``names`` (k,): the variables; ``keys[j]``: the (leg index from 0, field, component) each
    variable j sets (tied keys take the same value); ``labels[j]``: the same keys as the file
    writes them ("legs.1.la"); ``bounds[j]``: (low, high) in m; ``values``: the current design;
    ``default``: the file's (the values in [[legs]]); ``signs[j]``: +1 if the variable is
    positive over its bounds, -1 if negative, else 0 (the derivation's SymPy assumptions);
    ``closure_default``: [sensing] closure_tolerance was not given, so it follows the design."""
    names: tuple
    keys: tuple
    labels: tuple
    bounds: tuple
    values: tuple
    default: tuple
    signs: tuple
    closure_default: bool = True

    @property
    def size(self):
        return len(self.names)

    def variable_of(self):
        """{(leg, field, component): variable name} for every designed key."""
        return {key: name for name, keys in zip(self.names, self.keys) for key in keys}

    def formulation(self):
        """What enters the generated code: the names and the keys they set (not the values or
        bounds, so editing a default or a bound needs no new derivation)."""
        return [[name, list(labels)] for name, labels in zip(self.names, self.labels)]
