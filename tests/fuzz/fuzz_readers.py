"""Atheris harness of the Python readers and the command line (tests/fuzz/README.md).

The readers are Python (polyccd.apps._json, _csv, _scene_file, _queries, cli), so they
are fuzzed where they run: atheris instruments their bytecode for libFuzzer's coverage
feedback, and the bytes become the file a user would hand them. (A libFuzzer harness in
C could only drive the C API with structures it parsed itself, never these readers.)
The C library under them is the normal build (build/libpolyccd.so, not instrumented):
the C harnesses fuzz it with the sanitizers.

Input: byte 0 picks the path, the rest is the file's content:
  0  JSON: polyccd.apps._json.loads, then the query or scene reader (query_case,
     scene_from_doc: bodies and motions built through the bindings), then the solve
  1  CSV: _csv.read_csv on the bytes as a file, then _queries.decide_all
  2  the command line, `polyccd check FILE` on the bytes as a file
  3  the command line, `polyccd index FILE` (byte 1: --all-contacts, --broad-phase)
  4  the command line, `polyccd queries FILE.csv --kind K`

What counts as a bug: any exception but polyccd.InputError (and its subclasses) out of
a reader or a solve; an InternalError; a command line exit status other than 0 (done)
or 2 (an input error, with a "polyccd: FILE: ..." message); `queries` may also exit 1
(an answer differs from the file's truth column).

Cost limits (as the C harnesses', README.md): a document is solved only when every
number text has at most 64 characters and a decimal exponent within +-60, every
coefficient list at most 5 entries (degree 4; motions: translations 6, rotations 3),
at most 4 bodies of at most 12 vertices / triangles / balls, and CSV files at most
16 queries; other documents are read and validated, not solved.
"""
import io
import os
import re
import sys
import tempfile
from contextlib import redirect_stderr, redirect_stdout

import atheris

with atheris.instrument_imports(include=["polyccd"]):
    import polyccd
    from polyccd import InputError, InternalError
    from polyccd import BROAD_PHASES
    from polyccd.apps import _corpus, _csv, _json, _queries, _scene_file, cli

MAX_TEXT, MAX_EXP = 64, 60
MAX_COEFFS, MAX_TRANSLATION, MAX_ROTATION = 5, 6, 3
MAX_BODIES, MAX_ELEMENTS, MAX_CSV_QUERIES = 4, 12, 16
EXPONENT = re.compile(r"[eE][+-]?(\d+)")
TMP = tempfile.mkdtemp(prefix="polyccd-fuzz-")


class TooCostly(Exception):
    """Within the library's limits, beyond the harness's (not a bug)."""


def number_ok(text):
    if len(text) > MAX_TEXT:
        return False
    return all(int(m.group(1)) <= MAX_EXP for m in EXPONENT.finditer(text))


def cheap(value, max_list):
    """Every number text within the limits, every list within max_list entries."""
    if isinstance(value, str):
        return number_ok(value)
    if isinstance(value, list):
        return len(value) <= max_list and all(cheap(v, max_list) for v in value)
    if isinstance(value, dict):
        return all(cheap(v, max_list) for v in value.values())
    return True


def scene_cheap(doc):
    bodies = doc.get("bodies")
    if not isinstance(bodies, list) or len(bodies) > MAX_BODIES:
        return False
    for b in bodies:
        if not isinstance(b, dict):
            return True  # rejected by the reader
        motion = b.get("motion")
        if isinstance(motion, dict):
            if not cheap(motion.get("translation"), MAX_TRANSLATION):
                return False
            if not cheap(motion.get("rotation"), MAX_ROTATION):
                return False
        for key in ("mesh", "spheres"):
            if key in b and not cheap(b[key], MAX_ELEMENTS):
                return False
    return cheap({k: v for k, v in doc.items() if k != "bodies"}, MAX_COEFFS)


def doc_cheap(doc):
    if not isinstance(doc, dict):
        return True
    if doc.get("format") == _json.SCENE_FORMAT:
        return scene_cheap(doc)
    return cheap(doc, MAX_COEFFS)


def write(data, suffix):
    path = os.path.join(TMP, "case" + suffix)
    with open(path, "wb") as f:
        f.write(data)
    return path


def run_json(data):
    try:
        doc = _json.loads(data.decode("utf-8"))
    except UnicodeDecodeError:
        return
    except InputError:
        return
    try:
        try:
            case = _json.query_case(doc)
            if not doc_cheap(doc):
                return
            _corpus.solve_case(case)
        except _json.SceneNotSupported:
            scene = _scene_file.scene_from_doc(doc)
            if not doc_cheap(doc):
                return
            _corpus.solve_scene_case(scene, threads=1)
    except InputError:
        pass


def run_csv(data):
    path = write(data, ".csv")
    try:
        qs = _csv.read_csv(path, "vertex-face" if len(data) % 2 else "edge-edge")
    except InputError:
        return
    if len(qs.truth) <= MAX_CSV_QUERIES:
        try:
            _queries.decide_all(qs)
        except InputError:
            pass


def run_cli(argv, allowed=(0, 2)):
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        status = cli.main(argv)
    if status not in allowed:
        raise AssertionError(f"polyccd {' '.join(argv)} exited {status}: {err.getvalue()}")
    if status == 2 and not err.getvalue().startswith("polyccd: "):
        raise AssertionError(f"polyccd {' '.join(argv)}: message {err.getvalue()!r}")
    if "InternalError" in err.getvalue():
        raise AssertionError(err.getvalue())


def json_file_cheap(data):
    try:
        return doc_cheap(_json.loads(data.decode("utf-8-sig")))
    except (UnicodeDecodeError, InputError):
        return True  # the reader rejects it before any solve


def TestOneInput(data):
    if not data:
        return
    path_kind, body = data[0] % 5, data[1:]
    if path_kind == 0:
        run_json(body)
    elif path_kind == 1:
        run_csv(body)
    elif path_kind == 2:
        if json_file_cheap(body):
            run_cli(["check", write(body, ".json")])
    elif path_kind == 3:
        if len(body) < 1:
            return
        opts = body[0]
        body = body[1:]
        if json_file_cheap(body):
            argv = ["index", write(body, ".json"),
                    "--broad-phase", sorted(BROAD_PHASES)[opts % len(BROAD_PHASES)]]
            if opts & 16:
                argv.append("--all-contacts")
            run_cli(argv)
    else:
        if body.count(b"\n") <= 8 * MAX_CSV_QUERIES:
            run_cli(["queries", write(body, ".csv"), "--kind",
                     "vertex-face" if len(body) % 2 else "edge-edge"], allowed=(0, 1, 2))


if __name__ == "__main__":
    atheris.Setup(sys.argv, TestOneInput)
    atheris.Fuzz()
