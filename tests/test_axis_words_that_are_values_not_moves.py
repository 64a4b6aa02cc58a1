"""Blocks whose axis words are values the control keeps, not a place to go (docs/semantics.md §8):
the stored stroke check ``G22 X_ Z_ I_ K_`` gives the check's limits (FANUC 0i-TF and 0i-MF
operator's manuals, "stored stroke check"; GSK980TDi manual §3.31, "X_Y_Z_: 存储行程检测的正方向
极限坐标值 … I_J_K_: 负方向极限坐标值"), and cylindrical interpolation's ``G07.1 C_`` gives the
cylinder's radius (``G07.1 C0`` ends it; FANUC operator's manuals, "cylindrical interpolation");
``G68 X_ Y_ R_``, ``G51 X_ Y_ P_`` and ``G51.1 X_`` give the centre of a rotation, a scaling and a
mirror image (FANUC 0i-MF operator's manual, "coordinate system rotation", "scaling",
"programmable mirror image"), which this project does not simulate. None of these blocks moves
the tool; the moves before and after are as written. ``G92.1 IP0`` presets the workpiece
coordinate system: the named axes' G92 shift is cancelled, without a move."""

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


@pytest.mark.parametrize(
    ("profile", "mirror", "no_mirror"),
    [("fanuc-0i", "G51.1", "G50.1"), ("fanuc-30i", "G51.1", "G50.1"), ("haas", "G101", "G100"),
     ("mazak-eia", "G51.1", "G50.1"), ("mitsubishi-m70", "G51.1", "G50.1")],
)  # fmt: skip
def test_rotation_scaling_and_mirror_centres_move_nothing(
    tmp_path: Path, profile: str, mirror: str, no_mirror: str
) -> None:
    # Haas writes its mirror image G101 X_ (the centre), G100 to cancel (Haas 96-8000, G100/G101)
    program = lines(f"O1001 (cncmacro: dialect={profile})", "G90 G17 G00 X50. Y50. Z10.", "G68 X10. Y10. R90.",
                    "G01 X60. F1000.", "G69", "G51 X0 Y0 P2.", "G01 Y20.", "G50", f"{mirror} X0", "G01 X40.",
                    f"{no_mirror} X0", "M30")  # fmt: skip
    result = run_json(tmp_path, program, "O1001.nc")
    assert result["status"] == "completed"
    assert [mv["line"] for mv in result["moves"]] == [2, 4, 7, 10]
    assert ends(result, "X", "Y") == [(50.0, 50.0), (60.0, 50.0), (60.0, 20.0), (40.0, 20.0)]


def test_g92_1_cancels_the_g92_shift_without_a_move(tmp_path: Path) -> None:
    # at X20 Y0, G92 X0 Y0 makes that point X0 Y0; G92.1 X0 Y0 brings the work coordinates back:
    # the tool is at X20 Y0 again, so the rapid to X5 Y5 starts there
    program = lines("O0001", "G90 G00 X20. Y0 Z5.", "G92 X0 Y0", "G01 X10. F600", "G92.1 X0 Y0", "G00 X5. Y5.", "M30")
    result = run_json(tmp_path, program)
    assert [(mv["line"], mv["from"]["X"], mv["from"]["Y"]) for mv in result["moves"]] == [
        (2, 0.0, 0.0), (4, 0.0, 0.0), (6, 30.0, 0.0)]  # fmt: skip
    assert ends(result, "X", "Y") == [(20.0, 0.0), (10.0, 0.0), (5.0, 5.0)]


def test_g50_3_presets_a_lathes_work_coordinates(tmp_path: Path) -> None:
    # the 0i-TF's preset (system A): G50 X0 Z0 at X40 Z10 shifts, G50.3 X0 Z0 takes it back
    program = lines("O0001 (cncmacro: dialect=fanuc-0i-lathe)", "G00 X40. Z10.", "G50 X0 Z0", "G50.3 X0 Z0",
                    "G00 X50.", "M30")  # fmt: skip
    result = run_json(tmp_path, program, "O0001.nc")
    assert result["status"] == "completed"
    assert [(mv["from"]["X"], mv["from"]["Z"]) for mv in result["moves"]] == [(0.0, 0.0), (40.0, 10.0)]
