# `python -m pm2dof.cli`: the same as `pm2dof`.
import sys

from . import main

sys.exit(main())
