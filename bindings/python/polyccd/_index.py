"""The on-line collision problem (docs/python.md, "On-line index").

Only conversion here: the index is built in C (pccd_index_new: the stored body's
primitives as lifted points in range trees) and queried there (pccd_index_query); the
answers are read back like a two-body scene (body 0 the indexed body, body 1 the query).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Iterable, List, Optional

from ._types import Number

if TYPE_CHECKING:
    from ._limits import Limits
    from ._scene import SceneResult
from . import _handles as handles
from . import _limits
from ._errors import InputError, check
from ._numbers import show
from ._pccd import ffi, lib
from ._scene import Body, _bodies_list, _motion_handle, _options, _read, _scratch


class Index:
    """A body on its motion, preprocessed once, then checked against query bodies."""

    __slots__ = ("body", "_handle")

    def __init__(self, body: Body, *, limits: Optional[Limits] = None) -> None:
        """limits: a polyccd.Limits for the preprocessing (None: no limits; Ctrl-C still
        ends it)."""
        if not isinstance(body, Body):
            raise InputError(f"body: expected a polyccd.Body, got {show(body)}")
        cfg = _limits.config(limits)
        handle = _limits.run(cfg, handles.new, "index", body.shape._handle,
                             _motion_handle(body.motion), cfg, via="new_cfg")
        object.__setattr__(self, "body", body)
        object.__setattr__(self, "_handle", handle)

    def __setattr__(self, name, value):
        raise AttributeError("an Index cannot be changed; make a new one")

    def __repr__(self):
        return f"Index({self.body!r})"

    def __reduce__(self):
        """Pickles as its Body (exact inputs); unpickling preprocesses the body again."""
        return Index, (self.body,)

    def query(self, body: Body, *, time_tolerance: Number = "1e-12", all_contacts: bool = False,
              threads: int = 1, broad_phase: str = "auto", want_exact: bool = True,
              limits: Optional[Limits] = None, min_distance: Optional[Number] = None
              ) -> SceneResult:
        """The SceneResult of the two bodies (indexed body, query body); the keyword
        arguments as for polyccd.check."""
        if not isinstance(body, Body):
            raise InputError(f"body: expected a polyccd.Body, got {show(body)}")
        cfg, _keep, opt = _options(time_tolerance, all_contacts, threads, broad_phase, want_exact,
                                   limits, min_distance)
        rep = _scratch.report
        check(_limits.run(cfg, lib.pccd_index_query, self._handle, body.shape._handle,
                          _motion_handle(body.motion), cfg, opt, rep))
        return _read(rep, (self.body, body))

    def query_many(self, bodies: Iterable[Body], *, time_tolerance: Number = "1e-12",
                   all_contacts: bool = False, threads: int = 1, broad_phase: str = "auto",
                   want_exact: bool = True, limits: Optional[Limits] = None,
                   min_distance: Optional[Number] = None) -> List[SceneResult]:
        """The SceneResults of every query body, in order (one C call; `threads` workers
        share the queries, each query solved on one thread)."""
        bodies = _bodies_list(bodies)
        cfg, _keep, opt = _options(time_tolerance, all_contacts, threads, broad_phase, want_exact,
                                   limits, min_distance)
        n = len(bodies)
        shapes = ffi.new("pccd_body *[]", [b.shape._handle for b in bodies] or 1)
        motions = ffi.new("pccd_motion *[]", [_motion_handle(b.motion) for b in bodies] or 1)
        reps = [handles.new("report") for _ in range(n)]
        rep_array = ffi.new("pccd_report *[]", reps or 1)
        check(_limits.run(cfg, lib.pccd_index_query_many, self._handle, shapes, motions, n, cfg,
                          opt, rep_array))
        return [_read(r, (self.body, b)) for r, b in zip(reps, bodies)]
