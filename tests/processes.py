# What a child process started by a test inherits, set as a terminal would have it.
"""``terminal_sigint``: a ``preexec_fn`` that gives the child the default SIGINT disposition.

The tests that press Ctrl-C (SIGINT) on a pm2dof command expect what a terminal gives it:
SIGINT delivered, Python's KeyboardInterrupt. A test run started in the background by a
non-interactive shell (``make test &`` in a script) has SIGINT ignored, every process below it
inherits that, and Python then installs no handler: the command would never see the Ctrl-C.
"""
import signal


def terminal_sigint():
    """Restore SIGINT's default action in the child (before exec), as a terminal leaves it."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
