"""Progress bars for long runs (tqdm, on stderr).

A bar is shown only when asked for (enabled=True), or by default (enabled=None) when
both stdout and stderr are terminals, and never with --quiet (enabled=False) or when
tqdm is not installed: output piped to a file or another program stays exactly as it
was. The bar never writes to stdout.
"""
import sys


class _Silent:
    """The no-op bar: same calls as tqdm's, nothing shown."""

    def update(self, n=1):
        pass

    def close(self):
        pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def wanted(enabled=None):
    """Whether a bar is shown: enabled, or (None) stdout and stderr are terminals."""
    if enabled is not None:
        return bool(enabled)
    try:
        return sys.stdout.isatty() and sys.stderr.isatty()
    except (AttributeError, ValueError):  # closed or replaced streams
        return False


def bar(total, desc, unit="it", enabled=None):
    """A tqdm bar of `total` steps on stderr, or a silent one (see wanted)."""
    if not wanted(enabled):
        return _Silent()
    try:
        from tqdm import tqdm
    except ImportError:
        return _Silent()
    return tqdm(total=total, desc=desc, unit=unit, file=sys.stderr, leave=False,
                dynamic_ncols=True, mininterval=0.2)


def echo(text, file=None):
    """print(text) to file (default stdout), around any bar on screen: tqdm.write clears
    the bars, prints the line and draws them again (so a bar never shares a line)."""
    file = sys.stdout if file is None else file
    try:
        from tqdm import tqdm
    except ImportError:
        print(text, file=file, flush=True)
        return
    tqdm.write(text, file=file)
    file.flush()
