# Reference files: a binary file is one line (the logs' reader), and a reference must start at rest.
import subprocess
import sys
import warnings

import numpy as np
import pytest

import pm2dof
from pm2dof.analysis.reference_file import ReferenceFileError, read_trajectory, simulate_reference
from pm2dof.control.simulate import moving_start

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

KINDS = ["rrr4_platform", "prr3_platform", "shang2010_vertical"]   # platform, linear, gravity


def _write(path, traj, rates=True):
    """The trajectory as a reference CSV: positions, and with ``rates`` their _dot and _ddot."""
    names = ["x", "y", "phi"][:traj.xd.shape[1]]
    head = ["t", *names]
    cols = [traj.t[:, None], traj.xd]
    if rates:
        head += [f"{c}_dot" for c in names] + [f"{c}_ddot" for c in names]
        cols += [traj.xd_dot, traj.xd_ddot]
    rows = np.hstack(cols)
    path.write_text(",".join(head) + "\n" + "\n".join(",".join(repr(v) for v in r)
                                                      for r in rows.tolist()) + "\n")
    return path


def _sine(m, speed, hz=1.0, seconds=0.5):
    """A sine along the model's first move's direction from its start, starting at ``speed``
    (m/s): x(t) = x0 + u A sin(w t), A = speed / w; phi (a platform) held."""
    mv = pm2dof.model_move(m, next(iter(m.spec.trajectories)))
    x0, x1 = mv.xd[0], mv.xd[-1]
    u = np.zeros_like(x0)
    u[:2] = (x1 - x0)[:2] / np.linalg.norm((x1 - x0)[:2])
    T, w = mv.period, 2 * np.pi * hz
    t = np.arange(int(round(seconds / T)) + 1) * T
    A = speed / w
    xd = x0 + np.outer(A * np.sin(w * t), u)
    v = np.outer(A * w * np.cos(w * t), u)
    a = np.outer(-A * w * w * np.sin(w * t), u)
    return pm2dof.Trajectory.from_samples(xd, v, a, T)


# -- a binary file ----------------------------------------------------------------------------

def test_a_binary_reference_is_one_line_and_exit_2_like_a_binary_log(tmp_path):
    """It was a UnicodeDecodeError traceback from `simulate --reference`; `identify fit`
    refused the same file in one line. Both now read CSV text through one reader."""
    junk = tmp_path / "junk.csv"
    junk.write_bytes(bytes([0x4a, 0xae, 0x00, 0x13, 0xff]) * 600)
    with pytest.raises(ReferenceFileError, match=r"junk.csv: line 1 is not text \(byte 0xae at "
                                                 r"column 2 is not UTF-8\): a reference is a "
                                                 r"UTF-8 CSV or a Parquet file"):
        read_trajectory(junk)
    errs = {}
    for cmd in (["simulate", "--reference", str(junk)], ["identify", "fit", str(junk)]):
        r = subprocess.run([sys.executable, "-m", "pm2dof", *cmd], capture_output=True,
                           text=True, timeout=120)
        assert r.returncode == 2, (cmd, r.stderr)
        assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr
        errs[cmd[0]] = r.stderr.strip()
    # the same reader: the same words, each naming what its file is
    for what, err in (("a reference", errs["simulate"]), ("a log", errs["identify"])):
        assert err == (f"pm2dof: error: {junk}: line 1 is not text (byte 0xae at column 2 is "
                       f"not UTF-8): {what} is a UTF-8 CSV or a Parquet file"), err


def test_a_latin1_comment_in_a_reference_is_read(tmp_path):
    m = pm2dof.load_model()
    low = pm2dof.paper_move("low")
    f = _write(tmp_path / "ref.csv", low)
    f.write_bytes("# operator = Müller, 25 °C\n".encode("latin-1") + f.read_bytes())
    tr = read_trajectory(f)
    assert np.array_equal(tr.xd, low.xd) and np.array_equal(tr.xd_dot, low.xd_dot)
    assert simulate_reference(m, f, ("apd",))["apd"].rmse == \
        pm2dof.simulate(m, pm2dof.APDController(m), low).rmse


def test_an_unreadable_reference_is_one_line(tmp_path):
    d = tmp_path / "dir.csv"
    d.mkdir()
    with pytest.raises(ReferenceFileError, match="dir.csv: no such file"):
        read_trajectory(d)


# -- a reference that does not start at rest ---------------------------------------------------

@pytest.mark.parametrize("name", KINDS + ["shang2010"])
def test_a_reference_that_does_not_start_at_rest_is_refused_naming_its_velocity(name, tmp_path):
    m = pm2dof.load_model(name)
    tr = _sine(m, 0.2, hz=4.0)
    f = _write(tmp_path / "sine.csv", tr)
    v0 = ", ".join(f"{v:.4g}" for v in tr.xd_dot[0])
    cols = ", ".join(f"{c}_dot" for c in m.task_names)
    unit = "m/s" if m.dof == 2 else "m/s, rad/s"
    with pytest.raises(ReferenceFileError, match=rf"sine.csv: the desired velocity at t = 0 is "
                                                 rf"\({cols}\) = \({v0}\) {unit}, not rest"):
        simulate_reference(m, f, ("apd",))
    # positions only (rates differentiated): refused too
    with pytest.raises(ReferenceFileError, match="not rest"):
        simulate_reference(m, _write(tmp_path / "pos.csv", tr, rates=False), ("apd",))


@pytest.mark.parametrize("name", KINDS + ["shang2010"])
def test_every_move_written_as_a_reference_starts_at_rest(name, tmp_path):
    """The model's own S-curve moves, with all their columns and with positions only (rates
    differentiated: a one-sided difference of j T^2 / 3 at t = 0), pass: the rule refuses what
    does not start at rest, not what does."""
    m = pm2dof.load_model(name)
    for speed in m.spec.trajectories:
        mv = pm2dof.model_move(m, speed)
        for rates in (True, False):
            tr = read_trajectory(_write(tmp_path / f"{speed}.csv", mv, rates))
            assert moving_start(tr, m.task_names) is None, (speed, rates, tr.xd_dot[0])
            v0 = np.abs(tr.xd_dot[0])
            assert rates or v0.max() > 0           # differentiated: not exactly zero


def test_simulate_warns_on_a_trajectory_that_does_not_start_at_rest():
    """pm2dof.simulate runs it (a step may be studied on purpose) and warns, naming the
    velocity: on the paper's robot a 1 Hz sine starting at 0.42 m/s drives NA to its limit."""
    m = pm2dof.load_model()
    tr = _sine(m, 0.42)
    with pytest.warns(pm2dof.MovingStartWarning,
                      match=r"simulate \(na, model 'shang2010'\): the desired velocity at t = 0 "
                            r"is \(x_dot, y_dot\) = \(0\.297, -0\.297\) m/s, not rest"):
        r = pm2dof.simulate(m, pm2dof.NAController(m), tr)
    assert r.n_saturated > 0 and r.peak_tau == pytest.approx(30.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", pm2dof.MovingStartWarning)
        pm2dof.simulate(m, pm2dof.NAController(m), pm2dof.paper_move("high"))   # at rest


def test_the_simulate_command_refuses_a_moving_start_in_one_line(tmp_path):
    m = pm2dof.load_model("prr3_platform")
    f = _write(tmp_path / "sine.csv", _sine(m, 0.2, hz=4.0))
    r = subprocess.run([sys.executable, "-m", "pm2dof", "simulate", "--model", "prr3_platform",
                        "--reference", str(f)], capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert "the desired velocity at t = 0 is (x_dot, y_dot, phi_dot) = (" in r.stderr
    assert "start the reference at rest" in r.stderr
