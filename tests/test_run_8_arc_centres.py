"""docs/semantics.md §8 The simulated machine: a G02/G03 move carries its arc's centre.

The centre is in work coordinates, one value per axis like the move's end points; the axes
off the arc's plane keep their start values. I, J, K are incremental from the start; R > 0 is
the arc of at most 180°, R < 0 the longer one; G17 turns in X,Y, G18 in Z,X, G19 in Y,Z. On
the gsk980tdi lathe X is a diameter and I a radius value. Every path that runs a motion line
(the one-pass run of plain lines, the compiled plain line, the general block) gives the same
moves. Fanuc axes are X Y Z A; gsk980tdi axes are X Y Z C B.
"""

from __future__ import annotations

import pytest

from cncmacro.syntax.block_parser import parse_block
from running import lines, run


def moves(*body: str, dialect: str = "fanuc") -> list[tuple[float, tuple[float, ...], tuple[float, ...] | None]]:
    """(mode, end, centre) of each move of a run of ``body`` that must complete."""
    m = run(lines("O0001", *body, "M30"), dialect)
    assert m.status == "completed", m.alarm
    return [(mv.mode, mv.end, mv.centre) for mv in m.planner.moves]


def test_8_machine_arc_g17_quarter_circle_with_i_j():
    got = moves("G90 G17 G00 X10. Y0 Z5.", "G03 X0 Y10. I-10. J0 F100")
    assert got[-1] == (3.0, (0.0, 10.0, 5.0, 0.0), (0.0, 0.0, 5.0, 0.0))


def test_8_machine_arc_g17_full_circle_with_the_end_at_the_start():
    got = moves("G90 G00 X10. Y0", "G02 X10. Y0 I-10. F100")
    assert got[-1] == (2.0, (10.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0))


def test_8_machine_arc_i_j_without_axis_words_is_a_full_circle_and_r_alone_moves_nothing():
    got = moves("G90 G00 X10. Y5.", "G02 I-10. F100", "G03 J-5.", "G02 R7.")
    assert got[1:] == [
        (2.0, (10.0, 5.0, 0.0, 0.0), (0.0, 5.0, 0.0, 0.0)),
        (3.0, (10.0, 5.0, 0.0, 0.0), (10.0, 0.0, 0.0, 0.0)),
    ]


def test_8_machine_arc_g18_turns_in_z_x_with_k_and_i():
    got = moves("G90 G18 G00 X0 Y3. Z0", "G02 X10. Z10. K10. I0 F100")
    assert got[-1][2] == (0.0, 3.0, 10.0, 0.0)


def test_8_machine_arc_g18_with_r_takes_the_centre_right_of_the_chord_for_g02():
    """Z then X is the plane's order (seen from +Y): G02 from Z0 to Z10 with R13 bends
    towards +X, its centre 12 below the chord at X-12."""
    got = moves("G90 G18 G00 X0 Z0", "G02 Z10. R13. F100", "G90 G00 X0 Z0", "G03 Z10. R13.")
    assert got[1][2] == (-12.0, 0.0, 5.0, 0.0)
    assert got[3][2] == (12.0, 0.0, 5.0, 0.0)


def test_8_machine_arc_g19_turns_in_y_z_with_j_and_k():
    got = moves("G90 G19 G00 X7. Y10. Z0", "G03 Y0 Z10. J-10. K0 F100", "G02 Y10. Z0 R-10.")
    assert got[1] == (3.0, (7.0, 0.0, 10.0, 0.0), (7.0, 0.0, 0.0, 0.0))
    # R-10 from Y0 Z10 to Y10 Z0 clockwise: the three-quarter circle round Y10 Z10
    assert got[2][2] == (7.0, 10.0, 10.0, 0.0)


@pytest.mark.parametrize(
    ("mode", "radius", "centre_y"),
    [("G02", "13.", -12.0), ("G03", "13.", 12.0), ("G02", "-13.", 12.0), ("G03", "-13.", -12.0)],
)
def test_8_machine_arc_r_sign_and_direction_pick_the_side_of_the_chord(mode, radius, centre_y):
    """R > 0 the shorter arc (centre on the far side from the bulge), R < 0 the longer one."""
    got = moves("G90 G17 G00 X0 Y0", f"{mode} X10. Y0 R{radius} F100")
    assert got[-1][2] == (5.0, centre_y, 0.0, 0.0)


def test_8_machine_arc_r_shorter_than_half_the_chord_centres_on_the_midpoint():
    got = moves("G90 G00 X0 Y0", "G02 X10. Y0 R2. F100")
    assert got[-1][2] == (5.0, 0.0, 0.0, 0.0)


def test_8_machine_arc_r_wins_over_i_j_in_the_same_block():
    got = moves("G90 G00 X0 Y0", "G03 X10. Y0 R13. I1. J1. F100")
    assert got[-1][2] == (5.0, 12.0, 0.0, 0.0)


def test_8_machine_arc_g91_end_point_with_i_j_from_the_start():
    got = moves("G90 G00 X10. Y0", "G91 G03 X-10. Y10. I-10. F100", "G02 X10. Y-10. J-10.")
    assert got[1] == (3.0, (0.0, 10.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0))
    assert got[2] == (2.0, (10.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0))


def test_8_machine_arc_helical_z_keeps_the_start_value_in_the_centre():
    got = moves("G90 G17 G00 X10. Y0 Z0", "G03 X0 Y10. Z-2. I-10. F100")
    assert got[-1] == (3.0, (0.0, 10.0, -2.0, 0.0), (0.0, 0.0, 0.0, 0.0))


def test_8_machine_arc_non_arc_moves_and_arcs_without_centre_words_have_no_centre():
    # on haas: FANUC stops at "G02 X3." with alarm PS0022 "R or I, J, K command not found" (its PS
    # alarm list; test_8_arc_without_r_or_ijk.py), Haas cuts it as a straight line
    got = moves("G90 G00 X1. Y1.", "G01 X2. R5. F100", "G02 X3.", "G17 G02 X4. K2.", dialect="haas")
    assert [centre for _, _, centre in got] == [None, None, None, None]


def test_8_machine_arc_on_the_lathe_i_is_a_radius_value_while_x_is_a_diameter():
    """gsk980tdi, G18 (Z,X): from X20 (radius 10) Z0, G02 to X40 Z-10 with I10 K0 turns
    round radius 20, the diameter 40: X20 + 2*I. R10 finds the same centre, and so does U/W."""
    start = "G00 X20. Z0"
    with_ik = moves(start, "G02 X40. Z-10. I10. K0 F0.2", dialect="gsk980tdi")
    with_r = moves(start, "G02 X40. Z-10. R10. F0.2", dialect="gsk980tdi")
    with_uw = moves(start, "G02 U20. W-10. R10. F0.2", dialect="gsk980tdi")
    expected = (2.0, (40.0, 0.0, -10.0, 0.0, 0.0), (40.0, 0.0, 0.0, 0.0, 0.0))
    assert with_ik[-1] == with_r[-1] == with_uw[-1] == expected


def test_8_machine_arc_on_the_lathe_g03_with_r_bends_the_other_way():
    got = moves("G00 X20. Z0", "G03 X40. Z-10. R10. F0.2", dialect="gsk980tdi")
    assert got[-1][2] == (20.0, 0.0, -10.0, 0.0, 0.0)  # radius 10, Z-10: the other side of the chord


CAM = [
    "G90 G17 G00 X0 Y0 Z2.",
    "G01 Z-1. F300",
    "G02 X10. Y0 R13.",
    "X20. Y0 R-5.",
    "G03 X20. Y10. I0 J5.",
    "G91 G02 X-10. Y-10. I-10.",
    "G90 G18 G02 X0 Z-1. I-5. K0",
    "G19 G03 Y10. Z5. R8.",
    "G17 G01 X0 Y0",
]


def cam_moves(body: list[str], under_g66: bool = False) -> list[object]:
    head = ["G66 P9000" if under_g66 else "G67"]  # the same line numbers either way
    m = run(lines("O0001", *head, *body, "G67", "M30", "O9000", "M99"))
    assert m.status == "completed", m.alarm
    return m.planner.moves


def test_8_machine_arc_in_a_plain_cam_run_equals_the_general_path():
    """The CAM lines are plain (run in one pass); with a comment appended each is a general
    block; under G66 each plain line is compiled. All three runs leave the same moves."""
    assert all(parse_block(text).plain is not None for text in CAM)
    commented = [f"{text} (same block)" for text in CAM]
    assert all(parse_block(text).plain is None for text in commented)
    straight = cam_moves(CAM)
    assert straight == cam_moves(commented) == cam_moves(CAM, under_g66=True)
    centres = [mv.centre for mv in straight]
    assert centres[2] == (5.0, -12.0, -1.0, 0.0)
    assert centres[3] == (15.0, 0.0, -1.0, 0.0)  # R-5 over a chord of 10: the midpoint
    assert centres[4] == (20.0, 5.0, -1.0, 0.0)
    assert centres[5] == (10.0, 10.0, -1.0, 0.0)
    assert centres[6] == (5.0, 0.0, -1.0, 0.0)
    assert centres[0] is None and centres[1] is None and centres[8] is None


def test_8_machine_arc_full_circle_line_in_a_plain_run_equals_the_general_path():
    body = ["G90 G00 X10. Y0", "G02 I-10. F100", "G03 J5.", "G02 R3.", "G01 X0"]
    straight = cam_moves(body)
    assert straight == cam_moves([f"{t} (x)" for t in body]) == cam_moves(body, under_g66=True)
    assert [mv.centre for mv in straight] == [None, (0.0, 0.0, 0.0, 0.0), (10.0, 5.0, 0.0, 0.0), None]
