"""Cutter radius compensation's cost: a CAM contour of 100,000 G01 blocks (a circle of R50 in
steps of 0.5°, a Z step every lap) run with and without ``G41 D1`` (radius 3), the two taken in
turn, ``--rounds`` of each (best and median): the user CPU time of the run alone (parse
included), of ``cncmacro run`` as a whole (text output) and of the editor's open in-process (the
file opened and analysed to all its diagnostics, as ``analysis.py`` does), and the wall clock of
the editor's open over a real ``cncmacro lsp`` (from the open to the end of its analysis's
progress: the diagnostics of the run, the lenses' figures; ``lsp.py``'s client). User CPU time,
which another process on the machine disturbs less than the wall clock. ``--write DIR`` also
leaves the two programs there (``plain.nc``, ``comp.nc``).

    python benchmarks/cutter_comp.py [--moves 100000] [--rounds 7] [--write DIR]
"""

from __future__ import annotations

import argparse
import asyncio
import gc
import math
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from lsprotocol import types

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "server"))

from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.library.machine_file import MachineSettings
from cncmacro.machine import Machine

sys.path.insert(0, str(Path(__file__).resolve().parent))
from lsp import Session


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


def in_process(text: str) -> float:
    """User seconds of a run of ``text`` (moves recorded, as ``cncmacro run`` keeps them)."""
    c0 = cpu()
    m = Machine("fanuc", MachineSettings(max_blocks=10_000_000, date=20260101, time=0))
    m.start_file("contour.nc", text)
    m.run()
    spent = cpu() - c0
    del m
    gc.collect()  # this round's machine freed before the next round's clock starts
    return spent


def editor_open(text: str) -> float:
    """User seconds of an open of ``text`` to all its diagnostics (``WorkspaceAnalysis``)."""
    c0 = cpu()
    ws = WorkspaceAnalysis(settings=MachineSettings(date=20260101, time=0))
    ws.open("bench/contour.nc", text, 0)
    result = ws.analyze("bench/contour.nc")
    assert result is not None
    spent = cpu() - c0
    del ws, result
    gc.collect()  # this round's analysis freed before the next round's clock starts
    return spent


def command(path: Path) -> float:
    """User seconds of ``cncmacro run --no-save FILE`` in a process of its own."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    subprocess.run([sys.executable, "-m", "cncmacro", "run", "--no-save", str(path)], stdout=subprocess.DEVNULL,
                   check=False, cwd=Path(__file__).resolve().parents[1] / "server")  # fmt: skip
    return resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before


async def _served_open(path: Path) -> float:
    s = Session()
    await s.start(path.parent)  # a folder of its own: nothing else to index
    try:
        s.analysed = asyncio.Event()
        t0 = time.perf_counter()
        s.client.text_document_did_open(
            types.DidOpenTextDocumentParams(types.TextDocumentItem(path.as_uri(), "cnc-macro", 1, path.read_text()))
        )
        await asyncio.wait_for(s.analysed.wait(), 120)
        return time.perf_counter() - t0
    finally:
        await s.stop()


def served_open(path: Path) -> float:
    """Wall seconds from opening ``path`` in a fresh ``cncmacro lsp`` to the end of its analysis."""
    return asyncio.run(_served_open(path))


def compare(what: str, measure: Callable[[str], float], plain: str, compensated: str, rounds: int,
            budget: bool = True) -> None:  # fmt: skip
    """Both programs measured in turn, ``rounds`` times; the best and median of each."""
    a: list[float] = []
    b: list[float] = []
    for _ in range(rounds):
        a.append(measure(plain))
        b.append(measure(compensated))
    best, middle = min(b) / min(a) - 1, statistics.median(b) / statistics.median(a) - 1
    verdict = (" (budget 30%: " + ("met" if max(best, middle) <= 0.3 else "not met") + ")") if budget else ""
    print(f"{what}: {min(a):.3f} / {statistics.median(a):.3f} s without compensation (best / median), "
          f"{min(b):.3f} / {statistics.median(b):.3f} s with G41: "
          f"+{best * 100:.0f}% / +{middle * 100:.0f}%{verdict}")  # fmt: skip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--moves", type=int, default=100_000)
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--write", type=Path, help="a folder to leave the two programs in (plain.nc, comp.nc)")
    args = ap.parse_args()
    plain, compensated = contour(args.moves, False), contour(args.moves, True)
    if args.write is not None:
        args.write.mkdir(parents=True, exist_ok=True)
        (args.write / "plain.nc").write_text(plain)
        (args.write / "comp.nc").write_text(compensated)
    n = args.rounds
    compare("the run alone, user CPU", in_process, plain, compensated, n, budget=False)
    compare("the editor's open in-process, user CPU", editor_open, plain, compensated, n)
    with tempfile.TemporaryDirectory() as d:
        files = {}
        for name, text in (("plain", plain), ("comp", compensated)):
            (Path(d) / name).mkdir()
            files[text] = Path(d) / name / f"{name}.nc"
            files[text].write_text(text)
        compare("cncmacro run, user CPU", lambda t: command(files[t]), plain, compensated, n)
        compare("the editor's open over cncmacro lsp, wall clock", lambda t: served_open(files[t]), plain,
                compensated, n)  # fmt: skip


if __name__ == "__main__":
    main()
