# Model.at_design equals a conventional derivation of the file with those numbers, on every function.
"""The design check: for random designs of every design model, every generated function of
``m.at_design(values)`` (the compiled C, the design bound as an input) equals the CasADi
functions of a conventional derivation of the same file with those numbers written into
``[[legs]]`` and ``[design]`` dropped (tests/design/conventional.py), evaluated by CasADi's VM
in memory (no code generation, no compile), at 2 poses near the first move's start
(tests/design/equivalence.py: tolerance 1e-12 of max(1, |b|_inf), a controller's outputs also
of their terms through the velocity estimate; integer outputs exact; NaN at the same places).
The design's spec equals the conventional file's: the legs exactly, theta_nominal (links
given as rods follow the lengths), the plant's truth and the default closure tolerance to
1e-12.

Design models: the shipped ``pm2dof/models/*_design.toml`` (the paper's robot, a 4-RRR
platform with rods) and the fixtures ``tests/design/models/*.toml`` (a PRR platform: linear
actuators, a rail moved sideways; an RPR platform: a base and an attachment point; the paper's
robot under gravity), which the slow tier derives and compiles into a temporary folder once
per session. The whole module is in the slow tier (``make test-slow``, CI): one seeded design
per shipped model, and 20 per model, the first two at the bounds' low and high
ends, redrawing a design that ``at_design`` refuses (:class:`pm2dof.DesignError`: home or a
move out of reach), and fails when more than half are redrawn.

That design also checks the check: the same derivation against at_design with one
variable moved by 1e-7 m (each in turn) reports ik, fk, the forward dynamics and the NA
step (W and Me of q do not depend on a base). The self-checks of the tools (the TOML
writer, the inputs, the comparison on fixed models) are in test_equivalence_fixed.py.

Measured over the slow tier's 20 + 20 designs (shang2010_design, rrr4_platform_design; one
of rrr4's, all at the low ends, refused: a move out of reach): largest error / scale 1.0e-14
(every function; error / max(1, |b|_inf) the same outside the controllers, up to 8.9e-12 for
a controller step, whose velocity estimate divides fk's rounding by T).
"""
from __future__ import annotations

import zlib
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.core.model_file import read_model_file
from pm2dof.core.paths import SHIPPED_MODELS
from tests.design.conventional import conventional_file
from tests.design.equivalence import TOL, compare_all

pytestmark = pytest.mark.slow     # in-memory derivations of designs (seconds each): make test-slow (CI)

HERE = SHIPPED_MODELS.parent.parent / "tests" / "design"
SHIPPED_DESIGNS = sorted(SHIPPED_MODELS.glob("*_design.toml"))
FIXTURES = sorted((HERE / "models").glob("*.toml"))
DESIGN_FILES = SHIPPED_DESIGNS + FIXTURES
SLOW_COUNT = 20
POSES = 2

# {model: {function: largest error / scale}}, printed at module teardown (-s)
_OBSERVED: dict = {}
_PLAIN: dict = {}


@pytest.fixture(scope="module", autouse=True)
def _report_observed():
    yield
    for name in sorted(_OBSERVED):
        obs, plain = _OBSERVED[name], _PLAIN[name]
        worst, worst_plain = max(obs, key=obs.get), max(plain, key=plain.get)
        print(f"\n[test_design_equivalence] {name}: largest error / scale {obs[worst]:.3e} "
              f"({worst}); / max(1, |b|) {plain[worst_plain]:.3e} ({worst_plain})")


_LOADED: dict = {}


@pytest.fixture(scope="session")
def fixture_dir(tmp_path_factory):
    """Where the fixtures' generated C is derived and compiled (once per session)."""
    return tmp_path_factory.mktemp("design_fixtures")


def design_model(path, fixture_dir=None):
    """The design model of ``path``: a shipped model's generated code, or a fixture derived
    and compiled into ``fixture_dir``."""
    if path not in _LOADED:
        generated = None
        if path in FIXTURES:
            from pm2dof.derive.run import derive
            generated = derive(path, fixture_dir / path.stem, progress=lambda *a: None)
        _LOADED[path] = pm2dof.load_model(path, generated=generated)
    m = _LOADED[path]
    assert m.design_names, f"{path.name} has no [design] table"
    return m


def _seed(name, k):
    return zlib.crc32(f"{name}:{k}".encode())


def draw_designs(m, count, seed, ends):
    """``count`` designs (k,) that ``m.at_design`` accepts, drawn uniformly in the bounds
    (with ``ends``, first all at the low ends, then all at the high ends), and the ones it
    refused ([(values, message)]). Stops drawing once more than half of ``count`` (at least 2)
    are refused."""
    lo, hi = m.design_bounds.T
    rng = np.random.default_rng(seed)
    queue = [lo.copy(), hi.copy()] if ends else []
    limit = max(2, count // 2)
    accepted, refused = [], []
    while len(accepted) < count and len(refused) <= limit:
        values = queue.pop(0) if queue else rng.uniform(lo, hi)
        try:
            m.at_design(values)
        except pm2dof.DesignError as exc:
            refused.append((values.tolist(), str(exc)))
            continue
        accepted.append(values)
    return accepted, refused


def _close(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= TOL * max(1.0, np.max(np.abs(b),
                                                                                      initial=0))))


def spec_differences(spec, conv):
    """What differs between a design's spec and the conventional file's: the legs exactly;
    theta_nominal, the plant's truth and the closure tolerance to 1e-12."""
    out = []
    for i, (a, b) in enumerate(zip(spec.legs, conv.legs)):
        for key in ("base", "la", "lb", "attach", "rail_end", "elbow", "kind"):
            x, y = getattr(a, key, None), getattr(b, key, None)
            if (np.asarray(x, dtype=object) != np.asarray(y, dtype=object)).any():
                out.append(f"leg {i + 1} {key}: design {x}, conventional {y}")
    if not _close(spec.theta_nominal, conv.theta_nominal):
        out.append(f"theta_nominal: design {list(spec.theta_nominal)}, conventional "
                   f"{list(conv.theta_nominal)}")
    a, b = spec.sensing["closure_tolerance"], conv.sensing["closure_tolerance"]
    if not _close(a, b):
        out.append(f"closure_tolerance: design {a!r}, conventional {b!r}")
    if set(spec.plant) != set(conv.plant):
        out.append(f"plant fields: design {sorted(spec.plant)}, conventional {sorted(conv.plant)}")
    for key in sorted(set(spec.plant) & set(conv.plant)):
        if not _close(spec.plant[key], conv.plant[key]):
            out.append(f"plant {key}: design {spec.plant[key]}, conventional {conv.plant[key]}")
    return out


def check_design(m, values, tmp_path, seed):
    """Compare ``m.at_design(values)`` with the conventional derivation; the problems found."""
    from pm2dof.derive.model_functions import Derivation
    from pm2dof.derive.run import derive_functions
    m2 = m.at_design(values)
    path = conventional_file(m.spec.path, dict(zip(m.design_names, map(float, values))),
                             tmp_path / Path(m.spec.path).name)
    conv = read_model_file(path)
    functions = derive_functions(Derivation(conv), conv)
    observed, plain = _OBSERVED.setdefault(m.name, {}), _PLAIN.setdefault(m.name, {})
    bad = [str(b) for b in compare_all(m2, functions, np.random.default_rng(seed), POSES,
                                       observed, plain)]
    bad += spec_differences(m2.spec, conv)
    design = ", ".join(f"{k} = {v!r}" for k, v in zip(m.design_names, map(float, values)))
    assert not bad, (f"{m.name} at {design}: at_design differs from a conventional "
                     f"derivation of {path.name}:\n" + "\n".join(bad))
    return functions


# --- one seeded random design per shipped design model, and the check of the check ---------

@pytest.mark.parametrize("path", SHIPPED_DESIGNS, ids=lambda p: p.stem)
def test_a_random_design_equals_its_conventional_derivation(path, tmp_path):
    m = design_model(path)
    designs, refused = draw_designs(m, 1, _seed(m.name, 0), ends=False)
    assert designs, f"{m.name}: every design drawn was refused: {refused}"
    functions = check_design(m, designs[0], tmp_path, _seed(m.name, 1))
    # and the comparison sees a design 1e-7 m away, in each variable: the kinematics differ
    lo, hi = m.design_bounds.T
    for j, name in enumerate(m.design_names):
        moved = designs[0].copy()
        moved[j] += 1e-7 if moved[j] + 1e-7 <= hi[j] else -1e-7
        bad = {b.function for b in compare_all(m.at_design(moved), functions,
                                               np.random.default_rng(4), poses=1)}
        assert {"ik", "fk", "forward_dynamics", "na_step"} <= bad, (
            f"{m.name}: {name} moved by 1e-7 m, and the comparison reports only {sorted(bad)}")


# --- the slow tier: 20 designs per design model --------------------------------------------

_DRAWN: dict = {}


def slow_designs(m):
    if m.name not in _DRAWN:
        _DRAWN[m.name] = draw_designs(m, SLOW_COUNT, _seed(m.name, 20), ends=True)
    return _DRAWN[m.name]


@pytest.mark.slow
@pytest.mark.parametrize("path", DESIGN_FILES, ids=lambda p: p.stem)
def test_few_designs_are_refused(path, fixture_dir):
    m = design_model(path, fixture_dir)
    designs, refused = slow_designs(m)
    assert len(refused) <= SLOW_COUNT // 2 and len(designs) == SLOW_COUNT, (
        f"{m.name}: {len(refused)} of the designs drawn in the bounds were refused by at_design "
        f"(more than half of {SLOW_COUNT}): the bounds reach far outside the workspace:\n"
        + "\n".join(f"  {v}: {msg}" for v, msg in refused))


@pytest.mark.slow
@pytest.mark.parametrize("k", range(SLOW_COUNT))
@pytest.mark.parametrize("path", DESIGN_FILES, ids=lambda p: p.stem)
def test_twenty_designs_equal_their_conventional_derivations(path, k, tmp_path, fixture_dir):
    m = design_model(path, fixture_dir)
    designs, refused = slow_designs(m)
    if k >= len(designs):
        pytest.fail(f"{m.name}: only {len(designs)} designs accepted ({len(refused)} refused)")
    check_design(m, designs[k], tmp_path, _seed(m.name, 100 + k))
