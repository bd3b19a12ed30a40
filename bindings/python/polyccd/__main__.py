"""python -m polyccd: forwards to the polyccd command line (polyccd.apps.cli).

Guarded, so that a process started by multiprocessing's "spawn" method (the worker
processes of polyccd.apps.distributed's embedded cluster re-import the main module) does not
run the command line again."""
import sys

from .apps.cli import main

if __name__ == "__main__":
    sys.exit(main())
