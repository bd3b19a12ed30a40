"""Safe defaults of the outputs (issue 23, item 5): pictures are written to a temporary
file and renamed, so a symlink planted at the output path keeps its target's content
(to_png followed it and overwrote the target), an existing picture is replaced whole,
and a failed write leaves nothing behind; `polyccd demo` installs nothing itself.
The embedded dask cluster's addresses are checked in tests/test_distributed.py."""
import inspect
import os
import stat

import pytest

import polyccd as P

pytest.importorskip("matplotlib")


def contact():
    a = P.Body(P.Spheres([[0, 0, 0]], [1]), name="a")
    b = P.Body(P.Spheres([[3, 0, 0]], [1]), P.Motion.linear([3, 0, 0], [0, 0, 0]), name="b")
    return P.check([a, b])


def test_a_symlinked_output_keeps_its_target(tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("keep me")
    link = tmp_path / "out.png"
    link.symlink_to(secret)
    from polyccd.apps import to_png
    written = to_png(contact(), link)
    assert secret.read_text() == "keep me"
    assert not link.is_symlink() and link.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert written == link
    assert stat.S_IMODE(os.stat(link).st_mode) == 0o644
    assert [p.name for p in tmp_path.iterdir() if p.name.endswith(".part")] == []


def test_a_failed_write_leaves_no_file(tmp_path):
    from polyccd.apps._files import replace_file
    target = tmp_path / "sub" / "x.png"
    target.parent.mkdir()
    target.write_bytes(b"old")

    def fail(f):
        f.write(b"half")
        raise RuntimeError("disk full")
    with pytest.raises(RuntimeError):
        replace_file(target, fail)
    assert target.read_bytes() == b"old" and sorted(os.listdir(target.parent)) == ["x.png"]


def test_the_demo_installs_nothing():
    from polyccd.apps import _demo_scenes
    for scene in (_demo_scenes.mechanical_scene, _demo_scenes.ligand_scene):
        assert inspect.signature(scene).parameters["install"].default is False
