"""Blocks whose axis words are values the control keeps, not a place to go (docs/semantics.md §8):
the stored stroke check ``G22 X_ Z_ I_ K_`` gives the check's limits (FANUC 0i-TF and 0i-MF
operator's manuals, "stored stroke check"; GSK980TDi manual §3.31, "X_Y_Z_: 存储行程检测的正方向
极限坐标值 … I_J_K_: 负方向极限坐标值"), and cylindrical interpolation's ``G07.1 C_`` gives the
cylinder's radius (``G07.1 C0`` ends it; FANUC operator's manuals, "cylindrical interpolation").
Neither block moves the tool; the moves before and after are as written."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from cli_capture import run_json
from running import lines


def ends(result: dict[str, Any], *axes: str) -> list[tuple[float, ...]]:
    return [tuple(mv["to"][a] for a in axes) for mv in result["moves"]]


@pytest.mark.parametrize("profile", ["fanuc-0i-lathe", "gsk980tdi"])
def test_g22_limits_on_a_lathe_move_nothing(tmp_path: Path, profile: str) -> None:
    program = lines(f"O0001 (cncmacro: dialect={profile})", "G99 G97 S500 M03", "G00 X50. Z5.",
                    "G22 X200. Z150. I-10. K-200.", "G01 Z-20. F0.2", "G23", "G00 X60.", "M30")  # fmt: skip
    result = run_json(tmp_path, program, "O0001.nc")
    assert result["status"] == "completed"
    # the rapid in, the cut along Z from where the rapid left the tool, the rapid out
    assert ends(result, "X", "Z") == [(50.0, 5.0), (50.0, -20.0), (60.0, -20.0)]
    assert [mv["line"] for mv in result["moves"]] == [3, 5, 7]
    # the cut: 25 mm at 0.2 mm/rev x 500 rpm = 100 mm/min -> 15 s
    assert result["moves"][1]["time"] == pytest.approx(15.0)


def test_g22_limits_on_a_mill_move_nothing(tmp_path: Path) -> None:
    program = lines("O0001", "G90 G00 X10. Y10. Z5.", "G22 X300. Y200. Z100. I-300. J-200. K-400.",
                    "G01 X20. F600", "M30")  # fmt: skip
    result = run_json(tmp_path, program)
    assert ends(result, "X", "Y", "Z") == [(10.0, 10.0, 5.0), (20.0, 10.0, 5.0)]


def test_a_plain_looking_g22_line_inside_a_run_of_moves_moves_nothing(tmp_path: Path) -> None:
    # the same line among plain motion lines, which are run together (machine/straight_runs.py)
    program = lines("O0001", "G90 G00 X0 Y0 Z5.", "G01 X10. F600", "G22 X300. Y200. Z100.", "G01 Y10.", "M30")
    result = run_json(tmp_path, program)
    assert ends(result, "X", "Y") == [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0)]


def test_g07_1_names_the_cylinders_radius_and_turns_nothing(tmp_path: Path) -> None:
    program = lines("O0001 (cncmacro: dialect=fanuc-0i-lathe)", "G98 G00 X50. Z5. C0", "G07.1 C22.",
                    "G01 Z-30. F120.", "G07.1 C0", "G00 X60.", "M30")  # fmt: skip
    result = run_json(tmp_path, program, "O0001.nc")
    assert ends(result, "X", "Z", "C") == [(50.0, 5.0, 0.0), (50.0, -30.0, 0.0), (60.0, -30.0, 0.0)]
    # the cut: 35 mm at 120 mm/min -> 17.5 s, and nothing on C
    assert result["moves"][1]["time"] == pytest.approx(17.5)
