"""Python and command-line inputs of any size or spelling (issue 23, item 3).

Every number either converts exactly or fails with InputError and its place; unknown
keys of scene and query files are errors naming the key (with the nearest known key);
expect.pairs of one body with itself is refused; CSV integers are ASCII digits only;
messages quote a short excerpt of a long input; the command line exits 2 with a place
and no traceback. Each case is one the audit of issue 23 reproduced.
"""
import json
import subprocess
import sys
import time
from decimal import Decimal
from fractions import Fraction as F
from pathlib import Path

import pytest

import polyccd as P

ROOT = Path(__file__).resolve().parents[1]
POINTS = [[[0], [0], [0]], [["X", -1], [0], [0]]]  # point b from x = X to X - 1


def cli(*args):
    return subprocess.run([sys.executable, "-m", "polyccd", *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=120)


def fails_cleanly(done, *words):
    assert done.returncode == 2, (done.returncode, done.stderr[-400:])
    assert "Traceback" not in done.stderr and done.stderr.startswith("polyccd: ")
    for w in words:
        assert w in done.stderr, (w, done.stderr)
    assert len(done.stderr) < 400  # a short excerpt of the input, never all of it


def query_file(tmp_path, extra, name="q.json"):
    text = ('{"format": "polyccd-query/1", "kind": "vertex-vertex", '
            '"points": [[[0], [0], [0]], [[1, -1], [0], [0]]]' + extra + "}")
    path = tmp_path / name
    path.write_text(text)
    return path


def scene_doc(**motion):
    return {"format": "polyccd/1", "bodies": [
        {"name": "a", "mesh": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
                               "triangles": [[0, 1, 2]]}},
        {"name": "b", "spheres": {"centers": [[0, 0, 1]], "radii": [0.5]},
         "motion": {"translation": [[0], [0], [0, -2]], **motion}}]}


def test_decimal_numbers_convert_exactly_or_end_at_once():
    def solve(x):
        return P.solve("vertex-vertex", [[[0], [0], [0]], [[x, -1], [0], [0]]])
    assert solve(Decimal("0.5")).first_contact.exact == F(1, 2)
    assert solve(Decimal("25E-2")).first_contact.exact == F(1, 4)
    start = time.perf_counter()
    with pytest.raises(P.LimitError, match=r"^points\[1\]\[0\]\[0\]: .*1E\+999999999"):
        solve(Decimal("1e999999999"))  # as_integer_ratio() would build 10^999999999
    assert time.perf_counter() - start < 1
    for bad in (Decimal("NaN"), Decimal("-Infinity"), Decimal("sNaN")):
        with pytest.raises(P.InputError, match=r"^points\[1\]\[0\]\[0\]: .* is not a finite number"):
            solve(bad)


def test_integers_beyond_python_str_limit():
    big = 10 ** 5000 + 1  # 5,001 digits: str() and int() refuse it
    r = P.solve("vertex-vertex", [[[0], [0], [0]], [[F(1, big), -1], [0], [0]]],
                limits=P.Limits(max_number_bits=None))
    assert r.first_contact.exact == F(1, big)
    with pytest.raises(P.InputError, match=r"triangles\[0\]\[2\]: index an integer of \d+ bits "
                                           r"is not a valid 0-based index"):
        P.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 10 ** 5000]])


def test_long_numbers_in_files_convert_or_fail_with_a_place(tmp_path):
    zeros = "0" * 5000  # legal: leading zeros of a decimal exponent, or decimals
    same = cli("check", query_file(tmp_path, ', "options": {"time_tolerance": 1e-5}'))
    for extra in (f', "options": {{"time_tolerance": 1e-{zeros}5}}',
                  f', "options": {{"time_tolerance": 0.0000{zeros}1e{zeros}5000}}'):
        done = cli("check", query_file(tmp_path, extra))
        assert (done.returncode, done.stdout) == (0, same.stdout), done.stderr[-300:]
    done = cli("check", query_file(tmp_path, f', "options": {{"min_distance": 1{zeros}}}'))
    assert done.returncode == 0 and '"exact": "0"' in done.stdout
    fails_cleanly(cli("check", query_file(tmp_path, ', "options": {"time_tolerance": 1e0000099999999999}')),
                  "options.time_tolerance: the exponent of", "is beyond +-100000")
    fails_cleanly(cli("check", query_file(tmp_path, ', "expect": {"collides": true, '
                                                    '"first_contact": 1e99999999999}')),
                  "expect.first_contact: the exponent of")
    done = cli("corpus", query_file(tmp_path, f', "expect": {{"collides": true, '
                                              f'"first_contact": 1e-{zeros}1}}'))
    assert done.returncode == 1 and "Traceback" not in done.stderr + done.stdout
    doc = json.dumps(scene_doc()).replace("[0, 1, 2]", "[0, 1, " + "9" * 5000 + "]")
    (tmp_path / "tri.json").write_text(doc)
    fails_cleanly(cli("check", tmp_path / "tri.json"), "bodies[0].mesh.triangles[0][2]: index")


def test_unknown_keys_are_refused_by_name(tmp_path):
    cases = [(scene_doc(rotaton=[[1], [0], [0], [0]]),
              'bodies[1].motion.rotaton: unknown key (did you mean "rotation"?)'),
             ({**scene_doc(), "option": {}}, 'option: unknown key (did you mean "options"?)'),
             ({**scene_doc(), "options": {"min_distanse": 1}},
              'options.min_distanse: unknown key (did you mean "min_distance"?)'),
             ({**scene_doc(), "expect": {"colides": True}},
              'expect.colides: unknown key (did you mean "collides"?)')]
    doc = scene_doc()
    doc["bodies"][0]["mesh"]["triangle"] = []
    cases.append((doc, 'bodies[0].mesh.triangle: unknown key (did you mean "triangles"?)'))
    for k, (doc, message) in enumerate(cases):
        path = tmp_path / f"s{k}.json"
        path.write_text(json.dumps(doc))
        fails_cleanly(cli("check", path), f"{path}: {message}")
    fails_cleanly(cli("check", query_file(tmp_path, ', "kindd": 1')), 'kindd: unknown key (did you mean "kind"?)')
    fails_cleanly(cli("check", query_file(tmp_path, ', "zzz": 1')), "zzz: unknown key (known: format, kind")
    # Every corpus file still reads: the known keys are all the format's.
    assert cli("corpus", ROOT / "corpus" / "bodies" / "multi-body").returncode == 0


def test_a_pair_of_one_body_is_refused(tmp_path):
    path = tmp_path / "pairs.json"
    path.write_text(json.dumps({**scene_doc(), "expect": {"collides": True, "pairs": [["b", "b"]]}}))
    fails_cleanly(cli("check", path), 'expect.pairs[0]: a pair of one body ("b") with itself')


def test_csv_integers_are_ascii_digits(tmp_path):
    from polyccd.apps._csv import read_csv
    folder = tmp_path / "edge-edge"
    folder.mkdir()
    path = folder / "bad.csv"
    rows = ["0,1,0,1,0,1,0"] * 8
    for cell in ["1_000", "\u0661", " 1", "1 ", "0x1", "1.0", "+-1", "", "x" * 100000]:
        rows[3] = f"0,1,{cell},1,0,1,0"
        path.write_text("\n".join(rows) + "\n", encoding="utf-8")
        with pytest.raises(P.InputError) as e:
            read_csv(path, "edge-edge")
        assert str(e.value).startswith("line 4, column 3: expected an integer (ASCII digits)")
        assert len(str(e.value)) < 200
    fails_cleanly(cli("queries", path), "line 4, column 3: expected an integer (ASCII digits)")
    rows[3] = "0,1,+7,1,0,1,0"  # a sign is an ASCII integer (int() took it before too)
    path.write_text("\n".join(rows) + "\n")
    assert read_csv(path, "edge-edge").t0[0, 3, 1] == 7
