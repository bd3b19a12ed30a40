"""Shared pytest fixtures of polyccd's Python tests (keep this file small)."""
import os
import subprocess
import sys

import pytest


@pytest.fixture
def run_cli(tmp_path):
    """Runs `python -m polyccd ARGS...` in tmp_path; returns the CompletedProcess."""
    def run(*args, env=None):
        return subprocess.run([sys.executable, "-m", "polyccd", *map(str, args)],
                              cwd=tmp_path, capture_output=True, text=True, timeout=600,
                              env=None if env is None else {**os.environ, **env})
    return run
