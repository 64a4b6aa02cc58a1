"""GSK980TDi G36 X_ / G37 Z_, automatic tool offset measurement (its manual §3.17: "在执行程序段
G36 X__(或 G37 Z__)时，刀具首先快速移动到代码的测量位置", the tool first goes to the measuring
position at rapid; "非模态 G 代码(00 组)", a one-shot code): the move is a rapid whatever the motion in
force, which stays for the next block; the offset's update by the measuring signal is noted as not
simulated (docs/semantics.md §10.1). Rapids: X 6,000 mm/min on the radius (100 mm/s), Z 8,000."""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from cli_capture import run_json
from running import lines

PROGRAM = lines("O0036", "G50 X760 Z1100", "T0101", "G98 G01 X700 F100", "G36 X200", "X690", "G37 Z800", "M30")


def test_g36_and_g37_move_at_rapid_and_leave_the_motion_in_force(tmp_path: Path) -> None:
    result = run_json(tmp_path, PROGRAM, "O0036.nc", 'base = "gsk980tdi"\n')
    got = [(mv["line"], mv["kind"], mv["to"]["X"], mv["to"]["Z"], round(mv["time"], 3)) for mv in result["moves"]]
    assert got == [
        (4, "feed", 700.0, 1100.0, 18.0),  # 30 mm (radius) at 100 mm/min
        (5, "rapid", 200.0, 1100.0, 2.5),  # 250 mm (radius) at 100 mm/s; it was a feed of 150 s
        (6, "feed", 690.0, 1100.0, 147.0),  # G01 still in force: 245 mm at 100 mm/min
        (7, "rapid", 690.0, 800.0, 2.25),  # 300 mm at 8,000 mm/min; it was a feed of 180 s
    ]


def test_the_measurement_is_noted_as_not_simulated(tmp_path: Path) -> None:
    found = analyse_files(tmp_path, {"O0036.nc": PROGRAM}, "gsk980tdi")
    assert [(d.line + 1, d.severity) for d in found if d.code == "not-simulated"] == [(5, "information"),
                                                                                      (7, "information")]  # fmt: skip


@pytest.mark.parametrize("dialect", ["fanuc-0i-lathe"])
def test_other_lathes_keep_their_reading(tmp_path: Path, dialect: str) -> None:
    # no source at hand for the FANUC lathe's G36/G37 here: the block moves in the motion in force, as before
    result = run_json(tmp_path, PROGRAM, "O0036.nc", f'base = "{dialect}"\n')
    assert [mv["kind"] for mv in result["moves"] if mv["line"] == 5] == ["feed"]
