"""FANUC's direct drawing dimension programming: a straight move that names one coordinate of the
plane and an angle ``,A`` goes at that angle, measured from the plane's first axis toward its
second (G18: from +Z toward +X; G17: from +X toward +Y), to the coordinate it leaves out
(docs/semantics.md §8, "Chamfer and corner words"; planner/angled_moves.py). On a lathe X is a
diameter: the angle is of the radius's change. A block that names both coordinates moves as
written."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest

from cli_capture import cli, run_json
from running import lines


def ends(result: dict[str, Any], *axes: str) -> list[tuple[float, ...]]:
    return [tuple(round(mv["to"][a], 6) for a in axes) for mv in result["moves"]]


def test_a_lathe_move_at_an_angle_from_z(tmp_path: Path) -> None:
    # from X20 Z0: X30 ,A135 is 5 mm out on the radius at 135 deg from +Z: 5 mm toward -Z (Z-5);
    # X50 ,A120: 10 mm out, 10 / tan 120 = -5.7735 along Z (Z-10.7735); Z-40 ,A180: X stays
    program = lines("O0001 (cncmacro: dialect=fanuc-0i-lathe)", "G98 G00 X20. Z0", "G01 X30. ,A135. F100",
                    "X50. ,A120.", "Z-40. ,A180.", "M30")  # fmt: skip
    result = run_json(tmp_path, program, "O0001.nc")
    z2 = -5.0 - 10.0 / math.tan(math.radians(60.0))
    assert ends(result, "X", "Z") == [(20.0, 0.0), (30.0, -5.0), (50.0, round(z2, 6)), (50.0, -40.0)]
    # the first cut: 5 mm along each of the radius and Z, 7.071 mm at F100 -> 4.243 s
    assert result["moves"][1]["time"] == pytest.approx(math.hypot(5.0, 5.0) / 100 * 60)


def test_a_mill_move_at_an_angle_from_x_and_an_angle_from_a_variable(tmp_path: Path) -> None:
    # X10 ,A30 from X0 Y0: Y = 10 tan 30 = 5.7735; Y20 ,A#1 with #1 = 90: X stays 10
    program = lines("O0001", "G90 G17 G00 X0 Y0 Z5.", "#1=90.", "G01 X10. ,A30. F600", "Y20. ,A#1", "M30")
    result = run_json(tmp_path, program)
    assert ends(result, "X", "Y") == [(0.0, 0.0), (10.0, round(10 * math.tan(math.radians(30)), 6)), (10.0, 20.0)]


def test_a_block_with_both_coordinates_moves_as_written(tmp_path: Path) -> None:
    program = lines("O0001", "G90 G17 G00 X0 Y0", "G01 X10. Y3. ,A30. F600", "M30")
    assert ends(run_json(tmp_path, program), "X", "Y") == [(0.0, 0.0), (10.0, 3.0)]


def test_fanucs_two_block_form_goes_to_the_corner_where_the_lines_meet(tmp_path: Path) -> None:
    # ",A160." alone, then "X50. Z-60. ,A180.": from X30 Z-30 (radius 15) the line at 160 deg meets
    # the line through X50 Z-60 at 180 deg (radius 25) after t = 10 / sin 160 = 29.238 mm, at
    # Z = -30 + 29.238 cos 160 = -57.475: the first block goes there, the second on to Z-60. At
    # G98 F100: 29.238 mm = 17.543 s, then 2.525 mm = 1.515 s. No corner-word warning: the angle
    # alone is the form's first block
    program = lines("O0001 (cncmacro: dialect=fanuc-0i-lathe)", "G98 G00 X30. Z-30.", "G01 F100", ",A160.",
                    "X50. Z-60. ,A180.", "M30")  # fmt: skip
    result = run_json(tmp_path, program, "O0001.nc")
    t = 10.0 / math.sin(math.radians(160.0))
    corner = -30.0 + t * math.cos(math.radians(160.0))
    assert corner == pytest.approx(-57.475, abs=1e-3)
    assert [(mv["line"], *end) for mv, end in zip(result["moves"], ends(result, "X", "Z"), strict=True)] == [
        (2, 30.0, -30.0), (4, 50.0, round(corner, 6)), (5, 50.0, -60.0)]  # fmt: skip
    assert [mv["time"] for mv in result["moves"][1:]] == pytest.approx([t / 100 * 60, (60 + corner) / 100 * 60])
    path = tmp_path / "O0001.nc"
    code, out, _ = cli("check", str(path))
    assert (code, out) == (0, "")


def test_a_second_block_without_its_angle_goes_straight(tmp_path: Path) -> None:
    # ",A160." then "X50. Z-60." (no angle: no corner to work out): straight to X50 Z-60, and the
    # angle is not kept for a later block
    program = lines("O0001 (cncmacro: dialect=fanuc-0i-lathe)", "G98 G00 X30. Z-30.", "G01 F100", ",A160.",
                    "X50. Z-60.", "Z-70.", "X60. Z-80. ,A180.", "M30")  # fmt: skip
    result = run_json(tmp_path, program, "O0001.nc")
    assert ends(result, "X", "Z") == [(30.0, -30.0), (50.0, -60.0), (50.0, -70.0), (60.0, -80.0)]


def gsk_checked(tmp_path: Path, *body: str) -> tuple[dict[str, Any], str]:
    text = lines("O0001 (cncmacro: dialect=gsk980tdi)", "G98 G00 X20 Z0", *body, "M30")
    result = run_json(tmp_path, text, "O0001.nc")
    _, out, _ = cli("check", str(tmp_path / "O0001.nc"))
    return result, out


def test_gsk_q_is_the_angle_in_thousandths_of_a_degree(tmp_path: Path) -> None:
    # GSK980TDi manual §3.13: "Q_ 角度是直线与Z轴的夹角 …（单位：0.001°）". From X20 Z0, G01 X30 Q135000:
    # 5 mm out on the radius at 135 deg from +Z, so 5 mm toward -Z: X30 Z-5 (it ended at X30 Z0),
    # 7.071 mm at F100 -> 4.243 s. Then the two-block form (§3.13's third row): Q90000 alone (along +X)
    # and X60 Z-30 Q180000 (along Z through the end): the corner at X60 Z-5, then on to X60 Z-30
    result, out = gsk_checked(tmp_path, "G01 X30 Q135000 F100", "G01 Q90000", "G01 X60 Z-30 Q180000")
    assert ends(result, "X", "Z")[1:] == [(30.0, -5.0), (60.0, -5.0), (60.0, -30.0)]
    assert result["moves"][1]["time"] == pytest.approx(math.hypot(5.0, 5.0) / 100 * 60)
    assert out == ""


@pytest.mark.parametrize(
    ("body", "line", "end"),
    [
        # note 3: "X_ Q_（如果角度Q为（0°或180°）±1°以内的值时，将产生报警。）": 180.5 deg is within 1 deg
        (("G01 X30 Q180500 F100",), 3, (30.0, 0.0)),
        # note 4: "Z_ Q_（如果角度Q为（90°或270°）±1°以内的值时，将产生报警。）"
        (("G01 Z-10 Q269200 F100",), 3, (20.0, -10.0)),
        # note 5: "计算交点时，由两条直线构成的角度差在±1°之间时，将产生报警。" (90 and 90.5 deg)
        (("G01 Q90000 F100", "G01 X60 Z-30 Q90500"), 3, (60.0, -30.0)),
    ],
    ids=["x-along-z", "z-along-x", "two-lines-parallel"],
)
def test_gsk_alarms_on_a_line_within_a_degree_of_parallel(
    tmp_path: Path, body: tuple[str, ...], line: int, end: tuple[float, float]
) -> None:
    result, out = gsk_checked(tmp_path, *body)
    assert out.startswith(f"{tmp_path / 'O0001.nc'}:{line}:1: error: ") and out.rstrip().endswith("[drawing-angle]")
    # the move is drawn as written: straight to the end the block gives
    assert ends(result, "X", "Z")[-1] == end


def test_a_fanuc_lathes_bare_a_is_the_angle_as_a_comma_a_is(tmp_path: Path) -> None:
    # 0i-TF with parameter 3405#4 CCR = 0 writes the angle without a comma: G01 X30. A150. from X20
    # Z0 is 5 mm out on the radius at 150 deg from +Z: 5 / tan 30 = 8.660 toward -Z (Z-8.660). A is no
    # axis of the profile: the word was dropped and the move went to X30 Z0
    program = lines("O0001 (cncmacro: dialect=fanuc-0i-lathe)", "G98 G00 X20. Z0", "G01 X30. A150. F100",
                    "Z-20.", "M30")  # fmt: skip
    result = run_json(tmp_path, program, "O0001.nc")
    assert ends(result, "X", "Z") == [(20.0, 0.0), (30.0, round(-5.0 / math.tan(math.radians(30.0)), 6)), (30.0, -20.0)]
    assert cli("check", str(tmp_path / "O0001.nc"))[:2] == (0, "")
