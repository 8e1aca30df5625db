# A command started by a test with SIGINT's default action, as a terminal leaves it.
"""``from_a_terminal(args)``: ``args`` run with SIGINT's default disposition.

The tests that press Ctrl-C (SIGINT) on a pm2dof command expect what a terminal gives it:
SIGINT delivered, Python's KeyboardInterrupt. A test run started in the background by a
non-interactive shell (``make test &`` in a script) has SIGINT ignored, every process below it
inherits that, and Python then installs no handler: the command would never see the Ctrl-C.
The returned command resets SIGINT and then execs ``args`` in the same process (the same pid,
so signals sent to the Popen reach the command); no ``preexec_fn``, which is unsafe in a
process with threads (a pytest-xdist worker has some).
"""
import sys

_RESET_AND_EXEC = ("import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); "
                   "os.execv(sys.argv[1], sys.argv[1:])")


def from_a_terminal(args):
    """The command list running ``args`` (``args[0]`` a path to an executable) with SIGINT's
    default action."""
    return [sys.executable, "-c", _RESET_AND_EXEC, *map(str, args)]
