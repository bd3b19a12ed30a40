"""The layers of lib/ include only the layers before them (README, "Layout").

Order: arith -> poly -> motion -> pred -> narrow -> boxes -> bvh -> range -> scene -> step -> api, with
util (threads) below every layer that needs it. Only lib/api includes the public
header; inner layers keep their own copies of its constants (lib/api/constants.cpp).
"""
import re
from pathlib import Path

import pytest

LIB = Path(__file__).resolve().parent.parent / "lib"
ORDER = ["util", "arith", "poly", "motion", "pred", "narrow", "boxes", "bvh", "range", "scene", "step", "api"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def sources():
    return sorted(p for p in LIB.rglob("*") if p.suffix in (".h", ".cpp"))


def violations(path, text):
    """The includes of one file that break the layer order, as readable strings."""
    layer = path.relative_to(LIB).parts[0]
    rank = ORDER.index(layer)
    bad = []
    for inc in INCLUDE.findall(text):
        if inc == "polyccd.h":
            if layer != "api":
                bad.append(f"{path.relative_to(LIB)} includes the public header")
            continue
        target = inc.split("/")[0]
        if target not in ORDER:
            bad.append(f"{path.relative_to(LIB)} includes {inc}, not in a layer")
        elif ORDER.index(target) > rank:
            bad.append(f"{path.relative_to(LIB)} ({layer}) includes {inc} ({target}, a later layer)")
    return bad


def test_every_folder_is_a_layer_with_a_readme():
    folders = sorted(p.name for p in LIB.iterdir() if p.is_dir())
    assert folders == sorted(ORDER)
    for name in ORDER:
        assert (LIB / name / "README.md").is_file(), f"lib/{name} has no README.md"


def test_layers_include_only_earlier_layers():
    bad = [v for p in sources() for v in violations(p, p.read_text())]
    assert bad == []


@pytest.mark.parametrize("text,layer_file", [
    ('#include "scene/scene.h"\n', "narrow/pair_ctx.h"),
    ('#include "polyccd.h"\n', "motion/body.h"),
    ('#include "broad/narrow.h"\n', "range/range_index.cpp"),
])
def test_the_check_catches_a_violation(text, layer_file):
    assert violations(LIB / layer_file, text)


def test_no_source_file_is_over_450_lines():
    long = [f"{p.relative_to(LIB)}: {n}" for p in sources()
            if (n := len(p.read_text().splitlines())) > 450]
    assert long == []
