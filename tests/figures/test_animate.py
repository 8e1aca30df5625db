# The move animated: a real GIF, frames as asked, errors for bad options.
import pytest
from PIL import Image

import pm2dof
from pm2dof.cli import main
from pm2dof.figures.animate import animate_move

pytestmark = pytest.mark.slow     # draws animations: make test-slow (CI)


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


def test_frames_are_the_full_redraws_and_drawn_once(monkeypatch):
    """The GIF took 244 full redraws for 80 frames (35.8 s). The frames are now the
    background drawn once and only the moving artists per frame; each is the figure's full
    redraw to one grey level at a few antialiased text pixels."""
    import io

    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from pm2dof.control.controllers import NAController
    from pm2dof.control.simulate import simulate
    from pm2dof.control.trajectory import model_move
    from pm2dof.figures.animate import animation_figure, render_frames
    from pm2dof.figures.experiment import _plt
    m = pm2dof.load_model()
    r = simulate(m, NAController(m), model_move(m, "high"), settle_time=0.1)
    fig, draw, n = animation_figure(_plt(), m, r, "high", "na", 100.0, every=8)
    full = {}
    for j in (0, n // 2, n - 1):
        draw(j)
        buf = io.BytesIO()
        fig.savefig(buf, format="rgba", dpi=fig.dpi)
        w, h = fig.canvas.get_width_height()
        full[j] = np.frombuffer(buf.getvalue(), np.uint8).reshape(h, w, 4)[..., :3]
    draws = []
    real = FigureCanvasAgg.draw
    monkeypatch.setattr(FigureCanvasAgg, "draw", lambda self, *a: (draws.append(1),
                                                                   real(self, *a))[1])
    frames = render_frames(fig, draw, n)
    assert len(frames) == n and len(draws) == 1
    for j, want in full.items():
        d = np.abs(np.asarray(frames[j]).astype(int) - want.astype(int)).max(axis=2)
        assert d.max() <= 1 and np.count_nonzero(d) <= 4, (j, d.max(), np.count_nonzero(d))


@pytest.mark.parametrize("name", ["rrr3_platform", "prr_point"])
def test_a_png_is_one_frame_and_any_kind_animates(tmp_path, name):
    """``--out F.png`` writes the middle frame; on a platform animate_move crashed in its
    magnification (np.hypot of (x, y, phi))."""
    m = pm2dof.load_model(name)
    path, r = animate_move(m, tmp_path / "still.png", "low", "na", settle_time=0.0)
    with Image.open(path) as im:
        assert im.format == "PNG" and im.size[0] > 800
    path, r = animate_move(m, tmp_path / "a.gif", "low", "apd", every=50, settle_time=0.0)
    with Image.open(path) as im:
        assert im.format == "GIF" and im.n_frames == -(-len(r.t) // 50)
    with pytest.raises(ValueError, match=r"\.gif file .* or a \.png"):
        animate_move(m, tmp_path / "a.jpg")
