# `python -m pm2dof ...` is the `pm2dof` command.
import sys

from .cli import main

sys.exit(main())
