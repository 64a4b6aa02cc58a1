"""docs/semantics.md §12, "Interference": FANUC's interference check finds a block that would be
cut backwards while it reads ahead, and stops before that block moves (30i-A user's manual
B-63944EN-1/02 p.216: "since the direction programmed in block B is opposite to that of the path
after the tool nose radius compensation, the tool stops and an alarm is displayed", the figure's
"Stopped" at the end of the block before B). The run's alarm stands on the block whose reading
found it; the toolpath, the clock, the lengths and the position end with the block before the
reversing one (planner/cutter_stage.py, ``_reversal``).

The groove: radius 5, tool on the left, a 3 mm wide groove 10 deep. Line 4 starts up from (0,10)
going -Y (centre on +X: X5), line 5 +X along Y0 (centre Y5), line 6 -Y along X20 (centre X25),
line 7 +X along Y-10 (centre Y-5), 3 mm wide, line 8 or 9 +Y back up along X23 (centre X18).
Line 7's offset runs from x = 25 to x = 18: backwards, PS0041 found when the wall after it is read."""

from __future__ import annotations

import math

import pytest

from cncmacro.dialects.alarms import CUTTER_INTERFERENCE
from running import lines, machine, run

HEAD = ["O0001", "G10 L12 P1 R5.", "G90 G17 G00 X0 Y10.", "G41 D1 G01 Y0 F100", "X20.", "Y-10.", "X23."]
TAIL = ["Y0", "X40.", "G40 Y10.", "M30"]
PLAIN = lines(*HEAD, *TAIL)  # the wall after the groove on line 8
WITH_Z = lines(*HEAD, "Z-1.", *TAIL)  # a Z move (off the plane) on line 8 between, the wall on line 9


def centre(mv) -> list[tuple[float, float]]:  # type: ignore[no-untyped-def]
    path = mv.tool_path
    return [(path.start[0], path.start[1])] + [(pc.end[0], pc.end[1]) for pc in path.pieces]


@pytest.mark.parametrize(("text", "found_on"), [(PLAIN, 8), (WITH_Z, 9)], ids=["wall-next", "z-move-between"])
def test_an_interference_alarm_stops_the_tool_before_the_reversing_block(text: str, found_on: int) -> None:
    m = run(text)
    assert m.status == "alarm"
    assert (m.alarm.number, m.alarm.line + 1) == (CUTTER_INTERFERENCE, found_on)
    assert "line 7" in m.alarm.message
    moves = m.planner.moves
    # the last move drawn is line 6's, down the left wall: its centre from the corner with line 5,
    # x = 25 meeting y = 5, (25,5), to the corner with line 7, x = 25 meeting y = -5, (25,-5).
    # Line 7 (and the Z move after it) is not made
    assert [mv.line + 1 for mv in moves] == [3, 4, 5, 6]
    got = centre(moves[-1])
    assert all(math.dist(a, b) < 1e-6 for a, b in zip(got, [(25.0, 5.0), (25.0, -5.0)], strict=True)), got
    # cut: line 4 (0,10) -> (5,5) = sqrt(50) = 7.071068, line 5 (5,5) -> (25,5) = 20, line 6 = 10:
    # 37.071068 mm (line 7's 2 mm and the Z move's 1 mm no longer counted)
    assert math.isclose(m.planner.cut_length, 50**0.5 + 30.0, abs_tol=1e-6)
    # the clock is the moves' own: 37.071068 mm at F100 = 22.242641 s, and line 3's rapid
    assert math.isclose(m.planner.clock, sum(mv.seconds for mv in moves), abs_tol=1e-9)
    assert math.isclose(sum(mv.seconds for mv in moves[1:]), (50**0.5 + 30.0) / 100.0 * 60.0, abs_tol=1e-6)
    # the tool is where line 6 ends (line 7's start), X20 Y-10 Z0
    assert m.planner.pos[:3] == [20.0, -10.0, 0.0]


def test_going_back_before_the_alarm_gives_the_block_its_move_again() -> None:
    # a snapshot taken after line 7 ran, restored after the alarm took line 7's move back (the
    # debugger's step back): the toolpath has line 7 again, as the forward run made it
    m = machine(PLAIN)
    while not (m.planner.moves and m.planner.moves[-1].line + 1 == 7):
        m.step()
    snap = m.snapshot()
    m.run()
    assert m.status == "alarm"
    assert [mv.line + 1 for mv in m.planner.moves] == [3, 4, 5, 6]
    m.restore(snap)
    assert [mv.line + 1 for mv in m.planner.moves] == [3, 4, 5, 6, 7]
    m.run()
    assert m.status == "alarm"
    assert [mv.line + 1 for mv in m.planner.moves] == [3, 4, 5, 6]


def test_on_haas_the_interference_is_a_note_and_the_block_is_made() -> None:
    # Haas's manuals name no interference alarm: the run goes past with a note, line 7 drawn
    m = run(PLAIN, "haas")
    assert m.status == "completed", m.alarm
    assert 7 in [mv.line + 1 for mv in m.planner.moves]
