"""Interpreter speed: a 600k-statement macro loop and 100,000 plain motion blocks.

The loop is ``WHILE[#2 LT 200000]DO1 / #1=#1+#2*2 / #2=#2+1 / END1``; the motion program is
generated straight-line G00/G01/G02/G03 blocks. Each is run best of five (this machine's
timings vary by tens of percent) and the user CPU time is printed. When LinuxCNC's ``rs274``
is installed, the equivalent O-word loop and the same motion blocks are run through
``rs274 -g`` side by side and the ratio is printed.

    python benchmarks/interp.py [--loops 200000] [--moves 100000]
"""

from __future__ import annotations

import argparse
import os
import random
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "server"))

from cncmacro.library.machine_file import MachineSettings
from cncmacro.machine import Machine


def loop_program(n: int) -> str:
    return f"O0001\n#1=0\n#2=0\nWHILE[#2 LT {n}]DO1\n#1=#1+#2*2\n#2=#2+1\nEND1\nM30\n"


def motion_blocks(n: int, seed: int = 7) -> list[str]:
    rnd = random.Random(seed)
    out = []
    x = y = 0.0
    for k in range(n):
        x = round(x + rnd.uniform(-5, 5), 3)
        y = round(y + rnd.uniform(-5, 5), 3)
        r = k % 10
        if r == 0:
            out.append(f"G00 X{x:.3f} Y{y:.3f} Z{rnd.uniform(1, 5):.3f}")
        elif r == 1:
            out.append(f"G02 X{x:.3f} Y{y:.3f} R{rnd.uniform(10, 20):.3f}")
        elif r == 2:
            out.append(f"G01 X{x:.3f} Y{y:.3f} Z{rnd.uniform(-3, 0):.3f} F{rnd.randint(100, 900)}.")
        else:
            out.append(f"G01 X{x:.3f} Y{y:.3f}")
    return out


def cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime


def run_ours(text: str, record_moves: bool = True) -> tuple[float, float, int, str]:
    """(user seconds, wall seconds, blocks, status) of one run, parse included."""
    c0, w0 = cpu(), time.perf_counter()
    m = Machine("fanuc", MachineSettings(max_blocks=10_000_000, date=20260101, time=0))
    m.planner.record_moves = record_moves
    m.start_file("bench.nc", text)
    status = m.run()
    return cpu() - c0, time.perf_counter() - w0, m.blocks, status


def best(text: str, rounds: int = 5) -> tuple[float, float, int, str]:
    results = [run_ours(text) for _ in range(rounds)]
    return min(results, key=lambda r: r[0])


def rs274_time(ngc: str) -> float | None:
    exe = shutil.which("rs274")
    if exe is None:
        return None
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "bench.ngc"
        path.write_text(ngc)
        times = []
        for _ in range(5):
            before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
            subprocess.run([exe, "-g", str(path)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False,
                           env={**os.environ, "DISPLAY": ""})  # fmt: skip
            times.append(resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before)
        return min(times)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--loops", type=int, default=200_000)
    ap.add_argument("--moves", type=int, default=100_000)
    args = ap.parse_args()

    loop = loop_program(args.loops)
    user, wall, blocks, status = best(loop)
    statements = 3 * args.loops
    print(
        f"macro loop: {statements:,} statements ({blocks:,} blocks, {status}) in {user:.2f} s user, {wall:.2f} s wall"
    )
    ngc_loop = (
        "#1=0\n#2=0\no100 while [#2 LT %d]\n#1=[#1+#2*2]\n#2=[#2+1]\no100 endwhile\nM2\n" % args.loops  # noqa: UP031
    )
    ref = rs274_time(ngc_loop)
    if ref is not None:
        print(f"  rs274: {ref:.2f} s user; cncmacro is {ref / user:.2f}x as fast (budget: at least 6x)")
    else:
        print("  rs274 is not installed (Debian package linuxcnc-uspace); no side-by-side figure")

    moves = motion_blocks(args.moves)
    program = "O0002\nG21 G17 G90 G94 F500\n" + "\n".join(moves) + "\nM30\n"
    user, wall, blocks, status = best(program)
    print(
        f"motion: {args.moves:,} blocks ({blocks:,} run, {status}) in {user:.2f} s user, {wall:.2f} s wall,"
        " parse included"
    )
    ref = rs274_time("G21 G17 G90 G94 F500\n" + "\n".join(moves) + "\nM2\n")
    if ref is not None:
        print(f"  rs274: {ref:.2f} s user; cncmacro is {ref / user:.2f}x as fast (budget: at least 1.4x)")


if __name__ == "__main__":
    main()
