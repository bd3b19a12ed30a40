"""`polyccd demo`: the real scenes (CGAL pinions, a drug in its protein pocket), the robot
arm, the simulator step, the degenerate primitive cases and the shared benchmark summary,
in that order. Without the `demo` extra (trimesh, gemmi, matplotlib) the real scenes and
the robot are skipped with a message naming the extra; the rest runs on numpy alone."""
from .. import __version__
from ..extras import need
from ._demo import query_dir, run_cases

OK, FAILED = 0, 1  # the command line's exit codes (cli.py)


def run_demo(out_dir, threads, run_queries):
    """Runs every part; returns the exit code. run_queries: the CLI's queries runner."""
    print(f"polyccd {__version__} demo: real scenes, a robot arm and a simulator step, checked exactly\n")
    status = OK
    try:  # the real scenes read meshes and molecules and draw them: the demo extra
        need("polyccd demo (the real scenes)", "demo", "trimesh", "gemmi", "matplotlib")
    except ModuleNotFoundError as e:
        print(f"real scenes and robot skipped: {e}\n")
    else:
        from ._demo_bodies import run_demo_scenes
        results = run_demo_scenes(out_dir, threads=threads)
        status = OK if all(r[0].collides for r in results.values()) else FAILED
        from ._demo_robot import run_robot_demo  # skips itself without yourdfpy / robot data
        print()
        status = max(status, OK if run_robot_demo(out_dir)[2] else FAILED)
        print()
    from ._demo_step import run_step_demo  # numpy only; its picture needs matplotlib
    status = max(status, OK if run_step_demo(out_dir, threads=threads)[0].collides else FAILED)
    print("\nexact answers for degenerate moving primitives\n")
    status = max(status, OK if run_cases(print) else FAILED)
    folder = query_dir()
    if folder is None:
        print("shared benchmark queries not found (set POLYCCD_QUERY_DIR to the "
              "ccd-queries folder); skipped")
        return status
    print(f"benchmark queries of {folder} (decide only, against the truth column):")
    return max(status, run_queries([folder], root=folder))
