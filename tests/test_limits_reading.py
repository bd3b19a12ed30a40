"""The command line's reading limit on file sizes (issue 23: reading a 38 MB scene took
1.78 GB with --max-seconds 5). A JSON file takes about 48 times its size in memory
once read (apps/_reading.py), so `polyccd` reads at most --max-file-mb MiB (default
32) of a file: a larger one is refused by its size before it is read (a pipe: after
the limit's bytes), with exit 2 and a message naming the file, its size and the flag.
"""
import json
import subprocess
import sys

from polyccd.apps import _reading

SCENE = {"format": "polyccd/1", "bodies": [
    {"name": "still", "spheres": {"centers": [[0, 0, 0]], "radii": [1]}},
    {"name": "coming", "spheres": {"centers": [[3, 0, 0]], "radii": [1]},
     "motion": {"translation": [[0, -2], [0], [0]]}}]}

# Runs the command line in a child and prints its exit status and peak memory (KiB):
# the grandchild's ru_maxrss alone, whatever the test process itself holds.
PEAK = """
import resource, subprocess, sys
r = subprocess.run([sys.executable, "-m", "polyccd"] + sys.argv[1:],
                   capture_output=True, text=True)
print(r.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
print(r.stdout + r.stderr)
"""


def padded(tmp_path, mib, name="scene.json"):
    """The scene followed by spaces up to `mib` MiB (valid JSON of that size)."""
    text = json.dumps(SCENE)
    path = tmp_path / name
    path.write_text(text + " " * ((mib << 20) - len(text)))
    return path


def cli(*args, stdin=None):
    r = subprocess.run([sys.executable, "-m", "polyccd", *map(str, args)],
                       capture_output=True, text=True, input=stdin)
    return r.returncode, r.stdout, r.stderr


def test_a_file_above_the_limit_is_refused_by_its_size(tmp_path):
    assert _reading.DEFAULT_MAX_FILE_MB == 32
    big = padded(tmp_path, 33)
    code, out, err = cli("check", big)
    assert code == 2 and out == "" and "Traceback" not in err
    assert err.startswith(f"polyccd: {big}: the file has 34,603,008 bytes, more than the "
                          "reading limit of 33,554,432 bytes (--max-file-mb 32"), err
    # Refused before it is read: the child stays far below the 48 x 33 MiB of a reading.
    r = subprocess.run([sys.executable, "-c", PEAK, "check", str(big)], capture_output=True,
                       text=True)
    code, peak = map(int, r.stdout.split("\n")[0].split())
    assert code == 2 and peak < 200 * 1024, r.stdout
    # Raised past it, the same file is read and answered as the unpadded scene.
    small = tmp_path / "small.json"
    small.write_text(json.dumps(SCENE))
    code, out, err = cli("check", "--max-file-mb", "40", big)
    assert (code, err) == (0, "")
    assert json.loads(out) == json.loads(cli("check", small)[1])
    assert json.loads(out)["collides"] is True


def test_the_limit_holds_for_pipes_and_index(tmp_path):
    text = json.dumps(SCENE) + " " * (2 << 20)
    code, out, err = cli("check", "--max-file-mb", "1", "/dev/stdin", stdin=text)
    assert code == 2 and "the file has more than the reading limit of 1,048,576 bytes" in err
    code, out, err = cli("check", "--max-file-mb", "3", "/dev/stdin", stdin=text)
    assert code == 0 and json.loads(out)["collides"] is True
    big = padded(tmp_path, 2)
    code, out, err = cli("index", "--max-file-mb", "1", big)
    assert code == 2 and "--max-file-mb 1" in err and "Traceback" not in err
    code, out, err = cli("check", "--max-file-mb", "0", big)
    assert code == 2 and "--max-file-mb: expected a number > 0, got '0'" in err
