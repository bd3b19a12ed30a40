#!/usr/bin/env bash
# Memory checks of libpolyccd under valgrind (`make valgrind`, which builds build/test_*).
#
# Usage: run_valgrind.sh [PROGRAM...], programs by name in build/ (default: one per
# tests/c/test_*.c, what `make valgrind` passes).
#
# 1. The C API tests (build/test_config, test_query, ...) under memcheck: no error of any
#    kind, no definite or indirect leak, and each test itself must pass.
# 2. The regression corpus through the Python command line (`python -m polyccd corpus
#    corpus/`), plus the queries of VALGRIND_QUERY_FILES (default: the 324 degenerate
#    unit-test queries of the shared benchmark, unit-tests/*/*.csv, when present; about a
#    minute under valgrind) through `python -m polyccd queries`.
#    CPython is not valgrind-clean (uninitialised reads in int.from_bytes at start-up,
#    interned objects never freed at exit), so this step runs with PYTHONMALLOC=malloc and
#    judges the log instead of valgrind's exit code: it fails on any error record (invalid
#    access, uninitialised value, definite or indirect leak) with a stack frame in polyccd
#    code (libpolyccd.so, lib/<layer>/ sources, pccd:: / pccd_ functions, the cffi
#    wrappers _cffi_f_pccd_*), and on
#    a failing command. Error records entirely inside CPython, numpy or cffi are counted
#    and reported, not judged. Skipped (with a message) when .venv has no polyccd.
#
# Exit status: 0 when every step that ran is clean. Logs: build/valgrind-*.log.
set -u
cd "$(dirname "$0")/../.."

BUILD=${BUILD:-build}
VPY=${VPY:-.venv/bin/python}
QUERY_DIR=${POLYCCD_QUERY_DIR:-../shared/data/ccd-queries}
VALGRIND_QUERY_FILES=${VALGRIND_QUERY_FILES-$QUERY_DIR/unit-tests/*/*.csv}
VG=(valgrind --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect
    --show-leak-kinds=definite,indirect --track-origins=yes --num-callers=40)
status=0

if ! command -v valgrind >/dev/null; then
  echo "valgrind not installed (make deps installs it)"; exit 1
fi

# ---- 1. the C tests ------------------------------------------------------------------
progs=("$@")
if [ ${#progs[@]} -eq 0 ]; then
  for src in tests/c/test_*.c; do progs+=("$(basename "$src" .c)"); done
fi
for prog in "${progs[@]}"; do
  log="$BUILD/valgrind-$prog.log"
  echo "== valgrind $BUILD/$prog (log: $log)"
  "${VG[@]}" --log-file="$log" "$BUILD/$prog" > "$BUILD/valgrind-$prog.out"
  rc=$?
  tail -n 1 "$BUILD/valgrind-$prog.out"
  grep -E 'ERROR SUMMARY|definitely lost:|indirectly lost:|All heap blocks were freed' "$log" | sed 's/^==[0-9]*== /   /'
  if [ $rc -ne 0 ]; then
    echo "FAIL: $prog under valgrind exited with $rc (1 = a valgrind error or a failed check)"
    status=1
  else
    echo "ok: $prog is valgrind-clean"
  fi
done

# ---- 2. the corpus (and some benchmark queries) through the Python CLI ----------------
judge_python_log() { # $1 = valgrind log; prints a summary; returns 1 on polyccd errors
  python3 - "$1" <<'EOF'
import re, sys
path = sys.argv[1]
records, cur = [], []
for line in open(path, errors="replace"):
    m = re.match(r"==\d+== ?(.*)", line)
    if not m:
        continue
    text = m.group(1)
    if text == "":
        if cur:
            records.append(cur)
        cur = []
    else:
        cur.append(text)
if cur:
    records.append(cur)
heads = ("Invalid ", "Conditional jump", "Use of uninitialised", "Syscall param",
         "Mismatched free", "Source and destination overlap", "Argument ")
# polyccd code: the library (by object or source path, pccd:: or pccd_ functions) and the
# cffi wrappers _cffi_f_pccd_* of the bindings. Not cffi's one-time module initialisation
# (_cffi_init -> _my_Py_InitModule allocates a module definition it never frees).
ours = re.compile(r"libpolyccd\.so|\bpccd::|: pccd_\w+ \(|_cffi_f_pccd_\w+ \(|(^|/)lib/(util|arith|poly|motion|pred|narrow|boxes|range|scene|api)/")
mine, theirs = [], 0
for rec in records:
    head = rec[0]
    is_err = head.startswith(heads) or (
        "definitely lost" in head or "indirectly lost" in head) and "in loss record" in head
    if not is_err:
        continue
    if any(ours.search(f) for f in rec[1:]):
        mine.append(rec)
    else:
        theirs += 1
for rec in mine[:20]:
    print("   polyccd: " + "\n            ".join(rec[:14]))
print(f"   {len(mine)} error records in polyccd code, {theirs} elsewhere (CPython/numpy/cffi, not judged)")
sys.exit(1 if mine else 0)
EOF
}

run_py() { # $1 = log name, rest = arguments of python
  local name=$1; shift
  local log="$BUILD/valgrind-$name.log"
  echo "== valgrind $VPY $* (log: $log)"
  PYTHONMALLOC=malloc "${VG[@]}" --error-exitcode=0 --fullpath-after= --log-file="$log" \
    "$VPY" "$@" > "$BUILD/valgrind-$name.out" 2>&1
  local rc=$?
  tail -n 2 "$BUILD/valgrind-$name.out" | sed 's/^/   /'
  if [ $rc -ne 0 ]; then echo "FAIL: command exited with $rc"; status=1; fi
  if judge_python_log "$log"; then
    echo "ok: no valgrind error in polyccd code"
  else
    echo "FAIL: valgrind errors in polyccd code (see $log)"; status=1
  fi
}

if [ -x "$VPY" ] && "$VPY" -c "import polyccd" 2>/dev/null; then
  if [ -n "$(find corpus -name '*.json' -print -quit 2>/dev/null)" ]; then
    run_py corpus -m polyccd corpus corpus/
  else
    echo "== corpus/ has no *.json cases: corpus step skipped"
  fi
  files=()
  for f in $VALGRIND_QUERY_FILES; do [ -f "$f" ] && files+=("$f"); done
  if [ ${#files[@]} -gt 0 ]; then
    run_py queries -m polyccd queries "${files[@]}"
  else
    echo "== no benchmark query file found ($VALGRIND_QUERY_FILES): queries step skipped"
  fi
else
  echo "== $VPY cannot import polyccd (run make venv): Python steps skipped"
fi

if [ $status -eq 0 ]; then echo "valgrind: clean"; else echo "valgrind: FAILED"; fi
exit $status
