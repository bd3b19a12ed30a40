"""python -m polyccd: forwards to the polyccd command line (polyccd.apps.cli)."""
import sys

from .apps.cli import main

sys.exit(main())
