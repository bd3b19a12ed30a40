"""The polyccd command line (docs/formats.md, "The command line").

Exit status: 0 success; 1 a failed case, a wrong answer or an internal error; 2 an input
error (the message on stderr names the file and the place in it).

check, index, corpus and queries take --workers N / --scheduler ADDRESS to run on a
dask.distributed cluster (polyccd.apps.distributed: an embedded LocalCluster of N worker
processes, or the running scheduler at ADDRESS); the output is the serial run's, in the
same order. Long runs show a progress bar on stderr when stdout and stderr are
terminals, never with --quiet (polyccd.apps._progress).
"""
import argparse
import contextlib
import functools
import json
import sys

import polyccd
from polyccd import Error, Index, InputError, Limits, __version__
from ._corpus import (DEFAULT_TOLERANCE, check_case, files_under, read_case, solve_case,
                      solve_scene_case)
from ._csv import CSV_KINDS
from ._output import check_json, index_json
from ._queries import mismatch_lines, run_file
from ._progress import bar, echo
from . import _reading
from ._reading import read_within
from ._scene_file import load_scene

OK, FAILED, BAD_INPUT = 0, 1, 2


def _distributed(args):
    """True when the run goes to a dask cluster (--workers or --scheduler given)."""
    return getattr(args, "workers", None) is not None or getattr(args, "scheduler", None)


@contextlib.contextmanager
def _cluster(args):
    """The dask Client of --workers / --scheduler (polyccd.apps.distributed.cluster)."""
    try:
        from . import distributed
    except ImportError as e:
        raise InputError(f"--workers / --scheduler: {e}") from None
    with distributed.cluster(scheduler=args.scheduler, workers=args.workers) as client:
        yield distributed, client


def _progress(args):
    """None (automatic: a bar on terminals) or False (--quiet)."""
    return False if getattr(args, "quiet", False) else None


def _error(message):
    echo(f"polyccd: {message}", file=sys.stderr)


def _check_serial(files, threads, progress, limits=None, decide=False):
    """(SceneResult | Result | InputError) per file, in order (--max-seconds: read + solve)."""
    with bar(len(files), "check", "file", progress if len(files) > 1 else False) as b:
        for path in files:
            try:
                (what, case), mine = read_within(read_case, path, limits)
                yield (solve_scene_case(case, limits=mine, threads=threads,
                                        first_contact=not decide) if what == "scene"
                       else solve_case(case, mine))
            except InputError as e:
                yield e
            b.update()


def cmd_check(args):
    """One JSON result per file: for one file exactly the object of formats.md; for
    several, one line per file in order, each with "file" first."""
    files = args.file
    status = OK
    with contextlib.ExitStack() as stack:
        if _distributed(args) and args.decide:
            _error("--decide: not with a cluster (--scheduler / --workers)")
            return BAD_INPUT
        if _distributed(args):
            distributed, client = stack.enter_context(_cluster(args))
            results = distributed.check_map(files, threads=args.threads, client=client,
                                            limits=_limits(args),
                                            progress=_progress(args))
        else:
            results = _check_serial(files, args.threads, _progress(args), _limits(args),
                                    args.decide)
        stack.callback(results.close)  # the bar ends (and the cluster's tasks) before more output
        for path, result in zip(files, results):
            if isinstance(result, Exception):  # this file's error; the others go on
                bug = not isinstance(result, InputError)  # then an InternalError: status 1
                _error(f"{path}: {type(result).__name__ + ': ' if bug else ''}{result}")
                status = status or FAILED if bug else BAD_INPUT
                continue
            out = check_json(result, args.decide)
            echo(json.dumps(out if len(files) == 1 else {"file": path, **out}))
    return status


def cmd_index(args):
    """Indexes one body of a scene file (--stored, default the first) and checks every
    other body against the index; one JSON line per query body, in file order."""
    errors = []
    try:
        bodies, options, _ = load_scene(args.file)
        names = [b.name for b in bodies]
        stored = 0
        if args.stored is not None:
            if args.stored not in names:
                raise InputError(f"--stored: no body is named \"{args.stored}\" (the bodies are "
                                 + ", ".join(f'"{n}"' for n in names) + ")")
            stored = names.index(args.stored)
        tolerance = options.time_tolerance or DEFAULT_TOLERANCE
        try:
            ix = Index(bodies[stored])
        except InputError as e:
            raise InputError(f"bodies[{stored}].{e}") from None
        others = [k for k in range(len(bodies)) if k != stored]
        options = dict(time_tolerance=tolerance, all_contacts=args.all_contacts,
                       threads=args.threads, broad_phase=args.broad_phase, limits=_limits(args),
                       min_distance=options.min_distance)
        for k in others:  # every query motion checked first, as the serial run meets them
            if bodies[k].motion is not None:
                try:
                    bodies[k].motion.validate()
                except InputError as e:
                    raise InputError(f"bodies[{k}].motion: {e}") from None
        lines = []
        with contextlib.ExitStack() as stack:
            queries = [bodies[k] for k in others]
            if _distributed(args):
                distributed, client = stack.enter_context(_cluster(args))
                results = distributed.index_map(ix, queries, client=client,
                                                progress=_progress(args), **options)
            else:
                results = _index_serial(ix, queries, options, _progress(args))
            stack.callback(results.close)  # the bar ends before more output
            for j, (k, r) in enumerate(zip(others, results)):
                if isinstance(r, Exception):  # this query's error; the others go on
                    errors.append(f"{args.file}: bodies[{k}]: " + str(r).removeprefix(f"queries[{j}]: "))
                else:
                    lines.append(json.dumps(index_json(names[stored], names[k], r, args.all_contacts)))
    except InputError as e:
        _error(f"{args.file}: {e}")
        return BAD_INPUT
    for line in lines:
        print(line)
    if errors:  # one line each
        _error("\npolyccd: ".join(errors))
    return BAD_INPUT if errors else OK


def _index_serial(ix, queries, options, progress):
    with bar(len(queries), "index queries", "query", progress) as b:
        for j, q in enumerate(queries):
            try:
                yield ix.query(q, **options)
            except InputError as e:
                yield type(e)(f"queries[{j}]: {e}")
            b.update()


def cmd_corpus(args):
    try:
        files = files_under(args.paths, "*.json")
    except InputError as e:
        _error(str(e))
        return BAD_INPUT
    if not files:
        _error(f"no *.json case under {', '.join(args.paths)}")
    failed = 0
    with contextlib.ExitStack() as stack:
        if _distributed(args) and files:
            distributed, client = stack.enter_context(_cluster(args))
            outcomes = distributed.corpus_map(files, client=client, progress=_progress(args))
        else:
            outcomes = _corpus_serial(files, _progress(args))
        stack.callback(outcomes.close)  # the bar ends before the summary line
        for path, reasons in zip(files, outcomes):
            reasons = [str(reasons)] if isinstance(reasons, Exception) else reasons  # corpus_map
            if reasons:
                failed += 1
                echo(f"FAIL {path}: " + "; ".join(reasons))
    print(f"{len(files) - failed} passed, {failed} failed")
    return FAILED if failed else OK


def _corpus_serial(files, progress):
    with bar(len(files), "corpus", "case", progress) as b:
        for path in files:
            yield check_case(path)
            b.update()


def run_queries(paths, kind=None, as_json=False, out=echo, root=None, args=None):
    """Runs benchmark CSV files (and folders of them); the exit status. Files are
    named relative to root when given; args: the --workers / --scheduler / --quiet
    options (None: serial, automatic progress bar)."""
    try:
        files = files_under(paths, "*.csv")
    except InputError as e:
        _error(str(e))
        return BAD_INPUT
    if not files:
        _error(f"no *.csv file under {', '.join(map(str, paths))}")
        return BAD_INPUT
    reports = []
    with contextlib.ExitStack() as stack:
        progress = _progress(args)
        if args is not None and _distributed(args):
            distributed, client = stack.enter_context(_cluster(args))
            outcomes = distributed.queries_map(files, kind, client=client, progress=progress)
        else:
            outcomes = _queries_serial(files, kind, progress)
        stack.callback(outcomes.close)  # the bar ends before the total line
        bad = [_report_queries(path, r, root, as_json, out, reports) for path, r in zip(files, outcomes)]
    if any(bad):  # the first bad file's status (the others were still run)
        return next(b for b in bad if b)
    if not as_json:
        n = sum(r.queries for r in reports)
        seconds = sum(r.seconds_per_query * r.queries for r in reports)
        out(f"total: {len(reports)} files, {n} queries, "
            f"{sum(r.positives for r in reports)} positives, "
            f"{sum(r.false_positives for r in reports)} false positives, "
            f"{sum(r.false_negatives for r in reports)} false negatives, "
            f"{seconds / n * 1e6:.2f} us/query")
    return FAILED if any(r.mismatches for r in reports) else OK


def _queries_serial(files, kind, progress):
    with bar(len(files), "queries", "file", progress) as b:
        for path in files:
            try:
                yield run_file(path, kind)
            except InputError as e:
                yield InputError(f"{path}: {e}")
            b.update()


def _report_queries(path, report, root, as_json, out, reports):
    """Prints one file's report (or its error: then returns the exit status)."""
    if isinstance(report, Exception):  # InputError: status 2; a bug (InternalError): 1
        _error(f"{'' if isinstance(report, InputError) else type(report).__name__ + ': '}{report}")
        return BAD_INPUT if isinstance(report, InputError) else FAILED
    if root is not None:
        report.file = str(path.relative_to(root))
    reports.append(report)
    out(json.dumps(report.as_json()) if as_json else report.line())
    for line in mismatch_lines(report):
        echo(line, file=sys.stderr if as_json else sys.stdout)
    return None


def cmd_queries(args):
    return run_queries(args.files, args.kind, args.json, args=args)


def cmd_demo(args):
    from ._demo_all import run_demo
    return run_demo(args.out, args.threads, run_queries)


def _positive(kind):
    def parse(text):
        try:
            x = kind(text)
        except ValueError:
            x = 0
        if not (x > 0 and x < float("inf")):
            raise argparse.ArgumentTypeError(f"expected a number > 0, got {text!r}")
        return x
    return parse


def _limit_flags(c):
    """--max-seconds, --max-work, --max-number-bits (polyccd.Limits, pccd_config)."""
    c.add_argument("--max-seconds", type=_positive(float), metavar="S",
                   help="end a file's check after S seconds (exit 2 with the limit's message)")
    c.add_argument("--max-work", type=_positive(int), metavar="N",
                   help="end a file's check after N work steps (deterministic: the same "
                   "files end on every machine and thread count)")
    c.add_argument("--max-number-bits", type=_positive(int), metavar="B",
                   help=f"largest input number in bits (default {Limits().max_number_bits}); "
                   "raise it for inputs with longer numbers")
    c.add_argument("--max-file-mb", type=_positive(int), metavar="MB",
                   default=_reading.DEFAULT_MAX_FILE_MB, help="largest file read, in MiB "
                   f"(default {_reading.DEFAULT_MAX_FILE_MB}; reading takes ~48x it in memory)")


def _limits(args):
    """The polyccd.Limits of the flags (None: the defaults)."""
    if args.max_seconds is None and args.max_work is None and args.max_number_bits is None:
        return None
    return Limits(max_seconds=args.max_seconds, max_work=args.max_work,
                  max_number_bits=args.max_number_bits or Limits().max_number_bits)


def _threads(text):
    """A thread count; the range is the library's rule (polyccd.usable_threads)."""
    if not (text.isascii() and text.isdigit()):
        raise argparse.ArgumentTypeError(f"expected an integer, got {text!r}")
    try:
        polyccd.usable_threads(int(text))
    except InputError as e:
        raise argparse.ArgumentTypeError(str(e).replace("requested: ", "", 1)) from None
    return int(text)


def _workers(text):
    try:
        n = int(text)
    except ValueError:
        n = 0
    if n < 1:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, got {text!r}")
    return n


def _cluster_flags(c):
    """--workers, --scheduler (polyccd.apps.distributed) and --quiet."""
    c.add_argument("--workers", type=_workers, metavar="N",
                   help="run on a dask cluster: an embedded LocalCluster of N worker "
                   "processes (with --scheduler: wait for N workers); needs dask[distributed]")
    c.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on the running dask scheduler at ADDRESS (tcp://host:port)")
    c.add_argument("--quiet", action="store_true",
                   help="no progress bar (shown only when stdout and stderr are terminals)")


def parser():
    p = argparse.ArgumentParser(
        prog="polyccd", allow_abbrev=False, description="Exact continuous collision "
        "detection of moving primitives (file formats: docs/formats.md in the source "
        "repository).")
    p.add_argument("--version", action="version", version=f"polyccd {__version__}")
    # No abbreviated options in the subcommands either (`--thread` is not `--threads`).
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND",
                           parser_class=functools.partial(argparse.ArgumentParser,
                                                          allow_abbrev=False))
    p.subcommands = sub.choices  # name -> its parser (parse() reports through it)
    c = sub.add_parser("check", help="solve one scene or query file and print the JSON result "
                       "(several files: one JSON line per file, with \"file\")")
    c.add_argument("file", nargs="+", metavar="FILE.json")
    c.add_argument("--threads", type=_threads, default=1,
                   help="worker threads for scenes, 1 to 1024 (default 1)")
    c.add_argument("--decide", action="store_true",
                   help="scene files: decide mode (does anything touch on [0, 1]?), stopping "
                   "at the first pair found in contact; its first_contact is then an "
                   "enclosure of one of its contact times, not necessarily the first")
    _limit_flags(c)
    _cluster_flags(c)
    c.set_defaults(run=cmd_check)
    c = sub.add_parser("index", help="index one body of a scene file and check every other "
                       "body against it (one JSON line per query body)")
    c.add_argument("file", metavar="SCENE.json")
    c.add_argument("--stored", metavar="NAME", help="the body to index (default: the first)")
    c.add_argument("--broad-phase", choices=sorted(polyccd.BROAD_PHASES), default="auto",
                   help="how candidate feature pairs are found (default auto; all give the "
                   "same answers)")
    c.add_argument("--all-contacts", action="store_true",
                   help="list every touching feature pair with its own first time")
    c.add_argument("--threads", type=_threads, default=1, help="worker threads, 1 to 1024 "
                   "(default 1)")
    _limit_flags(c)
    _cluster_flags(c)
    c.set_defaults(run=cmd_index)
    c = sub.add_parser("corpus", help="check every *.json case under the paths "
                       "against its expect block")
    c.add_argument("paths", nargs="+", metavar="PATH")
    _cluster_flags(c)
    c.set_defaults(run=cmd_corpus)
    c = sub.add_parser("queries", help="run benchmark CSV files (or folders of them) "
                       "against their truth column")
    c.add_argument("files", nargs="+", metavar="FILE.csv")
    c.add_argument("--json", action="store_true", help="one JSON object per file and line")
    c.add_argument("--kind", choices=CSV_KINDS, help="the query kind (default: from the "
                   "folder name vertex-face/ or edge-edge/)")
    _cluster_flags(c)
    c.set_defaults(run=cmd_queries)
    c = sub.add_parser("demo", help="two real scenes (CGAL pinions, darunavir in HIV protease) "
                       "and a Panda arm past a thin plate with PNGs, illustrative primitive "
                       "answers, the benchmark summary")
    c.add_argument("--out", default="build/demo", help="folder of the PNGs (default build/demo)")
    c.add_argument("--threads", type=_threads, default=2, help="worker threads, 1 to 1024 "
                   "(default 2)")
    c.set_defaults(run=cmd_demo)
    return p


def parse(argv=None):
    """The arguments; a usage error exits 2 with the usage of the parser concerned: an
    option no subcommand knows is reported by that subcommand (its usage, its options),
    not by the top level."""
    p = parser()
    args, unknown = p.parse_known_args(argv)
    if unknown:
        p.subcommands[args.command].error("unrecognized arguments: " + " ".join(unknown))
    return args


def main(argv=None):
    args = parse(argv)
    _reading.max_file_bytes = getattr(args, "max_file_mb", _reading.DEFAULT_MAX_FILE_MB) << 20
    try:
        return args.run(args)
    except Error as e:  # InternalError: a bug, reported without a traceback
        _error(f"{type(e).__name__}: {e}")
        return FAILED
    except MemoryError as e:
        _error(f"out of memory: {e}")
        return FAILED
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        sys.stderr.close()  # the reader went away (e.g. `| head`): nothing more to say
        return FAILED
