"""docs/semantics.md §12: the geometry of cutter radius compensation (planner/offset_geometry.py),
with hand-computed points to 0.001 mm. A positive offset is to the left of the direction of
travel (G41), a negative one to the right (G42)."""

from __future__ import annotations

import math

import pytest

from cncmacro.planner.offset_geometry import (
    MEET,
    PERPENDICULAR_AFTER,
    PERPENDICULAR_BEFORE,
    Corner,
    NoIntersection,
    PathElement,
    join,
    offset_element,
    reverses,
)

Line = PathElement


def Arc(start: tuple[float, float], end: tuple[float, float], centre: tuple[float, float], ccw: bool) -> PathElement:
    return PathElement(start, end, centre, ccw)


def near(p: tuple[float, float], q: tuple[float, float]) -> bool:
    return math.dist(p, q) < 0.001


def same_corner(
    c: Corner, before_end: tuple[float, float], links: tuple[tuple[float, float], ...], after_start: tuple[float, float]
) -> bool:
    same_links = len(c.links) == len(links) and all(near(a, b) for a, b in zip(c.links, links, strict=True))
    return near(c.before_end, before_end) and same_links and near(c.after_start, after_start)


def test_a_line_is_offset_to_the_left_for_g41_and_to_the_right_for_g42() -> None:
    # along +X the left is +Y: (0,0)->(10,0) by +2 is (0,2)->(10,2), by -2 (0,-2)->(10,-2)
    assert offset_element(Line((0.0, 0.0), (10.0, 0.0)), 2.0) == Line((0.0, 2.0), (10.0, 2.0))
    assert offset_element(Line((0.0, 0.0), (10.0, 0.0)), -2.0) == Line((0.0, -2.0), (10.0, -2.0))


def test_an_arc_shrinks_on_its_centre_side_and_grows_on_the_other() -> None:
    # a counterclockwise arc has its centre on the left: radius 10 about (0,0) from (10,0) to (0,10)
    # by +2 is radius 8, (8,0)->(0,8); the same arc clockwise (centre on the right) by +2 is radius 12
    off = offset_element(Arc((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), True), 2.0)
    assert off is not None and near(off.start, (8.0, 0.0)) and near(off.end, (0.0, 8.0))
    off = offset_element(Arc((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), False), 2.0)
    assert off is not None and near(off.start, (12.0, 0.0)) and near(off.end, (0.0, 12.0))


def test_a_cutter_larger_than_an_inside_arc_has_no_offset() -> None:
    # an inside arc of radius 3 and a cutter of radius 5: 3 - 5 < 0; radius 5 exactly: 0, no arc either
    assert offset_element(Arc((3.0, 0.0), (0.0, 3.0), (0.0, 0.0), True), 5.0) is None
    assert offset_element(Arc((5.0, 0.0), (0.0, 5.0), (0.0, 0.0), True), 5.0) is None


def test_an_inside_corner_ends_both_offsets_at_their_intersection() -> None:
    # +X to (10,0) then +Y: a left turn, the tool left (+2): y = 2 meets x = 10 - 2 = 8 at (8,2)
    c = join(Line((0.0, 0.0), (10.0, 0.0)), Line((10.0, 0.0), (10.0, 10.0)), 2.0, 2.0)
    assert same_corner(c, (8.0, 2.0), (), (8.0, 2.0))


def test_an_obtuse_outside_corner_ends_at_the_intersection_of_the_extensions() -> None:
    # the same corner with the tool on the right (-2): y = -2 meets x = 10 + 2 = 12 at (12,-2)
    c = join(Line((0.0, 0.0), (10.0, 0.0)), Line((10.0, 0.0), (10.0, 10.0)), -2.0, -2.0)
    assert same_corner(c, (12.0, -2.0), (), (12.0, -2.0))


def test_an_acute_outside_corner_goes_through_two_extension_points() -> None:
    # +X to (10,0), then back up-left to (0,5): t2 = (-10,5)/sqrt(125) = (-0.894427, 0.447214), a
    # turn of 153.4°. Tool on the right (-2): the first offset ends at q1 = (10,-2), extended by the
    # radius along +X: c1 = (12,-2). The second starts at q2 = (10,0) + 2 * right normal of t2
    # (t2y, -t2x) = (10 + 0.894427, 1.788854); c2 = q2 - 2 * t2 = (10.894427 + 1.788854,
    # 1.788854 - 0.894427) = (12.683282, 0.894427). Lines: the first runs on to c1, the second from c2.
    c = join(Line((0.0, 0.0), (10.0, 0.0)), Line((10.0, 0.0), (0.0, 5.0)), -2.0, -2.0)
    assert same_corner(c, (12.0, -2.0), (), (12.683282, 0.894427))


def test_a_tangent_line_and_arc_need_no_corner() -> None:
    # +X to (10,0), then counterclockwise about (10,10): its start tangent is +X; by +2 both
    # offsets pass through (10,2)
    c = join(Line((0.0, 0.0), (10.0, 0.0)), Arc((10.0, 0.0), (20.0, 10.0), (10.0, 10.0), True), 2.0, 2.0)
    assert same_corner(c, (10.0, 2.0), (), (10.0, 2.0))


def test_an_inside_line_to_arc_corner_meets_the_offset_circle() -> None:
    # +X to (10,0), then clockwise about (20,0) radius 10 to (20,10): the arc starts going +Y, a left
    # turn; tool left (+2): inside. Line y = 2; the clockwise arc grows to 12: (x-20)² + 2² = 144,
    # x = 20 - sqrt(140) = 20 - 11.832160 = 8.167840 (the root nearer the corner)
    c = join(Line((0.0, 0.0), (10.0, 0.0)), Arc((10.0, 0.0), (20.0, 10.0), (20.0, 0.0), False), 2.0, 2.0)
    assert same_corner(c, (8.167840, 2.0), (), (8.167840, 2.0))


def test_an_obtuse_outside_line_to_arc_corner_meets_the_offset_circle() -> None:
    # the same with the tool right (-2): y = -2 and radius 10 - 2 = 8: x = 20 - sqrt(64 - 4) =
    # 20 - 7.745967 = 12.254033
    c = join(Line((0.0, 0.0), (10.0, 0.0)), Arc((10.0, 0.0), (20.0, 10.0), (20.0, 0.0), False), -2.0, -2.0)
    assert same_corner(c, (12.254033, -2.0), (), (12.254033, -2.0))


def test_an_inside_arc_to_line_corner_meets_the_offset_line() -> None:
    # clockwise about (20,0) from (10,0) to (20,10) ends going +X, then +Y from (20,10): a left turn,
    # tool left (+2): the arc at radius 12 meets x = 18: y = sqrt(144 - 4) = 11.832160
    c = join(Arc((10.0, 0.0), (20.0, 10.0), (20.0, 0.0), False), Line((20.0, 10.0), (20.0, 30.0)), 2.0, 2.0)
    assert same_corner(c, (18.0, 11.832160), (), (18.0, 11.832160))


def test_an_inside_corner_whose_offsets_never_meet_is_no_intersection() -> None:
    # +X to (10,0), then counterclockwise about (9,1) (radius sqrt2 = 1.414214): its start tangent
    # (-ry, rx) of r = (1,-1) is (1,1)/sqrt2, a left turn of 45°: inside for a tool on the left. By
    # +3 the arc, centre on the left, would shrink to 1.414214 - 3 < 0: nothing to meet
    with pytest.raises(NoIntersection):
        join(Line((0.0, 0.0), (10.0, 0.0)), Arc((10.0, 0.0), (10.0, 2.0), (9.0, 1.0), True), 3.0, 3.0)


def test_type_a_start_up_ends_on_the_perpendicular_of_the_next_block_type_b_at_the_intersection() -> None:
    # G42 (tool right, -5) started on +X to (0,0), next block +Y: a left turn, outside for a tool on
    # the right, 90°. Type A: the perpendicular right of +Y at (0,0) is (5,0). Type B: the offsets
    # y = -5 and x = 5 meet at (5,-5) (FANUC's start-up figures, outside corner, obtuse)
    startup, nxt = Line((-10.0, 0.0), (0.0, 0.0)), Line((0.0, 0.0), (0.0, 10.0))
    assert same_corner(join(startup, nxt, -5.0, -5.0, PERPENDICULAR_AFTER), (5.0, 0.0), (), (5.0, 0.0))
    assert same_corner(join(startup, nxt, -5.0, -5.0, MEET), (5.0, -5.0), (), (5.0, -5.0))


def test_an_inside_start_up_is_the_intersection_for_both_types() -> None:
    # G41 (tool left, +5) on the same corner: inside: x = -5 and y = 5 meet at (-5,5), types A and B
    startup, nxt = Line((-10.0, 0.0), (0.0, 0.0)), Line((0.0, 0.0), (0.0, 10.0))
    for outer in (PERPENDICULAR_AFTER, MEET):
        assert same_corner(join(startup, nxt, 5.0, 5.0, outer), (-5.0, 5.0), (), (-5.0, 5.0))


def test_type_a_cancel_starts_on_the_perpendicular_of_the_block_before_type_b_at_the_intersection() -> None:
    # G42 (-5) along +X to (10,0), cancel to (20,10), direction (1,1)/sqrt2: a left turn, outside.
    # Type A: the perpendicular right of +X at (10,0): (10,-5). Type B: y = -5 meets the cancel
    # line moved right by 5, (10 + 3.535534, -3.535534) + t(1,1): y - x = -17.071068, x = 12.071068
    before, cancel = Line((0.0, 0.0), (10.0, 0.0)), Line((10.0, 0.0), (20.0, 10.0))
    assert same_corner(join(before, cancel, -5.0, -5.0, PERPENDICULAR_BEFORE), (10.0, -5.0), (), (10.0, -5.0))
    assert same_corner(join(before, cancel, -5.0, -5.0, MEET), (12.071068, -5.0), (), (12.071068, -5.0))


def test_a_centre_path_that_runs_backwards_is_interference() -> None:
    # programmed +X from (0,0) to (10,0): a centre piece from (5,2) to (3,2) runs -X: reversed;
    # (0,2) to (8,2) does not
    line = Line((0.0, 0.0), (10.0, 0.0))
    assert reverses(line, Line((5.0, 2.0), (3.0, 2.0)))
    assert not reverses(line, Line((0.0, 2.0), (8.0, 2.0)))


def test_an_arc_whose_ends_crossed_over_is_interference() -> None:
    # programmed ccw about (0,0) from 0° to 90°; a centre piece on radius 8 from 50° to 40° turns
    # 350° counterclockwise, 260° more than the 90° programmed: reversed; from 10° to 80° it is not
    arc = Arc((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), True)

    def at(deg: float) -> tuple[float, float]:
        return (8.0 * math.cos(math.radians(deg)), 8.0 * math.sin(math.radians(deg)))

    assert reverses(arc, Arc(at(50), at(40), (0.0, 0.0), True))
    assert not reverses(arc, Arc(at(10), at(80), (0.0, 0.0), True))


def test_an_arc_of_no_radius_has_no_offset() -> None:
    # G02 X0 Y0 I0 J0 from X0 Y0: the centre on the start, radius 0: nothing to offset (no crash)
    assert offset_element(Arc((0.0, 0.0), (0.0, 0.0), (0.0, 0.0), False), 2.0) is None
