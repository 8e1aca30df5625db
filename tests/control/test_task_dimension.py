# The runtime follows the model's task dimension m = Model.dof: shapes, errors naming m, paths with
# an orientation, reference files, refusals of what a mechanism cannot do; Table 3 unchanged.
"""No runtime function assumes a task dimension of 2 (a platform's is 3).

Every shipped model today is a point end effector (m = 2); an m = 3 platform has no generated
code on this branch, so the checks are: every function's shapes follow ``Model.dof`` (read from
the generated code), errors name m, the pieces that do not need a model (paths with phi, the
3-D zonotope, ``line`` in (x, y, phi)) are checked in three dimensions against independent
computations, and a reference file round-trips through CSV and Parquet into ``simulate``.
``pm2dof table3 --json`` is byte-identical to before the change (``data/table3.json``; when a
change of the numbers is intended, regenerate it with ``pm2dof table3 --json``).
"""
import json
import math
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import pm2dof
from pm2dof.analysis.maps import zonotope_inradius
from pm2dof.analysis.reference_file import ReferenceFileError, read_trajectory
from pm2dof.control.trajectory import line_profile
from pm2dof.core.errors import (
    ArgumentError,
    PlanError,
    StaleGeneratedCodeError,
    UnsupportedMechanismError,
)
from pm2dof.core.paths import SHIPPED_MODELS
from pm2dof.core.task import orientation_length, require_rr_point, task_vector
from pm2dof.planning import TaskPath

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

DATA = Path(__file__).parent / "data"
SHIPPED = sorted(p.stem for p in SHIPPED_MODELS.glob("*.toml"))


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


@pytest.mark.parametrize("name", SHIPPED)
def test_dof_and_task_names_follow_the_generated_code(name):
    model = pm2dof.load_model(name)
    n, m = model.n_legs, model.dof
    assert (m, model.task_names) == (2, ("x", "y"))        # every shipped model: a point
    assert model.function("ik").sizes_in[0] == m            # the generated code's own size
    assert tuple(model.manifest["layouts"]["cl_input"][0]) == ("xd", m)
    xe = np.asarray(model.spec.trajectories[pm2dof.control.trajectory.line_moves(model)[0]]
                    ["start"], dtype=float)
    q = model.ik(xe)
    th = model.theta_nominal
    shapes = {"fk": (model.fk(q[:n]), (m,)), "W": (model.W(q), (2 * n, m)),
              "S": (model.S(q), (n, m)), "Me": (model.Me(q, th), (m, m)),
              "Ce": (model.Ce(q, np.ones(m), th), (m, m)), "Y": (model.Y(q, *np.ones((3, m))),
                                                                  (m, len(th))),
              "H": (model.H(q), (2 * n - m,)), "A": (model.A(q), (2 * n - m, 2 * n)),
              "forward_dynamics": (model.forward_dynamics(xe, np.zeros(m), np.zeros(n), th), (m,)),
              "inverse_dynamics": (model.inverse_dynamics(xe, np.zeros(m), np.zeros(m), th), (m,)),
              "sampled_step": (model.sampled_step(np.r_[xe, np.zeros(m)], np.zeros(n), th),
                               (2 * m,))}
    for key, (value, shape) in shapes.items():
        assert value.shape == shape, key
    A, B = model.linearize(xe, np.zeros(m), np.zeros(n), discrete=True)
    assert A.shape == (2 * m, 2 * m) and B.shape == (2 * m, n)
    c = pm2dof.NAController(model)
    c.reset(q[:n])
    c.step(q[:n], xe, np.zeros(m), np.zeros(m))
    assert all(c.diag[k].shape == (m,) for k in ("xe", "v", "e", "edot"))
    np.testing.assert_allclose(c.diag["xe"], xe, atol=1e-3)   # the diag's layout: xe first


def test_energies_are_the_generated_ones_or_ask_for_a_re_derivation(m):
    xe, xed, th = np.array([0.25, 0.26]), np.array([0.1, -0.2]), m.theta_nominal
    q = m.ik(xe)
    if f"{m.name}_kinetic_energy" not in m.manifest["functions"]:
        for call in (lambda: m.kinetic_energy(xe, xed), lambda: m.potential_energy(xe),
                     lambda: m.Ge(q, th)):
            with pytest.raises(StaleGeneratedCodeError, match="re-derive the model: `pm2dof "
                                                              "derive .*shang2010.toml`"):
                call()
        return
    T = m.kinetic_energy(xe, xed, th)                # generated: 1/2 xed^T Me xed (eq. 12)
    assert T == pytest.approx(0.5 * xed @ m.Me(q, th) @ xed, rel=1e-12)
    assert m.potential_energy(xe) == 0.0 and not m.Ge(q, th).any()   # a horizontal plane


def test_shape_errors_name_the_task_dimension(m):
    traj = pm2dof.Trajectory.hold([0.25, 0.26, 0.1], 0.01, 0.002)     # (x, y, phi)
    with pytest.raises(ArgumentError, match=r"task dimension m = 2 \(x, y\), so it must be "
                                            r"\(N, 2\)"):
        pm2dof.simulate(m, pm2dof.NAController(m), traj)
    with pytest.raises(ArgumentError, match=r"xe must be 2 finite numbers \(x, y: .*m = 2\)"):
        task_vector(m, "xe", [0.25, 0.26, 0.0])
    with pytest.raises(ArgumentError, match=r"m = 2 entries each \(x, y\)"):
        m.linearize([0.25, 0.26, 0.0], [0.0, 0.0], np.zeros(3), discrete=True)
    path = TaskPath.line([0.22, 0.29, 0.0], [0.27, 0.24, 0.3], orientation_length=0.1)
    with pytest.raises(PlanError, match=r"task dimension 3, model 'shang2010' m = 2"):
        pm2dof.check_path(m, path)


def _platform_spec():
    leg = SimpleNamespace(kind="RRR", attach=(0.03, 0.04), base=(0.0, 0.0))
    return SimpleNamespace(name="toy", n_legs=3, legs=(leg, leg, leg), end_effector="platform")


def test_what_needs_rr_legs_at_a_point_refuses_other_mechanisms_saying_why(m):
    from pm2dof.reference.model import Geometry
    spec = _platform_spec()
    with pytest.raises(UnsupportedMechanismError,
                       match=r"the Python reference formulation \(pm2dof.reference\) covers RRR "
                             r"legs meeting at a point only .* model 'toy' has 3 RRR legs at a "
                             r"moving platform"):
        Geometry.of_model(SimpleNamespace(spec=spec))
    prr = SimpleNamespace(name="prr", n_legs=2, end_effector="point",
                          legs=(SimpleNamespace(kind="PRR"), SimpleNamespace(kind="RRR")))
    with pytest.raises(UnsupportedMechanismError, match="2 PRR/RRR legs at a point"):
        require_rr_point(SimpleNamespace(spec=prr), "x")
    assert Geometry.of_model(m).n == 3 and require_rr_point(m, "x") is m
    assert orientation_length(SimpleNamespace(spec=spec)) == pytest.approx(0.05)
    assert orientation_length(m) is None


def test_a_path_with_phi_has_a_unit_tangent_in_the_metric_and_consistent_derivatives():
    ell = 0.08
    path = TaskPath.concat(
        TaskPath.line([0.22, 0.29, 0.0], [0.27, 0.24, 0.4], orientation_length=ell),
        TaskPath.line([0.27, 0.24, 0.4], [0.27, 0.24, -0.2], orientation_length=ell),  # rotation
        TaskPath.arc([0.25, 0.24], 0.02, 0.0, 1.5, phi=(-0.2, 0.1), orientation_length=ell))
    assert path.dim == 3 and path.kinds == ("line", "rotation", "arc")
    L1 = math.hypot(math.hypot(0.05, 0.05), ell * 0.4)
    assert path.breakpoints[1] == pytest.approx(L1, rel=1e-15)
    assert path.breakpoints[2] - path.breakpoints[1] == pytest.approx(ell * 0.6, rel=1e-14)
    assert path.length - path.breakpoints[2] == pytest.approx(math.hypot(0.03, ell * 0.3))
    s = np.linspace(0, path.length, 401)[1:-1]
    s = s[np.min(np.abs(s[:, None] - path.breakpoints[None]), axis=1) > 1e-4]
    p, dp, ddp = path.evaluate(s)
    w = np.array([1.0, 1.0, ell])                     # the metric ds^2 = dx^2 + dy^2 + (l dphi)^2
    np.testing.assert_allclose(np.linalg.norm(dp * w, axis=1), 1.0, rtol=1e-12)
    h = 1e-6                                          # central differences of p and p'
    (pp, dpp, _), (pm, dpm, _) = path.evaluate(s + h), path.evaluate(s - h)
    np.testing.assert_allclose((pp - pm) / (2 * h), dp, atol=1e-8)
    np.testing.assert_allclose((dpp - dpm) / (2 * h), ddp, atol=1e-6)
    np.testing.assert_allclose(path.start, [0.22, 0.29, 0.0])
    np.testing.assert_allclose(path.end, [0.25 + 0.02 * math.cos(1.5), 0.24 + 0.02 * math.sin(1.5),
                                          0.1], atol=1e-15)
    assert len(path.stops) == 4                       # each junction's tangent jumps
    with pytest.raises(PlanError, match="needs orientation_length"):
        TaskPath.line([0, 0, 0], [1, 0, 0])
    with pytest.raises(PlanError, match=r"must all be \(x, y\) or all \(x, y, phi\)"):
        TaskPath.concat(TaskPath.line([0, 0], [1, 0]), TaskPath.line([1, 0, 0], [2, 0, 0], 0.1))
    with pytest.raises(PlanError, match="no spline yet"):
        TaskPath.spline([[0, 0, 0], [1, 0, 0], [1, 1, 0]])


def test_line_in_x_y_phi_and_its_planar_case():
    tr = pm2dof.line([0.2, 0.3, 0.0], [0.25, 0.3, 0.5], 0.2, 5.0, 200.0, orientation_length=0.1)
    prof = line_profile([0.2, 0.3, 0.0], [0.25, 0.3, 0.5], 0.2, 5.0, 200.0, orientation_length=0.1)
    assert tr.xd.shape[1] == 3 and prof.L == pytest.approx(math.hypot(0.05, 0.05))
    np.testing.assert_array_equal(tr.xd[-1], [0.25, 0.3, 0.5])
    np.testing.assert_allclose(tr.xd_dot[:, 2] * 0.1, tr.xd_dot[:, 0], atol=1e-15)  # phi with x
    rot = pm2dof.line([0.2, 0.3, 0.0], [0.2, 0.3, 0.5], 0.2, 5.0, 200.0, orientation_length=0.1)
    assert not rot.xd_dot[:, :2].any() and rot.xd[-1, 2] == 0.5       # a pure rotation
    with pytest.raises(pm2dof.TrajectoryError, match="needs orientation_length"):
        pm2dof.line([0.2, 0.3, 0.0], [0.25, 0.3, 0.5], 0.2, 5.0, 200.0)
    planar = pm2dof.line((0.22, 0.29), (0.27, 0.24), 0.2, 5.0, 200.0)
    assert np.array_equal(planar.xd, pm2dof.paper_move("low").xd)


def test_zonotope_inradius_in_three_dimensions_against_sampled_directions():
    assert zonotope_inradius(np.diag([2.0, 3.0, 0.5])) == pytest.approx(0.5, rel=1e-15)
    assert zonotope_inradius([[1.0, 0, 0], [0, 1.0, 0], [2.0, 3.0, 0]]) == 0.0   # flat
    rng = np.random.default_rng(3)
    G = rng.normal(size=(5, 3))
    u = rng.normal(size=(200000, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    h = np.abs(u @ G.T).sum(axis=1)                   # support function h(u) = sum_i |g_i.u|
    r = zonotope_inradius(G)
    assert r <= h.min() * (1 + 1e-12) and r >= 0.97 * h.min()   # the facet normals' minimum


def _write_csv(path, traj, levels=3):
    names = ["x", "y"] + (["phi"] if traj.xd.shape[1] == 3 else [])
    cols = [("t", traj.t[:, None])] + [(suf, a) for suf, a in
                                       (("", traj.xd), ("_dot", traj.xd_dot),
                                        ("_ddot", traj.xd_ddot))][:levels]
    head = ["t"] + [f"{c}{suf}" for suf, _ in cols[1:] for c in names]
    rows = np.hstack([a for _, a in cols]).tolist()
    path.write_text("# a reference\n" + ",".join(head) + "\n"
                    + "\n".join(",".join(repr(v) for v in r) for r in rows) + "\n")
    return head, np.hstack([a for _, a in cols])


@pytest.fixture(scope="module")
def low():
    return pm2dof.paper_move("low")


def test_reference_round_trip_csv_and_parquet_simulates_as_the_move(m, low, tmp_path):
    pa = pytest.importorskip("pyarrow")
    import pyarrow.parquet as pq
    head, table = _write_csv(tmp_path / "low.csv", low)
    pq.write_table(pa.table({h: table[:, j] for j, h in enumerate(head)}), tmp_path / "low.parquet")
    want = pm2dof.simulate(m, pm2dof.NAController(m), low)
    for name in ("low.csv", "low.parquet"):
        tr = read_trajectory(tmp_path / name)
        for k in ("t", "xd", "xd_dot", "xd_ddot"):
            np.testing.assert_array_equal(getattr(tr, k), getattr(low, k), err_msg=k)
        r = pm2dof.simulate(m, pm2dof.NAController(m), tr)
        assert r.rmse == want.rmse and np.array_equal(r.tau_a, want.tau_a)


def test_reference_positions_only_are_differentiated(m, low, tmp_path):
    _write_csv(tmp_path / "pos.csv", low, levels=1)
    tr = read_trajectory(tmp_path / "pos.csv")
    prof = line_profile(**pm2dof.PAPER_MOVES["low"])
    vpeak, apeak = prof.v_peak, prof.a_peak
    # second-order differences of a jerk-limited profile: v within T^2 j / 3, a within T j
    assert np.abs(tr.xd_dot - low.xd_dot).max() <= 0.002 ** 2 * 200.0 / 3 + 1e-12 * vpeak
    assert np.abs(tr.xd_ddot - low.xd_ddot).max() <= 0.002 * 200.0 * 1.5
    assert np.abs(tr.xd_ddot).max() <= 1.1 * apeak
    ra = pm2dof.simulate(m, pm2dof.NAController(m), tr).rmse
    rb = pm2dof.simulate(m, pm2dof.NAController(m), low).rmse
    assert abs(ra - rb) <= 0.05 * rb


BAD = {
    "t,x\n0,1\n0.002,1\n": r"no column y",
    "t,x,y,z\n0,0.25,0.26,1\n0.002,0.25,0.26,1\n": r"unknown column\(s\) z",
    "t,x,y\n0,0.25,0.26\n0.002,0.25,oops\n": r"row 2 \(line 4\), column y: 'oops' is not a number",
    "t,x,y\n0,0.25,0.26\n0.002,0.25\n": r"row 2 \(line 4\) has 2 fields, the header 3",
    "t,x,y\n0,0.25,0.26\n0.002,0.25,inf\n": r"row 2 \(line 4\), column y: inf is not a finite",
    "t,x,y\n0,0.25,0.26\n0.002,0.25,nan\n": r"row 2 \(line 4\), column y: nan is not a finite",
    "t;x;y\n0;0.25;0.26\n0.002;0.25;0.26\n": r"line 2: the header is one column, 't;x;y': "
                                          r"columns must be separated by commas, not ';'",
    "t\tx\ty\n0\t0.25\t0.26\n": r"separated by commas, not tabs",
    "t,x,y\n0.002,0.25,0.26\n0,0.25,0.26\n": r"row 2, column t: t must increase from row to "
                                            r"row by one period, but it goes from 0.002 s",
    "t,x,y\n0,0.25,0.26\n0.002,0.25,0.26\n0.005,0.25,0.26\n": r"row 3, column t: t must increase",
    "t,x,y,x_dot\n0,0.25,0.26,0\n0.002,0.25,0.26,0\n": r"column\(s\) x_dot without y_dot",
    "t,x,y\n0,0.25,0.26\n": r"one row",
    "t,x,y\n": r"no data rows",
    "t,x,x\n0,1,1\n": r"column\(s\) x appear more than once",
}


@pytest.mark.parametrize("text", BAD, ids=range(len(BAD)))
def test_bad_reference_files_give_one_line_naming_file_row_and_column(text, tmp_path):
    f = tmp_path / "bad.csv"
    f.write_text("# comment\n" + text)
    with pytest.raises(ReferenceFileError, match=BAD[text]) as exc:
        read_trajectory(f)
    assert str(exc.value).startswith(str(f)) and "\n" not in str(exc.value)
    assert isinstance(exc.value, pm2dof.TrajectoryError)


def test_a_reference_out_of_reach_names_the_file(tmp_path):
    """A well-formed file whose first pose no leg reaches: the same WorkspaceError as
    simulate's check, with the file named (it was not)."""
    from pm2dof.analysis.reference_file import simulate_reference
    f = tmp_path / "reach.csv"
    f.write_text("t,x,y\n0,0.9,0.9\n0.002,0.9,0.9\n")
    with pytest.raises(pm2dof.WorkspaceError) as exc:
        simulate_reference(pm2dof.load_model(), f, ("na",))
    assert str(exc.value).startswith(f"{f}: trajectory sample 0"), str(exc.value)
    assert "out of reach of leg 1" in str(exc.value)


def test_simulate_command_runs_a_reference_and_refuses_a_bad_one(low, tmp_path):
    _write_csv(tmp_path / "low.csv", low)
    cmd = [sys.executable, "-m", "pm2dof", "simulate", "--reference"]
    r = subprocess.run(cmd + [str(tmp_path / "low.csv"), "--controller", "na", "ctc", "--json"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    out = json.loads(r.stdout)
    assert set(out) == {"na", "ctc"} and out["na"]["outcome"] == "completed"
    assert out["na"]["samples"] == len(low.t) and out["na"]["rmse_m"] < 1e-4
    (tmp_path / "bad.csv").write_text("t,x,y\n0,0.25,0.26\n0.002,0.25,x\n")
    r = subprocess.run(cmd + [str(tmp_path / "bad.csv")], capture_output=True, text=True)
    assert r.returncode == 2 and r.stderr.count("\n") == 1
    assert "bad.csv: row 2 (line 3), column y: 'x' is not a number" in r.stderr
    (tmp_path / "slow.csv").write_text("t,x,y\n0,0.25,0.26\n0.001,0.25,0.26\n")
    r = subprocess.run(cmd + [str(tmp_path / "slow.csv")], capture_output=True, text=True)
    assert r.returncode == 2 and "sample_period = 0.002 s" in r.stderr


def test_ctc_default_gains_apply_to_every_task_axis(m):
    c = pm2dof.CTCController(m)
    kp = c.params_layout.unpack(c.params)["Kp"]
    assert kp.shape == (m.dof,) and np.all(kp == (2 * math.pi * 20) ** 2)


def test_table3_json_is_byte_identical_to_before_the_task_dimension_change():
    r = subprocess.run([sys.executable, "-m", "pm2dof", "table3", "--json"], capture_output=True,
                       text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout == (DATA / "table3.json").read_text()
