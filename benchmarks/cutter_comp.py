"""Cutter radius compensation's cost: a CAM contour of 100,000 G01 blocks (a circle of R50 in
steps of 0.5°, a Z step every lap) run with and without ``G41 D1`` (radius 3), best of five, user
CPU time of the run alone (parse included), of ``cncmacro run`` as a whole (text output) and of
the editor's open (the file opened and analysed to all its diagnostics, in-process, as
``analysis.py`` does). User CPU time, which another process on the machine disturbs less than
the wall clock. ``--write DIR`` also leaves the two programs there (``plain.nc``, ``comp.nc``),
for timing an open over a real language server.

    python benchmarks/cutter_comp.py [--moves 100000] [--write DIR]
"""

from __future__ import annotations

import argparse
import gc
import math
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "server"))

from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.library.machine_file import MachineSettings
from cncmacro.machine import Machine


def contour(n: int, compensated: bool) -> str:
    """The contour's program text."""
    out = ["O0003", "G10 L12 P1 R3.", "G21 G17 G90 G94 F800", "G00 X60. Y-10.",
           ("G41 D1 " if compensated else "") + "G01 X50. Y0"]  # fmt: skip
    for k in range(1, n):
        a = math.radians(0.5 * k)
        z = f" Z{-0.001 * k:.3f}" if k % 720 == 0 else ""
        out.append(f"X{50 * math.cos(a):.3f} Y{50 * math.sin(a):.3f}{z}")
    out += [("G40 " if compensated else "") + "G00 X60. Y-10.", "M30"]
    return "\n".join(out) + "\n"


def cpu() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_utime


def in_process(text: str, rounds: int = 5) -> float:
    """Best user seconds of a run of ``text`` (moves recorded, as ``cncmacro run`` keeps them)."""
    best = math.inf
    for _ in range(rounds):
        c0 = cpu()
        m = Machine("fanuc", MachineSettings(max_blocks=10_000_000, date=20260101, time=0))
        m.start_file("contour.nc", text)
        m.run()
        best = min(best, cpu() - c0)
        del m
        gc.collect()  # the last round's machine freed before the next round's clock starts
    return best


def editor_open(text: str, rounds: int = 5) -> float:
    """Best user seconds of an open of ``text`` to all its diagnostics (``WorkspaceAnalysis``)."""
    best = math.inf
    for _ in range(rounds):
        c0 = cpu()
        ws = WorkspaceAnalysis(settings=MachineSettings(date=20260101, time=0))
        ws.open("bench/contour.nc", text, 0)
        result = ws.analyze("bench/contour.nc")
        assert result is not None
        best = min(best, cpu() - c0)
        del ws, result
        gc.collect()  # the last round's analysis freed before the next round's clock starts
    return best


def command(path: Path, rounds: int = 5) -> float:
    """Best user seconds of ``cncmacro run --no-save FILE`` in a process of its own."""
    best = math.inf
    for _ in range(rounds):
        before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
        subprocess.run([sys.executable, "-m", "cncmacro", "run", "--no-save", str(path)], stdout=subprocess.DEVNULL,
                       check=False, cwd=Path(__file__).resolve().parents[1] / "server")  # fmt: skip
        best = min(best, resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before)
    return best


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--moves", type=int, default=100_000)
    ap.add_argument("--write", type=Path, help="a folder to leave the two programs in (plain.nc, comp.nc)")
    args = ap.parse_args()
    plain, compensated = contour(args.moves, False), contour(args.moves, True)
    if args.write is not None:
        args.write.mkdir(parents=True, exist_ok=True)
        (args.write / "plain.nc").write_text(plain)
        (args.write / "comp.nc").write_text(compensated)
    a, b = in_process(plain), in_process(compensated)
    print(f"run: {a:.2f} s without compensation, {b:.2f} s with G41: +{(b / a - 1) * 100:.0f}%")
    f, g = editor_open(plain), editor_open(compensated)
    print(f"editor's open: {f:.2f} s without compensation, {g:.2f} s with G41: +{(g / f - 1) * 100:.0f}% (budget: 30%)")
    with tempfile.TemporaryDirectory() as d:
        p1, p2 = Path(d) / "plain.nc", Path(d) / "comp.nc"
        p1.write_text(plain)
        p2.write_text(compensated)
        c, e = command(p1), command(p2)
    print(f"cncmacro run: {c:.2f} s without compensation, {e:.2f} s with G41: +{(e / c - 1) * 100:.0f}% (budget: 30%)")


if __name__ == "__main__":
    main()
