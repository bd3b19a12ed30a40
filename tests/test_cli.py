"""The polyccd command line: check, corpus, queries, demo; exit codes 0/1/2 and the
messages for bad files (docs/formats.md, "The command line")."""
import json
from fractions import Fraction

import pytest

TRIANGLE = [[[0], [0], [0]], [[1], [0], [0]], [[0], [1], [0]]]
# A vertex grazing the triangle: z(t) = (2t - 1)^2 touches z = 0 only at t = 1/2.
GRAZE = [[[0.25], [0.25], [1, -4, 4]]] + TRIANGLE
# Edge (0,-1,z)-(0,1,z) falling along z = 1 - 2t^2 meets the x axis at t = 1/sqrt(2).
FALLING_EDGE = [[[-1], [0], [0]], [[1], [0], [0]],
                [[0], [-1], [1, 0, -2]], [[0], [1], [1, 0, -2]]]


def query(kind="vertex-face", points=GRAZE, **extra):
    return {"format": "polyccd-query/1", "kind": kind, "points": points, **extra}


def write(tmp_path, name, content):
    path = tmp_path / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(content if isinstance(content, str) else json.dumps(content))
    return path


def test_check_prints_the_exact_result(tmp_path, run_cli):
    write(tmp_path, "q.json", query())
    p = run_cli("check", "q.json")
    assert p.returncode == 0, p.stderr
    assert json.loads(p.stdout) == {
        "collides": True, "features": [{"kind": "vertex-face", "points": [0, 1, 2, 3]}],
        "first_contact": {"lo": "1/2", "hi": "1/2", "approx": 0.5, "exact": "1/2"},
        "bodies": None}


def test_check_no_contact(tmp_path, run_cli):
    lifted = [[["0.25"], ["0.25"], ["1.000000000000000000000000000001", -4, 4]]]  # +1e-30
    write(tmp_path, "q.json", query(points=lifted + TRIANGLE))
    out = json.loads(run_cli("check", "q.json").stdout)
    assert out["collides"] is False and out["first_contact"] is None and out["features"] == []


def test_check_honours_time_tolerance(tmp_path, run_cli):
    for tol in ("1e-3", "1e-20"):
        write(tmp_path, "q.json", query("edge-edge", FALLING_EDGE, options={"time_tolerance": tol}))
        first = json.loads(run_cli("check", "q.json").stdout)["first_contact"]
        lo, hi = Fraction(first["lo"]), Fraction(first["hi"])
        assert first["exact"] is None and hi - lo <= Fraction(tol)
        assert lo ** 2 <= Fraction(1, 2) <= hi ** 2


def test_json_numbers_are_exact_decimals(tmp_path, run_cli):
    # z(t) = 0.1 - t: 0.1 means exactly 1/10, so the contact is at exactly t = 1/10.
    write(tmp_path, "q.json", '{"format": "polyccd-query/1", "kind": "vertex-face", "points": '
          '[[[0.25], [0.25], [0.1, -1]], [[0],[0],[0]], [[1],[0],[0]], [[0],[1],[0]]]}')
    assert json.loads(run_cli("check", "q.json").stdout)["first_contact"]["exact"] == "1/10"


BAD_FILES = [
    ("empty.json", "", "empty file"),
    ("invalid.json", '{"format": ', "invalid JSON at line 1"),
    ("array.json", "[1, 2]", "expected a JSON object"),
    ("nan.json", json.dumps(query()).replace("[0.25]", "[NaN]", 1), "points[0][0][0]: NaN is not a number"),
    ("inf.json", json.dumps(query()).replace("[0.25]", "[-Infinity]", 1), "points[0][0][0]: -Infinity"),
    ("div0.json", query(points=[[["1/0"], [0], [0]]] + TRIANGLE), 'points[0][0][0]: "1/0"'),
    ("abc.json", query(points=[[[0], [0], [0, "abc"]]] + TRIANGLE), 'points[0][2][1]: "abc" is not a number'),
    ("bool.json", query(points=[[[0], [True], [0]]] + TRIANGLE), "points[0][1][0]: true is not a number"),
    ("null.json", query(points=[[[0], [0], [None]]] + TRIANGLE), "points[0][2][0]: null is not a number"),
    ("format.json", {**query(), "format": "polyccd-query/2"}, "format: expected"),
    ("noformat.json", {"kind": "vertex-face"}, "format: expected"),
    ("scene.json", {"format": "polyccd/1", "bodies": []}, "bodies: a scene needs at least 2 bodies"),
    ("kind.json", query(kind="face-face"), "kind: expected one of"),
    ("count.json", query(points=TRIANGLE), "points: expected 4 point trajectories"),
    ("traj.json", query(points=[[[0], [0]]] + TRIANGLE), "points[0]: expected [xs, ys, zs]"),
    ("radii.json", query(radii=[1, 1]), "radii: only sphere-sphere"),
    ("noradii.json", query("sphere-sphere", TRIANGLE[:2]), "radii: missing"),
    ("radius0.json", query("sphere-sphere", TRIANGLE[:2], radii=[1, 0]), "radii[1]"),
    ("tol.json", query(options={"time_tolerance": "0"}), "options.time_tolerance: "),
    ("degree.json", query(points=[[[0] * 66, [0], [0]]] + TRIANGLE), "points[0][0]: degree 65"),
    ("dup.json", '{"format": "polyccd-query/1", "format": "polyccd-query/1"}', 'key "format" appears more than once'),
    ("expect.json", query(expect={"collides": "yes"}), "expect.collides: expected true or false"),
    ("latin1.json", "\xff", None),
    ("deep.json", "[" * 100000, "invalid JSON: nested too deeply"),  # no RecursionError
]


@pytest.mark.parametrize("name, content, words", BAD_FILES, ids=[b[0] for b in BAD_FILES])
def test_check_input_errors_exit_2(tmp_path, run_cli, name, content, words):
    path = write(tmp_path, name, content)
    if name == "latin1.json":
        path.write_bytes(b"\xff\xfe{}")
        words = "not UTF-8"
    p = run_cli("check", name)
    assert p.returncode == 2, (p.stdout, p.stderr)
    assert p.stdout == "" and "Traceback" not in p.stderr
    assert p.stderr.startswith(f"polyccd: {name}: ") and words in p.stderr, p.stderr


def test_check_missing_file(run_cli):
    p = run_cli("check", "nowhere.json")
    assert p.returncode == 2 and "nowhere.json: cannot read" in p.stderr


def test_usage_errors_exit_2(run_cli):
    assert run_cli().returncode == 2
    assert run_cli("frobnicate").returncode == 2
    assert run_cli("queries", "x.csv", "--kind", "edge").returncode == 2
    p = run_cli("--version")
    assert p.returncode == 0 and p.stdout.strip() == "polyccd 0.1.0"


def test_corpus_counts_and_reasons(tmp_path, run_cli):
    write(tmp_path, "c/exact.json", query(expect={"collides": True, "first_contact": "1/2"}))
    write(tmp_path, "c/sub/range.json", query("edge-edge", FALLING_EDGE, expect={
        "collides": True, "first_contact": ["0.7071067811865", "0.7071067811866"]}))
    write(tmp_path, "c/sub/notes.txt", "not a case")
    p = run_cli("corpus", "c")
    assert (p.returncode, p.stdout) == (0, "2 passed, 0 failed\n")
    write(tmp_path, "c/wrong.json", query(expect={"collides": True, "first_contact": "1/3"}))
    write(tmp_path, "c/miss.json", query(expect={"collides": False}))
    write(tmp_path, "c/away.json", query("edge-edge", FALLING_EDGE, expect={
        "collides": True, "first_contact": ["0.70", "0.7071"]}))
    write(tmp_path, "c/wide.json", query("edge-edge", FALLING_EDGE,
                                         options={"time_tolerance": "0.1"}, expect={
                                             "collides": True, "first_contact": ["0.7", "0.71"]}))
    write(tmp_path, "c/noexpect.json", query())
    write(tmp_path, "c/broken.json", "{")
    p = run_cli("corpus", "c")
    lines = p.stdout.splitlines()
    assert p.returncode == 1 and lines[-1] == "3 passed, 5 failed", p.stdout
    text = p.stdout
    assert "wrong.json: first_contact: expected exactly 1/3, got exactly 1/2" in text
    assert "miss.json: collides: expected false, got true" in text
    assert "away.json: first_contact: the reported" in text and "does not intersect" in text
    assert "noexpect.json: no expect block" in text and "broken.json: invalid JSON" in text
    assert "wide.json" not in text  # 0.1 wide enclosures are allowed by its own tolerance
    assert "Traceback" not in p.stderr


def test_corpus_rules():
    # The EXPECT rules of formats.md on fabricated results (the engine itself always
    # honours the tolerance, so a too wide enclosure cannot be provoked end to end).
    from polyccd import ContactTime, Result
    from polyccd.apps._corpus import compare
    from polyccd.apps._json import Expect

    def result(lo, hi, exact=None):
        return Result(True, ContactTime(Fraction(lo), Fraction(hi), exact, 0.5), (), "exact")

    tol = Fraction(1, 10 ** 12)
    window = Expect(True, (Fraction(1, 3), Fraction(1, 2)))
    assert compare(window, result("1/4", "1/3"), Fraction(1)) == []  # touches lo: intersects
    assert compare(window, result("1/4", "1/3"), tol)  # but wider than the tolerance
    assert compare(window, result("1/2", "1/2", Fraction(1, 2)), tol)  # exact, not in (lo, hi)
    assert compare(window, result("2/5", "2/5", Fraction(2, 5)), tol) == []
    assert compare(Expect(True, Fraction(2, 5)), result("2/5", "2/5", Fraction(2, 5)), tol) == []
    assert compare(Expect(True, Fraction(2, 5)), result("0", "1"), Fraction(2))  # not exact
    assert compare(Expect(True, None), result("0", "1"), tol) == []
    assert compare(Expect(False, None), result("0", "1"), tol) == [
        "collides: expected false, got true"]


def test_corpus_missing_path_exits_2(run_cli):
    assert run_cli("corpus", "nowhere").returncode == 2


def csv_rows(queries):
    """Benchmark CSV text of vertex-face queries (t0 points, t1 points, truth)."""
    rows = []
    for t0, t1, truth in queries:
        for x, y, z in t0 + t1:
            row = []
            for v in (Fraction(x), Fraction(y), Fraction(z)):
                row += [v.numerator, v.denominator]
            rows.append(",".join(map(str, row + [truth])))
    return "\n".join(rows) + "\n"


TRI = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
HIT = ([(0.25, 0.25, 1)] + TRI, [(0.25, 0.25, -1)] + TRI)
MISS = ([(2, 2, 1)] + TRI, [(2, 2, -1)] + TRI)
THIRD = ([(Fraction(1, 3), Fraction(1, 3), 1)] + TRI, [(Fraction(1, 3), Fraction(1, 3), -1)] + TRI)


def test_queries_json_output(tmp_path, run_cli):
    write(tmp_path, "set/vertex-face/a.csv", csv_rows([(*HIT, 1), (*MISS, 0), (*THIRD, 1)]))
    p = run_cli("queries", "set", "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert list(out) == ["file", "kind", "queries", "positives", "false_positives",
                         "false_negatives", "seconds_per_query"]
    assert out["file"].endswith("a.csv") and out["kind"] == "vertex-face"
    counts = [out[k] for k in ("queries", "positives", "false_positives", "false_negatives")]
    assert counts == [3, 2, 0, 0]
    assert out["seconds_per_query"] > 0


def test_queries_mismatch_exits_1(tmp_path, run_cli):
    write(tmp_path, "q.csv", csv_rows([(*HIT, 0), (*MISS, 1), (*MISS, 0)]))
    p = run_cli("queries", "q.csv", "--kind", "vertex-face")
    assert p.returncode == 1
    assert "3 queries, 1 positives, 1 false positives, 1 false negatives" in p.stdout
    assert "false positive: query 0 (lines 1-8)" in p.stdout
    assert "false negative: query 1 (lines 9-16)" in p.stdout


@pytest.mark.parametrize("content, words", [
    ("1,1,1,1,1,1,0\n" * 7, "7 rows"),
    ("1,1,1,1,1,1\n" * 8, "line 1: expected 7 columns"),
    ("1,1,x,1,1,1,0\n" * 8, "line 1, column 3: expected an integer (ASCII digits)"),
    ("1,1,1,1,1,1,0\n" * 7 + "1,1,1,1,1,1,1\n", "line 8: truth 1 disagrees with line 1"),
    ("1,0,1,1,1,1,0\n" * 8, "line 1: zero denominator"),
])
def test_queries_bad_csv_exits_2(tmp_path, run_cli, content, words):
    write(tmp_path, "edge-edge/q.csv", content)
    p = run_cli("queries", "edge-edge/q.csv")
    assert p.returncode == 2 and words in p.stderr and "Traceback" not in p.stderr, p.stderr


def test_queries_unknown_kind_exits_2(tmp_path, run_cli):
    write(tmp_path, "q.csv", csv_rows([(*HIT, 1)]))
    p = run_cli("queries", "q.csv")
    assert p.returncode == 2 and "--kind" in p.stderr


def test_demo(run_cli):
    p = run_cli("demo", env={"POLYCCD_QUERY_DIR": "/nonexistent"})
    assert p.returncode == 0, p.stdout + p.stderr
    assert "MISMATCH" not in p.stdout and p.stdout.count("\n   OK\n") >= 5
    assert "not found" in p.stdout


# ---------------------------------------------------------------- polyccd index

CUBE = {"vertices": [[i & 1, (i >> 1) & 1, i >> 2] for i in range(8)],
        "triangles": [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                      [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]}
# A: the unit cube, standing. B: a unit cube sliding x = 3 - 3t (meets A at t = 2/3).
# C: a ball of radius 1/2 over A's top falling z = 3 - 2t (meets A's top at t = 3/4).
# D: a ball of radius 1/2 at x = 3 - 4t^2 (meets A's face x = 1 at t = sqrt(3/8)).
# E: a ball far away (meets nothing).
INDEX_SCENE = {"format": "polyccd/1", "options": {"time_tolerance": "1e-20"}, "bodies": [
    {"name": "A", "mesh": CUBE},
    {"name": "B", "mesh": CUBE, "motion": {"translation": [[3, -3], [0], [0]]}},
    {"name": "C", "spheres": {"centers": [["1/2", "1/2", 3]], "radii": ["1/2"]},
     "motion": {"translation": [[0], [0], [0, -2]]}},
    {"name": "D", "spheres": {"centers": [[3, "1/4", "1/2"]], "radii": ["1/2"]},
     "motion": {"translation": [[0, 0, -4], [0], [0]]}},
    {"name": "E", "spheres": {"centers": [[10, 10, 10]], "radii": [1]}},
]}


def index_lines(p):
    assert p.returncode == 0 and p.stderr == "", p.stderr
    return [json.loads(line) for line in p.stdout.splitlines()]


@pytest.mark.parametrize("stored", [None, "B"])
def test_index_equals_check_of_each_pair(tmp_path, run_cli, stored):
    write(tmp_path, "s.json", INDEX_SCENE)
    lines = index_lines(run_cli("index", "s.json", *(["--stored", stored] if stored else [])))
    names = [b["name"] for b in INDEX_SCENE["bodies"]]
    s = stored or "A"
    assert [(x["stored"], x["query"]) for x in lines] == [(s, n) for n in names if n != s]
    for line in lines:
        assert list(line) == ["stored", "query", "collides", "first_contact", "features"]
        pair = {**INDEX_SCENE, "bodies": [b for n in (s, line["query"])
                                          for b in INDEX_SCENE["bodies"] if b["name"] == n]}
        write(tmp_path, "pair.json", pair)
        p = run_cli("check", "pair.json")
        assert p.returncode == 0, p.stderr
        want = json.loads(p.stdout)
        for key in ("collides", "first_contact", "features"):
            assert line[key] == want[key], (line["query"], key)
        assert want["bodies"] == ([s, line["query"]] if want["collides"] else None)
    hits = {x["query"]: x["first_contact"] for x in lines if x["collides"]}
    if stored is None:  # the hand-derived times of the scene's comment
        assert hits["B"]["exact"] == "2/3" and hits["C"]["exact"] == "3/4"
        d = hits["D"]
        assert d["exact"] is None and Fraction(d["lo"]) ** 2 <= Fraction(3, 8) <= Fraction(d["hi"]) ** 2
        assert Fraction(d["hi"]) - Fraction(d["lo"]) <= Fraction(1, 10 ** 20)
        assert set(hits) == {"B", "C", "D"}  # not E


def test_index_options_do_not_change_answers(tmp_path, run_cli):
    import polyccd
    write(tmp_path, "s.json", INDEX_SCENE)
    base = run_cli("index", "s.json")
    for extra in (["--broad-phase", "brute"], ["--broad-phase", "boxes", "--threads", "3"]):
        p = run_cli("index", "s.json", *extra)
        assert (p.returncode, p.stdout) == (0, base.stdout), extra
    # --all-contacts: every touching feature pair with its own time, as the Python API
    # gives for the two-body scene.
    from polyccd.apps._json import time_json
    bodies = polyccd.apps.load_scene(str(tmp_path / "s.json"))[0]
    lines = index_lines(run_cli("index", "s.json", "--all-contacts", "--broad-phase", "range"))
    for line, q in zip(lines, bodies[1:]):
        r = polyccd.check([bodies[0], q], all_contacts=True, broad_phase="brute",
                          time_tolerance="1e-20")
        want = [{"bodies": list(p.names), "a": list(c.a), "b": list(c.b),
                 "first_contact": time_json(c.first_contact)} for p in r.pairs for c in p.contacts]
        assert line["features"] == want and line["collides"] == r.collides
    b = lines[0]["features"]
    assert len(b) > len(index_lines(base)[0]["features"])


def test_index_two_body_corpus_case_equals_check(run_cli):
    # An irrational first contact (a rotating edge): lo < t* < hi, the case's tolerance.
    import pathlib
    path = pathlib.Path(__file__).resolve().parent.parent / "corpus" / "bodies" / "mesh-mesh" / \
        "edge-edge-irrational-rotation.json"
    (line,) = index_lines(run_cli("index", path))
    want = json.loads(run_cli("check", path).stdout)
    assert line["first_contact"]["exact"] is None and line["collides"]
    for key in ("collides", "first_contact", "features"):
        assert line[key] == want[key]


VANISHING_MOTION = {"rotation": [[1, -2], [0], [0], [0]]}  # r(t) = 1 - 2t: zero at t = 1/2


@pytest.mark.parametrize("args, content, words", [
    (["--stored", "X"], INDEX_SCENE, '--stored: no body is named "X" (the bodies are "A", "B"'),
    ([], "{", "invalid JSON"),
    ([], query(), 'format: expected "polyccd/1"'),
    ([], {"format": "polyccd/1", "bodies": [{"name": "A", "mesh": CUBE}]},
     "bodies: a scene needs at least 2 bodies"),
    ([], {**INDEX_SCENE, "bodies": [{**INDEX_SCENE["bodies"][0], "motion": VANISHING_MOTION}]
          + INDEX_SCENE["bodies"][1:]}, "bodies[0].motion: the rotation quaternion"),
    (["--stored", "B"], {**INDEX_SCENE, "bodies": INDEX_SCENE["bodies"][:2] + [
        {**INDEX_SCENE["bodies"][2], "motion": VANISHING_MOTION}]}, "bodies[2].motion: "),
], ids=["stored", "json", "query-file", "one-body", "stored-motion", "query-motion"])
def test_index_input_errors_exit_2(tmp_path, run_cli, args, content, words):
    write(tmp_path, "s.json", content)
    p = run_cli("index", "s.json", *args)
    assert p.returncode == 2 and p.stdout == "", (p.stdout, p.stderr)
    assert p.stderr.startswith("polyccd: s.json: ") and words in p.stderr, p.stderr
    assert "Traceback" not in p.stderr


def test_index_usage_errors_exit_2(tmp_path, run_cli):
    write(tmp_path, "s.json", INDEX_SCENE)
    p = run_cli("index", "nowhere.json")
    assert p.returncode == 2 and "polyccd: nowhere.json: cannot read" in p.stderr
    for args in (["--threads", "0"], ["--threads", "x"], ["--broad-phase", "kd"], []):
        p = run_cli("index", *(["s.json"] if args else []), *args)
        assert p.returncode == 2 and "usage: polyccd index" in p.stderr, (args, p.stderr)
