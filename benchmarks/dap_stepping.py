"""Debugger speed: how fast a continue runs, with and without breakpoints, and a step back.

The program is the loop ``WHILE[#2 LT 100000]DO1 / #1=#1+#2*2 / #2=#2+1 / END1`` (400,003
blocks). A continue with no breakpoints runs the interpreter in chunks at full speed; with a
breakpoint anywhere it checks every block. Both keep the step-back history. Each is run best
of three and the wall time is printed.

    python benchmarks/dap_stepping.py [--loops 100000]
"""

from __future__ import annotations

import argparse
import time

from cncmacro.debugging.breakpoints import Breakpoints, LineBreakpoint
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import CONTINUE, Stepper
from cncmacro.library.machine_file import MachineSettings
from cncmacro.library.programs import ProgramLibrary
from cncmacro.machine import Machine


def one_run(text: str, with_breakpoint: bool) -> tuple[float, int, float]:
    m = Machine("fanuc", MachineSettings(max_blocks=10**9, date=20261122, time=80000), ProgramLibrary())
    m.start_file("LOOP.nc", text)
    breakpoints = Breakpoints()
    breakpoints.bind(m)
    if with_breakpoint:  # a breakpoint on a line the loop never reaches
        breakpoints.at[("elsewhere.nc", 0)] = [LineBreakpoint(1, path="elsewhere.nc", line=0)]
    history = History()
    history.reset(m)
    stepper = Stepper(m, breakpoints, history, lambda text, category: None)
    start = time.perf_counter()
    stepper.run(CONTINUE)
    elapsed = time.perf_counter() - start
    blocks = m.blocks
    start = time.perf_counter()
    history.go_to(m, blocks - history.interval // 2)
    back = time.perf_counter() - start
    return elapsed, blocks, back


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--loops", type=int, default=100_000)
    args = parser.parse_args()
    text = f"#2=0\nWHILE[#2 LT {args.loops}]DO1\n#1=#1+#2*2\n#2=#2+1\nEND1\nM30\n"
    for label, with_breakpoint in (("continue, no breakpoints", False), ("continue, a breakpoint set", True)):
        runs = [one_run(text, with_breakpoint) for _ in range(3)]
        elapsed, blocks, back = min(runs)
        print(f"{label:28} {blocks} blocks in {elapsed:.3f} s ({blocks / elapsed / 1e6:.2f}M blocks/s); "
              f"a step back replaying {History().interval // 2} blocks: {back * 1000:.1f} ms")  # fmt: skip


if __name__ == "__main__":
    main()
