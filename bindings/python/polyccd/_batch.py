"""Batches of linear queries in numpy arrays (pccd_solve_linear_batch_d): one C call for
n queries, so the Python call overhead is paid once per batch, not per query."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from typing import TYPE_CHECKING, Optional

from ._types import Number

if TYPE_CHECKING:
    from ._limits import Limits
from ._arrays import linear_batch
from ._errors import InputError, check
from ._pccd import ffi, lib
from ._results import STAGES
from . import _limits
from ._solve import _NPOINTS, _cached_config, _config, kind_code

_STAGE_NAMES = np.array(["none"] + [STAGES[k] for k in sorted(STAGES)])


@dataclass(frozen=True)
class LinearBatch:
    """Answers of n linear queries, entry k answering query k exactly as solve_linear:
    collides (bool), the first contact time's enclosure lo <= t* <= hi as doubles
    rounded outward (NaN without contact; as wide as [0, 1] without want_time), exact
    (bool: t* known exactly; then lo and hi are the doubles around it) and the deciding
    stage (str)."""
    collides: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    exact: np.ndarray
    stage: np.ndarray

    def __len__(self):
        return len(self.collides)


def solve_linear_many(kind: str, t0: np.ndarray, t1: np.ndarray, *,
                      time_tolerance: Number = "1e-12", want_time: bool = True,
                      want_exact: bool = True, threads: int = 1, limits: Optional[Limits] = None,
                      min_distance: Optional[Number] = None) -> LinearBatch:
    """Every query k of t0[k], t1[k] (float64 arrays of shape (n, npoints, 3): points
    moving linearly from t0 to t1) solved in one call on `threads` workers; answers
    do not depend on the number of threads. Returns a LinearBatch of numpy arrays."""
    code = kind_code(kind)
    a0 = linear_batch(t0, "t0", _NPOINTS[kind])
    a1 = linear_batch(t1, "t1", _NPOINTS[kind])
    if a0.shape != a1.shape:
        raise InputError(f"t1: expected shape {a0.shape} like t0, got {a1.shape}")
    threads = _limits.thread_count(threads)
    _limits.warn_threads(threads)
    n = a0.shape[0]
    if limits is None:
        cfg, _keep = _cached_config(time_tolerance, want_time, want_exact, min_distance)
    else:
        cfg, _keep = _config(time_tolerance, want_time, want_exact, limits, min_distance)
    opt = ffi.new("pccd_batch_options *")
    check(lib.pccd_batch_options_init(opt))
    opt.threads = threads
    # C writes 0 or 1 into these bytes: valid numpy bools, filled in place (no copy).
    collides = np.zeros(n, dtype=bool)
    exact = np.zeros(n, dtype=bool)
    stage = np.zeros(n, dtype=np.intc)
    lo = np.empty(n, dtype=np.float64)
    hi = np.empty(n, dtype=np.float64)
    out = ffi.new("pccd_batch_out *")
    out.struct_size = ffi.sizeof("pccd_batch_out")
    out.collides = ffi.from_buffer("unsigned char[]", collides)
    out.exact = ffi.from_buffer("unsigned char[]", exact)
    out.stage = ffi.from_buffer("int[]", stage)
    out.lo = ffi.from_buffer("double[]", lo)
    out.hi = ffi.from_buffer("double[]", hi)
    check(_limits.run(cfg, lib.pccd_solve_linear_batch_d, code, n, ffi.from_buffer("double[]", a0),
                      ffi.from_buffer("double[]", a1), cfg, opt, out))
    return LinearBatch(collides, lo, hi, exact, _STAGE_NAMES[stage])
