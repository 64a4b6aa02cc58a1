"""Every speed budget of the editor and of ``cncmacro check`` on the shared generator's
programs, measured in one go and printed row by row beside its budget, with a verdict.

The programs are the shared benchmark generator's CAM programs (``gen_programs.py --style cam
--seed 1 --percent end``; the generator is not part of this repository: give its path with
``--generator`` or ``CNCMACRO_GENERATOR``) of 2,000, 20,000, 100,000 and 1,000,000 lines, and
``lathe_cycles.py --write``'s 20,000-line lathe program full of cycles. Each is opened alone in
a fresh ``cncmacro lsp`` (``lsp.py``'s client: open to the first and to the last diagnostics,
one-digit edits at the middle and near the end of the file, hovers on ``#`` variables, peak
memory), and the 100k and 1M-line programs are checked by ``cncmacro check`` (the best of
``--rounds`` by wall time, with its processor time and peak memory). A program of at most
20,000 lines is opened ``--opens`` times, each in a fresh server, and its open counts by the
median, as the shared harness counts its runs: a single open of 30 ms varies by a third from one
to the next on a 2-core machine. The library budget
(``check --jobs``) is ``check_library.py``'s; compensation's is ``cutter_comp.py``'s; the
budgets of the lathe cycles' passes are ``lathe_cycles.py``'s.

    python benchmarks/budgets.py --generator PATH/gen_programs.py [--sizes 2000,20000,100000,1000000]
        [--edits 20] [--hovers 50] [--rounds 2] [--opens 5] [--no-lathe]

Figures from a busy machine are not comparable: run it on a quiet one, twice. The load average
at the end is printed with the table.
"""

from __future__ import annotations

import argparse
import asyncio
import os
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from check_library import generator, program
from lathe_cycles import long_program
from lsp import ProgramFigures, measure_program, pct

# lines -> the budgets of a program of that size opened in the editor (ms, MB)
OPEN_FIRST = {2_000: 30.0, 20_000: 200.0, 100_000: 800.0, 1_000_000: 500.0}
OPEN_ALL = {100_000: 600.0, 1_000_000: 6_000.0}
EDIT_P95 = {20_000: 10.0, 100_000: 20.0, 1_000_000: 100.0}
HOVER_P95 = {20_000: 2.0, 100_000: 2.0, 1_000_000: 5.0}
PEAK_MB = {20_000: 90.0, 100_000: 200.0, 1_000_000: 600.0}
CHECK_S = {100_000: 0.8, 1_000_000: 6.0}


@dataclass
class Checked:
    """One ``cncmacro check`` of a file: the best wall time, its processor time, peak memory."""

    seconds: float
    cpu: float
    peak_mb: float


def check_file(path: Path, rounds: int) -> Checked:
    """``cncmacro check PATH``, the best of ``rounds`` by wall time."""
    best: Checked | None = None
    for _ in range(rounds):
        start = time.perf_counter()
        child = subprocess.Popen([sys.executable, "-m", "cncmacro", "check", str(path)],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)  # fmt: skip
        _, status, usage = os.wait4(child.pid, 0)
        took = time.perf_counter() - start
        err = child.stderr.read().decode("utf-8", "replace") if child.stderr else ""
        child.returncode = os.waitstatus_to_exitcode(status)
        if child.returncode not in (0, 1):
            raise SystemExit(f"cncmacro check {path.name}: exit status {child.returncode}\n{err}")
        run = Checked(took, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024)
        if best is None or run.seconds < best.seconds:
            best = run
    assert best is not None
    return best


MEDIAN_UP_TO = 20_000  # lines: a program this small is opened ``--opens`` times


def measured(path: Path, edits: int, hovers: int, opens: int) -> ProgramFigures:
    """``measure_program`` of ``path`` opened ``opens`` times, each in a fresh server: the open's
    figures are the medians; the edits', hovers' and memory's are those of every open together."""
    runs = [asyncio.run(measure_program(path, edits, hovers)) for _ in range(max(1, opens))]
    f = runs[0]
    if len(runs) > 1:
        firsts = [r.first_ms for r in runs]
        f.first_ms = statistics.median(firsts)
        f.all_ms = statistics.median(r.all_ms for r in runs)
        for r in runs[1:]:
            for place, ms in r.edits_ms.items():
                f.edits_ms.setdefault(place, []).extend(ms)
            f.hovers_ms.extend(r.hovers_ms)
            f.timeouts += r.timeouts
            if r.peak_mb is not None:
                f.peak_mb = max(f.peak_mb or 0.0, r.peak_mb)
        f.notes.append(f"opened {len(runs)} times, first diagnostics {', '.join(f'{x:.0f}' for x in firsts)} ms: "
                       "the median counts")  # fmt: skip
    return f


def number(value: float) -> str:
    """A figure as the table shows it: two decimals under 10, whole numbers above."""
    return f"{value:,.2f}" if value < 10 else f"{value:,.0f}"


def verdict(value: float, limit: float) -> str:
    return "within" if value <= limit else "OVER"


def rows_of(f: ProgramFigures) -> list[tuple[str, float, float, str]]:
    """(row, measured, budget, unit) for each budget of an opened program of ``f.lines``."""
    out: list[tuple[str, float, float, str]] = []
    size = f.lines
    key = min(OPEN_FIRST, key=lambda k: abs(k - size))
    label = f"{key // 1000:,}k" if key < 1_000_000 else "1M"
    if key == size or abs(key - size) / key < 0.05:
        out.append((f"open -> first diagnostics, {label}", f.first_ms, OPEN_FIRST[key], "ms"))
        if key in OPEN_ALL:
            out.append((f"open -> all diagnostics, {label}", f.all_ms, OPEN_ALL[key], "ms"))
        edits = [ms for place in f.edits_ms.values() for ms in place]
        if key in EDIT_P95 and edits:
            out.append((f"edit p95, {label}", pct(edits, 0.95), EDIT_P95[key], "ms"))
        if key in HOVER_P95 and f.hovers_ms:
            out.append((f"hover p95, {label}", pct(f.hovers_ms, 0.95), HOVER_P95[key], "ms"))
        if key in PEAK_MB and f.peak_mb:
            out.append((f"peak memory, {label}", f.peak_mb, PEAK_MB[key], "MB"))
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--generator", default=os.environ.get("CNCMACRO_GENERATOR"),
                        help="the shared generator gen_programs.py (default: $CNCMACRO_GENERATOR)")  # fmt: skip
    parser.add_argument("--sizes", default="2000,20000,100000,1000000", help="the CAM programs' lines")
    parser.add_argument("--edits", type=int, default=20, help="edits at each of two places (default 20)")
    parser.add_argument("--hovers", type=int, default=50, help="hovers on # variables (default 50)")
    parser.add_argument("--rounds", type=int, default=2, help="runs of each check, the best counted (default 2)")
    parser.add_argument("--opens", type=int, default=5,
                        help=f"opens of a program of at most {MEDIAN_UP_TO:,} lines, the median counted")  # fmt: skip
    parser.add_argument("--no-lathe", action="store_true", help="leave out the 20k-line lathe program")
    args = parser.parse_args()
    if not args.generator:
        parser.error("give the shared generator's path: --generator PATH or CNCMACRO_GENERATOR=PATH")
    gen = generator(args.generator)
    sizes = [int(x) for x in args.sizes.split(",")]
    table: list[tuple[str, float, float, str]] = []
    opened: dict[str, ProgramFigures] = {}
    with tempfile.TemporaryDirectory() as tmp:
        for size in sizes:
            path = Path(tmp) / f"cam_{size}" / f"cam_{size}.nc"
            path.parent.mkdir()
            path.write_text(program(gen, size, 1), encoding="ascii", newline="")
            figures = measured(path, args.edits, args.hovers, args.opens if size <= MEDIAN_UP_TO else 1)
            opened[f"cam {size:,}"] = figures
            table += rows_of(figures)
            if size in CHECK_S:
                c = check_file(path, args.rounds)
                label = f"{size // 1000:,}k" if size < 1_000_000 else "1M"
                table.append((f"`cncmacro check`, {label} (CPU {c.cpu:.2f} s, {c.peak_mb:.0f} MB)", c.seconds,
                              CHECK_S[size], "s"))  # fmt: skip
            print(f"measured {path.name}", file=sys.stderr)
        if not args.no_lathe:
            path = Path(tmp) / "lathe" / "lathe_20k.nc"
            path.parent.mkdir()
            path.write_text(long_program(20_000), encoding="ascii", newline="")
            figures = measured(path, args.edits, args.hovers, args.opens)
            opened["lathe 20,000"] = figures
            mill = opened.get("cam 20,000")
            limit = mill.first_ms if mill is not None else OPEN_FIRST[20_000]
            against = "the 20k mill program's, this run" if mill is not None else "the 20k budget"
            table.append((f"open -> diagnostics, 20k lathe program (as fast as {against})", figures.all_ms,
                          limit, "ms"))  # fmt: skip
            print(f"measured {path.name}", file=sys.stderr)
    print(f"| budget (load average {os.getloadavg()[0]:.2f} at the end) | measured | limit | verdict |")
    print("| --- | ---: | ---: | --- |")
    for row, value, limit, unit in table:
        print(f"| {row} | {number(value)} {unit} | {number(limit)} {unit} | {verdict(value, limit)} |")
    print()
    for name, f in opened.items():
        edits = {f"{p:.0%}": f"{statistics.median(ms):.1f} / {pct(ms, 0.95):.1f}" for p, ms in f.edits_ms.items() if ms}
        print(f"{name} lines: {f.findings} findings in the first diagnostics; edits p50 / p95 ms {edits}; "
              f"open first / all {f.first_ms:,.0f} / {f.all_ms:,.0f} ms")  # fmt: skip
        for note in f.notes:
            print(f"  {note}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
