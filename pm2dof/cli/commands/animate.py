# `pm2dof animate --out F.gif`: one closed-loop move as an animation.
from ..options import POSITIVE, count, model, progress


def add_parser(sub, common):
    p = sub.add_parser("animate", parents=[common], help="animated GIF of a closed-loop move",
                       description="Simulate one move of the model file with one controller and "
                       "write an animated GIF: the legs and links to scale at the true pose, the "
                       "desired and actual paths, the same move zoomed with the error magnified "
                       "(its factor and a 0.1 mm scale bar shown), and |xd - xe| against time. "
                       "Uses matplotlib's animation with Pillow.",
                       epilog="example: pm2dof animate --move high --controller apd --out apd.gif")
    p.add_argument("--move", default="high", help="move of [trajectories] (default high)")
    p.add_argument("--controller", default="na", choices=["na", "apd"],
                   help="NA (eqs. 28-29, default) or APD (eq. 40)")
    p.add_argument("--split", choices=["min_norm", "min_max", "preload"],
                   help="torque split (default: [control].split)")
    p.add_argument("--out", default="move.gif", metavar="FILE.gif|FILE.png",
                   help="GIF to write (default move.gif), or a .png for one frame at the middle "
                   "of the move")
    p.add_argument("--magnify", type=POSITIVE, help="error magnification (default: a power of ten "
                   "that keeps the error below 0.3 of the move's length)")
    p.add_argument("--fps", type=count(1, 1000), default=20, help="GIF frames per second (default 20)")
    p.add_argument("--every", type=count(1, 100000), default=2,
                   help="2 ms samples per frame (default 2: the GIF is 12.5x slower than life)")
    return p


def run(args):
    from ...figures.animate import animate_move
    path, r = animate_move(model(args), args.out, args.move, args.controller, args.split,
                           args.magnify, args.fps, args.every, progress=progress(args),
                           command_line=args.command_line)
    print(f"wrote {path} ({r.controller}, {r.outcome_message}, RMSE {r.rmse:.4g} m, "
          f"{r.n_saturated} saturated samples)")
    return 0
