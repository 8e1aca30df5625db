# pm2dof export refuses what it cannot export yet (issue 26's kinds), instead of a traceback.
import pytest

import pm2dof


@pytest.mark.parametrize("name", ["rrr3_platform", "prr_point", "shang2010_vertical"])
def test_the_new_kinds_are_refused_not_exported_wrong(name, tmp_path):
    """Issue 26's platforms, prismatic legs and gravity: the API header and the reference data
    are written for RRR legs at a point in a horizontal plane, so the export refuses them
    (before: a platform crashed in the reference data with a ValueError)."""
    from pm2dof.export import export_project
    with pytest.raises(pm2dof.UnsupportedMechanismError, match="covers (RRR legs|a horizontal plane)"):
        export_project(name, tmp_path / "out")
    assert not (tmp_path / "out").exists()
