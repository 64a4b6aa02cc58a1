"""docs/semantics.md §12, "G41/G42 written again in offset mode": on FANUC (30i-MA user's manual
B-63944EN-2/02 p.158, 15i-MB B-63784EN/01 p.430, "cutter compensation G code in the offset mode": "The offset
vector can be set to form a right angle to the moving direction in the previous block,
irrespective of machining inner or outer side, by commanding the cutter compensation G code (G41,
G42) in the offset mode, independently") the block before the repeated G41 ends on the
perpendicular of its end, and the G41 block goes from there to its usual corner with the next
(``Dialect.repeated_side_perpendicular``, planner/cutter_stage.py). Mitsubishi's manual (§12.4,
G41/G42 without I, J: "intersection point calculation type vector") and the profiles without a
source keep the usual intersection.

The contour, radius 5, tool on the left: line 5 goes +Y along X0 from Y-10 to Y30 (centre at
X-5), line 6 (``G41 X30.``) +X along Y30 (centre at Y35), line 7 -Y along X30 (centre at X35).
Line 6 turns right into line 7, outside by 90°: the offsets meet at (35,35)."""

from __future__ import annotations

import math

import pytest

from running import lines, run

PROGRAM = [
    "O0001",
    "G10 L12 P1 R5.",
    "G90 G17 G00 X-20. Y-20.",
    "G41 D1 G01 X0 Y-10. F400",
    "Y30.",
    "G41 X30.",
    "Y0",
    "X-10.",
    "G40 X-20. Y-20.",
    "M30",
]


def path_of(m, line: int) -> tuple[list[tuple[float, float]], float]:  # type: ignore[no-untyped-def]
    """The XY points of the centre path of the move on (1-based) ``line`` and its seconds."""
    mv = next(mv for mv in m.planner.moves if mv.line + 1 == line)
    path = mv.tool_path
    return [(path.start[0], path.start[1])] + [(pc.end[0], pc.end[1]) for pc in path.pieces], mv.seconds


def near(got: list[tuple[float, float]], want: list[tuple[float, float]]) -> bool:
    return len(got) == len(want) and all(math.dist(a, b) < 0.001 for a, b in zip(got, want, strict=True))


@pytest.mark.parametrize("dialect", ["fanuc", "fanuc-30i"])
@pytest.mark.parametrize("alone", [False, True], ids=["g41-with-the-move", "g41-on-a-block-of-its-own"])
def test_g41_again_ends_the_previous_block_on_its_perpendicular(dialect: str, alone: bool) -> None:
    text = PROGRAM if not alone else [*PROGRAM[:5], "G41", "X30.", *PROGRAM[6:]]
    m = run(lines(*text), dialect)
    assert m.status == "completed", m.alarm
    shift = 1 if alone else 0
    # line 5 ends on the perpendicular of its end (0,30): (-5,30), not at the intersection (-5,35)
    five, _ = path_of(m, 5)
    assert near(five[-1:], [(-5.0, 30.0)])
    # the G41 block goes from (-5,30) to its corner with line 7, (35,35): sqrt(40² + 5²) =
    # 40.311289 mm at F400, 40.311289 / 400 * 60 = 6.046693 s (it was 40 mm, 6 s, from (-5,35))
    six, seconds = path_of(m, 6 + shift)
    assert near(six, [(-5.0, 30.0), (35.0, 35.0)])
    assert seconds == pytest.approx(6.046693, abs=1e-6)


@pytest.mark.parametrize("dialect", ["mitsubishi-m70", "haas"])
def test_g41_again_keeps_the_intersection_where_the_manual_says_so_or_is_silent(dialect: str) -> None:
    m = run(lines(*PROGRAM), dialect)
    assert m.status == "completed", m.alarm
    six, seconds = path_of(m, 6)
    assert near(six, [(-5.0, 35.0), (35.0, 35.0)])
    assert seconds == pytest.approx(6.0)
