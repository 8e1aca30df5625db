# Progress on long jobs: stage lines, and tqdm bars that redraw in place on a terminal only.
"""Progress reporting for the long jobs (demo, maps, splits sweep, studies, the excitation
design, the Monte Carlo, the benchmark).

A job takes ``progress``: None (silent), any callable taking a one-line message (a stage:
"simulating the low-speed move"), or a :class:`Progress`, which also draws bars for the job's
loops. Bars come from tqdm: they redraw in place on a terminal and are silent when the stream
is not a terminal (CI, logs, pipes), so a log holds the stage lines and no bar debris.
``pm2dof --quiet`` silences both.
"""
import sys

from tqdm import tqdm

__all__ = ["Progress", "bar"]


class Progress:
    """Where a job reports: stage lines (``progress(msg)``) and bars (:meth:`bar`).

    Parameters
    ----------
    stream : file, optional
        Default ``sys.stderr`` (results go to stdout).
    quiet : bool
        Neither lines nor bars.
    bars : bool, optional
        Draw bars; default: only when ``stream`` is a terminal.
    """

    def __init__(self, stream=None, quiet=False, bars=None):
        self.stream = sys.stderr if stream is None else stream
        self.quiet = quiet
        tty = getattr(self.stream, "isatty", lambda: False)()
        self.bars = (tty if bars is None else bars) and not quiet

    def __call__(self, msg):
        if not self.quiet:
            tqdm.write(f"  .. {msg}", file=self.stream)   # above any bar that is drawn

    def bar(self, total, desc, unit="step", **kw):
        """A tqdm bar of ``total`` steps (use it as a context manager and call ``update``)."""
        return tqdm(total=total, desc=f"  .. {desc}", unit=unit, file=self.stream,
                    disable=not self.bars, leave=False, dynamic_ncols=True, **kw)


def bar(progress, total, desc, unit="step", **kw):
    """The bar of ``progress`` if it is a :class:`Progress`, else a silent one (None, or a
    plain callable that takes stage lines only)."""
    if isinstance(progress, Progress):
        return progress.bar(total, desc, unit, **kw)
    return tqdm(total=total, disable=True)
