"""Shared pytest fixtures of polyccd's Python tests (keep this file small)."""
import os
import subprocess
import sys

import pytest

# The independent oracles (tests/oracle/) and the corpus generators (tests/tools/) are
# imported by plain name (`import oracle`, `import make_corpus`), as they import each
# other and as the generators run as scripts (`python tests/tools/make_corpus.py`).
_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(_HERE, "oracle"), os.path.join(_HERE, "tools")]


@pytest.fixture
def run_cli(tmp_path):
    """Runs `python -m polyccd ARGS...` in tmp_path; returns the CompletedProcess."""
    def run(*args, env=None):
        return subprocess.run([sys.executable, "-m", "polyccd", *map(str, args)],
                              cwd=tmp_path, capture_output=True, text=True, timeout=600,
                              env=None if env is None else {**os.environ, **env})
    return run
