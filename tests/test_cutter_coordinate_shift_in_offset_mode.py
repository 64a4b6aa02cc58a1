"""docs/semantics.md §12, "A coordinate shift in offset mode": a work offset (G54-G59), a local
coordinate system (G52) or a coordinate setting in G41/G42 moves the program position while the
machine stays (planner/offset_travel.py). The corner between the move before the shift and the
one after is worked out in one frame, the coordinates in force after it (planner/cutter_stage.py
``frame_moved``), so the tool centre's path goes on where it was on the machine; it jumped by the
shift and the time was that of the shorter, mixed path. On the GSK980TDi the shift sets the
compensation aside (§3.19 note 2 "执行G52时，将暂时取消刀尖半径补偿", §3.21 note 5 "在刀尖半径补偿模式中，
执行G54~G59时将暂时取消补偿，在下一段移动指令中恢复补偿"): the move before it ends on its perpendicular
and the next move is a start-up from there."""

from __future__ import annotations

import math

import pytest

from running import lines, run

# D1 radius 5, tool left. Line 5 cuts +Y along machine X0 to Y30 (centre at machine X-5); line 6
# shifts the program frame by X+10 (G52 X10., or G55 whose X is 10 more than G54's), so the
# machine's X0 Y30 is X-10 Y30 there; line 7 cuts +X to X20 (machine X30) with the centre at Y35,
# line 8 -Y along machine X30 (centre at machine X35).
MILL = [
    "O0001",
    "G10 L12 P1 R5.",
    "G10 L2 P2 X10. Y0",
    "G90 G17 G54 G00 X-20. Y-20.",
    "G41 D1 G01 X0 Y-10. F400",
    "Y30.",
    "SHIFT",
    "X20. Y30.",
    "Y0",
    "G40 X40. Y-20.",
    "M30",
]


def path_of(m, line: int, a: str = "X", b: str = "Y"):  # type: ignore[no-untyped-def]
    """The (a, b) points of the centre path of the move on (1-based) ``line`` and its seconds."""
    i, j = m.planner.axis_index[a], m.planner.axis_index[b]
    mv = next(mv for mv in m.planner.moves if mv.line + 1 == line)
    path = mv.tool_path
    return [(path.start[i], path.start[j])] + [(pc.end[i], pc.end[j]) for pc in path.pieces], mv.seconds


def near(got: list[tuple[float, float]], want: list[tuple[float, float]]) -> bool:
    return len(got) == len(want) and all(math.dist(x, y) < 0.001 for x, y in zip(got, want, strict=True))


@pytest.mark.parametrize("shift", ["G52 X10.", "G55"])
@pytest.mark.parametrize("dialect", ["fanuc", "haas"])
def test_the_corner_across_a_shift_is_worked_out_on_the_machine(dialect: str, shift: str) -> None:
    text = lines(*[shift if s == "SHIFT" else s for s in MILL])
    m = run(text, dialect)
    assert m.status == "completed", m.alarm
    # the corner at machine (0,30) turns right, outside for a left tool, by 90°: the offsets x = -5
    # and y = 35 meet at machine (-5,35): line 6 ends there, in G54's coordinates
    six, _ = path_of(m, 6)
    assert near(six[-1:], [(-5.0, 35.0)])
    # line 8 starts at the same machine point, (-15,35) in the shifted frame, and ends at its corner
    # with line 9, machine (35,35) = (25,35): 40 mm at F400 = 6 s (it was drawn from (-5,35), 30 mm
    # and 4.5 s, a jump of 10 mm on the machine between two moves)
    eight, seconds = path_of(m, 8)
    assert near(eight, [(-15.0, 35.0), (25.0, 35.0)])
    assert seconds == pytest.approx(6.0)


# a lathe, offset 01: nose radius 0.8, tip 3. Line 6 turns the diameter 20 toward the chuck under
# G42 (the nose centre at X21.6 on the diameter), line 7 shifts Z by -2 (G52 Z-2.): machine Z-10 is
# Z-8 there; line 8 is a taper up to X30 Z-15 (machine Z-17)
LATHE = [
    "O0001",
    "G10 P10001 R0.8 Q3",
    "T0101",
    "G98 G00 X30. Z2.",
    "G42 G01 X20. Z0. F100",
    "Z-10.",
    "G52 Z-2.",
    "X30. Z-15.",
    "Z-25.",
    "G40 G00 X40.",
    "G52 Z0",
    "M30",
]


def test_a_shift_on_the_gsk980tdi_sets_the_compensation_aside_until_the_next_move() -> None:
    m = run(lines(*LATHE), "gsk980tdi")
    assert m.status == "completed", m.alarm
    # line 6 ends on the perpendicular of its end: X20 + 2 x 0.8 = X21.6, Z-10
    six, _ = path_of(m, 6, "X", "Z")
    assert near(six[-1:], [(21.6, -10.0)])
    # line 8 starts again from where the nose centre is: Z-10 on the machine, Z-8 after G52 Z-2.
    eight, _ = path_of(m, 8, "X", "Z")
    assert near(eight[:1], [(21.6, -8.0)])


def test_a_shift_on_a_fanuc_lathe_keeps_the_offset_with_the_corner_on_the_machine() -> None:
    # In G54's (z, r) with r = X / 2: line 6 runs along r = 10 toward -Z, the nose on the +r side
    # (r = 10.8); line 8 runs from (-10, 10) to (-17, 15), direction (-7, 5) / sqrt(74), its right
    # normal (5, 7) / sqrt(74) = (0.581238, 0.813733): its offset passes (-9.535010, 10.650987).
    # The turn is toward the nose, an inside corner: r = 10.8 meets it after t = 0.149013 x
    # sqrt(74) / 5 = 0.256369, z = -9.535010 - 0.256369 x 7 / sqrt(74) = -9.743632. So line 6 ends at
    # X21.6 Z-9.743632 and line 8 starts at the same point, Z-7.743632 after G52 Z-2. (it was
    # -7.743632 for both: line 6 was drawn 2 mm short)
    m = run(lines(*LATHE), "fanuc-0i-lathe")
    assert m.status == "completed", m.alarm
    six, _ = path_of(m, 6, "X", "Z")
    assert near(six[-1:], [(21.6, -9.743632)])
    eight, _ = path_of(m, 8, "X", "Z")
    assert near(eight[:1], [(21.6, -7.743632)])
