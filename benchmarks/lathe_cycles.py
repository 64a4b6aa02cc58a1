"""Lathe cycle speed: a G71 of about 1,000 passes, on both lathe profiles.

The program roughs a Ø200 bar down to a cone (X0 at Z0 to X200 at Z-100) with a depth of cut of
0.1 mm (``G71 U0.1 R0.05``): 999 levels of four moves each, planned from the shape the cycle
reads, then the pass along the shape. Each run (parse included) is timed best of five, user CPU
time; the budget is 50 ms.

    python benchmarks/lathe_cycles.py
    python benchmarks/lathe_cycles.py --write lathe_20k.nc [--lines 20000]

With ``--write`` it writes instead a lathe program of about that many lines, full of cycles (a
G71/G70 shaft, a G92 thread repeated at four depths, a G90 and a G94 with taper, a G75 groove
and a G76 thread per part, each part with its own labels), for ``benchmarks/lsp.py --program``:
it opens in the editor as fast as the generated mill program of the same size.
"""

from __future__ import annotations

import argparse
import resource
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "server"))

from cncmacro.library.machine_file import MachineSettings
from cncmacro.machine import Machine

PROGRAM = """O0001
G97 S800 M03
G99
G00 X202. Z2.
G71 U0.1 R0.05
G71 P10 Q20 U0 W0 F0.25
N10 G00 X0.
G01 Z0.
N20 X200. Z-100.
M30
"""
BUDGET_MS = 50.0


def cpu() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_utime


def run_once(dialect: str) -> tuple[float, float, int, str]:
    """(user seconds, wall seconds, moves, status) of one run, parse included."""
    c0, w0 = cpu(), time.perf_counter()
    m = Machine(dialect, MachineSettings(max_blocks=1_000_000, date=20260101, time=0))
    m.start_file("bench.nc", PROGRAM)
    status = m.run()
    return cpu() - c0, time.perf_counter() - w0, len(m.planner.moves), str(status)


def part(k: int) -> list[str]:
    """One part of the long program: its cycles, labelled N(10k+…) so no two parts share a label."""
    n = 1000 + 100 * k
    d = 40 + k % 7
    return [
        f"(PART {k})", "T0101", "G97 S800 M03", f"G00 X{d + 2}. Z2.", "G71 U1.5 R0.5",
        f"G71 P{n + 1} Q{n + 2} U0.4 W0.1 F0.22", f"N{n + 1} G00 X{d - 20}.", "G01 Z0 F0.1",
        f"X{d - 16}. Z-2.", "Z-18.", f"G02 X{d - 8}. Z-22. R4.", "G01 Z-35.", f"N{n + 2} X{d + 2}.",
        f"G70 P{n + 1} Q{n + 2}", "G00 X100. Z100.", "T0202", "G00 X32. Z3.",
        "G92 X29.2 Z-30. F1.5", "X28.6", "X28.2", "X28.05", "G90 X30. Z-20. R-1. F0.2", "G94 X20. Z-1. R-0.5 F0.15",
        "G75 R0.5", "G75 X24. Z-28. P1500 Q2500 F0.08", "G76 P010060 Q100 R0.05", "G76 X28.05 Z-30. P975 Q400 F1.5",
        "G00 X100. Z100.", "M05",
    ]  # fmt: skip


def long_program(lines: int) -> str:
    out = ["%", "O0100 (cncmacro: dialect=fanuc-0i-lathe)", "G50 S2500", "G99 G18"]
    k = 0
    while len(out) < lines - 2:
        out.extend(part(k))
        k += 1
    return "\n".join([*out, "M30", "%"]) + "\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--write", type=Path, help="write a long lathe program here instead of timing")
    ap.add_argument("--lines", type=int, default=20_000)
    args = ap.parse_args()
    if args.write is not None:
        args.write.write_text(long_program(args.lines), encoding="utf-8")
        print(f"wrote {args.write} ({args.lines:,} lines)")
        return
    for dialect in ("gsk980tdi", "fanuc-0i-lathe"):
        user, wall, moves, status = min((run_once(dialect) for _ in range(5)), key=lambda r: r[0])
        verdict = "within" if user * 1000 <= BUDGET_MS else "OVER"
        print(f"{dialect}: G71 at 0.1 mm over Ø200: {moves:,} moves ({status}) in {user * 1000:.1f} ms user, "
              f"{wall * 1000:.1f} ms wall; {verdict} the budget of {BUDGET_MS:.0f} ms")  # fmt: skip


if __name__ == "__main__":
    main()
