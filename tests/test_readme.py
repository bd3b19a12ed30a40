"""The README's Python and C examples run exactly as written."""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _block(lang, k=0):
    text = open(os.path.join(ROOT, "README.md"), encoding="utf-8").read()
    blocks = re.findall(r"```" + lang + r"\n(.*?)```", text, re.S)
    assert len(blocks) > k, f"no {lang} block {k} in README.md"
    return blocks[k]


def _run_python_block(tmp_path, k):
    """Python block k of the README, run as a script from the checkout: its stdout."""
    script = tmp_path / f"block{k}.py"
    script.write_text(_block("python", k))
    out = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    return out.stdout


def test_python_example_runs(tmp_path):
    stdout = _run_python_block(tmp_path, 0)
    assert stdout.startswith("1/3 (Feature(kind='vertex-face'"), stdout


def test_python_scene_example_runs(tmp_path):
    # Cube edge 10 is (3, 5), the diagonal of the face x = 1 through its centre.
    stdout = _run_python_block(tmp_path, 1)
    assert stdout == "3/4 [(('edge', 10), ('sphere', 0))]\n", stdout


def test_python_index_example_runs(tmp_path):
    stdout = _run_python_block(tmp_path, 2)
    assert stdout == "['1', '3/4']\n", stdout


def test_c_example_runs(tmp_path):
    src = tmp_path / "ex.c"
    src.write_text(_block("c"))
    exe = tmp_path / "ex"
    lib = os.path.join(ROOT, "build")   # where `make` puts libpolyccd.so
    subprocess.run(["cc", "-std=c99", "-Wall", "-Werror", "-I" + os.path.join(ROOT, "include"),
                    str(src), "-L" + lib, "-lpolyccd", "-Wl,-rpath," + lib, "-o", str(exe)],
                   check=True)
    out = subprocess.run([str(exe)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout == "first contact at t = 1/2\n"
