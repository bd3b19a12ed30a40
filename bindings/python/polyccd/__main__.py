"""python -m polyccd: the polyccd command line."""
import sys

from .cli import main

sys.exit(main())
