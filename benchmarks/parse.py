"""Parse benchmark: a 100k-line CAM-style program, cold and after one-line edits.

Prints the cold parse throughput (lines per second, the whole file into a ``ParsedDocument``
with an empty block cache) and the time to bring the document up to date after one-line
edits: a change within a line (the usual keystroke), a line inserted and a line deleted.
The budgets (foundation issue) are >= 100,000 lines/s cold and <= 5 ms after a one-line edit.

    python benchmarks/parse.py [--lines N] [--edits N]
"""

from __future__ import annotations

import argparse
import random
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from camgen import cam_program
from cncmacro.syntax.block_parser import BlockCache, parse_block
from cncmacro.syntax.document import ParsedDocument


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lines", type=int, default=100_000)
    ap.add_argument("--edits", type=int, default=200)
    ap.add_argument("--rounds", type=int, default=3, help="cold parses; the best is reported")
    args = ap.parse_args()

    text = cam_program(args.lines)
    n = text.count("\n")
    parse_block("#1=1")  # build the grammar's tables once, as a running server has
    colds = []
    for _ in range(args.rounds):
        t0 = time.perf_counter()
        doc = ParsedDocument(text, BlockCache())
        colds.append(time.perf_counter() - t0)
    errors = sum(b.has_error for b in doc.blocks)
    best = min(colds)
    print(f"program: {n} lines, {len(text) / 1e6:.1f} MB, {errors} syntax errors")
    print(f"cold parse: best {best * 1000:.0f} ms of {args.rounds} -> {n / best:,.0f} lines/s (budget >= 100,000)")

    rnd = random.Random(3)
    for kind in ("change within a line", "insert a line", "delete a line"):
        times = []
        for _ in range(args.edits):
            i = rnd.randrange(10, len(doc.lines) - 10)
            t0 = time.perf_counter()
            if kind == "change within a line":
                old = doc.lines[i]
                doc.apply_change(i, 0, i, len(old), f"G01 X{rnd.uniform(-99, 99):.3f} Y{rnd.uniform(-99, 99):.3f}")
            elif kind == "insert a line":
                doc.apply_change(i, 0, i, 0, f"#{rnd.randint(100, 199)}=#{rnd.randint(100, 199)}+{rnd.random():.4f}\n")
            else:
                doc.apply_change(i, 0, i + 1, 0, "")
            times.append(time.perf_counter() - t0)
        times.sort()
        p95 = times[int(0.95 * (len(times) - 1))]
        print(
            f"one-line edit ({kind}): median {statistics.median(times) * 1000:.3f} ms, "
            f"p95 {p95 * 1000:.3f} ms, max {times[-1] * 1000:.3f} ms (budget <= 5 ms)"
        )
    fresh = ParsedDocument(doc.text, BlockCache())
    same = fresh.blocks == doc.blocks and fresh.program == doc.program
    print(f"after {3 * args.edits} edits the document equals a fresh parse: {same}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
