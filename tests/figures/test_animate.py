# The move animated (issue 11, part 5): a real GIF, frames as asked, errors for bad options.
import pytest
from PIL import Image

import pm2dof
from pm2dof.cli import main
from pm2dof.figures.animate import animate_move


def test_animation_is_a_gif_with_one_frame_per_every_samples(tmp_path):
    m = pm2dof.load_model()
    path, r = animate_move(m, tmp_path / "a.gif", "low", "apd", every=25, settle_time=0.0)
    with Image.open(path) as im:
        assert im.format == "GIF"
        assert im.n_frames == -(-len(r.t) // 25)
    assert not list(tmp_path.glob(".*tmp*"))             # written atomically, nothing left


def test_bad_options_are_refused(tmp_path):
    m = pm2dof.load_model()
    with pytest.raises(ValueError, match="controller"):
        animate_move(m, tmp_path / "a.gif", controller="pid")
    with pytest.raises(ValueError, match="every"):
        animate_move(m, tmp_path / "a.gif", every=0)
    assert main(["animate", "--move", "sideways", "--out", str(tmp_path / "b.gif")]) == 2
    assert not (tmp_path / "b.gif").exists()
