# The main job (`make demo`, `pm2dof demo`): the paper's experiment, its figures and results.json.
from dataclasses import dataclass
from pathlib import Path

from ..analysis.experiment import (
    format_sensitivity,
    format_table3,
    is_paper_robot,
    sensitivity,
    table3_json,
)
from ..infra.results import provenance, write_json
from .experiment import experiment_figures

__all__ = ["run_demo", "DemoResult", "demo_header", "format_demo"]


@dataclass(frozen=True)
class DemoResult:
    """What :func:`run_demo` did: ``data`` (written to ``json_path``, results.json), the
    figures ``paths``, and what :func:`format_demo` prints besides: whether the model is the
    paper's robot, the sensitivity rows, the repeated runs, the quick robustness study's size
    (``study_draws``) or the module it lacked (``study_skipped``), and the quick design study's
    front and the paper's design against it (``design``: the JSON of ``design show``, its
    ``file_design`` included; or the module it lacked, ``design_skipped``)."""
    data: dict
    paths: tuple
    json_path: object
    paper_robot: bool
    sensitivity: tuple
    repeated: object = None
    study_draws: object = None
    study_skipped: object = None
    design: object = None
    design_skipped: object = None


def demo_header(model):
    """The lines ``pm2dof demo`` prints before it starts."""
    return (f"pm2dof demo: the experiment of Shang & Cong (2010), Sect. 5, in simulation\n"
            f"model {model.name!r} from {model.spec.path}; generated C {model.library}\n")


def run_demo(model, out="out", runs=40, progress=None, command_line=None):
    """Simulate the experiment of Sect. 5 (Table 3 and a sensitivity table), repeat the move
    ``runs`` times, and write figures and ``results.json`` to ``out``, each with its
    provenance (``command_line``: the command it records, None: ``sys.argv``).

    Returns a :class:`DemoResult` (its text: :func:`format_demo`).
    """
    m = model
    results, rep, paths = experiment_figures(m, out, runs, progress, command_line)
    numbers = table3_json(results)
    sens = sensitivity(m)
    data = {"table3": numbers, "sensitivity": dict(sens), "provenance": provenance(m, command_line)}
    if rep is not None:
        data["repeated_runs"] = {"speed": rep["speed"], "rmse": rep["rmse"],
                                 "theta_hat_end": rep["theta_hat_end"][-1],
                                 "theta_truth": rep["theta_truth"], "param_names": m.param_names}
    # the redundancy: capability maps, the torque splits, the move animated
    from .animate import animate_move
    from .maps import maps_figures
    from .splits import splits_figure
    maps, map_paths = maps_figures(m, Path(out) / "maps", progress=progress,
                                   command_line=command_line)
    paths += map_paths
    if "high" in m.spec.trajectories:
        split_path, _ = splits_figure(m, out, "high", progress=progress,
                                      command_line=command_line)
        gif, _ = animate_move(m, Path(out) / "move_high_na.gif", progress=progress,
                              command_line=command_line)
        paths += [split_path, gif]
    data["maps"] = maps
    draws = skipped = None
    try:
        study = _demo_study(m, Path(out) / "study_robustness", progress, command_line)
    except ModuleNotFoundError as exc:     # Dask / pyarrow: the [studies] extra
        skipped, study = exc.name, None
    if study is not None:
        data["study_robustness_quick"] = study[0]
        paths += study[1]
        draws = study[2]
    design = design_skipped = None
    if is_paper_robot(m):
        try:
            design, design_paths = _demo_design(Path(out) / "design_paper_legs", progress,
                                                command_line)
        except ModuleNotFoundError as exc:     # pymoo, Dask, pyarrow
            design_skipped = exc.name
        else:
            data["design_paper_legs_quick"] = design
            paths += design_paths
    json_path = write_json(Path(out) / "results.json", data)
    return DemoResult(data, tuple(paths), json_path, is_paper_robot(m), tuple(sens), rep,
                      draws, skipped, design, design_skipped)


def format_demo(r):
    """A :class:`DemoResult` as ``pm2dof demo`` prints it (after :func:`demo_header`)."""
    lines = [format_table3(r.data["table3"], r.paper_robot),
             "\nSensitivity: the same table under other assumptions of the simulation (RMSE, m):",
             format_sensitivity(r.sensitivity)]
    if r.repeated is not None:
        rep, rmse = r.repeated, r.repeated["rmse"]
        lines.append(f"\nSame {rep['speed']}-speed move repeated {len(rmse)} times, theta_hat "
                     f"carried over: NA RMSE {rmse[0]:.3e} m (run 1) -> {rmse[-1]:.3e} m (run "
                     f"{len(rmse)}); APD {rep['apd_rmse']:.3e} m.")
    w = r.data["maps"]["over_clear_workspace"]["force_ratio"]
    lines.append(f"\nCapability maps (maps/): the min-max split's force in every direction is "
                 f"{w['min']:.3f}-{w['max']:.3f}x (median {w['median']:.3f}x) the minimum-norm "
                 f"split's over the workspace clear of singularities.")
    if r.study_skipped is not None:
        lines.append(f"\nRobustness study skipped: it needs {r.study_skipped}, which is not "
                     f"installed (pip install 'pm2dof[studies]').")
    elif "study_robustness_quick" in r.data:
        lines.append(f"\nRobustness study, quick size ({r.study_draws} random plants; the full "
                     f"study is `pm2dof study run robustness --out DIR`): RPE over APD on the "
                     f"same plants, median [5th, 95th percentile]:")
        for s in r.data["study_robustness_quick"]:
            lines.append(f"  {s['controller']:18s} {s['move']:5s} {s['median']:5.1f} % "
                         f"[{s['p05']:5.1f}, {s['p95']:5.1f}], better on "
                         f"{100 * s['share_better']:.0f} % of the plants")
    if r.design_skipped is not None:
        lines.append(f"\nDesign study skipped: it needs {r.design_skipped}, which is not "
                     f"installed (pip install 'pm2dof[studies]').")
    elif r.design is not None:
        fd, front = r.design["file_design"], r.design["front"]
        where = ("on the front" if fd["on_front"] else
                 f"dominated by {len(fd['dominated_by'])} of them, the best "
                 f"{100 * fd['distance']:.2f} % better in both objectives")
        lines.append(f"\nDesign study paper_legs, quick size ({r.design['designs']} designs of "
                     f"la, lb; the full "
                     f"study is `pm2dof design run paper_legs --out DIR`): {len(front)} "
                     f"designs on the front of dexterity and the high move's duration; the "
                     f"paper's la = lb = 0.244 m is {where}.")
    lines.append(f"\nfigures: {', '.join(str(p) for p in r.paths)}\nnumbers: {r.json_path}")
    return "\n".join(lines)


def _demo_design(out, progress, command_line):
    """The design study paper_legs at its --quick size, evaluated on an embedded Dask cluster
    of one worker process (a few seconds, mostly its start); its front figures. Returns (the
    JSON of ``design show`` with the count of designs, figure paths)."""
    import shutil

    from ..core.model import load_model
    from ..synthesis.front import read_front
    from ..synthesis.runner import run_design
    from ..synthesis.spec import read_design_study, with_overrides
    from .design import design_figures
    study = with_overrides(read_design_study("paper_legs"), quick=True)
    shutil.rmtree(out, ignore_errors=True)      # the demo's own folder: always a fresh run
    if progress:
        progress(f"design study {study.name!r} --quick: {study.optimizer['population']} x "
                 f"{study.optimizer['generations']} designs of la, lb")
    run_design(study, out, workers=1, progress=False, command_line=command_line)
    fr = read_front(out)
    paths = design_figures(fr, load_model(study.model_path), Path(out) / "figures",
                           fr.info.get("provenance"))
    return {"designs": int(fr.searched.sum()), **fr.payload()}, paths


def _demo_study(m, out, progress, command_line):
    """The robustness study at its --quick size (a local Dask cluster, a few seconds), when
    the study file's model is the demo's. Returns (RPE rows, figure paths, random plants) or
    None."""
    import shutil

    from ..studies import read_study, resolve_study, run_study
    from ..studies.report import columns_of, summarise
    from ..studies.store import read_results
    from .studies import study_figures
    study = read_study(resolve_study("robustness"), quick=True)
    if Path(study.model_path) != Path(m.spec.path).resolve():
        return None
    shutil.rmtree(out, ignore_errors=True)      # the demo's own folder: always a fresh run
    if progress:
        progress(f"study {study.name!r} --quick: {study.n_rollouts} rollouts on a local Dask "
                 f"cluster")
    run_study(study, out, progress=False, command_line=command_line)
    info, table = read_results(out)
    cols = columns_of(table)
    s = summarise(cols, {**info, "grid_keys": []})
    return s["rpe"], study_figures(cols, s, out / "figures", info["provenance"]), study.draws
