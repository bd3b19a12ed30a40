"""Building under the call's limits (issue 33): check_step's mesh (the C step set, the
broad phase's boxes and trees) and a Mesh (pccd_body_new_mesh_cfg_d) count work steps,
so a work limit below what building takes ends the call there, with LimitError and no
pair solved; a generous one changes nothing. Untimed: work steps depend on the inputs
only (tests/bench/bench_step_limits.py measures the time of a 1M-triangle step)."""
import numpy as np
import pytest

import polyccd as P


def grid(side):
    i, j = np.meshgrid(np.arange(side), np.arange(side), indexing="ij")
    v = np.stack([i.ravel(), j.ravel(), np.zeros(side * side)], axis=1).astype(np.float64)
    a = (i[:-1, :-1] * side + j[:-1, :-1]).ravel()
    faces = np.concatenate([np.stack([a, a + 1, a + side], 1), np.stack([a + 1, a + side + 1, a + side], 1)])
    return v, faces


def test_check_step_building_counts_work():
    v, faces = grid(120)  # 28,322 triangles
    for work in (1, 20, 40):
        with pytest.raises(P.LimitError, match=rf"^config\.max_work: the limit of {work} work steps") as e:
            P.check_step(v, v + [0, 0, 1], faces, limits=P.Limits(max_work=work))
        assert "primitive pairs solved" not in str(e.value)  # ended in the building
    # The whole call takes 355 work steps, the solve's queries 224 of them (measured by
    # bisection on 7a1e97b, where building counted none and 224 sufficed): 300 ends it.
    with pytest.raises(P.LimitError, match=r"^config\.max_work: the limit of 300 work steps"):
        P.check_step(v, v + [0, 0, 1], faces, limits=P.Limits(max_work=300))
    r = P.check_step(v, v + [0, 0, 1], faces, limits=P.Limits(max_work=355))
    assert not r.collides and r.stepsize == 1.0


def test_mesh_building_counts_work():
    v, faces = grid(60)
    with pytest.raises(P.LimitError, match=r"^config\.max_work: the limit of 1 work steps"):
        P.Mesh(v, faces, limits=P.Limits(max_work=1))
    a, b = P.Mesh(v, faces, limits=P.Limits(max_work=10 ** 6)), P.Mesh(v, faces)
    assert (a.n_edges, a.n_triangles) == (b.n_edges, b.n_triangles) == (3 * 59 * 59 + 2 * 59, 2 * 59 * 59)
    with pytest.raises(P.InputError, match=r"^limits: expected a polyccd\.Limits or None, got 5"):
        P.Mesh(v, faces, limits=5)
