# Studies (pm2dof/studies): study files, draws, rows against simulate(), determinism, the output
# folder, the report. The cluster tests (real scheduler and worker processes) are in
# tests/test_studies_cluster.py.
#
# Every row of a study must be the rollout simulate() gives for the same controller, plant
# truth, encoder resolution and theta_hat(0), to the last bit: both run the same generated
# closed loop on the same inputs (rollout_inputs), and accumulate_batch is accumulate per row
# (tests/test_cbind.py). So the comparisons here are exact (assert_array_equal / ==).
import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.core.paths import SHIPPED_MODELS
from pm2dof.studies import (
    SHIPPED_STUDIES,
    StudyFileError,
    StudyOutError,
    check_study,
    read_results,
    read_study,
    rollout_setup,
    run_chunk,
)
from pm2dof.studies.draws import sample_draw
from pm2dof.studies.report import columns_of, summarise
from pm2dof.studies.store import finish_out, prepare_out, write_chunk

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

ROOT = Path(__file__).resolve().parents[2]
STUDIES = SHIPPED_STUDIES
MODEL = SHIPPED_MODELS / "shang2010.toml"

BASE = f"""
[study]
name = "t"
model = "{MODEL}"
moves = ["high"]
seed = 7
draws = 3
runs = 1

[[controllers]]
name = "apd"
law = "apd"

[uncertainty]
payload_mass = {{uniform = [0.0, 0.5]}}
"""


def _write(tmp_path, text, name="s.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


def _all_rows(study):
    """Every row, chunk after chunk, in this process."""
    parts = [run_chunk(study, i) for i in range(study.n_chunks)]
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}


# --------------------------------------------------------------------------------------
# bad study files: StudyFileError naming the file, the key and the reason, before any rollout
# --------------------------------------------------------------------------------------

@pytest.mark.parametrize("edit, key, reason", [
    (("[study]", "[study]\ncolour = 1"), "study.colour", "unknown key"),
    (("[uncertainty]", "[uncertainty]\nwind = 1.0"), "uncertainty.wind", "unknown key"),
    (("law = \"apd\"", "law = \"apd\"\nKq = 3"), "controllers.Kq (entry 1)", "unknown key"),
    (("[study]", "[studdy]\nx = 1\n[study]"), "studdy", "unknown key"),
    (("draws = 3", "draws = \"3\""), "study.draws", "must be an integer"),
    (("draws = 3", "draws = 0"), "study.draws", "must be >= 1"),
    (("draws = 3", "draws = -5"), "study.draws", "must be >= 1"),
    (("runs = 1", "runs = 1.5"), "study.runs", "must be an integer"),
    (("seed = 7", "seed = true"), "study.seed", "must be an integer"),
    (("[0.0, 0.5]", "[0.5, 0.5]"), "uncertainty.payload_mass.uniform", "empty or negative range"),
    (("[0.0, 0.5]", "[0.5, 0.1]"), "uncertainty.payload_mass.uniform", "empty or negative range"),
    (("uniform = [0.0, 0.5]", "uniform = []"), "uncertainty.payload_mass.uniform", "non-empty"),
    (("uniform = [0.0, 0.5]", "normal = [0.1, 0.2]"), "uncertainty.payload_mass",
     "can draw -1.1, below the allowed >= 0"),
    (("uniform = [0.0, 0.5]", "uniform = [-0.2, 0.5]"), "uncertainty.payload_mass",
     "below the allowed"),
    (("uniform = [0.0, 0.5]", "gamma = [1, 2]"), "uncertainty.payload_mass", "unknown distribution"),
    (("payload_mass = {uniform = [0.0, 0.5]}", "inertia_error_percent = {uniform = [-100, 5]}"),
     "uncertainty.inertia_error_percent", "below the allowed > -100"),
    (("payload_mass = {uniform = [0.0, 0.5]}", "encoder_counts_per_rev = {uniform = [1, 5]}"),
     "uncertainty.encoder_counts_per_rev", "whole numbers"),
    (("law = \"apd\"", "law = \"pid\""), "controllers.law (entry 1)", "must be one of"),
    (("law = \"apd\"", "law = \"apd\"\nKp = {grid = []}"), "controllers.Kp.grid (entry 1)", "non-empty"),
    (("law = \"apd\"", "law = \"apd\"\nKp = {grid = [1.0, 1.0]}"), "controllers.Kp.grid (entry 1)",
     "distinct"),
    (("law = \"apd\"", "law = \"apd\"\nKp = -5.0"), "controllers.Kp (entry 1)", "must be > 0"),
    (("law = \"apd\"", "law = \"apd\"\nsplit = {grid = [\"min_norm\"]}"),
     "controllers.split (entry 1)", "cannot be a grid"),
    (("name = \"apd\"\nlaw", "name = \"apd\"\nlaw = \"apd\"\n[[controllers]]\nname = \"apd\"\nlaw"),
     "controllers.name (entry 2)", "used twice"),
    (("moves = [\"high\"]", "moves = []"), "study.moves", "non-empty"),
    (("moves = [\"high\"]", "moves = [{name = \"l\", start = [0.2, 0.3]}]"),
     "study.moves.j_max (entry 1)", "missing"),
    (("runs = 1", "runs = 3\n[payload_change]\nafter_run = 3\npayload_mass = 1.0"),
     "payload_change.after_run", "must be < study.runs"),
])
def test_bad_study_files_name_the_key(tmp_path, edit, key, reason):
    text = BASE.replace(*edit, 1)
    assert text != BASE, edit
    p = _write(tmp_path, text)
    with pytest.raises(StudyFileError) as exc:
        read_study(p)
    msg, problems = str(exc.value), exc.value.problems
    assert isinstance(exc.value, ValueError)
    assert msg.startswith(f"{p}: ") and f"[{key}] " in msg, msg
    assert any(pr.key == key and reason in pr.reason for pr in problems), problems


def test_a_bad_quick_value_is_named_under_quick(tmp_path):
    """[quick] overrides [study] under --quick; a bad value there was reported as
    [study.draws] (review finding), where the value is fine."""
    p = _write(tmp_path, BASE + "\n[quick]\ndraws = -1\n")
    read_study(p)                                          # without --quick: not used
    with pytest.raises(StudyFileError) as exc:
        read_study(p, quick=True)
    assert [(pr.key, pr.reason) for pr in exc.value.problems] == [("quick.draws",
                                                                   "must be >= 1, got -1")]


def test_not_toml_and_missing_file(tmp_path):
    with pytest.raises(StudyFileError, match="not valid TOML"):
        read_study(_write(tmp_path, "[study\nname="))
    with pytest.raises(StudyFileError, match="cannot read the study file"):
        read_study(tmp_path / "absent.toml")
    with pytest.raises(StudyFileError, match=r"\[study\.model\] no model file"):
        read_study(_write(tmp_path, BASE.replace(str(MODEL), "nowhere.toml")))


def test_unreachable_or_singular_moves_and_rejected_gains_are_refused_before_any_rollout(tmp_path):
    far = BASE.replace('moves = ["high"]', 'moves = ["high", {name = "far", start = [0.24, 0.27], '
                       'end = [0.9, 0.9], v_max = 0.2, a_max = 5.0, j_max = 200.0}]')
    s = read_study(_write(tmp_path, far), check=False)
    m = pm2dof.load_model(MODEL)
    with pytest.raises(StudyFileError, match=r"\[study\.moves \(entry 2, 'far'\)\] trajectory sample "
                       r"\d+ .*(singularity|reach)"):
        check_study(s, m)
    out = tmp_path / "out"
    from pm2dof.studies import run_study
    with pytest.raises(StudyFileError, match=r"\[study\.moves \(entry 2, 'far'\)\]"):
        run_study(s, out, progress=False)
    assert not out.exists()                     # refused before the folder or a cluster
    # the five-bar: a line across its parallel-singular curve
    five = SHIPPED_MODELS / "fivebar.toml"
    text = BASE.replace(str(MODEL), str(five)).replace(
        'moves = ["high"]', 'moves = [{name = "across", start = [0.4366773, 0.19502559], '
        'end = [0.274602, 0.000219374], v_max = 0.2, a_max = 5.0, j_max = 200.0}]')
    s = read_study(_write(tmp_path, text, "five.toml"), check=False)
    with pytest.raises(StudyFileError, match=r"\[study\.moves \(entry 1, 'across'\)\] trajectory sample "
                       r"\d+ .*(assembly mode|singular)"):
        check_study(s, pm2dof.load_model(five))
    bad = read_study(_write(tmp_path, BASE.replace('law = "apd"', 'law = "apd"\nsplit = "fair"'),
                            "bad.toml"), check=False)
    with pytest.raises(StudyFileError, match=r"\[controllers \(entry 1, 'apd'\)\] split must be one of"):
        check_study(bad, m)


def test_the_file_and_the_model_checks_in_one_pass(tmp_path, capsys):
    """A study file's own problems came first, and those that need the model (an unreachable
    move, a split the controller refuses) only after they were fixed: 6 problems, then 2
    more. Now one error lists them all, entries numbered from 1."""
    text = (BASE.replace("draws = 3", "draws = 0")
            .replace('moves = ["high"]', 'moves = ["high", {name = "far", start = [0.24, 0.27], '
                     'end = [0.9, 0.9], v_max = 0.2, a_max = 5.0, j_max = 200.0}]')
            .replace('law = "apd"', 'law = "apd"\nsplit = "fair"'))
    p = _write(tmp_path, text)
    with pytest.raises(StudyFileError) as exc:
        read_study(p)
    keys = [pr.key for pr in exc.value.problems]
    assert keys == ["study.draws", "controllers (entry 1, 'apd')", "study.moves (entry 2, 'far')"]
    from pm2dof import cli
    assert cli.main(["study", "run", str(p), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert f"{p}: 3 problems:" in err and not (tmp_path / "out").exists()


def test_every_problem_of_a_study_file_in_one_error(tmp_path):
    """Independent problems of [study], [uncertainty], [[controllers]] and [payload_change]:
    one StudyFileError, one line each (entries numbered from 1), also as exc.problems."""
    text = (BASE.replace("draws = 3", "draws = 0")
            .replace("[uncertainty]", "[uncertainty]\nwind = 1.0")
            .replace('law = "apd"', 'law = "apd"\nKv = -1.0\n\n[[controllers]]\nlaw = "pid"')
            + "\n[payload_change]\nafter_run = 1\n")
    p = _write(tmp_path, text)
    with pytest.raises(StudyFileError) as exc:
        read_study(p)
    expected = [
        ("study.draws", "must be >= 1, got 0"),
        ("uncertainty.wind", "unknown key; allowed here: ['encoder_counts_per_rev', 'fc_scale', "
                             "'fv_scale', 'inertia_error_percent', 'payload_mass', "
                             "'stribeck_scale']"),
        ("controllers.Kv (entry 1)", "must be > 0, got -1.0"),
        ("controllers.law (entry 2)", "must be one of ['apd', 'ctc', 'lqr', 'na'], got 'pid'"),
        ("payload_change.payload_mass", "missing (required)"),
    ]
    assert [tuple(pr) for pr in exc.value.problems] == expected
    assert str(exc.value).splitlines() == ([f"{p}: 5 problems:"]
                                           + [f"  [{k}] {r}" for k, r in expected])


@pytest.mark.parametrize("edit, key", [
    (('law = "apd"', 'law = ["apd"]'), "controllers.law (entry 1)"),
    (('moves = ["high"]', 'moves = [{name = ["l"], start = [0.2, 0.3], end = [0.25, 0.25], '
      'v_max = 0.2, a_max = 5.0, j_max = 200.0}]'), "study.moves.name (entry 1)"),
    (("draws = 3", f"draws = {10 ** 400}"), "study.draws"),
    ((f'model = "{MODEL}"', "model = 3"), "study.model"),
])
def test_wrong_types_are_study_file_errors_not_crashes(tmp_path, edit, key):
    """Values of the wrong type where a name or a number is expected (a list as the law, as a
    move's name; an integer too large for a float; a number as the model): StudyFileError, not
    TypeError or OverflowError."""
    text = BASE.replace(*edit, 1)
    assert text != BASE
    p = _write(tmp_path, text)
    with pytest.raises(StudyFileError) as exc:
        read_study(p)
    assert key in [pr.key for pr in exc.value.problems], exc.value


def test_binary_study_file(tmp_path):
    p = tmp_path / "s.toml"
    p.write_bytes(b"[study]\nname = \"\xff\xfe\"\n")
    with pytest.raises(StudyFileError, match=r"not a text \(UTF-8\) file"):
        read_study(p)


def test_check_study_lists_every_refused_variant_and_move_by_its_entry(tmp_path):
    """The second [[controllers]] entry is entry 2 even when the first expands into a grid of
    three variants (it was reported as controllers[3], the variant's index); a refused
    controller and an unreachable move are reported together."""
    text = BASE.replace('moves = ["high"]', 'moves = ["high", {name = "far", start = [0.24, 0.27], '
                        'end = [0.9, 0.9], v_max = 0.2, a_max = 5.0, j_max = 200.0}]').replace(
        'law = "apd"', 'law = "apd"\nKp = {grid = [30000.0, 35000.0, 40000.0]}\n\n'
        '[[controllers]]\nname = "na"\nlaw = "na"\nsplit = "fair"')
    s = read_study(_write(tmp_path, text), check=False)
    assert [v.name for v in s.variants] == ["apd", "apd", "apd", "na"]
    with pytest.raises(StudyFileError) as exc:
        check_study(s, pm2dof.load_model(MODEL))
    keys = [pr.key for pr in exc.value.problems]
    assert keys == ["controllers (entry 2, 'na')", "study.moves (entry 2, 'far')"], exc.value
    assert "split must be one of" in exc.value.problems[0].reason


# --------------------------------------------------------------------------------------
# draws and enumeration
# --------------------------------------------------------------------------------------

def test_enumeration_covers_every_rollout_once():
    s = read_study(STUDIES / "adaptation.toml", quick=True)
    s = dataclasses.replace(s, chunk=7 * s.runs)
    seen = []
    for i in range(s.n_chunks):
        for u in s.chunk_units(i):
            c, m, d = s.unit(u)
            seen += [s.rollout(c, m, d, r) for r in range(s.runs)]
    assert seen == list(range(s.n_rollouts))
    with pytest.raises(IndexError):
        s.chunk_units(s.n_chunks)


def test_a_draw_depends_only_on_seed_and_draw_index():
    s = read_study(STUDIES / "robustness.toml", quick=True)
    more = dataclasses.replace(s, draws=1000, chunk=13)
    for d in (0, 5, 39):
        a, b = sample_draw(s, d, 3), sample_draw(more, d, 3)
        assert a.keys() == b.keys()
        for k in a:
            np.testing.assert_array_equal(a[k], b[k])
    other = dataclasses.replace(s, seed=s.seed + 1)
    assert sample_draw(other, 0, 3)["payload_mass"] != sample_draw(s, 0, 3)["payload_mass"]
    # every sampled value lies in its distribution's support
    vals = np.array([sample_draw(s, d, 3)["payload_mass"] for d in range(200)])
    assert vals.min() >= 0.0 and vals.max() <= 1.0 and vals.std() > 0.2


# --------------------------------------------------------------------------------------
# a study row is simulate() to the last bit
# --------------------------------------------------------------------------------------

def _simulate_rows(study, c, m, d):
    """The rows of unit (c, m, d) by simulate(), carrying theta_hat like repeated_runs."""
    rows, theta = [], None
    for r in range(study.runs):
        model, ctrl, traj, truth, counts, _, cols = rollout_setup(study, c, m, d, r)
        res = pm2dof.simulate(model, ctrl, traj, truth=truth, encoder_counts_per_rev=counts,
                              theta_hat0=theta, quantise=study.quantise)
        theta = res.theta_hat[-1].copy()
        e = res.e[:res.n_move]
        rows.append((res.rmse, math.sqrt(float(np.max(np.sum(e * e, axis=1)))), res.peak_tau,
                     res.n_saturated, res.n_singular, res.n_non_finite, cols,
                     res.theta_hat[-1], pm2dof.theta_truth(model, truth)))
    return rows


@pytest.mark.parametrize("name", ["adaptation", "robustness", "model_based"])
def test_study_rows_equal_simulate_bit_for_bit(name):
    s = read_study(STUDIES / f"{name}.toml", quick=True)
    rows = _all_rows(s)
    from pm2dof.identification.base import identifiability
    N = identifiability(pm2dof.load_model(s.model_path)).null_space
    P = np.eye(N.shape[0]) - N @ N.T
    units = range(0, s.n_units, max(1, s.n_units // 9))
    for u in units:
        c, m, d = s.unit(u)
        for r, ref in enumerate(_simulate_rows(s, c, m, d)):
            i = s.rollout(c, m, d, r)
            assert rows["rollout"][i] == i
            assert (rows["controller"][i], rows["move"][i], rows["draw"][i], rows["run"][i]) == \
                (s.variants[c].name, s.moves[m][0], d, r)
            got = [rows[k][i] for k in ("rmse", "max_error", "peak_tau", "n_saturated",
                                        "n_singular", "n_non_finite")]
            assert got == list(ref[:6]), (name, u, r, got, ref[:6])
            for k, v in ref[6].items():
                assert rows[k][i] == v, (k, rows[k][i], v)
            if s.variants[c].law == "na":
                th, tt = ref[7], ref[8]
                assert rows["theta_error"][i] == np.linalg.norm(P @ (th - tt)) / \
                    np.linalg.norm(P @ tt)
            else:
                assert np.isnan(rows["theta_error"][i])
    if name == "adaptation":   # the payload change reached the plant of the later runs
        after, mass = s.payload_change
        assert np.all(rows["payload_mass"][rows["run"] >= after] == mass)
        assert np.all(rows["payload_mass"][rows["run"] < after] != mass)


def test_rows_do_not_depend_on_the_chunking():
    s = read_study(STUDIES / "gains.toml", quick=True)
    a = _all_rows(dataclasses.replace(s, chunk=5))
    b = _all_rows(dataclasses.replace(s, chunk=1000))
    assert a.keys() == b.keys()
    for k in a:
        np.testing.assert_array_equal(a[k], b[k], err_msg=k)
    assert len(a["rollout"]) == s.n_rollouts
    # the grid columns hold each variant's grid point
    for v in s.variants:
        sel = a["controller"] == v.name
        for key, val in v.grid:
            assert np.any(a[key][sel] == val)


# --------------------------------------------------------------------------------------
# the output folder
# --------------------------------------------------------------------------------------

def test_out_folder_resume_refusal_and_unwritable(tmp_path):
    s = read_study(STUDIES / "robustness.toml", quick=True)
    m = pm2dof.load_model(s.model_path)
    out = tmp_path / "out"
    assert prepare_out(out, s, m) == set()
    write_chunk(out, 2, run_chunk(s, 2), s)
    (out / "results" / ".chunk-000003.parquet.tmp123").write_bytes(b"half")  # a killed write
    assert prepare_out(out, s, m) == {2}
    assert not list((out / "results").glob(".chunk-*"))
    assert finish_out(out, s) == len(s.chunk_units(2)) * s.runs
    other = dataclasses.replace(s, seed=s.seed + 1)
    with pytest.raises(StudyOutError, match=r"holds 1 chunk\(s\) of this study .* the study's "
                                            r"seed"):
        prepare_out(out, other, m)
    blocker = tmp_path / "a_file"
    blocker.write_text("x")
    with pytest.raises(StudyOutError, match=r"--out .*a_file/sub: cannot write there"):
        prepare_out(blocker / "sub", s, m)
    with pytest.raises(StudyFileError, match="no study.json"):
        read_results(tmp_path / "empty")


def test_resume_follows_the_values_not_the_bytes_and_names_the_change(tmp_path):
    """A comment added to the model file blocked resuming, and the message called the study's
    own file 'another study'. The identity is the model file's parsed values."""
    s0 = read_study(STUDIES / "robustness.toml", quick=True)
    model_file = tmp_path / "robot.toml"
    model_file.write_text(Path(s0.model_path).read_text())
    m = pm2dof.load_model(s0.model_path)                 # (for the provenance only)
    s = dataclasses.replace(s0, model_path=str(model_file))
    assert s.identity == s0.identity                     # the same values: the same rows
    out = tmp_path / "out"
    prepare_out(out, s, m)
    write_chunk(out, 0, run_chunk(s0, 0), s)
    model_file.write_text("# operator's note: same robot\n" + model_file.read_text() + "\n# end\n")
    assert prepare_out(out, s, m) == {0}                 # resumed: the values are the same
    text = model_file.read_text()
    i = text.index("[plant]")
    j = text.index("payload_mass", i)
    k = text.index("\n", j)
    model_file.write_text(text[:j] + "payload_mass = 0.123" + text[k:])
    with pytest.raises(StudyOutError, match=r"holds 1 chunk\(s\) of this study .* other inputs: "
                                            r"the model file's values in \[plant\]\. Use"):
        prepare_out(out, s, m)
    with pytest.raises(StudyOutError, match=r"the study's seed \(\d+ then, \d+ now\)"):
        prepare_out(out, dataclasses.replace(s, seed=s.seed + 1), m)


# --------------------------------------------------------------------------------------
# the report against direct computations on the rows
# --------------------------------------------------------------------------------------

def test_report_numbers_match_direct_computation(tmp_path):
    s = read_study(STUDIES / "robustness.toml", quick=True)
    m = pm2dof.load_model(s.model_path)
    out = tmp_path / "out"
    prepare_out(out, s, m, ["pm2dof", "study", "run", "robustness"])
    for i in range(s.n_chunks):
        write_chunk(out, i, run_chunk(s, i), s)
    finish_out(out, s)
    info, table = read_results(out)
    assert info["complete"] and info["rows"] == s.n_rollouts == table.num_rows
    assert table.column("rollout").to_pylist() == list(range(s.n_rollouts))
    assert table.column("theta_error").null_count == s.n_rollouts // 3   # the APD rows
    cols = columns_of(table)
    rep = summarise(cols, {**info, "grid_keys": []})
    for r in rep["rmse"]:
        x = [row["rmse"] for row in table.to_pylist()
             if row["controller"] == r["controller"] and row["move"] == r["move"]]
        assert r["rollouts"] == len(x) and r["median"] == pytest.approx(np.median(x), rel=1e-15)
    rows = table.to_pylist()
    apd = {(x["move"], x["draw"]): x["rmse"] for x in rows if x["controller"] == "apd"}
    for r in rep["rpe"]:
        rpe = [100 * (apd[(x["move"], x["draw"])] - x["rmse"]) / apd[(x["move"], x["draw"])]
               for x in rows if x["controller"] == r["controller"] and x["move"] == r["move"]]
        assert r["pairs"] == len(rpe) == s.draws
        assert r["median"] == pytest.approx(np.median(rpe), rel=1e-12)
        assert r["share_better"] == np.mean(np.array(rpe) > 0)
    # the job of `pm2dof study report`: the same summary, written with the run's provenance
    from pm2dof.studies.jobs import run_report
    job = run_report(out)
    assert job.summary == rep and set(job.columns) == set(cols)
    assert job.provenance["command_line"] == ["pm2dof", "study", "run", "robustness"]
    assert job.provenance["model"] == m.name
    written = json.loads((out / "summary.json").read_text())
    assert written["provenance"] == job.provenance and written["rows"] == rep["rows"]


def test_study_file_doc_lists_every_law_and_its_keys():
    """docs/study-file.md listed the laws as apd/na; the parser accepts ctc and lqr too."""
    import re

    from pm2dof.studies.spec import LAWS
    doc = (Path(__file__).resolve().parents[2] / "docs" / "study-file.md").read_text()
    law_row = next(ln for ln in doc.splitlines() if ln.startswith("| `law` |"))
    assert set(re.findall(r'`"(\w+)"`', law_row)) == set(LAWS)
    for key in {k for keys in LAWS.values() for k in keys}:
        row = next(ln for ln in doc.splitlines()
                   if ln.startswith("|") and f"`{key}`" in ln.split("|")[1])
        laws = row.split("|")[3].strip()
        want = {law for law, keys in LAWS.items() if key in keys}
        assert (laws == "all") == (want == set(LAWS)), (key, laws)
        if laws != "all":
            assert {w.strip() for w in laws.split(",")} == want, (key, laws)


def test_the_study_file_pages_example_is_a_valid_study_file(tmp_path):
    """docs/study-file.md's example is read as the page shows it (it had runs = 1 with
    [payload_change] after_run = 10, which the parser refuses)."""
    import re
    doc = (Path(__file__).resolve().parents[2] / "docs" / "study-file.md").read_text()
    assert doc.count("```") % 2 == 0, "an unclosed code fence swallows the page"
    example = re.search(r"```toml\n(.*?)```", doc, re.S).group(1)
    s = read_study(_write(tmp_path, example), check=True)
    assert s.name == "robustness" and s.payload_change is not None
    assert s.runs > s.payload_change[0]


def test_a_wrong_tau_max_length_is_said_once_by_the_controller(tmp_path):
    """tau_max of 2 values on the 3-actuator robot gave NumPy's broadcast error, once per grid
    point; now the controllers' own message, once for the entry."""
    text = BASE.replace('law = "apd"', 'law = "apd"\ntau_max = [1.0, 2.0]\n'
                        'Kp = {grid = [30000.0, 35000.0, 40000.0]}')
    with pytest.raises(StudyFileError) as exc:
        read_study(_write(tmp_path, text), check=True)
    reasons = [pr.reason for pr in exc.value.problems]
    assert len(reasons) == 1, reasons
    assert reasons[0].startswith("at every grid point: tau_max must be one finite number or "
                                 "3 (one per actuator)"), reasons
