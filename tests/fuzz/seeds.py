"""Seed corpora of the fuzzers, written from corpus/ and the shared query set.

The C harnesses read a byte format (tests/fuzz/fuzz_input.h and the comment at the top
of each harness); this script encodes the repository's cases in it: every query case of
corpus/ for fuzz_query (polynomial trajectories as exact strings), a sample of the
shared CSV queries for fuzz_query (linear, as doubles), every scene of corpus/bodies for
fuzz_scene, each of its bodies for fuzz_body and each of its motions for fuzz_motion;
every number text of corpus/ and a few at the parser's limits for fuzz_numbers.
Cases beyond a harness's cost limits (degree, element counts) are left out. The Python
harness (fuzz_readers.py) gets the case files themselves and slices of the CSV files.

    python tests/fuzz/seeds.py OUT_DIR [--queries DIR]

writes OUT_DIR/<harness>/<name> files and prints how many per harness.
"""
import argparse
import csv
import json
import os
import struct
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
KINDS = ["vertex-face", "edge-edge", "vertex-edge", "vertex-vertex", "sphere-sphere"]
NPOINTS = {"vertex-face": 4, "edge-edge": 4, "vertex-edge": 3, "vertex-vertex": 2,
           "sphere-sphere": 2}
# The harnesses' limits (the #defines of the same names in fuzz_query.c, fuzz_scene.c).
QUERY_MAX_DEGREE = 4
SCENE_MAX_ELEMENTS, SCENE_MAX_BALLS = 12, 6
SCENE_MAX_TRANSLATION, SCENE_MAX_ROTATION = 5, 2
CSV_SEEDS_PER_FILE = 40


def number(x):
    """fuzz_input.h's number: a small integer (tag 0), a double (tag 1) or a text (tag 2)."""
    if isinstance(x, bool):
        raise ValueError("not a number")
    if isinstance(x, int) and -128 <= x <= 127:
        return b"\x00" + struct.pack("<b", x)
    if isinstance(x, float):
        return b"\x01" + struct.pack("<d", x)
    text = str(x).encode()
    if len(text) > 255:
        raise ValueError("text too long")
    return b"\x02" + bytes([len(text)]) + text


def numbers(xs):
    return b"".join(number(x) for x in xs)


def load(path):
    # numbers stay texts (exact), integers become ints
    return json.loads(Path(path).read_text(), parse_float=str)


def query_seed(doc, cross_check):
    """fuzz_query variant 0 (polynomial trajectories through _s), or None beyond limits."""
    kind = doc["kind"]
    head = 16 if cross_check else 0
    out = bytearray([head, KINDS.index(kind)])
    tol = doc.get("options", {}).get("time_tolerance")
    out.append(32 if tol is not None else 0)
    if tol is not None:
        out += number(tol)
    for traj in doc["points"]:
        for coeffs in traj:
            if len(coeffs) > QUERY_MAX_DEGREE + 1:
                return None
            out.append(0x80 | len(coeffs))
            out += numbers(coeffs)
    if kind == "sphere-sphere":
        out.append(3)
        out += numbers(doc["radii"])
    return bytes(out)


def csv_seeds(path, kind):
    """fuzz_query variant 1 (linear, doubles) for a sample of the queries of a CSV file."""
    rows = list(csv.reader(open(path, newline="")))
    n = len(rows) // 8
    step = max(1, n // CSV_SEEDS_PER_FILE)
    for q in range(0, n, step):
        pts = [[int(r[2 * a]) / int(r[2 * a + 1]) for a in range(3)] for r in rows[8 * q:8 * q + 8]]
        head = 4 | (16 if q % 2 == 0 else 0)  # variant 1; half with the cross-checks
        cfg = 0 if q % 3 else 2  # a third decide-only (want_time 0)
        out = bytes([head, KINDS.index(kind), cfg])
        out += b"".join(number(float(c)) for p in pts for c in p)
        yield q, out


def body_parts(b):
    """(fuzz_body seed, fuzz_scene body bytes or None) of a scene body."""
    if "mesh" in b:
        verts, tris = b["mesh"]["vertices"], b["mesh"]["triangles"]
        coords = numbers(c for v in verts for c in v)
        idx = bytes(i for t in tris for i in t)
        body = bytes([4, len(verts), len(tris)]) + coords + idx  # mesh_s
        fits = len(verts) <= SCENE_MAX_ELEMENTS and len(tris) <= SCENE_MAX_ELEMENTS
        scene = bytes([0, len(verts), len(tris)]) + coords + idx if fits else None
    else:
        centers, radii = b["spheres"]["centers"], b["spheres"]["radii"]
        nums = numbers(c for v in centers for c in v) + numbers(radii)
        body = bytes([12, len(radii), 0]) + nums  # spheres_s
        scene = bytes([2, len(radii)]) + nums if len(radii) <= SCENE_MAX_BALLS else None
    return body, scene


def motion_parts(mo):
    """(fuzz_motion seed, fuzz_scene motion bytes or None) of a scene motion (or None)."""
    if mo is None:
        return None, b"\x00"
    tr = mo.get("translation", [[0], [0], [0]])
    rot = mo.get("rotation", [[1], [0], [0], [0]])
    ops = bytearray([4])  # head: round-to-nearest, failed setters checked
    for axis, cs in enumerate(tr):
        ops += bytes([0x41, axis, len(cs)]) + numbers(cs)  # set_translation_s, raw n
    for comp, cs in enumerate(rot):
        ops += bytes([0x43, comp, len(cs)]) + numbers(cs)  # set_rotation_s, raw n
    ops += bytes([10])  # copy
    ops += bytes([11]) + numbers([1, "1/2", -3, "1/3"])  # position of (1, 1/2, -3) at 1/3
    scene = None
    if (all(len(cs) <= SCENE_MAX_TRANSLATION + 1 for cs in tr)
            and all(len(cs) <= SCENE_MAX_ROTATION + 1 for cs in rot)):
        scene = bytearray([5])
        for cs in tr:
            scene += bytes([len(cs) - 1]) + numbers(cs)
        for cs in rot:
            scene += bytes([len(cs) - 1]) + numbers(cs)
        scene = bytes(scene)
    return bytes(ops), scene


def scene_seeds(doc):
    """(fuzz_scene seed or None, [fuzz_body seeds], [fuzz_motion seeds]) of a scene."""
    bodies = doc["bodies"]
    tol = doc.get("options", {}).get("time_tolerance")
    parts, body_seeds, motion_seeds, fits = [], [], [], len(bodies) <= 4
    for b in bodies:
        body, sb = body_parts(b)
        motion, sm = motion_parts(b.get("motion"))
        body_seeds.append(body)
        if motion:
            motion_seeds.append(motion)
        fits = fits and sb is not None and sm is not None
        parts.append((sb or b"") + (sm or b""))
    if not fits:
        return None, body_seeds, motion_seeds
    head = 3 << 3  # the auto broad phase, no cross-check (the fuzzer sets them)
    cfg = 1 if tol is not None else 0
    out = bytes([head, 0, cfg]) + (number(tol) if tol is not None else b"")
    out += bytes([len(bodies) - 2]) + b"".join(parts)
    return out, body_seeds, motion_seeds


def number_texts(value, out):
    """Every number text (and integer) of a parsed case file."""
    if isinstance(value, (list, tuple)):
        for v in value:
            number_texts(v, out)
    elif isinstance(value, dict):
        for k, v in value.items():
            if k not in ("format", "name", "source", "kind"):
                number_texts(v, out)
    elif isinstance(value, (int, str)) and not isinstance(value, bool):
        out.add(str(value))


# Texts at and around the parser's limits and corners (polyccd.h, "Limits").
EDGE_TEXTS = ["1e-100000", "1e100001", "1e-0000000000100000", "1e0000000001", "-7/3", "1/0",
              "+.5e-3", "5.", ".5", "-0", "0/7", "00012/0004", "1e+5", "1E5", "4/-6", " 1", "1 ",
              "9" * 400, "0." + "0" * 300 + "1"]


def write(out_dir, harness, name, data, counts):
    d = out_dir / harness
    d.mkdir(parents=True, exist_ok=True)
    (d / name).write_bytes(data)
    counts[harness] = counts.get(harness, 0) + 1


def binary_seeds(doc):
    """[(harness, seed name with NAME for the file's stem, seed)] of a corpus case for the
    binary harnesses; ValueError when a number does not fit their encoding."""
    out = []
    if doc.get("format") == "polyccd-query/1":
        for cross in (False, True):
            seed = query_seed(doc, cross)
            if seed is not None:
                out.append(("fuzz_query", f"NAME-{int(cross)}", seed))
        return out
    scene, body_seeds, motion_seeds = scene_seeds(doc)
    if scene is not None:
        out.append(("fuzz_scene", "NAME", scene))
    out += [("fuzz_body", f"NAME-{k}", s) for k, s in enumerate(body_seeds)]
    out += [("fuzz_motion", f"NAME-{k}", s) for k, s in enumerate(motion_seeds)]
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n")[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("--queries", type=Path, default=Path(os.environ.get(
        "POLYCCD_QUERY_DIR", ROOT.parent / "shared" / "data" / "ccd-queries")))
    args = ap.parse_args(argv)
    counts = {}
    texts = set(EDGE_TEXTS)
    for path in sorted((ROOT / "corpus").rglob("*.json")):
        doc = load(path)
        number_texts(doc, texts)
        name = path.stem
        write(args.out, "fuzz_readers", name + ".json", b"\x00" + path.read_bytes(), counts)
        try:
            binary = binary_seeds(doc)
        except ValueError:  # a number text beyond the binary harnesses' 255 bytes
            print(f"seeds: {path.name}: a number too long for the binary harnesses "
                  "(fuzz_readers gets the file)", file=sys.stderr)
            continue
        for harness, seed_name, seed in binary:
            write(args.out, harness, seed_name.replace("NAME", name), seed, counts)
    for k, text in enumerate(sorted(texts)):  # fuzz_numbers: the text, then a mode byte
        write(args.out, "fuzz_numbers", f"n{k}", text.encode() + b"\x00", counts)
    if args.queries.is_dir():
        for path in sorted(args.queries.rglob("*.csv")):
            kind = path.parent.name
            if kind not in ("vertex-face", "edge-edge"):
                continue
            stem = f"{path.parent.parent.name}-{kind}-{path.stem}"
            for q, seed in csv_seeds(path, kind):
                write(args.out, "fuzz_query", f"{stem}-{q}", seed, counts)
            lines = path.read_bytes().splitlines(keepends=True)[:16]
            write(args.out, "fuzz_readers", f"{stem}.csv", b"\x01" + b"".join(lines), counts)
    else:
        print(f"seeds: no shared query set at {args.queries} (CSV seeds left out)",
              file=sys.stderr)
    print("seeds: " + ", ".join(f"{h} {n}" for h, n in sorted(counts.items())))


if __name__ == "__main__":
    main()
