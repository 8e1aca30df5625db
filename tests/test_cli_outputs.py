# Outputs that cannot be written are refused before any work, one line, exit 2 (review findings).
import re

import pytest

import pm2dof
from pm2dof import cli
from pm2dof.analysis.splits import preload_settings
from pm2dof.infra.results import output_folder, output_path, write_atomic


@pytest.fixture
def a_file(tmp_path):
    f = tmp_path / "afile"
    f.write_text("not a folder")
    return f


@pytest.mark.parametrize("argv, match", [
    (["table3", "--save", "{dir}"], "cannot write {dir}: it is a folder"),
    (["identify", "excite", "--out", "{dir}"], "cannot write {dir}: it is a folder"),
    (["animate", "--out", "{file}/x.gif"], "cannot write {file}/x.gif: {file} is a file, not a folder"),
    (["animate", "--out", "{dir}/x.png"], "out must name a .gif file"),
    (["maps", "--out", "{file}"], "cannot write into {file}: {file} is a file, not a folder"),
    (["plan", "--out", "{file}/sub"], "cannot write into {file}/sub: {file} is a file"),
    (["splits", "--preload-sign", "1", "1"], r"preload_sign must be one finite number or 3 "
                                             r"\(one per actuator\), got \[1.0, 1.0\]"),
])
def test_cli_refuses_an_output_it_cannot_write(argv, match, tmp_path, a_file, capsys):
    fill = {"dir": str(tmp_path), "file": str(a_file)}
    rc = cli.main([a.format(**fill) for a in argv] + ["--quiet"] * (argv[0] != "identify"))
    err = capsys.readouterr().err
    assert rc == 2, err
    assert err.count("\n") == 1 and err.startswith("pm2dof: error: ")
    assert re.search(match.format(**fill), err), err


def test_write_atomic_names_what_is_in_the_way(tmp_path, a_file):
    with pytest.raises(pm2dof.OutputError, match="it is a folder"):
        write_atomic(tmp_path, b"x")
    with pytest.raises(pm2dof.OutputError, match=f"{a_file} is a file, not a folder"):
        write_atomic(a_file / "deeper" / "x.json", b"x")
    assert write_atomic(tmp_path / "new" / "x.json", b"x").read_bytes() == b"x"
    assert output_folder(tmp_path / "not" / "yet") == tmp_path / "not" / "yet"
    assert not (tmp_path / "not").exists()          # checked, not created
    assert output_path(tmp_path / "made" / "f.txt").parent.is_dir()


def test_preload_settings_broadcast_one_value_and_refuse_a_wrong_count():
    m = pm2dof.load_model()
    pre, sgn = preload_settings(m, preload=2.0, preload_sign=[1, -1, 1])
    assert pre.tolist() == [2.0, 2.0, 2.0] and sgn.tolist() == [1.0, -1.0, 1.0]
    with pytest.raises(pm2dof.ArgumentError, match="preload must be one finite number or 3"):
        preload_settings(m, preload=[1.0, 2.0])
