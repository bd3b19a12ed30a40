"""The on-line collision problem (bindings/python/API.md, "On-line index").

Only conversion here: the index is built in C (pccd_index_new: the stored body's
primitives as lifted points in range trees) and queried there (pccd_index_query); the
answers are read back like a two-body scene (body 0 the indexed body, body 1 the query).
"""
from ._errors import InputError
from ._numbers import show
from ._pccd import ffi, lib
from ._scene import Body, _motion_handle, _names, _new, _options, _read, _solved


class Index:
    """A body on its motion, preprocessed once, then checked against query bodies."""

    __slots__ = ("body", "_handle")

    def __init__(self, body):
        if not isinstance(body, Body):
            raise InputError(f"body: expected a polyccd.Body, got {show(body)}")
        out = ffi.new("pccd_index **")
        _solved(lib.pccd_index_new(out, body.shape._handle, _motion_handle(body.motion)))
        object.__setattr__(self, "body", body)
        object.__setattr__(self, "_handle", ffi.gc(out[0], lib.pccd_index_free))

    def __setattr__(self, name, value):
        raise AttributeError("an Index cannot be changed; make a new one")

    def __repr__(self):
        return f"Index({self.body!r})"

    def query(self, body, *, time_tolerance="1e-12", all_contacts=False, threads=1,
              broad_phase="auto", want_exact=True):
        """The SceneResult of the two bodies (indexed body, query body); the keyword
        arguments as for polyccd.check."""
        if not isinstance(body, Body):
            raise InputError(f"body: expected a polyccd.Body, got {show(body)}")
        cfg, _keep, opt = _options(time_tolerance, all_contacts, threads, broad_phase, want_exact)
        rep = _new("report")
        _solved(lib.pccd_index_query(self._handle, body.shape._handle, _motion_handle(body.motion),
                                     cfg, opt, rep))
        return _read(rep, _names([self.body, body]))
