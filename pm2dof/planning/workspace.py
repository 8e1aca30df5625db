# Scratch buffers the planner's passes reuse from one solve to the next (no fresh pages per round).
"""A :class:`Workspace`: named float64 scratch arrays, grown geometrically and reused, so that
a plan's passes do not ask the allocator for fresh ~1 MB blocks every round (glibc serves
blocks that large with mmap, or trims the heap after them: each use then pays its page faults
again). Pinocchio's Model/Data split, in the small: the data a pass writes lives here, not in
the arrays the plan returns. :func:`workspace` is the calling thread's own (the C passes run
without the GIL, so threads must not share one)."""
import threading

import numpy as np

__all__ = ["Workspace", "workspace", "KEEP_MAX"]

#: the largest buffer (float64 entries, 8 MB) a workspace keeps between solves; a larger one
#: (a grid of tens of thousands of points) is allocated for the solve that needs it and dropped
KEEP_MAX = 1 << 20
_GROWTH = 1.5
_local = threading.local()


class Workspace:
    """Named scratch arrays. ``take(name, shape)`` returns an uninitialised float64 array of
    ``shape``, a view of the buffer ``name`` (grown by 1.5x when too small): valid until the
    next ``take`` of that name. The caller writes every entry it reads."""

    def __init__(self):
        self._buf = {}

    def take(self, name, shape):
        n = int(np.prod(shape))
        buf = self._buf.get(name)
        if buf is None or buf.size < n:
            size = max(n, int(_GROWTH * buf.size) if buf is not None else n)
            buf = np.empty(size)
            if size <= KEEP_MAX:
                self._buf[name] = buf
            else:
                self._buf.pop(name, None)
        return buf[:n].reshape(shape)


def workspace():
    """The calling thread's :class:`Workspace`."""
    ws = getattr(_local, "ws", None)
    if ws is None:
        ws = _local.ws = Workspace()
    return ws
