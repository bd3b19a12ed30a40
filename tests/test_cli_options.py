"""The command line's options: `check --decide` prints only what decide mode computed, a
misspelt or abbreviated option is refused with the usage of its own subcommand
(docs/cli.md)."""
import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
# A unit box sliding into a wall: the first contact is at exactly t = 2/5 (its expect
# block; the README's command-line quick start).
BOX_MEETS_WALL = ROOT / "examples" / "cli" / "box_meets_wall.json"


def _times(out):
    """Every "first_contact" value of a check result, wherever it appears."""
    yield out["first_contact"]
    for f in out["features"]:
        yield f["first_contact"]
    for p in out["pairs"]:
        yield p["first_contact"]
        for f in p["features"]:
            yield f["first_contact"]


def test_decide_prints_no_time_it_did_not_compute(run_cli):
    """Decide mode answers whether anything touches, with the pair and features that
    stopped the solve; no time (the library's enclosure there may be [0, 1] with its
    midpoint 0.5, for a contact at 2/5)."""
    full = json.loads(run_cli("check", BOX_MEETS_WALL).stdout)
    assert full["first_contact"]["exact"] == "2/5" and "mode" not in full
    p = run_cli("check", "--decide", BOX_MEETS_WALL)
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["collides"] is True and out["mode"] == "decide"
    assert out["bodies"] == ["box", "wall"] and out["features"], out
    assert all(f["bodies"] == ["box", "wall"] for f in out["features"])
    assert list(_times(out)) == [None] * len(list(_times(out))), out


def test_decide_without_contact_is_null_too(tmp_path, run_cli):
    scene = json.loads(BOX_MEETS_WALL.read_text())
    # The box's centre stops at x = -2: its face at x = -3/2 stays short of the wall's -1/10.
    scene["bodies"][0]["motion"] = {"translation": [[-3, 1], [0], [0]]}
    del scene["expect"]
    (tmp_path / "s.json").write_text(json.dumps(scene))
    out = json.loads(run_cli("check", "--decide", "s.json").stdout)
    assert out["collides"] is False and out["first_contact"] is None and out["features"] == []


@pytest.mark.parametrize("command, args", [
    ("check", ["x.json", "--thread", "2"]),          # --threads abbreviated
    ("check", ["x.json", "--decid"]),
    ("check", ["x.json", "--max-sec", "1"]),
    ("index", ["x.json", "--store", "A"]),
    ("corpus", ["c", "--quite"]),
    ("queries", ["q.csv", "--jso"]),
    ("demo", ["--thread", "2"]),
])
def test_a_misspelt_option_shows_its_subcommands_usage(run_cli, command, args):
    p = run_cli(command, *args)
    assert p.returncode == 2 and p.stdout == "", p.stdout
    assert p.stderr.startswith(f"usage: polyccd {command} "), p.stderr
    bad = next(a for a in args if a.startswith("--"))
    assert f"unrecognized arguments: {bad}" in p.stderr, p.stderr


def test_a_misspelt_top_level_option_shows_the_top_level_usage(run_cli):
    p = run_cli("--versio")
    assert p.returncode == 2 and p.stderr.startswith("usage: polyccd [-h]"), p.stderr
