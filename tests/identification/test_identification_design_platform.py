# Optimal excitation of a platform: x, y and phi series, phi's own limits, its file, a fit from its log.
import dataclasses

import numpy as np
import pytest

import pm2dof
from pm2dof.core.errors import ArgumentError
from pm2dof.identification.base import base_parameters
from pm2dof.identification.design import (
    LimitOptions,
    SeriesOptions,
    SolverOptions,
    check_excitation,
    design_excitation,
    phi_limits,
    regressor_condition,
)
from pm2dof.identification.signals import (
    ExcitationError,
    load_excitation,
    multisine,
    trajectory_of,
    write_excitation,
)

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

# one 1 s period of 3 harmonics of 1 Hz, run twice (2 s); the (x, y) limits the defaults
SMALL = dict(base_hz=1.0, harmonics=3, periods=2, samples=40, constraint_samples=100,
             tau_fraction=0.3)
V_MAX, A_MAX, RADIUS = 0.5, 10.0, 0.06


def options(**fields):
    """The design's option objects (series, limits, solver) from their fields by name."""
    kinds = (SeriesOptions, LimitOptions, SolverOptions)
    names = {f.name for kind in kinds for f in dataclasses.fields(kind)}
    assert set(fields) <= names, set(fields) - names
    return tuple(kind(**{f.name: fields[f.name] for f in dataclasses.fields(kind)
                         if f.name in fields}) for kind in kinds)


@pytest.fixture(scope="module")
def platform():
    return pm2dof.load_model("rrr3_platform")


@pytest.fixture(scope="module")
def designed(platform):
    return design_excitation(platform, *options(**SMALL))


def test_phi_limits_default_from_the_model_file(platform):
    """v_max / l, a_max / l with l the platform's radius, and the phi turn of its moves: read
    here from the model file itself (attachment points on a 0.05 m circle; moves turn 0.2 rad)."""
    spec = platform.spec
    l = max(np.hypot(*leg.attach) for leg in spec.legs)
    assert l == pytest.approx(0.05, abs=1e-4)
    turn = max(abs(t["end"][2] - t["start"][2]) for t in spec.trajectories.values())
    assert turn == pytest.approx(0.2)
    assert phi_limits(platform) == pytest.approx(
        {"phi_v_max": V_MAX / l, "phi_a_max": A_MAX / l, "phi_range": turn}, rel=1e-12)
    assert phi_limits(platform, phi_range=0.1)["phi_range"] == 0.1
    with pytest.raises(ArgumentError, match="phi_range > 0"):
        phi_limits(platform, phi_range=-1.0)


def test_a_point_has_no_phi_to_limit():
    point = pm2dof.load_model()
    assert phi_limits(point) == {}
    with pytest.raises(ArgumentError, match=r"phi_v_max limit a platform's orientation phi; "
                                            r"model 'shang2010' has task \('x', 'y'\), no phi"):
        design_excitation(point, limits=LimitOptions(phi_v_max=1.0))


def test_platform_design_meets_every_constraint_every_millisecond(platform, designed):
    exc, info = designed, designed.info
    assert info["ipopt_status"] == "Solve_Succeeded"
    assert exc.a.shape == exc.b.shape == (3, SMALL["harmonics"]) and exc.center.shape == (3,)
    limits = phi_limits(platform)
    assert {k: info[k] for k in limits} == limits           # the file records the phi limits
    chk = check_excitation(
        platform, exc, v_max=V_MAX, a_max=A_MAX, radius=RADIUS,
        tau_limit=SMALL["tau_fraction"] * np.max(platform.spec.limits["tau_max"]),
        sing_min=max(platform.singularity_threshold,
                     platform.parallel_singularity_threshold) + 0.1, step=1e-3, **limits)
    assert chk["ok"], chk
    assert {"phi_speed", "phi_acceleration", "phi_range"} <= set(chk)
    # phi moves, and independently of the checker: at 1 ms, straight from the series
    t = np.arange(1001) * 1e-3
    x, v, a = exc.evaluate(t)
    assert 0.05 < np.abs(x[:, 2] - info["region_center"][2]).max() <= limits["phi_range"]
    assert np.abs(v[:, 2]).max() <= limits["phi_v_max"]
    assert np.abs(a[:, 2]).max() <= limits["phi_a_max"]
    assert np.hypot(*v[:, :2].T).max() <= V_MAX and np.hypot(*a[:, :2].T).max() <= A_MAX
    # starts and ends at rest, periodic in all three
    x, v, a = exc.evaluate([0.0, exc.duration])
    assert np.abs(v).max() < 1e-12 and np.abs(a).max() < 1e-9
    assert np.allclose(x[0], x[1], rtol=0, atol=1e-12)
    assert info["logdet_after"] > info["logdet_before"]


def test_platform_file_round_trip(tmp_path, platform, designed):
    p = write_excitation(tmp_path / "exc.toml", designed, platform)
    text = p.read_text()
    assert "j = x, y, phi" in text and "a_phi = [" in text and "b_phi = [" in text
    back = load_excitation(p, platform)
    for k in ("center", "a", "b"):
        assert np.array_equal(getattr(back, k), getattr(designed, k)), k
    assert back.info == designed.info
    bad = tmp_path / "bad.toml"
    bad.write_text("\n".join(ln for ln in text.splitlines() if not ln.startswith("b_phi")))
    with pytest.raises(ExcitationError, match=r"\[excitation.b_phi\] missing \(required\)"):
        load_excitation(bad)
    # b_phi alone makes it a platform's file: a_phi is then missing, and a 2-entry center wrong
    lines = [ln for ln in text.splitlines() if not ln.startswith("a_phi")]
    lines = [re_center(ln) for ln in lines]
    bad.write_text("\n".join(lines))
    with pytest.raises(ExcitationError) as err:
        load_excitation(bad)
    assert "[excitation.a_phi] missing (required)" in str(err.value)
    assert "[excitation.center] must be a list of 3 numbers" in str(err.value)
    with pytest.raises(ExcitationError, match=r"written for model 'rrr3_platform'"):
        load_excitation(p, pm2dof.load_model())


def re_center(line):
    """``center = [x, y, phi]`` without its phi."""
    if not line.startswith("center = ["):
        return line
    x, y, _ = line.split("[")[1].split("]")[0].split(", ")
    return f"center = [{x}, {y}]"


def test_base_parameters_identified_from_a_simulated_log_of_it(platform, designed,
                                                              identified_within_3_std):
    """As tests/mechanisms' test of the multisine: a noise-free run of the design on the plant,
    identify_log, each base parameter of the truth within 3 of its std plus 2 %."""
    from pm2dof.control.plant import plant_truth
    from pm2dof.identification.excitation import excite
    truth = plant_truth(platform, fs=[0.0] * platform.n_legs)
    log = excite(platform, designed, truth=truth, quantise=False)
    ident = identified_within_3_std(platform, log, truth)
    assert np.isfinite(ident.condition_number)


def test_platform_design_beats_a_multisine_on_its_criterion(platform, designed):
    """The design maximises log det(Phi^T Phi / K) (D-optimality; design.py says why not the
    condition number): on the run, independently of the design's CasADi graph
    (regressor_condition, NumPy on the C functions), it must beat a multisine of the same
    duration. Measured: log det 77.9 against 56.4. Its condition number is not what it
    optimises, and here it is worse (156 against 55: the weakest direction, m_p against the
    links' inertias, needs phi accelerations the default 0.2 rad range leaves out);
    docs/results-identification.md reports both."""
    base = base_parameters(platform)
    ours = regressor_condition(platform, base, trajectory_of(platform, designed))
    theirs = regressor_condition(platform, base, trajectory_of(
        platform, multisine(platform, duration=designed.duration)))
    assert ours[1] > theirs[1], (ours, theirs)
