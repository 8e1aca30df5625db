# Ctrl-C during a long native solve (IPOPT), recorded instead of raised inside it.
"""A Ctrl-C (SIGINT) raised inside IPOPT is caught by CasADi, which prints a warning and
returns ``NonIpopt_Exception_Thrown`` as if the solve had failed. :func:`noticing_ctrl_c`
records it instead; the solve's iteration callback stops IPOPT (``User_Requested_Stop``) when
the record is not empty, and the caller raises KeyboardInterrupt itself. Used by
``pm2dof plan --smooth`` and ``pm2dof identify design``."""
import contextlib
import signal
import threading

__all__ = ["noticing_ctrl_c"]


@contextlib.contextmanager
def noticing_ctrl_c():
    """A list that records each SIGINT (Ctrl-C) during the block instead of raising
    KeyboardInterrupt; the caller stops its solver when the list is not empty and raises
    KeyboardInterrupt itself. Left alone (nothing recorded, Python's own behaviour) where
    Python does not own SIGINT: ignored, another handler installed, or not the main thread."""
    hit = []
    if (threading.current_thread() is not threading.main_thread()
            or signal.getsignal(signal.SIGINT) is not signal.default_int_handler):
        yield hit
        return
    signal.signal(signal.SIGINT, lambda signum, frame: hit.append(signum))
    try:
        yield hit
    finally:
        signal.signal(signal.SIGINT, signal.default_int_handler)
