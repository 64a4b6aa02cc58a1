"""Static-check benchmark: ``static_diagnostics`` on a generated 100k-line CAM program.

Prints the time of the static checks alone (the file already parsed), best of a few rounds,
and how many diagnostics they found. The budget is 0.3 s for 100,000 lines.

    python benchmarks/static_checks.py [--lines N] [--rounds N]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from camgen import cam_program
from cncmacro.analysis.checks.static_checks import static_diagnostics
from cncmacro.dialects import get_dialect
from cncmacro.library.machine_file import MachineSettings
from cncmacro.library.programs import ProgramLibrary
from cncmacro.syntax.block_parser import BlockCache
from cncmacro.syntax.document import ParsedDocument


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lines", type=int, default=100_000)
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()

    text = cam_program(args.lines)
    doc = ParsedDocument(text, BlockCache())
    dialect = get_dialect("fanuc")
    settings = MachineSettings()
    times = []
    found = []
    for _ in range(args.rounds):
        t0 = time.perf_counter()
        found = static_diagnostics(doc.program, "CAM.nc", dialect, settings, ProgramLibrary())
        times.append(time.perf_counter() - t0)
    print(f"lines: {len(doc.lines)}")
    print(f"static checks: best {min(times):.3f} s, worst {max(times):.3f} s of {args.rounds} rounds")
    print(f"diagnostics: {len(found)}")
    for d in found[:5]:
        print(f"  {d.line + 1}:{d.column + 1}: {d.severity}: {d.message} [{d.code}]")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
