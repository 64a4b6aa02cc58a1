"""Chamfers and corner R cut as the control cuts them (docs/semantics.md §8, "Chamfer and corner
words"): FANUC's and Haas's ``,C`` is a chamfer ``,C`` from the virtual corner along each move,
``,R`` an arc of that radius tangent to both moves, between lines and arcs in the plane of the
program; the move before and the move after are shortened, and the toolpath, the time and the path
length show it. The program position #5001… stays the programmed corner. Before, the moves ran
as written and the sharp corner stayed."""

from __future__ import annotations

from math import asin, cos, pi, sin, sqrt

import pytest

from running import lines, machine, run

MILLS = ("fanuc-0i", "fanuc-30i", "haas")


def _ends(m):
    return [(mv.line + 1, mv.mode, tuple(round(v, 6) for v in mv.end[:2])) for mv in m.planner.moves]


@pytest.mark.parametrize("profile", MILLS)
def test_8_machine_a_chamfer_c_is_its_distance_from_the_virtual_corner_along_each_move(profile):
    m = run(lines(
        "O1000", "G90 G17 G21 G94 G00 X0 Y0",
        "G01 X50. ,C3. F600.",
        "#100=#5001", "#101=#5002",
        "G01 Y50.",
        "#102=#5001", "#103=#5002",
        "M30"), profile)  # fmt: skip
    assert m.status == "completed", m.alarm
    # ,C3 between +X and +Y: X50-3 = X47 Y0, then X50 Y0+3 = Y3; the next move from there
    assert _ends(m) == [(2, 0.0, (0.0, 0.0)), (3, 1.0, (47.0, 0.0)), (3, 1.0, (50.0, 3.0)), (6, 1.0, (50.0, 50.0))]
    starts = [tuple(round(v, 6) for v in mv.start[:2]) for mv in m.planner.moves]
    assert starts[1:] == [(0.0, 0.0), (47.0, 0.0), (50.0, 3.0)]
    # at F600 (10 mm/s): 47 mm 4.7 s, the chamfer 3·√2 = 4.242641 mm 0.4242641 s, 47 mm 4.7 s
    assert [round(mv.seconds, 6) for mv in m.planner.moves][1:] == [4.7, 0.424264, 4.7]
    assert m.planner.cut_length == pytest.approx(47.0 + 3.0 * sqrt(2.0) + 47.0)
    assert m.planner.clock == pytest.approx(9.4 + 0.3 * sqrt(2.0))
    v = m.variables()
    # #5001 is the block's end point as programmed: the virtual corner, then the next block's end
    assert (v[100], v[101], v[102], v[103]) == (50.0, 0.0, 50.0, 50.0)


def test_8_machine_a_corner_r_between_a_line_and_an_arc_is_tangent_to_both():
    m = run(lines(
        "O1000", "G90 G17 G00 X0 Y0",
        "G01 X50. ,R5. F600.",
        "G02 X70. Y20. R20.",
        "M30"), "fanuc-0i")  # fmt: skip
    assert m.status == "completed", m.alarm
    # the arc: centre X70 Y0 (clockwise, the short way), leaving X50 Y0 along +Y: a left turn.
    # The rounding's centre is 5 left of the line (Y5) and 5 outside the arc (radius 25 about
    # X70 Y0): (x-70)² + 5² = 25², x = 70 - √600 = 45.505103. It touches the line at X45.505103
    # Y0 and the arc at X70 Y0 + 20/25·(-24.494897, 5) = X50.404082 Y4
    w = 70.0 - sqrt(600.0)
    t2 = (70.0 - 20.0 * sqrt(600.0) / 25.0, 4.0)
    assert _ends(m) == [(2, 0.0, (0.0, 0.0)), (3, 1.0, (round(w, 6), 0.0)), (3, 3.0, tuple(round(c, 6) for c in t2)),
                        (4, 2.0, (70.0, 20.0))]  # fmt: skip
    rounding, arc = m.planner.moves[2], m.planner.moves[3]
    assert rounding.centre[:2] == pytest.approx((w, 5.0))
    assert arc.start[:2] == pytest.approx(t2) and arc.centre[:2] == pytest.approx((70.0, 0.0))
    # the path: the line w, the rounding 5 · (its turn: the angle between (0,-5) and (t2 - F)),
    # the arc 20 · (90° less the angle it lost, atan2(4, 19.595918))
    turn = pi / 2.0 - asin(5.0 / 25.0)  # from straight down to the direction of the arc's centre
    lost = asin(4.0 / 20.0)
    length = w + 5.0 * turn + 20.0 * (pi / 2.0 - lost)
    assert m.planner.cut_length == pytest.approx(length)
    assert m.planner.clock == pytest.approx(length / 10.0)


def test_8_machine_a_chamfer_after_an_arc_takes_the_point_of_the_arc_that_far_from_the_corner():
    m = run(lines(
        "O1000", "G90 G17 G00 X50. Y0",
        "G02 X70. Y20. R20. ,C3. F600.",
        "G01 X90.",
        "M30"), "fanuc-0i")  # fmt: skip
    assert m.status == "completed", m.alarm
    # the arc ends at X70 Y20 going +X (tangent to the line: no chamfer there would be asked for a
    # rounding, but a chamfer is cut): the point of the arc 3 from the corner is 2·asin(3/40) back
    # round the centre X70 Y0, at 90° + 8.598°: X70 - 20·sin(2·asin(3/40)) Y20·cos(…)
    a = 2.0 * asin(3.0 / 40.0)
    p1 = (70.0 - 20.0 * sin(a), 20.0 * cos(a))
    assert _ends(m) == [(2, 0.0, (50.0, 0.0)), (3, 2.0, tuple(round(c, 6) for c in p1)), (3, 1.0, (73.0, 20.0)),
                        (4, 1.0, (90.0, 20.0))]  # fmt: skip


def test_8_machine_a_corner_r_on_a_lathe_takes_x_as_a_diameter():
    m = run(lines(
        "O1000", "G99 S500 M03",
        "G00 X20. Z2.",
        "G01 Z0 F0.1",
        "G01 X40. ,C2.",
        "G01 Z-20. ,R4.",
        "G01 X60.",
        "M30"), "fanuc-0i-lathe")  # fmt: skip
    assert m.status == "completed", m.alarm
    ends = [(mv.line + 1, mv.mode, round(mv.end[0], 6), round(mv.end[1], 6)) for mv in m.planner.moves]
    # ,C2 between +X and -Z at X40 Z0 (radius 20): X(20-2)·2 = X36, then Z-2. ,R4 between -Z and +X
    # (a clockwise turn in the Z-X plane, G02): Z-20+4 = Z-16, then X(20+4)·2 = X48 Z-20, about X40 Z-16
    assert ends == [(3, 0.0, 20.0, 2.0), (4, 1.0, 20.0, 0.0), (5, 1.0, 36.0, 0.0), (5, 1.0, 40.0, -2.0),
                    (6, 1.0, 40.0, -16.0), (6, 2.0, 48.0, -20.0), (7, 1.0, 60.0, -20.0)]  # fmt: skip
    assert m.planner.moves[5].centre[:2] == pytest.approx((48.0, -16.0))
    # G99 F0.1 at S500: 50 mm/min. 2 + 8 + 2√2 + 14 + 4·π/2 + 6 mm of tool motion
    length = 2.0 + 8.0 + 2.0 * sqrt(2.0) + 14.0 + 2.0 * pi + 6.0
    assert m.planner.cut_length == pytest.approx(length)
    cutting = sum(mv.seconds for mv in m.planner.moves if mv.mode != 0.0)
    assert cutting == pytest.approx(length / 50.0 * 60.0)


def test_8_machine_two_moves_on_one_line_take_no_chamfer():
    m = run(lines("O1000", "G90 G17 G00 X0 Y0", "G01 X50. ,C3. F600.", "X80.", "M30"), "fanuc-0i")
    assert _ends(m) == [(2, 0.0, (0.0, 0.0)), (3, 1.0, (50.0, 0.0)), (4, 1.0, (80.0, 0.0))]


def test_8_machine_a_corner_with_no_cut_after_it_stays_sharp():
    # a G00 after the block: no chamfer (only between G01, G02, G03 moves in the plane). On Haas;
    # FANUC's alarm list makes it PS0052 "CODE IS NOT G01 AFTER CHF/CNR" there
    # (test_corner_next_block_alarms_ps0051_ps0052.py)
    m = run(lines("O1000", "G90 G17 G00 X0 Y0", "G01 X50. ,C3. F600.", "G00 Y50.", "M30"), "haas")
    assert _ends(m) == [(2, 0.0, (0.0, 0.0)), (3, 1.0, (50.0, 0.0)), (4, 0.0, (50.0, 50.0))]


def test_8_machine_a_move_shorter_than_its_chamfer_is_alarm_ps0055_on_fanuc():
    # X2 is 2 long, the chamfer 3: its start would be off the move (PS0055 "MISSING MOVE VALUE IN
    # CHF/CNR": "the move distance is less than chamfer or corner R amount"), found reading the next
    m = run(lines("O1000", "G90 G17 G00 X0 Y0", "G01 X2. ,C3. F600.", "Y50.", "M30"), "fanuc-0i")
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (55, 4)
    assert "too short" in m.alarm.message


def test_8_machine_a_corner_r_too_large_is_a_note_on_haas_and_the_corner_stays_sharp():
    m = run(lines("O1000", "G90 G17 G00 X0 Y0", "G01 X2. ,R3. F600.", "Y50.", "M30"), "haas")
    assert m.status == "completed", m.alarm
    assert _ends(m) == [(2, 0.0, (0.0, 0.0)), (3, 1.0, (2.0, 0.0)), (4, 1.0, (2.0, 50.0))]
    assert any("radius 3" in n.message and "left sharp" in n.message for n in m.notes)


def test_8_machine_a_chamfer_under_cutter_compensation_is_not_inserted_and_noted():
    m = run(lines(
        "O1000", "#13001=5.", "G90 G17 G00 X-10. Y-10.",
        "G41 D1 G01 X0 Y0 F600.",
        "X50. ,C3.",
        "Y50.",
        "G40 G00 X60. Y60.", "M30"), "fanuc-0i")  # fmt: skip
    assert m.status == "completed", m.alarm
    assert [(mv.line + 1, mv.end[:2]) for mv in m.planner.moves][2:4] == [(5, (50.0, 0.0)), (6, (50.0, 50.0))]
    assert any(n.line + 1 == 5 and "not inserted" in n.message for n in m.notes)


def test_8_machine_stepping_back_to_a_held_chamfer_gives_the_move_its_corner_again():
    # a snapshot taken after line 3 ran (its move held to the corner X50 Y0, 5 s at F600), restored
    # after line 4 shortened it to X47 Y0 (the debugger's step back): the move reaches the corner
    # again, the clock is 5 s, and running on cuts the chamfer once more
    m = machine(lines("O1000", "G90 G17 G00 X0 Y0", "G01 X50. ,C3. F600.", "G01 Y50.", "M30"), "fanuc-0i")
    while not (m.planner.moves and m.planner.moves[-1].line + 1 == 3):
        m.step()
    snap = m.snapshot()
    m.run()
    assert _ends(m)[1:] == [(3, 1.0, (47.0, 0.0)), (3, 1.0, (50.0, 3.0)), (4, 1.0, (50.0, 50.0))]
    m.restore(snap)
    assert _ends(m)[1:] == [(3, 1.0, (50.0, 0.0))]
    assert m.planner.clock == pytest.approx(5.0)
    m.run()
    assert _ends(m)[1:] == [(3, 1.0, (47.0, 0.0)), (3, 1.0, (50.0, 3.0)), (4, 1.0, (50.0, 50.0))]
    assert m.planner.clock == pytest.approx(9.4 + 0.3 * sqrt(2.0))
