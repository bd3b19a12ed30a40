"""The optional dependencies: a feature that needs a package the installation lacks says
which, and which extra of the package brings it (pyproject.toml [project.optional-
dependencies]), instead of a bare ModuleNotFoundError from deep inside another library."""
import importlib


def need(what, extra, *modules):
    """Imports the modules (e.g. "trimesh", "scipy") that `what` (the feature, e.g.
    "polyccd.apps.to_trimesh") needs and returns the first; ModuleNotFoundError naming
    the missing one and `pip install "polyccd[extra]"` when one is not installed (pip adds
    the extra's packages to the polyccd already installed: no package index serves
    polyccd itself)."""
    out = []
    for name in modules:
        try:
            out.append(importlib.import_module(name))
        except ImportError as e:
            raise ModuleNotFoundError(
                f"{what} needs the package {name.split('.')[0]!r}, which is not installed "
                f"({e}); install it with: pip install \"polyccd[{extra}]\" (adds the "
                f"'{extra}' extra's packages to this installed polyccd)", name=name) from None
    return out[0]
