# `pm2dof models`: the shipped models, or a copy of one to start your own robot.
import pathlib
import shutil


def add_parser(sub, common):
    p = sub.add_parser("models", help="list the shipped models",
                       description="List the models that come with pm2dof: their name (for "
                       "--model NAME and load_model(NAME)), leg count and description. With "
                       "--copy NAME DIR, copy one into a folder of yours as a starting point "
                       "for your own robot.")
    p.add_argument("--copy", nargs=2, metavar=("NAME", "DIR"),
                   help="copy shipped model NAME's file into the folder DIR (created if need be; "
                   "or to DIR if it ends in .toml), then edit and `pm2dof derive` it")
    return p


def run(args):
    return _copy(args) if args.copy else _list()


def _list():
    from ...core.model_file import read_model_file
    from ...core.paths import shipped_models
    rows = []
    for name, (path, desc) in shipped_models().items():
        spec = read_model_file(path)
        rows.append((name, f"{spec.n_legs} legs", desc))
    w = max(len(r[0]) for r in rows)
    for name, legs, desc in rows:
        print(f"{name:{w}s}  {legs}  {desc}")
    print("\nLoad one with --model NAME or pm2dof.load_model(NAME). To start your own robot, "
          "copy one (pm2dof models --copy NAME DIR) and run pm2dof derive DIR/NAME.toml.")
    return 0


def _copy(args):
    from ...core.errors import ArgumentError, OutputError
    from ...core.paths import resolve_model
    src = resolve_model(args.copy[0])
    dest = pathlib.Path(args.copy[1]).expanduser()
    if dest.suffix != ".toml":      # a folder (created if need be), as in `--copy NAME ~/robots`
        dest = dest / src.name
    if dest.exists():
        raise ArgumentError(f"{dest} exists; not overwritten (choose another folder or remove it)")
    try:
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(src, dest)
    except OSError as exc:
        raise OutputError(f"cannot write {dest}: {exc.strerror or exc}") from None
    print(f"wrote {dest}. Edit it (keep or change [model].name), then: pm2dof derive {dest}")
    return 0
