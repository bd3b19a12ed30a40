"""The public Python API is annotated (the package ships py.typed, PEP 561): every
parameter and return of the public functions and methods of the annotated modules has a
type, and every annotation names something that exists (so a type checker or
typing.get_type_hints can read it)."""
import inspect
import typing

import pytest

import polyccd
import polyccd.robot
from polyccd import _batch, _body, _chain, _index, _limits, _motion, _scene, _solve, _step, _types
from polyccd import robot as _robot

PUBLIC = [polyccd.solve, polyccd.solve_linear, polyccd.collides_linear, polyccd.solve_linear_many,
          polyccd.Motion, polyccd.Mesh, polyccd.Spheres, polyccd.Index, polyccd.Limits,
          polyccd.Cancel, polyccd.check_step, polyccd.collision_free_stepsize,
          polyccd.check, polyccd.Body, polyccd.Chain, polyccd.robot.Robot, polyccd.robot.load_urdf,
          polyccd.usable_threads, polyccd.kind_points]


def callables():
    for obj in PUBLIC:
        if inspect.isclass(obj):
            for name, member in vars(obj).items():
                if name == "__init__" or not name.startswith("_"):
                    fn = member.__func__ if isinstance(member, (classmethod, staticmethod)) else member
                    if inspect.isfunction(fn):
                        yield f"{obj.__name__}.{name}", fn
        else:
            yield obj.__name__, obj


@pytest.mark.parametrize("name, fn", list(callables()), ids=[n for n, _ in callables()])
def test_public_callables_are_annotated(name, fn):
    sig = inspect.signature(fn)
    missing = [p.name for p in sig.parameters.values()
               if p.name not in ("self", "cls") and p.annotation is inspect.Parameter.empty]
    assert not missing, f"{name}: unannotated {missing}"
    assert sig.return_annotation is not inspect.Signature.empty, f"{name}: no return type"


@pytest.mark.parametrize("module", [_batch, _body, _chain, _index, _limits, _motion, _scene, _solve,
                                    _step, _robot])
def test_annotations_resolve(module):
    """Every annotation evaluates in its module (names imported for type checking only
    included), as a type checker would read it."""
    ns = dict(vars(module))
    ns.update(vars(_types))
    ns.update({n: getattr(polyccd, n) for n in ("Limits", "Result", "SceneResult", "Motion",
                                                "Mesh", "Spheres", "Body", "LinearBatch", "Cancel")})
    ns.update({n: getattr(_robot, n) for n in ("Robot", "RobotResult", "PathResult")})
    for name, fn in callables():
        if fn.__module__ == module.__name__:
            typing.get_type_hints(fn, globalns=ns)


def test_py_typed_is_shipped():
    from importlib import resources
    assert resources.files("polyccd").joinpath("py.typed").is_file()
