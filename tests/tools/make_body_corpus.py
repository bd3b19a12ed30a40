"""Builds corpus/bodies/<category>/<name>.json (polyccd/1 scene cases) whose expectations
come from the independent body oracle (tests/oracle/oracle_body.py), never from polyccd.

    python tests/tools/make_body_corpus.py [--out corpus/bodies] [--check]

Every case carries the answer reasoned out by hand (`want`, derivation in the comment
next to it) and the script stops if the oracle disagrees; a few cases say "any" (the
oracle's answer is written as it is). `features` (optional in EXPECT) is written when
the oracle finds the touching feature set at t* > 0 unambiguous (one vertex-triangle,
edge-edge or ball-ball pair, or one ball touching a triangle inside its open face);
where the case lists `feat`, the oracle must find exactly that. The output is
deterministic; --check only verifies that the files on disk are what this script writes.
"""
import argparse
import json
import os
import sys
import time
from fractions import Fraction as F

TESTS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The oracles live in tests/oracle/ and import each other by plain name.
sys.path.insert(0, os.path.join(TESTS, "oracle"))
import oracle_body as OB          # noqa: E402
from oracle import decimal_str, fraction_str, time_strictly_in   # noqa: E402
# The cases, registered in CASES on import (one module per family of cases).
from body_corpus_shapes import CASES, CUBE_TRIS, Raw, padd, pmul   # noqa: E402,F401
import body_corpus_meshes          # noqa: E402,F401
import body_corpus_spheres         # noqa: E402,F401
import body_corpus_scenes          # noqa: E402,F401

SOURCE = "tests/tools/make_body_corpus.py (oracle: tests/oracle/oracle_body.py)"
ENCLOSURE = F(1, 10 ** 20)
OUT = os.path.join(TESTS, "..", "corpus", "bodies")


# ---------------------------------------------------------------- building files

def expectation(res, n_bodies):
    exp = {"collides": res.collides}
    if res.collides:
        t = res.first
        if isinstance(t, F):
            exp["first_contact"] = fraction_str(t)
        else:
            lo, hi = t.enclosure(ENCLOSURE, denominator=10 ** 22)
            exp["first_contact"] = [decimal_str(lo), decimal_str(hi)]
    if n_bodies > 2:
        exp["pairs"] = [[res.bodies[i].name, res.bodies[j].name] for (i, j) in sorted(res.pairs)]
    feats = OB.unambiguous_features(res)
    if feats:
        exp["features"] = feats
    return exp


def check_want(c, res):
    want, name = c["want"], c["category"] + "/" + c["name"]
    if want is None:
        ok = not res.collides
    elif want == "any":
        ok = True
    elif isinstance(want, tuple) and want[0] == "irr":
        _, poly, lo, hi = want
        t = res.first
        ok = res.collides and not isinstance(t, F)
        if ok:
            coeffs = [int(x) for x in t.f.coeffs()]
            ok = coeffs == list(poly) or coeffs == [-x for x in poly]
            ok = ok and time_strictly_in(t, lo, hi)
    else:
        ok = res.collides and isinstance(res.first, F) and res.first == F(want)
    if not ok:
        raise SystemExit("%s: oracle says %r, hand answer %r" % (name, res, want))
    if c["pairs"] is not None:
        got = [[res.bodies[i].name, res.bodies[j].name] for (i, j) in sorted(res.pairs)]
        if got != c["pairs"]:
            raise SystemExit("%s: oracle pairs %r, hand answer %r" % (name, got, c["pairs"]))
    if c["feat"] is not None:
        got = OB.unambiguous_features(res)
        if got != c["feat"]:
            raise SystemExit("%s: oracle features %r (touching %r), hand answer %r"
                             % (name, got, [p.touching for p in res.pair_list], c["feat"]))


def scene_doc(c):
    doc = {"format": "polyccd/1", "name": c["name"], "source": SOURCE, "bodies": c["bodies"]}
    if c["options"]:
        doc["options"] = c["options"]
    return doc


def render(doc):
    """Stable JSON text: one line per body, Raw numbers written as JSON numbers."""
    def enc(x):
        if isinstance(x, Raw):
            return str(x)
        if isinstance(x, dict):
            return "{" + ", ".join("%s: %s" % (json.dumps(k), enc(v)) for k, v in x.items()) + "}"
        if isinstance(x, list):
            return "[" + ", ".join(enc(v) for v in x) + "]"
        return json.dumps(x)
    lines = []
    for k, v in doc.items():
        if k == "bodies":
            lines.append('  "bodies": [\n%s\n  ]' % ",\n".join("    " + enc(b) for b in v))
        else:
            lines.append("  %s: %s" % (json.dumps(k), enc(v)))
    return "{\n" + ",\n".join(lines) + "\n}\n"


def build(c):
    doc = scene_doc(c)
    # the oracle reads the text it will be compared against (exact numbers as in the file)
    parsed = json.loads(render(doc), parse_float=__import__("decimal").Decimal)
    res = OB.solve_scene(parsed)
    check_want(c, res)
    doc["expect"] = expectation(res, len(c["bodies"]))
    return render(doc), res


def all_files(timings=None):
    files = {}
    for c in CASES:
        t0 = time.perf_counter()
        text, _ = build(c)
        if timings is not None:
            timings[c["category"] + "/" + c["name"]] = time.perf_counter() - t0
        rel = os.path.join(c["category"], c["name"] + ".json")
        if rel in files:
            raise SystemExit("duplicate case " + rel)
        files[rel] = text
    return files


def main():
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=OUT)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--times", action="store_true")
    args = ap.parse_args()
    timings = {}
    t0 = time.perf_counter()
    files = all_files(timings)
    total = time.perf_counter() - t0
    stale = []
    for rel, text in sorted(files.items()):
        path = os.path.join(args.out, rel)
        old = open(path).read() if os.path.exists(path) else None
        if old != text:
            stale.append(rel)
            if not args.check:
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "w") as fh:
                    fh.write(text)
    if args.times:
        for k, v in sorted(timings.items(), key=lambda kv: -kv[1]):
            print("%7.2fs  %s" % (v, k))
    print("%d cases in %.1fs, %d %s" % (len(files), total, len(stale),
                                        "differ from this script" if args.check else "written"))
    if args.check and stale:
        print("\n".join(stale))
        sys.exit(1)


if __name__ == "__main__":
    main()
