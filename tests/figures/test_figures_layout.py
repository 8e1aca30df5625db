# Layout of every figure pm2dof writes, checked as a reader would: nothing
# clipped, no text over text, no legend or note over the data, readable ticks, colour bars named.
"""The figures, built from small runs of the real analyses, must pass :func:`layout_problems`.

The checker is written here on its own (it does not call pm2dof's legend placement): it walks
every text the canvas draws (titles, labels, drawn tick labels, offset texts, notes, legends)
and every line and scatter point of every axes, in display pixels after a full draw at the
resolution the PNGs are written at. The first tests show that it catches each kind of
problem on a deliberately bad figure, so that a pass means something.
"""
import numpy as np
import pytest

import pm2dof
from pm2dof.analysis.experiment import repeated_runs, table3
from pm2dof.analysis.maps import workspace_maps
from pm2dof.analysis.splits import tau_max_sweep
from pm2dof.control.trajectory import model_move
from pm2dof.figures import animate, experiment, maps, planning, splits, studies
from pm2dof.planning.pathfile import read_path_file
from pm2dof.studies import SHIPPED_STUDIES, read_study, run_chunk
from pm2dof.studies.report import summarise
from pm2dof.studies.spec import GRID_KEYS

pytestmark = pytest.mark.slow     # draws every figure of every model (40 s): make test-slow (CI)

TOL = 1.0        # px
PNG_DPI = 110    # pm2dof.infra.results.save_figure


# --------------------------------------------------------------------------------------
# The checker
# --------------------------------------------------------------------------------------

def _drawn_ticklabels(axis):
    out = []
    for tick in axis._update_ticks():          # the ticks inside the view: the ones drawn
        for lab in (tick.label1, tick.label2):
            if lab.get_visible() and lab.get_text().strip():
                out.append(lab)
    return out


def _is_colorbar(ax):
    return hasattr(ax, "_colorbar")


def _name(t):
    return repr(t.get_text()[:40])


def _texts(fig):
    """[(owner, Text)]: every visible, non-empty text that the canvas draws, once."""
    out = [("figure", t) for t in ([fig._suptitle] if fig._suptitle else []) + fig.texts]
    for k, ax in enumerate(fig.axes):
        if not ax.get_visible():
            continue
        own = f"axes {k}" + (" (colour bar)" if _is_colorbar(ax) else f" {ax.get_title()[:30]!r}")
        out += [(own, t) for t in (ax.title, ax._left_title, ax._right_title, ax.xaxis.label,
                                   ax.yaxis.label, ax.xaxis.offsetText, ax.yaxis.offsetText)]
        out += [(own, t) for t in _drawn_ticklabels(ax.xaxis) + _drawn_ticklabels(ax.yaxis)]
        out += [(own, t) for t in ax.texts]
    seen, uniq = set(), []
    for o, t in out:
        if id(t) not in seen and t.get_visible() and t.get_text().strip():
            seen.add(id(t))
            uniq.append((o, t))
    return uniq


def _inside(bb, fb):
    return (bb.x0 >= fb.x0 - TOL and bb.y0 >= fb.y0 - TOL and bb.x1 <= fb.x1 + TOL
            and bb.y1 <= fb.y1 + TOL)


def _overlap(a, b):
    return min(a.x1, b.x1) - max(a.x0, b.x0) > TOL and min(a.y1, b.y1) - max(a.y0, b.y0) > TOL


def _dense(xy, step=2.0):
    """Points along the polyline xy (display px), at most ``step`` apart."""
    xy = xy[np.all(np.isfinite(xy), axis=1)]
    if len(xy) < 2:
        return xy
    seg = np.diff(xy, axis=0)
    n = np.maximum(1, np.ceil(np.hypot(seg[:, 0], seg[:, 1]) / step).astype(int))
    parts = [xy[i] + np.outer(np.arange(n[i]) / n[i], seg[i]) for i in range(len(seg))]
    return np.vstack(parts + [xy[-1:]])


def _data_points(ax):
    """Display px of the axes' data inside the axes: every line (steps expanded, sampled every
    2 px; markers at the vertices) and every scatter point."""
    from matplotlib.cbook import STEP_LOOKUP_MAP
    from matplotlib.collections import PathCollection
    box = ax.get_window_extent()
    pts = []
    for line in ax.get_lines():
        xy = np.asarray(line.get_xydata(), dtype=float)
        if not line.get_visible() or len(xy) == 0:
            continue
        ds = line.get_drawstyle()
        if ds != "default" and len(xy) > 1:
            xy = np.column_stack(STEP_LOOKUP_MAP[ds](xy[:, 0], xy[:, 1]))
        disp = line.get_transform().transform(xy)
        drawn = line.get_linestyle() not in ("None", "none", "", " ")
        pts.append(_dense(disp) if drawn else disp)
    for c in ax.collections:
        if isinstance(c, PathCollection) and c.get_visible() and len(c.get_offsets()):
            pts.append(c.get_offset_transform().transform(np.asarray(c.get_offsets())))
    p = np.vstack(pts) if pts else np.empty((0, 2))
    return p[(p[:, 0] >= box.x0) & (p[:, 0] <= box.x1) & (p[:, 1] >= box.y0) & (p[:, 1] <= box.y1)]


def _has_image(ax):
    from matplotlib.collections import QuadMesh
    return bool(ax.images) or any(isinstance(c, QuadMesh) for c in ax.collections)


def layout_problems(fig):
    """What a careful reader would complain about in ``fig``, drawn, as a list of strings:

    * a text (title, label, tick label, note) or a legend reaching outside the canvas;
    * two texts overlapping (tick labels included), or a legend over a text;
    * a legend or a note inside an axes covering its lines, markers or scatter points (any part
      of an image or mesh); a figure legend over an axes;
    * an axis that draws exactly one tick label; an offset text ("1e-10+1") on an axis;
    * an axis showing tick labels without an axis label (its own or a shared partner's);
    * a colour bar without a label, or labelled "1".
    """
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    fb, bad = fig.bbox, []
    boxes = [(o, t, t.get_window_extent(r)) for o, t in _texts(fig)]
    legends = [("figure", lg) for lg in fig.legends] + [
        (f"axes {k}", ax.get_legend()) for k, ax in enumerate(fig.axes) if ax.get_legend()]
    legends = [(o, lg, lg.get_window_extent(r)) for o, lg in legends]
    for o, t, bb in boxes:
        if not _inside(bb, fb):
            bad.append(f"{o}: text {_name(t)} reaches outside the figure {bb.bounds}")
    for o, _, bb in legends:
        if not _inside(bb, fb):
            bad.append(f"{o}: the legend reaches outside the figure {bb.bounds}")
    for i, (oi, ti, bi) in enumerate(boxes):
        for oj, tj, bj in boxes[i + 1:]:
            if _overlap(bi, bj):
                bad.append(f"texts overlap: {oi} {_name(ti)} and {oj} {_name(tj)}")
    for o, _, lb in legends:
        bad += [f"{o}: the legend covers {ot} {_name(t)}" for ot, t, bb in boxes
                if _overlap(lb, bb)]
    for k, ax in enumerate(fig.axes):
        if not ax.get_visible() or _is_colorbar(ax):
            continue
        pts, abox = _data_points(ax), ax.get_window_extent(r)
        covers = [(f"axes {k}: the legend", ax.get_legend())] if ax.get_legend() else []
        covers += [(f"axes {k}: text {_name(t)}", t) for t in ax.texts
                   if t.get_visible() and t.get_text().strip()]
        for what, art in covers:
            bb = art.get_window_extent(r)
            n = int(((pts[:, 0] > bb.x0 + TOL) & (pts[:, 0] < bb.x1 - TOL)
                     & (pts[:, 1] > bb.y0 + TOL) & (pts[:, 1] < bb.y1 - TOL)).sum())
            if n:
                bad.append(f"{what} covers {n} px of data")
        if ax.get_legend() and _has_image(ax) and _overlap(
                ax.get_legend().get_window_extent(r), abox):
            bad.append(f"axes {k}: the legend covers part of an image")
        bad += [f"the figure legend overlaps axes {k}" for o, _, lb in legends
                if o == "figure" and _overlap(lb, abox)]
    for k, ax in enumerate(fig.axes):
        if not ax.get_visible():
            continue
        for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
            if _is_colorbar(ax) and axis is not ax._colorbar.long_axis:
                continue
            labels = _drawn_ticklabels(axis)
            if len(labels) == 1:
                bad.append(f"axes {k}: the {name} axis draws one tick label {_name(labels[0])}")
            if axis.offsetText.get_visible() and axis.offsetText.get_text().strip():
                bad.append(f"axes {k}: the {name} axis has an offset text "
                           f"{_name(axis.offsetText)}")
            shared = (ax.get_shared_x_axes() if name == "x" else ax.get_shared_y_axes())
            named = [a for a in shared.get_siblings(ax)
                     if (a.xaxis if name == "x" else a.yaxis).label.get_text().strip()]
            if labels and not named:
                bad.append(f"axes {k}: the {name} axis has tick labels but no label")
        if _is_colorbar(ax) and ax._colorbar.long_axis.label.get_text().strip() in ("", "1"):
            bad.append(f"axes {k}: a colour bar labelled "
                       f"{ax._colorbar.long_axis.label.get_text()!r}")
    return bad


def _check(fig, what, dpi=PNG_DPI):
    fig.set_dpi(dpi)
    problems = layout_problems(fig)
    experiment._plt().close(fig)
    assert not problems, f"{what}:\n  " + "\n  ".join(problems)


# --------------------------------------------------------------------------------------
# The checker catches each problem (so that a pass means something)
# --------------------------------------------------------------------------------------

@pytest.fixture
def plt():
    return experiment._plt()


def test_checker_sees_a_title_beyond_the_figure_and_overlapping_texts(plt):
    fig, ax = plt.subplots(figsize=(3, 3))
    ax.plot([0, 1], [0, 1])
    ax.set(xlabel="x (m)", ylabel="y (m)")
    fig.suptitle("a title much too long for a figure three inches wide, as the conditioning "
                 "map had")
    ax.set_title("an axes title", y=1.0)
    fig.text(0.5, 0.98, "a note on the title", ha="center", va="top")
    got = layout_problems(fig)
    assert any("reaches outside the figure" in p for p in got), got
    assert any("texts overlap" in p for p in got), got


def test_checker_sees_a_legend_over_a_curve_and_one_tick_label_on_a_log_axis(plt):
    fig, ax = plt.subplots(figsize=(5, 4))
    x = np.linspace(0.04, 0.3, 50)
    ax.step(x, np.linspace(0, 1, 50), where="post", label="a step curve")
    ax.axhline(0.9, label="a line across")
    ax.set_xscale("log")                                 # one decade boundary: 1e-1 only,
    ax.xaxis.set_minor_formatter(plt.NullFormatter())    # as rmse_ecdf.png had
    ax.set(xlabel="RMSE (mm)", ylabel="share")
    ax.legend(loc="upper left")
    got = layout_problems(fig)
    assert any("legend covers" in p and "px of data" in p for p in got), got
    assert any("draws one tick label" in p for p in got), got


def test_checker_sees_unlabelled_colour_bars_offsets_and_legends_on_images(plt):
    fig, ax = plt.subplots(figsize=(5, 4))
    im = ax.pcolormesh(1.0 + 1e-10 * np.random.default_rng(0).random((5, 5)))
    ax.plot([2], [2], "r*", label="best")
    ax.legend(loc="center")
    fig.colorbar(im, ax=ax, label="1")
    got = layout_problems(fig)
    assert any("colour bar labelled '1'" in p for p in got), got
    assert any("offset text" in p for p in got), got
    assert any("covers part of an image" in p for p in got), got
    assert any("has tick labels but no label" in p for p in got), got


def test_checker_sees_a_figure_legend_over_an_axes(plt):
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot([0, 1], [0, 1], label="a")
    ax.set(xlabel="x (m)", ylabel="y (m)")
    fig.legend(loc="center")
    assert any("figure legend overlaps" in p for p in layout_problems(fig))


# --------------------------------------------------------------------------------------
# Every figure pm2dof writes
# --------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def paper():
    m = pm2dof.load_model("shang2010")
    res = table3(m)
    rep = repeated_runs(m, "high", 6)
    rep.update(speed="high", apd_rmse=res["high"]["apd"].rmse)
    return m, res, rep


def test_experiment_figures(paper, plt):
    m, res, rep = paper
    names = list(m.param_names)
    for speed in res:
        _check(experiment._errors(plt, res, speed), f"errors_{speed}.png")
    _check(experiment._torques(plt, res), "torques.png")
    _check(experiment._theta(plt, res, names), "theta_hat.png")
    fig = experiment._repeated(plt, rep, names, "high")
    runs = [t.get_text() for t in _drawn_ticklabels(fig.axes[0].xaxis)]
    assert all(s.lstrip("\N{MINUS SIGN}-").isdigit() for s in runs), runs   # whole runs only
    _check(fig, "repeated_runs.png")


def test_maps_figures(coulomb_viscous_model, plt):
    """Singularity, conditioning, force and acceleration maps of every geometry of the shipped models
    (the other model files differ from these only by their friction model); a platform's at its
    home orientation, which the note names."""
    model = coulomb_viscous_model
    mp = workspace_maps(model, 41)
    assert mp["reachable"].any(), f"{model.name}: nothing reachable on the map's grid"
    note = maps.maps_note(model, phi=mp["phi"])
    if model.dof == 3:
        assert mp["phi"] == model.spec.home[2] and f"phi = {mp['phi']:g} rad" in note, note
    for name, keys in maps.FIGURES.items():
        _check(maps.maps_figure(plt, model, mp, keys, note), f"{model.name}: {name}")


def test_splits_figure(paper, plt):
    m = paper[0]
    levels = np.linspace(5.0, 8.0, 4)
    for preload in (None, 1.0):
        sw = tau_max_sweep(m, levels, "high", preload)
        _check(splits.sweep_figure(plt, m, sw, "high", preload), f"splits, preload {preload}")


@pytest.mark.parametrize("name", ["robustness", "gains", "adaptation"])
def test_study_figures(name):
    study = read_study(SHIPPED_STUDIES / f"{name}.toml", quick=True)
    parts = [run_chunk(study, i) for i in range(study.n_chunks)]
    cols = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
    s = summarise(cols, {"name": name, "complete": True, "rollouts": study.n_rollouts,
                         "grid_keys": [k for k in cols if k in GRID_KEYS]})
    makers = studies.study_figure_makers(cols, s, (2, 1.2) if name == "adaptation" else None)
    assert len(makers) >= 2, [f for f, _ in makers]
    for file, make in makers:
        _check(make(), f"study {name}: {file}")


def test_animation_frames(coulomb_viscous_model, plt):
    """First, middle and last frame of the high-speed move's GIF, for every geometry."""
    model = coulomb_viscous_model
    speed = "high" if "high" in model.spec.trajectories else next(iter(model.spec.trajectories))
    r = pm2dof.simulate(model, pm2dof.NAController(model), model_move(model, speed),
                        settle_time=0.1)
    fig, draw, n = animate.animation_figure(plt, model, r, speed, "na", 100.0, every=4)
    for j in (0, n // 2, n - 1):
        draw(j)
        fig.set_dpi(animate.DPI)
        problems = layout_problems(fig)
        assert not problems, f"{model.name}, frame {j}:\n  " + "\n  ".join(problems)
    plt.close(fig)


@pytest.mark.parametrize("name", ["pick_and_place", "curve"])
def test_planning_figures(paper, plt, name):
    """The three figures of `pm2dof plan --out` for each shipped path at 6 N m (both splits and
    the kinematic S-curve): the legends once covered base A3, the map and hundreds of pixels
    of the torque curves."""
    m = paper[0]
    path = read_path_file(name).path
    w = np.full(m.n_legs, 6.0)
    plans = {sp: pm2dof.plan_time_optimal(m, path, tau_max=w, split=sp, grid=300)
             for sp in ("min_norm", "min_max")}
    plans["kinematic"] = pm2dof.plan_kinematic(path, 0.5, 10.0, 400.0)
    _check(planning._phase(plt, name, plans), f"plan_{name}_phase.png")
    _check(planning._torques(plt, m, name, plans, w), f"plan_{name}_torques.png")
    _check(planning._map(plt, m, name, path, workspace_maps(m, 41, tau_max=w)),
           f"plan_{name}_map.png")
