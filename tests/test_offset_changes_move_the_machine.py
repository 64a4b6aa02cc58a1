"""A change of offset between two moves moves the machine (docs/semantics.md §8,
planner/offset_travel.py): a new work offset keeps the tool where it is on the machine, so its
program position takes the difference (an axis the next block leaves out stays where it is), and
a mill's new tool length offset is travelled with the next move. The run kept the program
position: going from one vise to the other took no time and drew nothing.

fanuc-0i rapids: 24,000 mm/min on X, Y and Z (each axis on its own: the longest decides)."""

from __future__ import annotations

import pytest

from running import lines, run

RAPID = 24000.0  # mm/min


def seconds(mm: float, rate: float = RAPID) -> float:
    return mm / rate * 60.0


VISES = ("G21 G17 G90", "G10 L2 P1 X-300. Y-200. Z-100.", "G10 L2 P2 X-100. Y-200. Z-150.")


def test_going_to_the_other_vise_is_a_move_of_the_difference() -> None:
    # the tool starts at machine 0; G54 X0 Y0 goes to machine X-300 Y-200 (300 mm: 0.75 s), Z left
    # out stays at machine 0 (program Z100). G55 X0 Y0: machine X-100: 200 mm (0.5 s), drawn from
    # X-200 (machine -300 seen in G55) to X0; Z stays at machine 0, which is Z150 in G55. G54 X0 Y0
    # again: 200 mm back (0.5 s)
    m = run(lines(*VISES, "G00 G54 X0 Y0", "#100=#5023", "G55 X0 Y0", "#101=#5023", "#102=#5003",
                  "G54 X0 Y0", "#103=#5021", "M30"))  # fmt: skip
    assert m.status == "completed", m.alarm
    g54, g55, back = m.planner.moves
    assert [mv.seconds for mv in (g54, g55, back)] == pytest.approx([seconds(300.0), seconds(200.0), seconds(200.0)])
    assert (g55.start[0], g55.end[0]) == (-200.0, 0.0)
    assert (m.C[100], m.C[101], m.C[102], m.C[103]) == (0.0, 0.0, 150.0, -300.0)
    assert m.planner.clock == pytest.approx(seconds(700.0))


def test_a_g10_of_the_offset_in_force_keeps_the_tool_where_it_is() -> None:
    # at G54 X0 (machine X-300), G10 L2 P1 X-310. moves G54 by 10 mm: the tool, still at machine
    # -300, is at program X10, and X0 is a move of 10 mm (0.025 s)
    m = run(lines(*VISES, "G00 G54 X0 Y0", "G10 L2 P1 X-310.", "#100=#5001", "G00 X0", "M30"))
    assert m.C[100] == 10.0
    assert m.planner.moves[-1].seconds == pytest.approx(seconds(10.0))


def test_a_length_offset_is_travelled_with_the_next_move() -> None:
    # H1 = 150 (geometry 150, wear 0), G54 Z-400. After G91 G28 Z0 the tool is at machine Z0, program
    # Z400. G43 H1 Z50.: machine Z = -400 + 50 + 150 = -200, a move of 200 mm (0.5 s), not the 350 mm
    # of program Z (0.875 s). G49 then G00 Z50.: machine -350, 150 mm further down (0.375 s)
    m = run(lines("G21 G17 G90", "G10 L2 P1 Z-400.", "G10 L10 P1 R150.", "G91 G28 Z0", "G90 G54",
                  "G43 H1 Z50.", "#100=#5023", "G49", "G00 Z50.", "#101=#5023", "M30"))  # fmt: skip
    assert m.status == "completed", m.alarm
    g43, g49 = m.planner.moves[-2:]
    assert (g43.seconds, g49.seconds) == pytest.approx((seconds(200.0), seconds(150.0)))
    assert (m.C[100], m.C[101]) == (-200.0, -350.0)
