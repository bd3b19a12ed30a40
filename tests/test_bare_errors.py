"""Issue 33 finding 3: arguments that raised bare Python errors (TypeError: 'int' object
is not iterable, ValueError from numpy) now raise polyccd.InputError naming the
argument. The systematic check is tests/test_arguments_*.py (hypothesis); these are
the audit's own inputs, kept as they were reported."""
import numpy as np
import pytest

import polyccd as P
from polyccd import InputError
from arm_urdf import arm_urdf

V0 = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.25, 0.25, 1]], dtype=np.float64)
V1 = V0 + np.array([0, 0, 0.5])
F = np.array([[0, 1, 2]])


@pytest.mark.parametrize("obstacles", [5, None, 2.5, object()])
def test_check_step_obstacles_that_are_not_a_sequence(obstacles):
    with pytest.raises(InputError, match=r"^obstacles: expected a sequence of \(V, faces\) or "
                                         r"\(V0, V1, faces\), got "):
        P.check_step(V0, V1, F, obstacles=obstacles)
    with pytest.raises(InputError, match=r"^obstacles: "):
        P.collision_free_stepsize(V0, V1, F, obstacles=obstacles)


def test_check_step_obstacle_that_is_not_a_pair():
    with pytest.raises(InputError, match=r"^obstacles\[0\]: expected \(V, faces\) or \(V0, V1, faces\), got int"):
        P.check_step(V0, V1, F, obstacles=[5])


ARM = arm_urdf(6, wrist=True)


@pytest.fixture(scope="module")
def robot(tmp_path_factory):
    pytest.importorskip("yourdfpy")
    from polyccd.robot import load_urdf
    path = tmp_path_factory.mktemp("arm") / "arm.urdf"
    path.write_text(ARM)
    return load_urdf(str(path))


@pytest.mark.parametrize("q, message", [
    (["a", 0, 0], r"^q0: expected real numbers \(float64 values\), got dtype <U"),
    ([1j, 0, 0], r"^q0: expected real numbers \(float64 values\), got dtype complex128"),
    ({"shoulder": 0}, r"^q0: \{'shoulder': 0\} is not a number"),
    (None, r"^q0: None is not a number"),
    ([[0, 0, 0]], r"^q0: expected 3 joint values \(shoulder, elbow, wrist\), got shape \(1, 3\)"),
    ([True, 0, 0], r"^q0\[0\]: True is not a number"),
])
def test_robot_joint_values_of_the_wrong_type(robot, q, message):
    with pytest.raises(InputError, match=message):
        robot.check(q, [0, 0, 0])
    with pytest.raises(InputError, match=message.replace("q0", "q1")):
        robot.check([0, 0, 0], q)
    with pytest.raises(InputError, match=message):
        robot.motions(q, [0, 0, 0])


@pytest.mark.parametrize("obstacles", [5, None])
def test_robot_obstacles_that_are_not_iterable(robot, obstacles):
    with pytest.raises(InputError, match=r"^obstacles: expected an iterable of polyccd\.Body, got "):
        robot.check([0, 0, 0], [0, 0, 1], obstacles)
