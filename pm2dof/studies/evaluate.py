# One chunk of a study: its rollouts in batches (one C call per run of one controller and move).
"""Evaluate one chunk of a study into result columns.

A chunk's units of one controller variant and one move share the closed-loop function and the
desired motion, so their draws run as one :meth:`Function.accumulate_batch` call per
repetition (the GIL released, the per-rollout Python overhead amortised). Each row is exactly
the rollout :func:`pm2dof.simulate` gives for the same controller, plant truth, encoder
resolution and theta_hat(0): the same generated function on the same inputs
(:func:`pm2dof.control.simulate.rollout_inputs`), and the metrics are the same arithmetic as
:class:`pm2dof.SimResult`'s.

Runs on the workers; imports no Dask or pyarrow (the client turns columns into Parquet).
"""
import numpy as np

from ..control.controllers import APDController, CTCController, NAController
from ..control.plant import plant_vector, theta_truth
from ..control.plant_step import check_plant_step, rest_poses
from ..control.simulate import batch_inputs, check_trajectory, completed_samples
from ..control.trajectory import line, model_move
from ..core.model import load_model
from ..core.status import Status
from .draws import draw_columns, plant_of, sample_draw

__all__ = ["run_chunk", "make_controller", "make_trajectory", "rollout_setup",
           "METRICS", "columns", "plant_problems"]

#: metric columns of every row (units in docs/study-file.md, "The results folder")
METRICS = ("rmse", "max_error", "peak_tau", "n_saturated", "n_singular", "n_non_finite",
           "diverged", "theta_error")
_CACHE = {}


def make_controller(model, variant, trajectory=None):
    """The controller of a study's controller variant; an LQR is planned along
    ``trajectory`` (the study's move, its settling samples included)."""
    o = dict(variant.options)
    kw = {k: o[k] for k in ("Kp", "Kv", "Kd", "Q", "velocity_filter_hz", "split", "project",
                            "Q_position", "Q_velocity", "R", "tau_max") if k in o}
    if variant.law == "apd":
        return APDController(model, **kw)
    if variant.law == "ctc":
        return CTCController(model, **kw)
    if variant.law == "lqr":
        from ..linear.lqr import LQRController
        return LQRController(model, trajectory, **kw)
    if "Gamma_scale" in o:
        kw["Gamma"] = o["Gamma_scale"] * np.asarray(model.spec.gains["na"]["Gamma"], dtype=float)
    return NAController(model, **kw)


def make_trajectory(model, move, period):
    """A study move: a name of the model file's [trajectories] or a line's (sorted) items."""
    name, items = move
    if items is None:
        return model_move(model, name, period)
    d = dict(items)
    return line(d["start"], d["end"], d["v_max"], d["a_max"], d["j_max"], period=period)


def _context(study):
    key = (study.model_path, study.generated_path, study.variants, study.moves,
           study.settle_time)                                                   # what ctx holds
    ctx = _CACHE.get(key)
    if ctx is None:
        from ..identification.base import identifiability
        model = load_model(study.model_path, study.generated_path)
        T = model.spec.sensing["sample_period"]
        trajs = []
        for mv in study.moves:
            tr = make_trajectory(model, mv, T)
            check_trajectory(model, tr)
            trajs.append((tr.extended(study.settle_time) if study.settle_time > 0 else tr,
                          len(tr.t)))
        # (variant, move) -> controller: an LQR's gains belong to its move
        ctrls = {(c, m): make_controller(model, v, trajs[m][0])
                 for c, v in enumerate(study.variants) for m in range(len(trajs))}
        N = identifiability(model).null_space
        ctx = {"model": model, "ctrls": ctrls, "trajs": trajs,
               "P_id": np.eye(N.shape[0]) - N @ N.T,   # projector on the identifiable directions
               "draw_cols": draw_columns(study, model.n_legs)}
        _CACHE.clear()
        _CACHE[key] = ctx
    return ctx


def rollout_setup(study, c, m, d, r, theta_hat0=None):
    """What rollout (c, m, d, r) runs, as :func:`pm2dof.simulate`'s arguments: (model,
    controller, trajectory, truth, encoder counts or None, theta_hat0, column values)."""
    ctx = _context(study)
    model = ctx["model"]
    truth, counts, cols = plant_of(model, study, sample_draw(study, d, model.n_legs), r)
    return model, ctx["ctrls"][c, m], ctx["trajs"][m][0], truth, counts, theta_hat0, cols


def columns(study, n_legs):
    """(name, kind) of every result column, in order; kind is int, str, float or bool."""
    return ([("rollout", "int"), ("controller", "str"), ("law", "str"), ("move", "str"),
             ("draw", "int"), ("run", "int")]
            + [(k, "float") for k in study.grid_keys]
            + [(k, "int" if k == "encoder_counts_per_rev" else "float")
               for k in draw_columns(study, n_legs)]
            + [(k, "bool" if k == "diverged" else "int" if k.startswith("n_") else "float")
               for k in METRICS])


def run_chunk(study, index):
    """Rows of chunk ``index``: {column: ndarray}, one row per rollout, ordered by rollout."""
    ctx = _context(study)
    model = ctx["model"]
    units = study.chunk_units(index)
    n_rows = len(units) * study.runs
    dt = {"int": np.int64, "str": object, "float": np.float64, "bool": np.bool_}
    out = {k: np.full(n_rows, np.nan) if t == "float" else np.zeros(n_rows, dt[t])
           for k, t in columns(study, model.n_legs)}
    groups = {}    # (variant, move) -> its draws in this chunk: one batch per run
    for u in units:
        c, m, d = study.unit(u)
        groups.setdefault((c, m), []).append(d)
    plants = {}    # draw -> per run: (truth, encoder counts, columns, plant vector, theta truth)
    for d in dict.fromkeys(d for ds in groups.values() for d in ds):
        values = sample_draw(study, d, model.n_legs)
        plants[d] = []
        for r in range(study.runs):
            truth, counts, cols = plant_of(model, study, values, r)
            plants[d].append((truth, counts, cols, plant_vector(model, truth, study.quantise, counts),
                              theta_truth(model, truth)))
    row0 = units[0] * study.runs
    for (c, m), draws in groups.items():
        _run_group(study, ctx, c, m, draws, plants, out, row0)
    return out


def _run_group(study, ctx, c, m, draws, plants, out, row0):
    model, ctrl, (traj, n_move) = ctx["model"], ctx["ctrls"][c, m], ctx["trajs"][m]
    variant = study.variants[c]
    K = len(draws)
    theta = None
    Y = None
    for r in range(study.runs):
        rows = np.array([study.rollout(c, m, d, r) for d in draws]) - row0
        f, X, u, P, ylay = batch_inputs(model, ctrl, traj, [plants[d][r][3] for d in draws],
                                        theta)
        for k, d in enumerate(draws):
            for key, v in plants[d][r][2].items():
                out[key][rows[k]] = v
        if Y is None:
            Y = np.empty((K, len(traj.t), ylay.size))
        f.accumulate_batch(X, u, P, Y)
        Yf = ylay.unpack(Y.reshape(K * len(traj.t), ylay.size))
        xe = Yf["xe"].reshape(K, -1, model.dof)
        tau = Yf["tau_a"].reshape(K, -1, model.n_legs)
        status = Yf["status"].reshape(K, -1)
        th = Yf["theta_hat"].reshape(K, len(traj.t), -1)
        n_ok = completed_samples(model, Y, ylay)       # SimResult's samples: where a run ended
        _metrics(out, rows, traj.xd, xe, tau, status, n_move, n_ok)
        th_end = th[np.arange(K), n_ok - 1]            # SimResult.theta_hat[-1]
        if variant.law == "na":
            Pid = ctx["P_id"]
            for k, d in enumerate(draws):
                t_true = plants[d][r][4]
                out["theta_error"][rows[k]] = (np.linalg.norm(Pid @ (th_end[k] - t_true))
                                               / np.linalg.norm(Pid @ t_true))
        theta = [th_end[k].copy() for k in range(K)]   # carried into the next run
        out["rollout"][rows] = row0 + rows
        out["controller"][rows] = variant.name
        out["law"][rows] = variant.law
        out["move"][rows] = study.moves[m][0]
        out["draw"][rows] = draws
        out["run"][rows] = r
        for key, v in variant.grid:
            out[key][rows] = v


def _metrics(out, rows, xd, xe, tau, status, n_move, n_ok):
    """SimResult's metrics, one row per rollout: rmse (eq. 41) and max |e| over the move's
    samples, m (``inf`` for a run that did not complete: ``diverged``); peak |tau_a| N*m and
    the status counts over the samples the run completed (the first ``n_ok`` (K,)). The error
    is the position's (x, y), as :attr:`pm2dof.SimResult.rmse` (a platform's phi left out)."""
    e = xd[:n_move, :2] - xe[:, :n_move, :2]
    e2 = np.sum(e * e, axis=-1)
    diverged = n_ok < xe.shape[1]                     # SimResult.outcome != "completed"
    held = np.arange(xe.shape[1]) < n_ok[:, None]     # the samples a SimResult holds
    with np.errstate(invalid="ignore"):
        out["rmse"][rows] = np.where(diverged, np.inf, np.sqrt(np.mean(e2, axis=-1)))  # eq. 41
        out["max_error"][rows] = np.where(diverged, np.inf, np.sqrt(np.max(e2, axis=-1)))
    out["peak_tau"][rows] = np.max(np.where(held[..., None], np.abs(tau), 0.0), axis=(1, 2))
    out["n_singular"][rows] = np.sum(held & (status == Status.SINGULAR), axis=1)
    out["n_saturated"][rows] = np.sum(held & (status == Status.SATURATED), axis=1)
    out["n_non_finite"][rows] = np.sum(held & (status == Status.NON_FINITE), axis=1)
    out["diverged"][rows] = diverged


def model_problems(pr, model, variants, moves):
    """Record in ``pr`` (a :class:`~pm2dof.core.validate.Problems`) every controller variant
    its controller refuses and every move that is unreachable or singular on ``model``.
    ``variants`` None: the [[controllers]] entries had problems of their own (not checked)."""
    from ..control.trajectory import TrajectoryError
    from ..core.errors import SingularityError, WorkspaceError
    from ..core.validate import entry
    T = model.spec.sensing["sample_period"]
    try:   # an LQR variant is checked on the first move (a bad move is reported below)
        first = make_trajectory(model, moves[0], T)
        check_trajectory(model, first)
    except (WorkspaceError, SingularityError, TrajectoryError):
        first = None
    entries = list(dict.fromkeys(v.name for v in variants or ()))   # one per [[controllers]]
    failed = {}         # (entry, message) -> the grid points where it holds, in order
    for v in variants or ():
        if v.law == "lqr" and first is None:
            continue
        try:
            make_controller(model, v, first)
        except (ValueError, TypeError) as exc:
            failed.setdefault((entries.index(v.name), str(exc)), []).append(v.grid)
    for (k, msg), points in failed.items():
        n_points = sum(v.name == entries[k] for v in variants)
        point = ("" if not points[0] else "at every grid point: " if len(points) == n_points > 1
                 else f"at grid point {dict(points[0])}: ")
        pr.add(entry("controllers", f"entry {k + 1}, {entries[k]!r}"), f"{point}{msg}")
    for i, mv in enumerate(moves):
        try:
            check_trajectory(model, make_trajectory(model, mv, T))
        except (WorkspaceError, SingularityError, TrajectoryError) as exc:
            pr.add(entry("study.moves", f"entry {i + 1}, {mv[0]!r}"), str(exc))


def plant_problems(pr, model, study):
    """Record in ``pr`` the first draw whose plant the closed loop cannot integrate stably at
    rest on one of the study's moves (:func:`pm2dof.control.plant_step.check_plant_step`:
    its friction, scaled by the draw, too stiff for the model's RK4 substeps), so that a study
    is refused before any rollout rather than in a chunk. Every draw is checked in its first
    run and, with a ``[payload_change]``, in the run the payload changes."""
    from ..core.errors import ArgumentError
    from ..core.validate import entry
    T = model.spec.sensing["sample_period"]
    runs = sorted({0, study.payload_change[0]} if study.payload_change else {0})
    runs = [r for r in runs if r < study.runs]
    poses = [rest_poses(model, make_trajectory(model, mv, T).xd) for mv in study.moves]
    for d in range(study.draws):
        values = sample_draw(study, d, model.n_legs)
        for r in runs:
            truth = plant_of(model, study, values, r)[0]
            for mv, xd in zip(study.moves, poses):
                try:
                    check_plant_step(model, xd, truth)
                except ArgumentError as exc:
                    return pr.add(entry("uncertainty", f"draw {d}, run {r}, move {mv[0]!r}"),
                                  f"the draw's plant cannot be simulated (narrow the friction "
                                  f"scales, or raise the model's substeps): {exc}")
    return None
