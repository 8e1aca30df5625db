# The main job (`make demo`, `pm2dof demo`): the paper's experiment, its figures and results.json.
from pathlib import Path

from ..analysis.experiment import (format_sensitivity, format_table3, is_paper_robot,
                                   sensitivity, table3_json)
from ..infra.results import provenance, write_json
from .experiment import experiment_figures

__all__ = ["run_demo"]


def run_demo(model, out="out", runs=40, echo=print, progress=None):
    """Simulate the experiment of Sect. 5, print Table 3 beside the paper's and a sensitivity
    table, repeat the move ``runs`` times, and write figures and ``results.json`` to ``out``.

    Returns the dict written to ``results.json``.
    """
    m = model
    echo(f"pm2dof demo: the experiment of Shang & Cong (2010), Sect. 5, in simulation\n"
         f"model {m.name!r} from {m.spec.path}; generated C {m.library}\n")
    results, rep, paths = experiment_figures(m, out, runs, progress)
    numbers = table3_json(results)
    echo(format_table3(numbers, is_paper_robot(m)))
    sens = sensitivity(m)
    echo("\nSensitivity: the same table under other assumptions of the simulation (RMSE, m):")
    echo(format_sensitivity(sens))
    if rep is not None:
        r = rep["rmse"]
        echo(f"\nSame {rep['speed']}-speed move repeated {len(r)} times, theta_hat carried over:"
             f" NA RMSE {r[0]:.3e} m (run 1) -> {r[-1]:.3e} m (run {len(r)}); "
             f"APD {rep['apd_rmse']:.3e} m.")
    data = {"table3": numbers, "sensitivity": dict(sens), "provenance": provenance(m)}
    if rep is not None:
        data["repeated_runs"] = {"speed": rep["speed"], "rmse": rep["rmse"],
                                 "theta_hat_end": rep["theta_hat_end"][-1],
                                 "theta_truth": rep["theta_truth"], "param_names": m.param_names}
    # the redundancy (issue 11): capability maps, the torque splits, the move animated
    from .animate import animate_move
    from .maps import maps_figures
    from .splits import splits_figure
    maps, map_paths = maps_figures(m, Path(out) / "maps", progress=progress)
    w = maps["over_clear_workspace"]["force_ratio"]
    echo(f"\nCapability maps (maps/): the min-max split's force in every direction is "
         f"{w['min']:.3f}-{w['max']:.3f}x (median {w['median']:.3f}x) the minimum-norm split's "
         f"over the workspace clear of singularities.")
    paths += map_paths
    if "high" in m.spec.trajectories:
        split_path, _ = splits_figure(m, out, "high", progress=progress)
        gif, _ = animate_move(m, Path(out) / "move_high_na.gif", progress=progress)
        paths += [split_path, gif]
    data["maps"] = maps
    try:
        study = _demo_study(m, Path(out) / "study_robustness", echo, progress)
    except ModuleNotFoundError as exc:     # Dask / pyarrow: the [studies] extra
        echo(f"\nRobustness study skipped: it needs {exc.name}, which is not installed "
             f"(pip install 'pm2dof[studies]').")
        study = None
    if study is not None:
        data["study_robustness_quick"] = study[0]
        paths += study[1]
    json_path = write_json(Path(out) / "results.json", data)
    echo(f"\nfigures: {', '.join(str(p) for p in paths)}\nnumbers: {json_path}")
    return data


def _demo_study(m, out, echo, progress):
    """The robustness study at its --quick size (a local Dask cluster, a few seconds), when
    the study file's model is the demo's. Returns (RPE rows, figure paths) or None."""
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
    run_study(study, out, progress=False, echo=lambda *a: None)
    info, table = read_results(out)
    cols = columns_of(table)
    s = summarise(cols, {**info, "grid_keys": []})
    echo(f"\nRobustness study, quick size ({study.draws} random plants; the full study is "
         f"`pm2dof study run robustness --out DIR`): RPE over APD on the same "
         f"plants, median [5th, 95th percentile]:")
    for r in s["rpe"]:
        echo(f"  {r['controller']:18s} {r['move']:5s} {r['median']:5.1f} % "
             f"[{r['p05']:5.1f}, {r['p95']:5.1f}], better on {100 * r['share_better']:.0f} % of "
             f"the plants")
    return s["rpe"], study_figures(cols, s, out / "figures", info["provenance"])
