"""polyccd: exact continuous collision detection of moving primitives.

Python bindings of libpolyccd (see docs/python.md). Every answer comes from the C
library; this package converts inputs exactly and raises clear errors. The applications
(command line, file readers, corpus runner, data loaders, rendering, dask maps, demo)
live in polyccd.apps, which `import polyccd` does not import and no module of this core
imports (tests/test_layers.py checks it).
"""
__version__ = "0.1.0"

try:
    from ._pccd import ffi as _ffi, lib as _lib
except ImportError as _e:  # pragma: no cover - depends on the build
    raise ImportError("polyccd: the C extension polyccd._pccd is missing or cannot load "
                      f"libpolyccd ({_e}); reinstall it (`pip install ./bindings/python` from a "
                      "checkout, or `make venv` at the repository root for the dev venv)") from _e


def _check_version():
    """The loaded library, the header it was built with and this package must agree."""
    loaded = _ffi.string(_lib.pccd_version()).decode()
    header = _ffi.string(_lib.PCCD_VERSION_STRING).decode()
    if not loaded == header == __version__:
        raise ImportError(f"polyccd {__version__}: the loaded libpolyccd is {loaded} and "
                          f"the extension was built with polyccd.h {header}; reinstall "
                          "(`pip install ./bindings/python`, or `make venv` in a checkout)")


_check_version()

from ._errors import Error, InputError, InternalError, LimitError  # noqa: E402
from ._results import KINDS, Answers, ContactTime, Feature, Result, answers  # noqa: E402
from ._solve import collides_linear, kind_points, solve, solve_linear  # noqa: E402
from ._batch import LinearBatch, solve_linear_many  # noqa: E402
from ._motion import Motion  # noqa: E402
from ._body import Mesh, Spheres  # noqa: E402
from ._scene import BROAD_PHASES, Body, Contact, PairResult, SceneResult  # noqa: E402
from ._scene import check_scene as check  # noqa: E402
from ._index import Index  # noqa: E402
from ._limits import Cancel, Limits, usable_threads  # noqa: E402
from ._chain import Chain  # noqa: E402
from ._contact import ContactGeometry  # noqa: E402
from ._step import StepContacts, StepResult, check_step, collision_free_stepsize  # noqa: E402

__all__ = ["__version__", "KINDS", "BROAD_PHASES", "kind_points", "usable_threads", "solve", "solve_linear", "collides_linear",
           "solve_linear_many",
           "LinearBatch", "Result", "Answers", "answers",
           "ContactTime", "Feature", "Motion", "Chain", "Mesh", "Spheres", "Body", "check",
           "Index", "Limits", "Cancel", "check_step", "collision_free_stepsize",
           "StepResult", "StepContacts",
           "SceneResult", "PairResult", "Contact", "ContactGeometry", "Error", "InputError",
           "LimitError", "InternalError"]

