"""Writing output files safely (issue 23): a picture is written to a temporary file in
the target's directory and renamed onto the target. The rename replaces whatever the
target path is, a symlink included, and never writes through it: a link planted at
out.png keeps its target's content (to_png used to follow it and overwrite the target),
and a reader never sees a half-written file."""
import contextlib
import os
import tempfile
from pathlib import Path


def replace_file(path, write, mode=0o644):
    """Calls write(f) with a binary file object, then renames its file onto path (made
    with its parent folders); returns path as a Path. The file gets `mode` (mkstemp
    makes it 0600)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".part")
    try:
        with os.fdopen(fd, "wb") as f:
            write(f)
        os.chmod(tmp, mode)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
    return path
