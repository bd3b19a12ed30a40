"""Optional dependencies, for applications built on polyccd (polyccd.apps is one).

``need(what, extra, *modules)`` imports the packages a feature needs and returns the
first; when one is missing it raises ModuleNotFoundError naming the package and the
extra that brings it (``pip install "polyccd[extra]"``, which adds the extra's packages to
the installed polyccd: no package index serves polyccd itself), instead of a bare ImportError
from deep inside another library. The extras are those of pyproject.toml
[project.optional-dependencies]."""
from ._extras import need

__all__ = ["need"]
