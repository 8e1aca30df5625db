# IPOPT's iterations in plan_smooth, watched: progress while it runs, and Ctrl-C as a stop.
"""What :func:`pm2dof.planning.smooth.plan_smooth` shows while IPOPT runs (a Ctrl-C is
recorded by :func:`pm2dof.infra.interrupt.noticing_ctrl_c`).

* :func:`iteration_watch` -- IPOPT's iteration callback: one step of a bar per iteration on a
  terminal (:class:`pm2dof.infra.progress.Progress`), else a stage line every
  :data:`LINE_EVERY` seconds (iteration count and elapsed time), so that a log shows a long
  solve alive; it stops IPOPT (``User_Requested_Stop``) at the iteration after a Ctrl-C.

CasADi is imported inside the functions: the planning layer imports it lazily.
"""
import time

from ..infra.progress import Progress

__all__ = ["iteration_watch", "LINE_EVERY"]

#: s between two stage lines of a running IPOPT when no bar is drawn
LINE_EVERY = 10.0


def iteration_watch(nx, ng, progress, stop, what, max_iter):
    """An IPOPT iteration callback (a ``casadi.Callback`` for the ``iteration_callback``
    option) for a problem of ``nx`` variables and ``ng`` constraints: reports to ``progress``
    (None: silent; a :class:`~pm2dof.infra.progress.Progress` that draws bars: a bar of
    ``max_iter`` steps named ``what``; any other callable: a stage line every LINE_EVERY s) and
    stops IPOPT once ``stop`` (a list) is not empty. Close it (``.close()``) after the solve:
    its bar, if any. ``.iterations``: the calls so far (IPOPT's iterations 0, 1, ...)."""
    import casadi as ca

    class Watch(ca.Callback):
        def __init__(self):
            ca.Callback.__init__(self)
            self.nx, self.ng, self.stop, self.iterations = nx, ng, stop, 0
            self.t0 = self.last = time.monotonic()
            draw = isinstance(progress, Progress) and progress.bars
            self.bar = progress.bar(int(max_iter), what, unit="it") if draw else None
            self.construct("plan_smooth_watch", {})

        def get_n_in(self):
            return ca.nlpsol_n_out()

        def get_n_out(self):
            return 1

        def get_name_in(self, i):
            return ca.nlpsol_out(i)

        def get_name_out(self, i):
            return "ret"

        def get_sparsity_in(self, i):
            name = ca.nlpsol_out(i)
            if name == "f":
                return ca.Sparsity.scalar()
            if name in ("x", "lam_x"):
                return ca.Sparsity.dense(self.nx)
            if name in ("g", "lam_g"):
                return ca.Sparsity.dense(self.ng)
            return ca.Sparsity(0, 0)

        def eval(self, arg):
            self.iterations += 1
            now = time.monotonic()
            if self.bar is not None:
                self.bar.update(1)
            elif progress is not None and now - self.last >= LINE_EVERY:
                self.last = now
                progress(f"{what}: iteration {self.iterations - 1}, {now - self.t0:.0f} s")
            return [1 if self.stop else 0]

        def close(self):
            if self.bar is not None:
                self.bar.close()

    return Watch()
