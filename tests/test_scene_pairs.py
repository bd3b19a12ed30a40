"""The scene pair mask (pccd_scene_set_pair_check, check(..., skip_pairs=...)): with some
body pairs skipped, every broad phase gives exactly brute force's answer with the same
pairs skipped, and each remaining pair's report is the one of the full brute-force scene
(pair reports do not depend on other pairs); the skipped pairs never appear. Random
scenes of tests/test_scene_property.py with 3 to 4 bodies."""
import random

import pytest

import polyccd as P
from polyccd import InputError
from test_scene_property import random_mesh, random_motion, random_spheres, summary

SEED = 20261124


def scene(rng):
    bodies = []
    for i in range(rng.choice([3, 3, 4])):
        shape = random_mesh(rng) if rng.random() < 0.65 else random_spheres(rng)
        bodies.append(P.Body(shape, random_motion(rng), name=f"b{i}"))
    return bodies


@pytest.mark.parametrize("k", range(30))
def test_skipped_pairs_in_every_broad_phase(k):
    rng = random.Random(SEED + k)
    bodies = scene(rng)
    n = len(bodies)
    all_pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
    full = P.check(bodies, broad_phase="brute", time_tolerance="1e-9")
    # Skip some of the pairs in contact (when there are) and some others, named either way.
    touching = [p.bodies for p in full.pairs]
    skipped = set(rng.sample(touching, rng.randint(0, len(touching))))
    skipped |= set(rng.sample(all_pairs, rng.randint(0, 2)))
    given = [(j, i) if rng.random() < 0.5 else (f"b{i}", f"b{j}") for i, j in sorted(skipped)]
    brute = P.check(bodies, broad_phase="brute", time_tolerance="1e-9", skip_pairs=given)
    want_pairs = tuple(p for p in summary(full)[2] if p[0] not in skipped)
    assert summary(brute)[2] == want_pairs, (SEED, k, skipped)
    assert brute.collides == bool(want_pairs)
    for phase in ("boxes", "bvh", "range", "auto"):
        got = P.check(bodies, broad_phase=phase, time_tolerance="1e-9", skip_pairs=given)
        assert summary(got) == summary(brute), (SEED, k, phase, skipped)


def test_skip_pairs_errors():
    b = [P.Body(P.Spheres([[0, 0, 0]], [1]), name="a"), P.Body(P.Spheres([[1, 0, 0]], [1]), name="b")]
    assert P.check(b).collides and not P.check(b, skip_pairs=[("a", "b")]).collides
    with pytest.raises(InputError, match=r"^skip_pairs\[0\]\[1\]: 'c' is not the name"):
        P.check(b, skip_pairs=[("a", "c")])
    with pytest.raises(InputError, match=r"^skip_pairs\[0\]\[0\]: 2 out of range \(2 bodies\)"):
        P.check(b, skip_pairs=[(2, 0)])
    with pytest.raises(InputError, match=r"^j: 0 equals i"):
        P.check(b, skip_pairs=[(0, 0)])
    with pytest.raises(InputError, match=r"^skip_pairs\[0\]: expected a pair"):
        P.check(b, skip_pairs=[(0, 1, 2)])
