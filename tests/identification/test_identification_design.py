# Optimal excitation: constraints hold at dense samples, rest at both ends, the CasADi graph is the model's C, file round trip.
import dataclasses
import re
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof import cli
from pm2dof.identification.base import base_parameters
from pm2dof.identification.design import (
    IPOPT_OPTIONS,
    LimitOptions,
    SeriesOptions,
    SolverOptions,
    _casadi_openblas,
    check_excitation,
    design_excitation,
    objective_logdet,
    random_start,
    regressor_condition,
    sample_function,
)
from pm2dof.identification.log import read_log
from pm2dof.identification.signals import (
    ExcitationError,
    FourierExcitation,
    load_excitation,
    multisine,
    trajectory_of,
    write_excitation,
)
from pm2dof.infra.progress import Progress

pytestmark = pytest.mark.slow     # runs IPOPT designs: make test-slow (CI)

LIMITS = {"v_max": 0.4, "a_max": 6.0, "tau_fraction": 0.3}
SMALL = dict(base_hz=0.5, harmonics=4, periods=1, samples=80, constraint_samples=200, **LIMITS)
SHIPPED = Path(__file__).resolve().parents[2] / "examples" / "excitation_shang2010.toml"


def options(**fields):
    """The design's option objects (series, limits, solver) from their fields by name."""
    kinds = (SeriesOptions, LimitOptions, SolverOptions)
    names = {f.name for kind in kinds for f in dataclasses.fields(kind)}
    assert set(fields) <= names, set(fields) - names
    return tuple(kind(**{f.name: fields[f.name] for f in dataclasses.fields(kind)
                         if f.name in fields}) for kind in kinds)


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


class _Bar:
    """What a progress bar was told: its postfixes and steps (``on_step`` called at each)."""

    def __init__(self, total, desc, on_step):
        self.total, self.desc, self.n, self.postfixes, self.on_step = total, desc, 0, [], on_step

    def set_postfix_str(self, s, refresh=True):
        self.postfixes.append(s)

    def update(self, n=1):
        self.n += n
        self.on_step()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


class Recorder(Progress):
    """A Progress that records its stage lines and bars instead of drawing them."""

    def __init__(self, on_step=lambda: None):
        super().__init__(quiet=True)
        self.lines, self.bars_made, self.on_step = [], [], on_step

    def __call__(self, msg):
        self.lines.append(msg)

    def bar(self, total, desc, unit="step", **kw):
        self.bars_made.append(_Bar(total, desc, self.on_step))
        return self.bars_made[-1]


@pytest.fixture(scope="module")
def designed(m):
    """A small design (4 harmonics of 0.5 Hz, one 2 s period; a few seconds of IPOPT) with
    limits below the defaults, so that some of them bind."""
    return design_excitation(m, *options(**SMALL))


def test_design_meets_every_constraint_every_millisecond(m, designed):
    exc = designed
    assert exc.info["ipopt_status"] == "Solve_Succeeded"
    tau_limit = LIMITS["tau_fraction"] * np.max(m.spec.limits["tau_max"])
    chk = check_excitation(m, exc, v_max=LIMITS["v_max"], a_max=LIMITS["a_max"],
                           tau_limit=tau_limit, sing_min=0.2, radius=0.06, step=1e-3)
    assert chk["ok"], chk
    # the design uses its room: the speed limit binds (within the 2 % safety factor)
    assert chk["speed"] > 0.95 * LIMITS["v_max"], chk
    # starts and ends at rest, and is periodic
    x, v, a = exc.evaluate([0.0, exc.duration])
    assert np.abs(v).max() < 1e-12 and np.abs(a).max() < 1e-9
    assert np.allclose(x[0], x[1], rtol=0, atol=1e-12)
    # better conditioned than its random start, and more informative
    assert exc.info["cond_after"] < exc.info["cond_before"] / 2
    assert exc.info["logdet_after"] > exc.info["logdet_before"]


def test_casadi_graph_is_the_model_c(m):
    """The design's per-sample function (casadi.external on the compiled library) gives the
    Model's Y, min-norm torque and singularity measures."""
    I = list(base_parameters(m).independent)
    f = sample_function(m, I)
    # the design's smooth Coulomb columns S^T e_i tanh(qd_i / d) become the C's sign() as d -> 0
    f_sharp = sample_function(m, I, smooth_sign=1e-12)
    rng = np.random.default_rng(4)
    for _ in range(5):
        x = np.array([0.245, 0.265]) + rng.uniform(-0.04, 0.04, 2)
        v, a = rng.normal(0, 0.3, 2), rng.normal(0, 5, 2)
        Yv, tau, sing = (np.array(o).ravel() for o in f(x, v, a))
        q = m.ik(x)
        assert np.allclose(Yv.reshape(len(I), 2).T, m.Y(q, v, v, a)[:, I], rtol=1e-12, atol=1e-12)
        assert np.allclose(np.array(f_sharp(x, v, a)[0]).ravel(), Yv, rtol=1e-12, atol=1e-12)
        S = m.S(q)
        ref = m.torque_splits(q, m.Y(q, v, v, a) @ m.theta_nominal)["min_norm"]  # eq. 21 in C
        assert np.allclose(tau, ref, rtol=1e-10, atol=1e-10)
        assert np.allclose(S.T @ tau, m.Y(q, v, v, a) @ m.theta_nominal, rtol=1e-10, atol=1e-10)
        assert np.allclose(sing, m.singularity_measures(q), rtol=0, atol=1e-14)
        # and its finite-difference derivative agrees with differences of the Model's Y
        import casadi as ca
        xs = ca.MX.sym("x", 2)
        J = ca.Function("J", [xs], [ca.jacobian(f(xs, v, a)[0], xs)])(x).full()
        h = 1e-6
        fd = np.column_stack([(m.Y(m.ik(x + e), v, v, a)[:, I] - m.Y(m.ik(x - e), v, v, a)[:, I]
                               ).T.ravel() / (2 * h) for e in (np.array([h, 0]), np.array([0, h]))])
        assert np.abs(J - fd).max() < 1e-4 * max(1.0, np.abs(fd).max())


def test_file_round_trip_and_bad_files(tmp_path, m, designed):
    p = write_excitation(tmp_path / "exc.toml", designed, m)
    back = load_excitation(p, m)
    for k in ("center", "a", "b"):
        assert np.array_equal(getattr(back, k), getattr(designed, k)), k
    assert back.base_hz == designed.base_hz and back.periods == designed.periods
    assert back.info == designed.info          # [design] with its sub-tables, exactly
    assert back.model == {"model": "shang2010", "model_name": "shang2010",
                          "formulation_sha256": m.spec.formulation_sha256}
    text = p.read_text()
    # the file is a function of the design alone: no wall time, no date
    assert write_excitation(tmp_path / "again.toml", back, m).read_text() == text
    bad = tmp_path / "bad.toml"
    write_excitation(bad, designed, pm2dof.load_model("fivebar"))
    with pytest.raises(ExcitationError, match=r"written for model 'fivebar' \(model fivebar, "
                                              r"formulation [0-9a-f]{12}\), not 'shang2010'"):
        load_excitation(bad, m)
    # a file of before pm2dof 0.3 names its model by name alone: refused, with a model or not
    old = "\n".join(l for l in text.splitlines() if not l.startswith(("model_name",
                                                                       "formulation_sha256")))
    bad.write_text(old)
    for model in (m, None):
        with pytest.raises(ExcitationError, match=r"records its model by model without "
                                                  r"model_name, formulation_sha256: a file of "
                                                  r"pm2dof before 0.3"):
            load_excitation(bad, model)
    # with no model entries at all: a file of the model the caller gives
    none = "\n".join(l for l in old.splitlines() if not l.startswith("model ="))
    bad.write_text(none)
    assert load_excitation(bad, m).model == {}
    bad.write_text("\n".join(l for l in text.splitlines() if not l.startswith("b_y")))
    with pytest.raises(ExcitationError, match=r"\[excitation.b_y\] missing \(required\)"):
        load_excitation(bad, m)
    moving = FourierExcitation(0.5, 1, designed.center, designed.a + 0.01, designed.b)
    write_excitation(bad, moving, m)
    with pytest.raises(ExcitationError, match="does not start at rest"):
        load_excitation(bad, m)


def test_excite_runs_the_file(tmp_path, m, designed, capsys):
    p = write_excitation(tmp_path / "exc.toml", designed, m)
    logp = tmp_path / "run.parquet"
    assert cli.main(["identify", "excite", "--excitation", str(p), "--out", str(logp)]) == 0
    capsys.readouterr()
    log = read_log(logp)
    traj = trajectory_of(m, designed)
    assert len(log.t) == len(traj.t) and float(log.meta["excitation_max_hz"]) == 2.0
    # the optimised motion is better conditioned than the default multi-sine of excite
    base = base_parameters(m)
    assert (regressor_condition(m, base, traj)[0]
            < regressor_condition(m, base, trajectory_of(
                m, multisine(m, duration=designed.duration)))[0])


def test_design_is_deterministic_and_runs_ipopt_blas_on_one_thread(m, designed):
    """The same arguments give the same file bit for bit, whatever CasADi's OpenBLAS was set
    to before (its default, one thread per core, changed the shipped design's IPOPT path);
    during the solve it runs on one thread, and is restored after."""
    lib = _casadi_openblas()
    assert lib is not None, "CasADi's bundled OpenBLAS was not found"
    seen = []
    lib.openblas_set_num_threads(2)
    progress = Recorder(on_step=lambda: seen.append(lib.openblas_get_num_threads()))
    again = design_excitation(m, *options(**SMALL), progress=progress)
    assert lib.openblas_get_num_threads() == 2
    assert seen and set(seen) == {1}, seen
    # one bar, one step per IPOPT iteration (its iterations 0..n call back)
    (iterations,) = progress.bars_made
    assert iterations.n == again.info["ipopt_iterations"] + 1 and iterations.total == 500
    for k in ("center", "a", "b"):
        assert np.array_equal(getattr(again, k), getattr(designed, k)), k
    assert again.info == designed.info
    assert designed.info["blas_threads"] == 1
    # the copy IPOPT uses is the one set: the process maps exactly one
    with open("/proc/self/maps") as fh:
        assert len({ln.split()[-1] for ln in fh if "libcasadi-tp-openblas" in ln}) == 1


def test_progress_bar_and_summary_report_one_log_det(m):
    """The progress bar's log det is the objective's log det(Phi^T Phi / K) (not IPOPT's
    column-scaled value): stopped at iteration 25, the bar's last postfix equals
    :func:`objective_logdet` of the result, which the summary reports as the objective's."""
    progress = Recorder()
    exc = design_excitation(m, *options(**{**SMALL, "max_iter": 25}), progress=progress)
    (iterations,) = progress.bars_made
    assert iterations.n == 26 and len(iterations.postfixes) == 26      # iterations 0..25
    value = float(re.fullmatch(r"objective log det (-?[0-9.]+)", iterations.postfixes[-1])[1])
    assert any(ln.startswith("IPOPT: 18 coefficients") for ln in progress.lines), progress.lines
    # 3 decimals printed; the result is IPOPT's iterate projected exactly onto the rest
    # conditions (a change of IPOPT's constraint tolerance)
    assert value == pytest.approx(exc.info["objective_logdet_after"], abs=2e-3)
    assert exc.info["objective_logdet_after"] == pytest.approx(
        objective_logdet(m, exc, SMALL["samples"]), rel=1e-12)


def test_shipped_file_records_what_recomputes_from_its_coefficients(m):
    """examples/excitation_shang2010.toml: its [design] holds the arguments
    of ``pm2dof identify design`` today (the README's command), IPOPT's options,
    what it was designed with, and figures that recompute from its coefficients with today's
    model: cond and log det on the run's samples and on the objective's, at the optimum and at
    the start (rebuilt from the recorded seed). A change of the defaults, or of the model that
    moves these figures, makes this fail until the file is designed again."""
    exc = load_excitation(SHIPPED, m)
    info = exc.info
    defaults = {f.name: f.default for kind in (SeriesOptions, LimitOptions, SolverOptions)
                for f in dataclasses.fields(kind) if not f.name.startswith("phi_")}
    assert {k: info[k] for k in defaults} == defaults
    # a point has no phi: its file records no phi limits (the 2-D file is as before platforms)
    assert not any(k.startswith("phi_") for k in info)
    # IPOPT's options today: a change of them fails here until the file is designed again
    # (and docs/results-identification.md's Monte Carlo tables measured again with it)
    assert info["ipopt"] == IPOPT_OPTIONS
    assert info["ipopt_status"] == "Solve_Succeeded" and info["blas_threads"] == 1
    # what it was designed with (a model change that matters shows in the figures below)
    assert {"pm2dof", "casadi", "numpy", "model_file_sha256", "formulation_sha256", "machine",
            "libc"} <= set(info["provenance"])
    first = next(iter(m.spec.trajectories.values()))       # the middle of the first move
    assert np.array_equal(info["region_center"],
                          (np.asarray(first["start"], float) + first["end"]) / 2)
    assert (exc.base_hz, exc.periods, exc.harmonics) == (
        info["base_hz"], info["periods"], info["harmonics"])
    base = base_parameters(m)
    start = random_start(m, **{k: info[k] for k in ("base_hz", "harmonics", "periods", "v_max",
                                                  "a_max", "radius", "seed")})
    for when, e in (("after", exc), ("before", start)):
        cond, logdet = regressor_condition(m, base, trajectory_of(m, e))
        assert cond == pytest.approx(info[f"cond_{when}"], rel=1e-9), when
        assert logdet == pytest.approx(info[f"logdet_{when}"], rel=1e-9, abs=1e-9), when
        assert objective_logdet(m, e, info["samples"], base) == pytest.approx(
            info[f"objective_logdet_{when}"], rel=1e-9, abs=1e-9), when
    chk = check_excitation(m, exc, v_max=info["v_max"], a_max=info["a_max"],
                           tau_limit=info["tau_fraction"] * np.max(m.spec.limits["tau_max"]),
                           sing_min=max(m.singularity_threshold,
                                        m.parallel_singularity_threshold)
                           + info["singularity_margin"], radius=info["radius"])
    assert chk["ok"], chk


def test_ctrl_c_during_design_writes_nothing_and_exits_130(tmp_path):
    """IPOPT catches SIGINT and returns User_Requested_Stop: the design used to write that
    half-made excitation and exit 0."""
    import fcntl
    import os
    import signal
    import struct
    import subprocess
    import sys
    import termios
    import time

    from tests.processes import from_a_terminal
    out = tmp_path / "exc.toml"
    env = {**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[2])}
    # stderr on a terminal (a pty), as where Ctrl-C is pressed: the bar of IPOPT's iterations
    # is drawn there, and the Ctrl-C is sent once it shows a step (IPOPT's callback at its
    # iteration 0): inside IPOPT's iterations for sure, not after a guessed sleep (was 3 s)
    master, slave = os.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 120, 0, 0))  # 120 columns
    p = subprocess.Popen(from_a_terminal([sys.executable, "-m", "pm2dof", "identify", "design",
                                          "--out", out]),
                         stdout=subprocess.PIPE, stderr=slave, text=True, env=env)
    os.close(slave)

    def read():
        try:
            return os.read(master, 65536).decode(errors="replace")
        except OSError:                          # EIO: the command closed its terminal
            return ""
    err, t0 = "", time.monotonic()
    try:
        while not re.search(r"IPOPT[^\r\n]*\b[1-9][0-9]*/500\b", err):
            chunk = read()
            assert chunk, f"the design ended before IPOPT iterated: {err}"
            assert time.monotonic() - t0 < 300, err
            err += chunk
        p.send_signal(signal.SIGINT)
        rest = ""
        while chunk := read():
            rest += chunk
        stdout = p.communicate(timeout=300)[0]
    finally:
        p.kill()
        p.wait()
        os.close(master)
    assert p.returncode == 130, (stdout, rest)
    assert not out.exists() and not list(tmp_path.iterdir())
    assert rest.strip().splitlines()[-1].startswith("pm2dof: interrupted (IPOPT stopped after ")
    assert rest.strip().splitlines()[-1].endswith(f"{out} not written)")
    assert "wrote" not in stdout
    assert "WARNING" not in rest and "Traceback" not in rest, rest   # CasADi printed one


def test_not_met_stands_next_to_the_limit_that_failed(tmp_path, m, monkeypatch):
    """The shipped excitation reaches 58.8 mm from c0: with a 30 mm region that limit fails,
    and the printed check says so there (it read as 'does not start at rest')."""
    from pm2dof.identification import design
    exc = load_excitation(SHIPPED, m)
    exc = FourierExcitation(exc.base_hz, exc.periods, exc.center, exc.a, exc.b,
                            {**exc.info, "radius": 0.03})
    monkeypatch.setattr(design, "design_excitation", lambda *a, **k: exc)
    text = design.format_design(design.run_design(m, tmp_path / "e.toml"))
    line = next(ln for ln in text.splitlines() if ln.startswith("checked"))
    assert re.search(r"\|x - c0\| 58\.\d <= 30\.0 mm NOT MET, starts and ends at rest: "
                     r"NOT MET: radius$", line), line
    assert line.count("NOT MET") == 2


def test_bad_design_arguments_are_named(m, tmp_path, capsys):
    """Each wrong argument is named with its value and rule (the API), and from the CLI by its
    flag (argparse, exit 2), before IPOPT runs."""
    with pytest.raises(pm2dof.ArgumentError) as info:
        design_excitation(m, *options(**{**SMALL, "base_hz": -1.0, "tau_fraction": 2.0}))
    msg = str(info.value)
    assert "base_hz must be > 0, got -1.0" in msg and "tau_fraction must be in (0, 1]" in msg
    assert "harmonics" not in msg                        # only what was wrong
    out = tmp_path / "exc.toml"
    for flag, value in (("--base-hz", "-1"), ("--harmonics", "0"), ("--tau-fraction", "2")):
        with pytest.raises(SystemExit) as stop:
            cli.main(["identify", "design", "--out", str(out), flag, value])
        assert stop.value.code == 2
        assert flag in capsys.readouterr().err
    assert not out.exists()


def test_stage_lines_when_stderr_is_not_a_terminal(m, monkeypatch):
    """Not a terminal, no bar is drawn: the design printed nothing for 812 s (the vertical
    3-RRR). A stage line every STAGE_SECONDS of IPOPT (0 here: one per iteration)."""
    import io

    from pm2dof.identification import design
    monkeypatch.setattr(design, "STAGE_SECONDS", 0.0)
    stream = io.StringIO()
    progress = Progress(stream=stream)
    assert not progress.bars                       # a StringIO is not a terminal
    exc = design_excitation(m, *options(**{**SMALL, "max_iter": 3}), progress=progress)
    lines = [ln for ln in stream.getvalue().splitlines() if "IPOPT iteration" in ln]
    assert [int(re.search(r"IPOPT iteration (\d+) of at most 3:", ln)[1]) for ln in lines] == [
        0, 1, 2, 3], lines                         # IPOPT's iterations 0..3
    assert all(re.search(r"objective log det -?[0-9.]+, \d+ s$", ln) for ln in lines), lines
    assert exc.info["ipopt_iterations"] == 3


@pytest.mark.parametrize("accept", [False, True])
def test_a_design_that_did_not_converge_says_so_and_exits_1(tmp_path, capsys, accept):
    """The vertical 3-RRR's design stopped at Maximum_Iterations_Exceeded and was written with
    exit 0, as if optimal. Now: one line, converged = false in the file, exit 1 unless
    --accept-unconverged."""
    out = tmp_path / "exc.toml"
    code = cli.main(["identify", "design", "--model", "shang2010_vertical", "--harmonics", "2",
                     "--periods", "1", "--base-hz", "0.5", "--max-iter", "2", "--out", str(out),
                     "--quiet", *(["--accept-unconverged"] if accept else [])])
    stdout, stderr = capsys.readouterr()
    assert code == (0 if accept else 1), (stdout, stderr)
    assert stdout.splitlines()[0] == (
        f"NOT CONVERGED: IPOPT stopped at Maximum_Iterations_Exceeded after 2 iterations; {out} "
        f"holds its last iterate, marked converged = false in [design]")
    assert ("converged = false" in stderr) != accept, stderr
    exc = load_excitation(out)
    assert exc.info["converged"] is False
    assert exc.info["ipopt_status"] == "Maximum_Iterations_Exceeded"


def test_a_converged_design_says_nothing_more(m, designed, tmp_path, monkeypatch, capsys):
    from pm2dof.identification import design
    monkeypatch.setattr(design, "design_excitation", lambda *a, **k: designed)
    assert designed.info["converged"] is (designed.info["ipopt_status"] in design.CONVERGED)
    assert designed.info["converged"], designed.info["ipopt_status"]
    r = design.run_design(m, tmp_path / "e.toml")
    assert r.converged and not design.format_design(r).startswith("NOT CONVERGED")
    assert load_excitation(tmp_path / "e.toml").info["converged"] is True


def test_design_takes_its_options_as_three_objects(m):
    """design_excitation's 16 settings are three option objects (the series, the limits, the
    solver) with their defaults in one place each; anything else is refused by type before
    IPOPT runs."""
    for k, kind in enumerate((SeriesOptions, LimitOptions, SolverOptions)):
        args = [None, None, None]
        args[k] = {"base_hz": 0.5}
        with pytest.raises(pm2dof.ArgumentTypeError, match=rf"expected a {kind.__name__}"):
            design_excitation(m, *args)
    with pytest.raises(dataclasses.FrozenInstanceError):
        SeriesOptions().base_hz = 1.0
    assert len(dataclasses.fields(SeriesOptions) + dataclasses.fields(LimitOptions)
               + dataclasses.fields(SolverOptions)) == 16
