# The registry of commands: name -> module, in the order `pm2dof --help` lists them.
"""The commands of ``pm2dof``, as pip keeps its own: each command's name and the module that
holds it, ``pm2dof.cli.commands.<name>``, in the order ``pm2dof --help`` lists them. A module
has ``add_parser(sub, common)``, which adds its sub-parser (with the shared options
``common`` as a parent, where it takes a model) and returns it, and ``run(args) -> int``, which
calls its layer, prints the result and returns the exit status. A module is imported only when
its command runs, or for ``pm2dof --help``."""

__all__ = ["COMMANDS"]

#: command name -> its module
COMMANDS = {name: f"{__name__}.{name}" for name in (
    "models", "report", "demo", "table3", "simulate", "figures", "identify", "splits", "maps",
    "animate", "plan", "study", "design", "bench", "derive", "export")}
