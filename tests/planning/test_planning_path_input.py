# Path input from the API and from path files: typed errors that name the argument, the segment
# and the file (never a NumPy traceback, never a coerced bool); platform paths from a file.
import json
import math

import numpy as np
import pytest

import pm2dof
from pm2dof import PlanError, TaskPath
from pm2dof.cli import main
from pm2dof.core.task import orientation_length
from pm2dof.planning.pathfile import PathFileError, read_path_file

HEAD = "[kinematic]\nv_max = 0.5\na_max = 10.0\nj_max = 400.0\n"
POLY = ('[[segments]]\nkind = "polyline"\npoints = {points}\nblend_radius = 0.02\n')


def _file(tmp_path, text, name="p.toml"):
    f = tmp_path / name
    f.write_text(HEAD + text)
    return f


@pytest.fixture(scope="module")
def platform():
    return pm2dof.load_model("rrr3_platform")


# --- 1. a 2-D path on a 3-coordinate model: the dimension error, before any evaluation -------

def test_cli_refuses_a_path_of_the_wrong_dimension(capsys):
    """`plan --model rrr3_platform --path pick_and_place` ended in a ValueError of the
    generated ik's map (the kinematic S-curve's torques ran before any check)."""
    assert main(["plan", "--model", "rrr3_platform", "--path", "pick_and_place"]) == 2
    err = capsys.readouterr().err
    assert "the path has task dimension 2, model 'rrr3_platform' m = 3" in err
    assert "pick_and_place.toml" in err and "Traceback" not in err


def test_plan_paths_checks_the_dimension_first(platform):
    from pm2dof.planning.jobs import plan_paths
    item = read_path_file("pick_and_place")             # it has [kinematic]: the S-curve first
    with pytest.raises(PlanError, match=r"path file .*pick_and_place.toml: the path has task "
                                        r"dimension 2, model 'rrr3_platform' m = 3"):
        plan_paths(platform, [item], grid=100)


# --- 2, 3. malformed points and numbers: PlanError naming the argument -----------------------

@pytest.mark.parametrize("make, match", [
    (lambda: TaskPath.line([0.22, [0.29]], [0.27, 0.24]), r"p0 must be .* got \[0.22, \[0.29\]\]"
                                                          r": ragged"),
    (lambda: TaskPath.line([0.22, 0.29], [0.27, [0.24]]), r"p1 must be .*: ragged"),
    (lambda: TaskPath.arc([0.25, [0.27]], 0.02, 0.0, 1.0), r"center must be a finite point .*"
                                                           r": ragged"),
    (lambda: TaskPath.polyline([[0.2, 0.2], [0.3]], 0.0), r"polyline: points must be .*: ragged"),
    (lambda: TaskPath.polyline([[0.2, 0.2], "ab"]), r"polyline: points .*'ab' \(str\) is not"),
    (lambda: TaskPath.spline([[0.2, 0.2], [0.3], [0.3, 0.3]]), r"spline: waypoints .*: ragged"),
    (lambda: TaskPath.line([0.22 + 1j, 0.29], [0.27, 0.24]), r"p0 .*\(0.22\+1j\) \(complex\) is "
                                                             r"not a number"),
    (lambda: TaskPath.spline({"a": 1}), r"spline: waypoints must be .*, got dict \{'a': 1\}"),
    (lambda: TaskPath.spline(p for p in [[0.2, 0.2], [0.3, 0.3]]), r"waypoints .* got generator"),
    (lambda: TaskPath.line([True, 0.29], [0.27, 0.24]), r"p0 .*True \(bool\) is not a number"),
    (lambda: TaskPath.line(np.array([True, False]), [0.27, 0.24]), r"p0 .*\(ndarray\) is not a"),
    (lambda: TaskPath.polyline([[0.2, 0.2], [0.3, 0.3]], False), r"blend_radius \(m\) .*got bool"),
    (lambda: TaskPath.arc([0.25, 0.27], "0.02", 0.0, 1.0), r"radius \(m\) must be a finite "
                                                           r"number > 0, got str '0.02'"),
    (lambda: TaskPath.arc([0.25, 0.27], 0.02, True, 1.0), r"angle0 \(rad\) .* got bool True"),
    (lambda: TaskPath.line([0.2, 0.2, 0.0], [0.3, 0.2, 0.1], "0.1"), r"orientation_length .* got"
                                                                     r" str"),
    (lambda: TaskPath.line([10**400, 0.29], [0.27, 0.24]), r"p0 .*beyond float's range"),
    (lambda: TaskPath.arc([0.25, 0.27], 10**400, 0.0, 1.0), r"radius \(m\) must be a finite"),
    (lambda: TaskPath.line(np.array(0.5, dtype=object), [0.27, 0.24]), r"p0 must be a finite "
                                                                        r"point"),
    (lambda: TaskPath.arc([0.25, 0.27], 0.02, 0.0, 1.0, phi=0.1, orientation_length=0.1),
     r"phi must be \(phi0, phi1\): the orientation at the start and the end, two finite angles "
     r"in rad, got 0.1"),
])
def test_bad_points_and_numbers_are_plan_errors(make, match):
    """ValueError (ragged, from NumPy) or TypeError (complex, a dict, a generator) before; bools
    and number-strings were read as numbers."""
    with pytest.raises(PlanError, match=match):
        make()


def test_numeric_arrays_and_numpy_scalars_still_accepted():
    a = TaskPath.line(np.array([0.22, 0.29]), (np.int64(0), np.float32(0.24)))
    assert a.start.tolist() == [0.22, 0.29]
    assert TaskPath.arc([0.25, 0.27], np.float64(0.02), 0, 1).length == pytest.approx(0.02)


@pytest.mark.parametrize("segment, key, match", [
    (POLY.format(points='[[0.16, 0.22], "abc", [0.36, 0.27]]'), "points",
     "'abc' (str) is not a number"),
    (POLY.format(points="[[0.16, 0.22], [0.16], [0.36, 0.27]]"), "points", "ragged"),
    (POLY.format(points="[[true, 0.22], [0.16, 0.27], [0.36, 0.27]]"), "points",
     "True (bool) is not a number"),
    ('[[segments]]\nkind = "spline"\nwaypoints = [[0.22, 0.29], [0.25], [0.27, 0.24]]\n',
     "waypoints", "waypoints must be a list of two or more points"),
    ('[[segments]]\nkind = "arc"\ncenter = [0.25, [0.27]]\nradius = 0.02\nangle0 = 0.0\n'
     'angle1 = 1.0\n', "center", "center must be a finite point (x, y) in m"),
    ('[[segments]]\nkind = "arc"\ncenter = [0.25, 0.27]\nradius = "0.02"\nangle0 = 0.0\n'
     'angle1 = 1.0\n', "radius", "radius (m) must be a finite number > 0, got str '0.02'"),
    ('[[segments]]\nkind = "line"\nstart = [0.22, [0.29]]\nend = [0.27, 0.24]\n', "start",
     "start must be a finite point"),
])
def test_path_file_with_a_malformed_point(tmp_path, capsys, segment, key, match):
    """From a file: one PathFileError naming the file, the segment and the key (the CLI
    printed a NumPy traceback, or read `true` as 1.0)."""
    f = _file(tmp_path, segment)
    with pytest.raises(PathFileError) as exc:
        read_path_file(f)
    (problem,) = exc.value.problems
    assert problem.key == f"segments.{key} (segment 1)" and match in problem.reason
    assert main(["plan", "--path", str(f)]) == 2
    err = capsys.readouterr().err
    assert str(f) in err and match in err and "Traceback" not in err


def test_every_problem_of_a_segment_is_listed(tmp_path, capsys):
    """A misspelt key hid a negative radius: the segment stopped at its first problem (the keys
    before the values, then the constructor's first refusal). Now every key and every value,
    as model and study files; the constructor's own checks (a blend that does not fit, equal
    angles) once the segment's values are right."""
    f = _file(tmp_path, '[[segments]]\nkind = "arc"\ncenter = [0.25, 0.25]\nradius = -0.02\n'
                        'angle0 = 0.0\nangl1 = 1.0\n'
                        '[[segments]]\nkind = "polyline"\npoints = [[0.2, 0.2], [0.3, 0.2]]\n'
                        'blend_radius = -1\ncolour = 3\n'
                        '[[segments]]\nkind = "line"\nstart = [0.2, "a"]\nend = [0.3]\n'
                        '[[segments]]\nkind = "line"\nstart = [0.0, 0.0, 0.1]\n'
                        'end = [0.02, 0.0, true]\n')
    with pytest.raises(PathFileError) as exc:
        read_path_file(f, orientation_length=0.1)
    got = [(p.key, p.reason) for p in exc.value.problems]
    assert [k for k, _ in got] == [
        "segments.angl1 (segment 1)", "segments.angle1 (segment 1)",
        "segments.radius (segment 1)",
        "segments.colour (segment 2)", "segments.blend_radius (segment 2)",
        "segments.start (segment 3)", "segments.end (segment 3)",
        "segments.end (segment 4)"], got
    reasons = dict(got)
    assert reasons["segments.radius (segment 1)"] == ("radius (m) must be a finite number > 0, "
                                                      "got -0.02")
    assert "got -1" in reasons["segments.blend_radius (segment 2)"]
    assert "'a' (str) is not a number" in reasons["segments.start (segment 3)"]
    assert "got [0.3]" in reasons["segments.end (segment 3)"]
    assert "True (bool) is not a number" in reasons["segments.end (segment 4)"]
    assert main(["plan", "--model", "rrr3_platform", "--path", str(f)]) == 2
    err = capsys.readouterr().err
    assert f"{f}: 8 problems:" in err and "Traceback" not in err


# --- 4. counts numbered from 1, points rounded ------------------------------------------

@pytest.mark.parametrize("text, match", [
    (POLY.format(points="[[0.16, 0.22], [0.16, 0.27], [0.36, 0.27]]").replace("0.02", "0.5"),
     "[segments (segment 1)] polyline: blend_radius 0.5 m does not fit on line 1 (points 1 -> 2,"
     " (0.16, 0.22) m -> (0.16, 0.27) m, 0.05 m; lines and points numbered from 1)"),
    (POLY.format(points="[[0.16, 0.22], [0.16, 0.27], [0.16, 0.27], [0.36, 0.27]]"),
     "[segments (segment 1)] polyline: points 2 and 3 coincide at (0.16, 0.27) m (points "
     "numbered from 1)"),
    (POLY.format(points="[[0.16, 0.22], [0.16, 0.27], [0.36, 0.27], [0.36, 0.22]]")
     + POLY.format(points="[[0.30, 0.22], [0.36, 0.27]]"),
     "[segments (segment 2)] segment 2 starts at (0.3, 0.22) m, 0.06 m from where segment 1 "
     "ends ((0.36, 0.22) m)"),
])
def test_path_file_messages_count_from_1(tmp_path, text, match):
    """The file's segments were counted from 1, their lines, points and joins from 0, and a
    join printed 0.22000000000000003."""
    with pytest.raises(PathFileError) as exc:
        read_path_file(_file(tmp_path, text))
    assert match in str(exc.value), str(exc.value)


def test_every_gap_between_segments_is_listed(tmp_path):
    seg = '[[segments]]\nkind = "line"\nstart = [{}, 0.2]\nend = [{}, 0.2]\n'
    with pytest.raises(PathFileError) as exc:
        read_path_file(_file(tmp_path, seg.format(0.1, 0.2) + seg.format(0.25, 0.3)
                             + seg.format(0.35, 0.4)))
    assert [p.key for p in exc.value.problems] == ["segments (segment 2)", "segments (segment 3)"]


# --- 5. a point out of reach names the path file and the segment --------------------------

def test_out_of_reach_names_the_file_and_the_segment(tmp_path, capsys):
    """It printed `s = 0.26625 m, point [0.4859390359360225, 0.3027988754686843] is out of
    reach`: no file, the floats' repr."""
    f = _file(tmp_path, '[[segments]]\nkind = "line"\nstart = [0.22, 0.29]\nend = [0.27, 0.24]\n'
                        '[[segments]]\nkind = "spline"\nwaypoints = [[0.27, 0.24], [0.6, 0.3], '
                        '[0.3, 0.25]]\n')
    assert main(["plan", "--path", str(f)]) == 2
    err = capsys.readouterr().err
    assert f"(path file {f}, segment 2)" in err, err
    assert "singularity at s = " in err and "Traceback" not in err
    point = err.split("point (")[1].split(")")[0]
    assert all(len(v.split(".")[-1]) <= 6 for v in point.split(", ")), err    # 6 digits


# --- 6. (x, y, phi) path files on a platform model ---------------------------------------

PLATFORM = ('[[segments]]\nkind = "polyline"\npoints = [[0.0, 0.0, 0.0], [0.04, 0.0, 0.1], '
            '[0.04, 0.03, 0.2]]\n')


def _platform_length(ell):
    """The two lines' length in the metric ds^2 = dx^2 + dy^2 + (l dphi)^2 (docs)."""
    return math.hypot(0.04, ell * 0.1) + math.hypot(0.03, ell * 0.1)


def test_platform_path_file_plans_with_the_model_orientation_length(tmp_path, capsys, platform):
    """The CLI never passed the model's orientation_length: every (x, y, phi) file failed."""
    ell = orientation_length(platform)
    f = _file(tmp_path, PLATFORM)
    assert main(["plan", "--model", "rrr3_platform", "--path", str(f), "--grid", "200",
                 "--json"]) == 0
    row = json.loads(capsys.readouterr().out)["paths"][0]
    assert row["length_m"] == pytest.approx(_platform_length(ell), rel=1e-12)
    assert row["min_max"]["duration_s"] > 0
    over = _file(tmp_path, PLATFORM, "over.toml")                 # [path] overrides the model's
    over.write_text("[path]\norientation_length = 0.2\n" + over.read_text())
    path = read_path_file(over, orientation_length=ell).path
    assert path.length == pytest.approx(_platform_length(0.2), rel=1e-12)
    with pytest.raises(PathFileError, match=r"an orientation \(x, y, phi\) needs the "
                                            r"orientation length"):
        read_path_file(f)                                         # neither: a problem


def test_arc_with_phi_in_a_path_file(tmp_path, platform):
    """docs/using-planning.md gives arcs phi = (phi0, phi1): the file refused `phi`."""
    f = _file(tmp_path, '[[segments]]\nkind = "arc"\ncenter = [0.0, 0.0]\nradius = 0.02\n'
                        'angle0 = 0.0\nangle1 = 1.0\nphi = [0.0, 0.1]\n')
    ell = orientation_length(platform)
    path = read_path_file(f, orientation_length=ell).path
    assert path.dim == 3 and path.end[2] == pytest.approx(0.1)
    assert path.length == pytest.approx(math.hypot(0.02, ell * 0.1), rel=1e-12)
    pm2dof.check_path(platform, path)


# --- 7. plan's help ------------------------------------------------------------------

def test_plan_help_explains_the_grid_and_names_no_issue(capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "200")
    with pytest.raises(SystemExit):
        main(["plan", "--help"])
    out = capsys.readouterr().out
    assert "issue" not in out
    assert "graded" in out and "at least 2 intervals between two stops" in out
    assert "the count used is in the output" in out
