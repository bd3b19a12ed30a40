"""Running benchmark CSV files against their truth column (`polyccd queries`)."""
import time
from dataclasses import dataclass, field
from typing import List, Tuple

import numpy as np

from ._csv import ROWS, kind_of, read_csv
from .. import collides_linear, solve


@dataclass
class FileReport:
    """The outcome of one CSV file; positives = queries polyccd reports colliding."""
    file: str
    kind: str
    queries: int
    positives: int
    false_positives: int
    false_negatives: int
    seconds_per_query: float
    mismatches: List[Tuple[int, bool, bool]] = field(default_factory=list)  # (query, truth, got)

    def as_json(self):
        """The --json line of formats.md."""
        return {"file": self.file, "kind": self.kind, "queries": self.queries,
                "positives": self.positives, "false_positives": self.false_positives,
                "false_negatives": self.false_negatives,
                "seconds_per_query": self.seconds_per_query}

    def line(self):
        """The human-readable summary line."""
        return (f"{self.file}: {self.kind}, {self.queries} queries, {self.positives} "
                f"positives, {self.false_positives} false positives, {self.false_negatives} "
                f"false negatives, {self.seconds_per_query * 1e6:.2f} us/query")


def decide_all(qs):
    """polyccd's decide-only answer for every query of a QuerySet, and the seconds taken."""
    answers = np.empty(len(qs.truth), dtype=bool)
    kind, t0, t1, inexact = qs.kind, qs.t0, qs.t1, qs.inexact
    start = time.perf_counter()
    for i in range(len(answers)):
        if i in inexact:
            answers[i] = solve(kind, inexact[i], time_tolerance=None, want_time=False,
                               want_exact=False).collides
        else:
            answers[i] = collides_linear(kind, t0[i], t1[i])
    return answers, time.perf_counter() - start


def run_file(path, kind=None):
    """Decides every query of a CSV file and compares with its truth column."""
    qs = read_csv(path, kind_of(path, kind))
    answers, seconds = decide_all(qs)
    truth = qs.truth
    n = len(truth)
    bad = np.nonzero(answers != truth)[0]
    return FileReport(
        file=str(path), kind=qs.kind, queries=n, positives=int(answers.sum()),
        false_positives=int((answers & ~truth).sum()),
        false_negatives=int((~answers & truth).sum()),
        seconds_per_query=seconds / n,
        mismatches=[(int(q), bool(truth[q]), bool(answers[q])) for q in bad])


def mismatch_lines(report, limit=10):
    """One line per wrong answer (the first `limit`), naming the query's CSV lines."""
    out = []
    for q, truth, got in report.mismatches[:limit]:
        what = "false positive" if got else "false negative"
        out.append(f"  {what}: query {q} (lines {q * ROWS + 1}-{(q + 1) * ROWS}): "
                   f"truth {int(truth)}, polyccd {int(got)}")
    if len(report.mismatches) > limit:
        out.append(f"  ... and {len(report.mismatches) - limit} more")
    return out
