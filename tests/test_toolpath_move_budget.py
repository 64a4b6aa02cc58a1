"""A run keeps at most ``Planner.move_budget`` moves for its toolpath (1,000,000; a drilling
cycle's K repeat makes 9,999 moves of one block, so a short program can make millions): beyond
it the run goes on to its end, its clock and its path count every move, and it says once, on the
block that filled the toolpath, that the toolpath stops there. ``cncmacro run --json`` writes the
moves as they come and the debug adapter's toolpath answer is a page (tests/dap)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from running import lines, machine

# 300 holes 10 mm apart from Z10: rapid to the R point Z2 (R-8. from the initial level), feed 5 mm
# to Z-3 (Z-5. from R) at F100, back to Z10 (G98): 300 x 5 mm = 1500 mm of cut, 300 x 3 s of feed
HOLES = lines("O0001", "G90 G00 X0 Y0 Z10.", "G91 G98 G81 X10. Z-5. R-8. F100 K300", "G80", "M30")


def test_a_run_past_the_move_budget_keeps_the_first_moves_and_counts_them_all() -> None:
    m = machine(HOLES)
    m.planner.move_budget = 100
    while m.run() == "paused":
        m.resume()
    assert m.status == "completed"
    p = m.planner
    assert len(p.moves) == 100 and p.moves_cut  # the rapid to Z10. and the first 99 holes
    assert p.cut_length == pytest.approx(1500.0)  # every hole's 5 mm, the 200 beyond the budget too
    assert p.moves[-1].line == 2  # the last move kept is a hole of the cycle block
    [said] = [n.message for n in m.notes if "toolpath keeps the first 100 moves" in n.message]
    assert "the run goes on" in said


def test_a_run_within_the_budget_keeps_every_move() -> None:
    m = machine(HOLES)
    while m.run() == "paused":
        m.resume()
    assert len(m.planner.moves) == 301 and not m.planner.moves_cut  # the rapid and 300 holes


@pytest.mark.skipif(sys.platform == "win32", reason="resource.getrusage of a child process")
def test_run_json_writes_a_hundred_thousand_moves_without_holding_their_text(tmp_path: Path) -> None:
    # 10 blocks of 9,999 holes: the JSON was built whole first (1,178 MB for 20 such blocks)
    program = tmp_path / "O0002.nc"
    blocks = ["O0002", "G90 G00 X0 Y0 Z10."] + ["G91 G98 G81 X0.01 Z-1. R-2. F1000 K9999"] * 10 + ["G80", "M30"]
    program.write_text(lines(*blocks), encoding="utf-8")
    out = tmp_path / "out.json"
    # a small parent of its own runs the command, so that its peak is that command's alone (the
    # suite's other children, a language server on a million lines, would count too)
    wrap = ("import resource, subprocess, sys\n"
            "with open(sys.argv[1], 'w', encoding='utf-8') as sink:\n"
            "    code = subprocess.run(sys.argv[2:], stdout=sink).returncode\n"
            "print(code, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n")  # fmt: skip
    command = [sys.executable, "-m", "cncmacro", "run", "--no-save", "--json", str(program)]
    done = subprocess.run([sys.executable, "-c", wrap, str(out), *command], capture_output=True, text=True, timeout=300)
    code, peak_kb = done.stdout.split()
    assert code == "0", done.stderr
    peak_mb = int(peak_kb) / 1024
    size_mb = out.stat().st_size / 1e6
    assert sum(1 for line in out.open(encoding="utf-8") if line.startswith('  {"file"')) == 1 + 10 * 9999
    assert size_mb > 20 and peak_mb < size_mb + 150, f"peak {peak_mb:.0f} MB for {size_mb:.0f} MB of JSON"
