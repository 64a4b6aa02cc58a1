"""Analysis speed on the 100k-line CAM program of ``camgen.py``: a full check, then
re-analysis after a one-line edit near the end and near the start, after Enter (a line
added) near the end, and the median and 95th percentile of one-line edits at 50 random lines.
Then a macro opened alone in a folder of 1,000 small program files and one program of
``--lines`` lines: the index of who calls whom (every file read, the ones with a call word
parsed), the first analysis (index, then the runs of its callers on disk) and an edit in it.

The full check is what ``cncmacro check`` does for the file (parse, syntax and static checks,
the analysis run, not-executed ranges); the edits are typed into one line, as an editor
sends them. Each single figure is the best of three (wall-clock seconds); the random edits
are each measured once, at lines drawn with a fixed seed.

    python benchmarks/analysis.py [--lines 100000]
"""

from __future__ import annotations

import argparse
import random
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "server"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from camgen import cam_program
from cncmacro.analysis.indexes.call_index import CallIndex
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.library.machine_file import MachineSettings

PATH = "bench/O0001.nc"


def full(text: str) -> tuple[float, WorkspaceAnalysis, int]:
    t0 = time.perf_counter()
    ws = WorkspaceAnalysis(settings=MachineSettings(date=20260101, time=0))
    ws.open(PATH, text, 0)
    result = ws.analyze(PATH)
    assert result is not None
    count = sum(len(d) for d in result.diagnostics.values())
    return time.perf_counter() - t0, ws, count


def edit_at(ws: WorkspaceAnalysis, line: int, version: int) -> float:
    """Type a digit into a coordinate of ``line`` (a motion line keeps its structure)."""
    doc = ws.document(PATH)
    assert doc is not None
    while "X" not in doc.lines[line] or "N" in doc.lines[line] or "#" in doc.lines[line]:
        line += 1
    col = doc.lines[line].index("X") + 1
    t0 = time.perf_counter()
    ws.change(PATH, line, col, line, col, "1", version)
    result = ws.analyze(PATH)
    assert result is not None and result.version == version
    return time.perf_counter() - t0


def enter_at(ws: WorkspaceAnalysis, line: int, version: int) -> float:
    """Press Enter at the end of ``line`` (a new empty line after it)."""
    doc = ws.document(PATH)
    assert doc is not None
    col = len(doc.lines[line])
    t0 = time.perf_counter()
    ws.change(PATH, line, col, line, col, "\n", version)
    result = ws.analyze(PATH)
    assert result is not None and result.version == version
    return time.perf_counter() - t0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lines", type=int, default=100_000)
    args = ap.parse_args()
    text = cam_program(args.lines)
    runs = [full(text) for _ in range(3)]
    best = min(r[0] for r in runs)
    ws, count = runs[-1][1], runs[-1][2]
    run = next(iter(ws.runs.values()))
    print(f"full check of {args.lines:,} lines: {best:.2f} s ({run.machine.blocks:,} blocks run, "
          f"{count} diagnostics; budget 2 s)")  # fmt: skip
    n = len(text.splitlines())
    near_end = min(edit_at(ws, n - 200 - k, 10 + k) for k in range(3))
    print(f"one-line edit near the end: {near_end * 1000:.0f} ms (budget 50 ms)")
    enter = min(enter_at(ws, n - 300 - k, 30 + k) for k in range(3))
    print(f"Enter near the end: {enter * 1000:.0f} ms")
    near_start = min(edit_at(ws, 10 + k, 20 + k) for k in range(3))
    print(f"one-line edit near the start: {near_start * 1000:.0f} ms")
    rnd = random.Random(5)
    times = sorted(edit_at(ws, rnd.randrange(10, n - 50), 100 + k) for k in range(50))
    p95 = times[min(len(times) - 1, round(0.95 * len(times)) - 1)]
    print(f"one-line edits at 50 random lines: p50 {statistics.median(times) * 1000:.0f} ms, "
          f"p95 {p95 * 1000:.0f} ms (budget 100 ms)")  # fmt: skip
    workspace_figures(text)


MACRO = """O9100 (BOLT CIRCLE)
IF[#11 EQ #0] THEN #3000=1(HOLE COUNT MISSING)
#30=0
WHILE[#30 LT #11] DO1
G81 X[#24+#18*COS[#30*360/#11]] Y[#25+#18*SIN[#30*360/#11]] Z#26 R2. F#9
#30=#30+1
END1
G80
M99
"""


def small_program(k: int) -> str:
    """A short program; every tenth calls O9100, the others call other macros or nothing."""
    lines = [f"O{1000 + k} (PART {k})", "G21 G17 G40 G90", "T01 M06", "S1200 M03", "G00 X0 Y0 Z50."]
    if k % 10 == 0:
        lines.append(f"G65 P9100 X0 Y0 R{20 + k % 30}. H{3 + k % 5} Z-5. F100.")
    elif k % 3 == 0:
        lines.append(f"M98 P{2000 + k % 40}")
    lines += [f"G01 X{j}. Y{k % 7}. F200." for j in range(12)] + ["G00 Z100.", "M30"]
    return "\n".join(lines) + "\n"


def workspace_figures(text: str) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for k in range(1000):
            (folder / f"O{1000 + k}.nc").write_text(small_program(k), encoding="utf-8")
        (folder / "O0001.nc").write_text(text, encoding="utf-8")
        (folder / "O9100.nc").write_text(MACRO, encoding="utf-8")
        settings = MachineSettings(date=20260101, time=0)
        t0 = time.perf_counter()
        index = CallIndex([tmp], settings, None)
        held = index.size
        build = time.perf_counter() - t0
        print(f"index of a folder of {held:,} files (1,000 small, one of {text.count(chr(10)):,} lines): "
              f"{build:.2f} s ({index.files_read:,} read, {index.files_parsed} parsed)")  # fmt: skip
        macro = str(folder / "O9100.nc")
        t0 = time.perf_counter()
        ws = WorkspaceAnalysis(settings=settings, workspace_folders=[tmp])
        ws.open(macro, MACRO, 0)
        result = ws.analyze(macro)
        first = time.perf_counter() - t0
        assert result is not None
        print(f"opening the macro there: {first:.2f} s (index and {len(ws.runs)} runs of callers on disk)")
        t0 = time.perf_counter()
        ws.change(macro, 4, 1, 4, 1, "0", 1)  # G81 -> G081
        assert ws.analyze(macro) is not None
        print(f"an edit in the macro: {(time.perf_counter() - t0) * 1000:.0f} ms")


if __name__ == "__main__":
    main()
