"""File path arguments (load_urdf's path and srdf, Robot.allowed_from_srdf): a str or
an os.PathLike naming a file; anything else (an int, which os.path would take as a file
descriptor, None, bytes) is an InputError naming the argument."""
import os

from ._errors import InputError
from ._numbers import show


def file_path(value, name: str) -> str:
    """The path text of value, or InputError "name: expected a file path ..."."""
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    if not isinstance(value, str):
        raise InputError(f"{name}: expected a file path (str or os.PathLike), got {show(value)}")
    if "\0" in value:
        raise InputError(f"{name}: a file path cannot hold a NUL character")
    return value
