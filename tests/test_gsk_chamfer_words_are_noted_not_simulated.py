"""GSK980TDi's chamfer words (its manual §3.11 "倒角功能": "直线倒角的代码地址为 L", a straight chamfer
L; "圆弧倒角的代码地址为 D", a rounding arc of radius D; "倒角必须在 G01、G02 或 G03 代码段中使用")
are not simulated, as FANUC's ,C and ,R are not: the moves run as written, the corner stays sharp,
and the run notes each such block as `not-simulated` (docs/semantics.md §10.1). It said nothing."""

from __future__ import annotations

from pathlib import Path

from analysis_helpers import analyse_files
from cli_capture import run_json
from running import lines

PROGRAM = lines("O0004", "T0101", "G98 M03 S500", "G0 X0 Z2", "G01 Z0 F100", "X40 L2", "Z-20 D3", "X60", "G0 Z2 L1",
                "M30")  # fmt: skip


def test_the_moves_keep_the_sharp_corner(tmp_path: Path) -> None:
    result = run_json(tmp_path, PROGRAM, "O0004.nc", 'base = "gsk980tdi"\n')
    feeds = [(mv["to"]["X"], mv["to"]["Z"], round(mv["time"], 3)) for mv in result["moves"] if mv["kind"] == "feed"]
    # at 100 mm/min: Z 2 mm 1.2 s; X 20 mm (radius) 12 s; Z 20 mm 12 s; X 10 mm (radius) 6 s
    assert feeds == [(0.0, 0.0, 1.2), (40.0, 0.0, 12.0), (40.0, -20.0, 12.0), (60.0, -20.0, 6.0)]


def test_each_chamfer_block_is_noted(tmp_path: Path) -> None:
    found = analyse_files(tmp_path, {"O0004.nc": PROGRAM}, "gsk980tdi")
    notes = [(d.line + 1, d.severity, d.message.split(" between")[0]) for d in found if d.code == "not-simulated"]
    # G00's L1 is no chamfer (only G01, G02, G03 take one)
    assert notes == [(6, "information", "the chamfer L2"), (7, "information", "the corner rounding D3")]
