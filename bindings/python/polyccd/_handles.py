"""The one place that creates library handles: every pccd_<kind> handle Python holds
(query, result, motion, body, scene, report, index) comes from new(), checked, and is
released by the garbage collector with pccd_<kind>_free."""
from ._errors import check
from ._pccd import ffi, lib


def new(kind, *args, via="new"):
    """A new pccd_<kind> handle from pccd_<kind>_<via>(&out, *args) (e.g. via="copy",
    "new_mesh_s"), owned by Python: pccd_<kind>_free runs when it is collected. Raises
    the mapped exception (_errors.check) when the constructor fails."""
    out = ffi.new(f"pccd_{kind} **")
    check(getattr(lib, f"pccd_{kind}_{via}")(out, *args))
    return ffi.gc(out[0], getattr(lib, f"pccd_{kind}_free"))
