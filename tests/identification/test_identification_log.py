# Identification logs: CSV/Parquet round trips bit for bit; every bad log is a LogError naming row/column.
import numpy as np
import pytest

import pm2dof
from pm2dof.identification.log import MIN_ROWS, IdentLog, LogError, log_poses, read_log, write_log
from pm2dof.identification.model_ref import model_entries
from pm2dof.identification.signals import multisine, trajectory_of


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


@pytest.fixture(scope="module")
def good(m):
    """A consistent log: angles of a smooth motion (ik), arbitrary torques, passive angles."""
    ex = trajectory_of(m, multisine(m, duration=0.4))
    q = np.array([m.ik(x) for x in ex.xd])
    rng = np.random.default_rng(0)
    return IdentLog(t=ex.t, qa=q[:, :3], tau=rng.normal(0, 2, (len(ex.t), 3)), qb=q[:, 3:],
                    meta={**model_entries(m), "sample_period": ex.period})


def _csv(tmp_path, log, edit=None):
    """Write ``log`` as CSV, optionally edit its lines (list of str), return the path."""
    p = tmp_path / "log.csv"
    write_log(p, log)
    if edit:
        lines = p.read_text().splitlines()
        edit(lines)
        p.write_text("\n".join(lines) + "\n")
    return p


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_round_trip_is_bitwise(tmp_path, good, suffix):
    p = write_log(tmp_path / f"log{suffix}", good)
    back = read_log(p)
    for name in ("t", "qa", "tau", "qb"):
        assert np.array_equal(getattr(back, name), getattr(good, name)), name
    assert back.meta == good.meta and back.n_legs == 3
    assert back.period == pytest.approx(0.002, rel=1e-9)


def test_log_poses_returns_the_geometry(m, good):
    xe, q = log_poses(m, good)
    assert np.allclose(q, np.column_stack([good.qa, good.qb]), atol=1e-12)
    assert np.allclose([m.fk(a) for a in good.qa], xe, atol=0)


def _header_index(lines):
    return next(i for i, s in enumerate(lines) if s.startswith("t,"))


def test_missing_column_is_named(tmp_path, good):
    def drop_tau2(lines):
        h = _header_index(lines)
        j = lines[h].split(",").index("tau2")
        for i in range(h, len(lines)):
            f = lines[i].split(",")
            del f[j]
            lines[i] = ",".join(f)
    with pytest.raises(LogError, match=r"tau2 is missing"):
        read_log(_csv(tmp_path, good, drop_tau2))
    with pytest.raises(LogError, match=r"missing column\(s\) tau1\.\.taun"):
        read_log(_csv(tmp_path, IdentLog(t=good.t, qa=good.qa, tau=good.tau), lambda ls: [
            ls.__setitem__(i, ",".join(ls[i].split(",")[:4])) for i in range(1, len(ls))]))


def test_nan_row_is_named(tmp_path, good):
    tau = good.tau.copy()
    tau[17, 1] = np.nan
    with pytest.raises(LogError, match=r"column tau2 is not finite at row 18 .*1 such row"):
        read_log(_csv(tmp_path, IdentLog(t=good.t, qa=good.qa, tau=tau)))


def test_every_problem_of_a_log_file_is_listed_at_once(tmp_path, good):
    """A LogError is an InputFileError like a model file's: the file, then one line per problem
    (as every input file's); before, only the first (the NaN) was named."""
    from pm2dof.core.errors import InputFileError
    t, tau = good.t.copy(), good.tau.copy()
    tau[17, 1] = np.nan
    t[30] = t[28]
    p = _csv(tmp_path, IdentLog(t=t, qa=good.qa, tau=tau))
    with pytest.raises(LogError) as info:
        read_log(p)
    err = info.value
    assert isinstance(err, InputFileError) and err.path == str(p) and len(err.problems) == 2
    assert str(err).splitlines() == [
        f"{p}: 2 problems:",
        f"  {err.problems[0].reason}", f"  {err.problems[1].reason}"]
    assert err.problems[0].reason.startswith("column tau2 is not finite at row 18 ")
    assert err.problems[1].reason.startswith("column t is not increasing at row 31 ")


def test_text_in_a_number_field_is_named(tmp_path, good):
    def spoil(lines):
        h = _header_index(lines)
        f = lines[h + 5].split(",")
        f[2] = "n/a"
        lines[h + 5] = ",".join(f)
    with pytest.raises(LogError, match=r"row 5 \(line \d+\), column qa2: 'n/a' is not a number"):
        read_log(_csv(tmp_path, good, spoil))


def test_time_going_back_is_named(tmp_path, good):
    t = good.t.copy()
    t[30] = t[28]
    with pytest.raises(LogError, match=r"column t is not increasing at row 31"):
        read_log(_csv(tmp_path, IdentLog(t=t, qa=good.qa, tau=good.tau)))


def test_irregular_time_is_named(tmp_path, good):
    t = good.t.copy()
    t[40:] += 0.002                       # a dropped sample
    with pytest.raises(LogError, match=r"column t is irregular at row 41 .*1 irregular step"):
        read_log(_csv(tmp_path, IdentLog(t=t, qa=good.qa, tau=good.tau)))
    # jitter well inside the tolerance passes (timestamps printed with 7 digits)
    read_log(_csv(tmp_path, IdentLog(t=np.round(good.t, 7), qa=good.qa, tau=good.tau)))


def test_too_short_is_refused(tmp_path, good):
    k = MIN_ROWS - 1
    with pytest.raises(LogError, match=rf"too short: {k} rows"):
        read_log(_csv(tmp_path, IdentLog(t=good.t[:k], qa=good.qa[:k], tau=good.tau[:k])))


def test_another_leg_count_is_refused(tmp_path, m, good):
    two = read_log(_csv(tmp_path, IdentLog(t=good.t, qa=good.qa[:, :2], tau=good.tau[:, :2])))
    with pytest.raises(LogError, match=r"2 legs .*'shang2010' has 3"):
        log_poses(m, two)
    with pytest.raises(LogError, match=r"tau4 is extra"):
        read_log(_csv(tmp_path, IdentLog(t=good.t, qa=good.qa, tau=good.tau), lambda ls: [
            ls.__setitem__(i, ls[i] + (",tau4" if ls[i].startswith("t,") else ",0"))
            for i in range(_header_index(ls), len(ls))]))


def test_another_model_is_refused_by_name_or_formulation(m, good):
    # another model by name
    meta = {"model": "myrobot", "model_name": "myrobot", "formulation_sha256": "ab" * 32}
    other = IdentLog(t=good.t, qa=good.qa, tau=good.tau, meta=meta)
    with pytest.raises(LogError, match=r"written for model 'myrobot' \(model myrobot, "
                                       r"formulation abababababab\), not 'shang2010' "
                                       r"\(.*shang2010.toml, formulation "):
        log_poses(m, other)
    # the same name, another formulation (e.g. a leg length changed after the log was written)
    meta = {"model": "shang2010", "model_name": "shang2010", "formulation_sha256": "ab" * 32}
    with pytest.raises(LogError, match=r"written for model 'shang2010' \(model shang2010, "
                                       r"formulation abababababab\), not 'shang2010'"):
        log_poses(m, IdentLog(t=good.t, qa=good.qa, tau=good.tau, meta=meta))
    # a log of before pm2dof 0.3 named its model by `model` alone: refused, even its own
    for meta in ({"model": "shang2010"}, {"model": "fivebar"},
                 {"model_name": "shang2010", "formulation_sha256": m.spec.formulation_sha256}):
        with pytest.raises(LogError, match=r"records its model by .* without .*: a file of "
                                           r"pm2dof before 0.3, whose format this version does "
                                           r"not read"):
            log_poses(m, IdentLog(t=good.t, qa=good.qa, tau=good.tau, meta=meta))


def test_angles_outside_the_workspace_are_named(m, good):
    qa = good.qa.copy()
    qa[12] = np.degrees(qa[12])           # a row logged in degrees: the legs cannot close
    with pytest.raises(LogError, match=r"row 13 .*do not close the loops.*angles must be in rad"):
        log_poses(m, IdentLog(t=good.t, qa=qa, tau=good.tau))


def test_a_singular_row_is_named(m, good):
    # a pose where leg 1 is almost stretched: type I measure below the 0.1 threshold
    A, L = np.asarray(m.spec.legs[0].base), m.spec.legs[0].la + m.spec.legs[0].lb
    u = np.array([0.245, 0.265]) - A
    x = A + 0.9995 * L * u / np.linalg.norm(u)
    q = m.ik(x)
    assert m.singularity_measures(q)[0] < m.singularity_threshold
    qa = good.qa.copy()
    qa[7] = q[:3]
    with pytest.raises(LogError, match=r"row 8 .*type I"):
        log_poses(m, IdentLog(t=good.t, qa=qa, tau=good.tau))


def test_an_encoder_offset_is_named(m, good):
    qa = good.qa.copy()
    qa[:, 2] += 0.01                      # encoder 3 off by 0.01 rad: 430 counts of 17 bits
    # three encoders for two degrees of freedom: detected, but not attributable to one column
    with pytest.raises(LogError, match=r"encoders qa1\.\.qa3 do not close the loops"):
        log_poses(m, IdentLog(t=good.t, qa=qa, tau=good.tau))
    qb = good.qb.copy()
    qb[:, 0] *= -1                        # passive angle with the wrong sign
    with pytest.raises(LogError, match=r"column qb1 disagrees"):
        log_poses(m, IdentLog(t=good.t, qa=good.qa, tau=good.tau, qb=qb))


def test_a_utf8_bom_is_read_as_the_same_log(tmp_path, good):
    """Excel's "CSV UTF-8" starts with a BOM: it hid the first comment line (taken as the
    header) or showed as '\\ufefft' in 'missing column(s) t'."""
    p = _csv(tmp_path, good)
    bom = tmp_path / "bom.csv"
    bom.write_bytes(b"\xef\xbb\xbf" + p.read_bytes())
    back = read_log(bom)
    assert np.array_equal(back.t, good.t) and np.array_equal(back.tau, good.tau)
    assert back.meta == read_log(p).meta


def test_a_misspelled_column_is_named(tmp_path, good):
    def rename(lines):
        h = _header_index(lines)
        lines[h] = lines[h].replace("qa2", "qa_2")
    with pytest.raises(LogError, match=r"qa2 is missing; not recognised: qa_2 \(names are "
                                       r"lower case"):
        read_log(_csv(tmp_path, good, rename))


def test_time_in_ms_is_named_against_the_sample_period(tmp_path, good):
    ms = IdentLog(t=1000 * good.t, qa=good.qa, tau=good.tau, qb=good.qb, meta=good.meta)
    with pytest.raises(LogError, match=r"column t steps 2 s \(median\) but the log's "
                                       r"sample_period is 0.002 s: t must be in s"):
        read_log(_csv(tmp_path, ms))


def test_latin1_comment_is_read_and_binary_junk_is_one_line(tmp_path, good, capsys):
    """Both were a UnicodeDecodeError traceback from read_log and identify fit."""
    p = write_log(tmp_path / "log.csv", good)
    raw = p.read_bytes()
    latin = tmp_path / "latin.csv"
    latin.write_bytes("# operator = Müller, 25 °C\n".encode("latin-1") + raw)
    back = read_log(latin)
    assert back.meta["operator"] == "Müller, 25 °C"
    assert np.array_equal(back.qa, good.qa)
    junk = tmp_path / "junk.csv"
    lines = raw.split(b"\n")
    k = next(i for i, ln in enumerate(lines) if not ln.startswith(b"#")) + 3
    lines[k] = b"\x00\xff\xfe" + lines[k]
    junk.write_bytes(b"\n".join(lines))
    with pytest.raises(LogError, match=rf"junk.csv: line {k + 1} is not text \(byte 0xff at "
                                       r"column 2 is not UTF-8\)"):
        read_log(junk)
    from pm2dof import cli
    assert cli.main(["identify", "fit", str(junk)]) != 0
    err = capsys.readouterr().err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1, err
