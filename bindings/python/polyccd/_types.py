"""Type aliases of the public API's annotations (the package ships py.typed).

Every number polyccd takes is converted exactly: ints, Fractions, exact decimal or
fraction strings ("0.1", "-7/3"), floats and numpy numbers at their exact binary values.
"""
from fractions import Fraction
from typing import Sequence, Tuple, Union

import numpy as np

Number = Union[int, float, Fraction, str, np.integer, np.floating]
# A polynomial of t: its coefficients in ascending powers.
Coefficients = Sequence[Number]
Vector = Sequence[Number]            # (x, y, z)
Quaternion = Sequence[Number]        # (w, x, y, z), any nonzero length
# A 4x4 pose matrix (row major, last row 0 0 0 1) or a (position, quaternion) pair.
Pose = Union[np.ndarray, Sequence[Sequence[float]], Tuple[Vector, Quaternion]]
# Points as an (n, 3) array or nested sequences.
Points = Union[np.ndarray, Sequence[Vector]]
Indices = Union[np.ndarray, Sequence[Sequence[int]]]
