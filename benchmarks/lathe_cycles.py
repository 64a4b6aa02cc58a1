"""Lathe cycle speed: a G71 of about 1,000 passes, on both lathe profiles.

The program roughs a Ø200 bar down to a cone (X0 at Z0 to X200 at Z-100) with a depth of cut of
0.1 mm (``G71 U0.1 R0.05``): 999 levels of four moves each, planned from the shape the cycle
reads, then the pass along the shape. Each run (parse included) is timed best of five, user CPU
time; the budget is 50 ms.

    python benchmarks/lathe_cycles.py
"""

from __future__ import annotations

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


def main() -> None:
    for dialect in ("gsk980tdi", "fanuc-0i-lathe"):
        user, wall, moves, status = min((run_once(dialect) for _ in range(5)), key=lambda r: r[0])
        verdict = "within" if user * 1000 <= BUDGET_MS else "OVER"
        print(f"{dialect}: G71 at 0.1 mm over Ø200: {moves:,} moves ({status}) in {user * 1000:.1f} ms user, "
              f"{wall * 1000:.1f} ms wall; {verdict} the budget of {BUDGET_MS:.0f} ms")  # fmt: skip


if __name__ == "__main__":
    main()
