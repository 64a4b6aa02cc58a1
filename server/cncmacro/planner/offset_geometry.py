"""The geometry of a path offset by a tool's radius, in one plane (docs/semantics.md, "Cutter
radius compensation").

Pure functions of points in the plane's two axes: nothing here knows of G codes, controls or
lathes. A programmed element (``PathElement``) is a straight line or an arc (its centre and its
turning sense); ``offset_element`` moves it sideways by a signed distance (positive to the left
of the direction of travel, negative to the right); ``join`` decides how the offset elements of
two blocks meet at their common programmed point: at the intersection of the offsets on an
inside corner and on an obtuse outside one, through two extension points on an acute outside one
(``MEET``), or at the perpendicular of one of them (``PERPENDICULAR_AFTER``: a start-up of type A,
``PERPENDICULAR_BEFORE``: a cancel of type A). ``centre_segment`` is the piece of an offset
element between two points on it, and ``reverses`` says whether that piece runs against the
programmed element (the interference a control alarms on). Lengths are in whatever unit the
points are; angles in radians.
"""

from __future__ import annotations

from math import atan2, hypot, pi, sqrt
from typing import NamedTuple

Point = tuple[float, float]
EPSILON = 1e-9  # lengths below this are zero (the points are on a 0.001 or 0.0001 grid)
_TWO_PI = 2.0 * pi

MEET = "meet"  # intersection, or the extension points of an acute outside corner
PERPENDICULAR_AFTER = "perpendicular-after"  # outside: end on the perpendicular of the element after
PERPENDICULAR_BEFORE = "perpendicular-before"  # outside: end on the perpendicular of the element before


class NoIntersection(ValueError):
    """The offsets of two elements that form an inside corner do not meet (the cutter is too
    large for the shape there)."""


class PathElement(NamedTuple):
    """A programmed or offset element in the plane: a line from ``start`` to ``end`` (``centre``
    None) or an arc about ``centre`` turning counterclockwise when ``ccw`` (a full circle when
    ``start`` is ``end``)."""

    start: Point
    end: Point
    centre: Point | None = None
    ccw: bool = False


class Corner(NamedTuple):
    """Where two offset elements meet: the element before ends at ``before_end`` (on its offset,
    trimmed or extended), the tool goes straight through ``links`` and on to ``after_start``, where
    the element after starts (on its offset)."""

    before_end: Point
    links: tuple[Point, ...]
    after_start: Point


def _unit(x: float, y: float) -> Point:
    n = hypot(x, y)
    return (x / n, y / n) if n > EPSILON else (0.0, 0.0)


def start_direction(s: PathElement) -> Point:
    """The unit direction of travel at the start of ``s``."""
    if s.centre is None:
        return _unit(s.end[0] - s.start[0], s.end[1] - s.start[1])
    rx, ry = s.start[0] - s.centre[0], s.start[1] - s.centre[1]
    return _unit(-ry, rx) if s.ccw else _unit(ry, -rx)


def end_direction(s: PathElement) -> Point:
    """The unit direction of travel at the end of ``s``."""
    if s.centre is None:
        return start_direction(s)
    rx, ry = s.end[0] - s.centre[0], s.end[1] - s.centre[1]
    return _unit(-ry, rx) if s.ccw else _unit(ry, -rx)


def _shift(p: Point, t: Point, d: float) -> Point:
    """``p`` moved ``d`` to the left of direction ``t`` (to the right when negative)."""
    return (p[0] - t[1] * d, p[1] + t[0] * d)


def offset_element(s: PathElement, d: float) -> PathElement | None:
    """``s`` moved ``d`` to the left of its direction of travel (right when ``d`` is negative);
    None for an arc whose offset radius would be zero or less (the tool does not fit inside it)
    and for an arc of no radius."""
    if s.centre is None:
        t = start_direction(s)
        return PathElement(_shift(s.start, t, d), _shift(s.end, t, d))
    cx, cy = s.centre
    r0 = hypot(s.start[0] - cx, s.start[1] - cy)
    r1 = hypot(s.end[0] - cx, s.end[1] - cy)
    if r0 <= EPSILON or r1 <= EPSILON:  # an arc of no radius: nothing to offset
        return None
    # the centre is on the left of a counterclockwise arc: an offset to the left shrinks it
    k0 = (r0 - d) / r0 if s.ccw else (r0 + d) / r0
    k1 = (r1 - d) / r1 if s.ccw else (r1 + d) / r1
    if k0 <= EPSILON or k1 <= EPSILON:
        return None
    start = (cx + (s.start[0] - cx) * k0, cy + (s.start[1] - cy) * k0)
    end = start if s.start == s.end else (cx + (s.end[0] - cx) * k1, cy + (s.end[1] - cy) * k1)
    return PathElement(start, end, s.centre, s.ccw)


def _radius(s: PathElement) -> float:
    assert s.centre is not None
    return 0.5 * (hypot(s.start[0] - s.centre[0], s.start[1] - s.centre[1])
                  + hypot(s.end[0] - s.centre[0], s.end[1] - s.centre[1]))  # fmt: skip


def _line_line(a: PathElement, b: PathElement) -> list[Point]:
    ax, ay = a.end[0] - a.start[0], a.end[1] - a.start[1]
    bx, by = b.end[0] - b.start[0], b.end[1] - b.start[1]
    den = ax * by - ay * bx
    if abs(den) <= EPSILON * max(hypot(ax, ay) * hypot(bx, by), EPSILON):
        return []
    t = ((b.start[0] - a.start[0]) * by - (b.start[1] - a.start[1]) * bx) / den
    return [(a.start[0] + t * ax, a.start[1] + t * ay)]


def _line_circle(line: PathElement, circle: PathElement) -> list[Point]:
    assert circle.centre is not None
    (px, py), (qx, qy) = line.start, line.end
    dx, dy = qx - px, qy - py
    n = hypot(dx, dy)
    if n <= EPSILON:
        return []
    dx, dy = dx / n, dy / n
    cx, cy = circle.centre
    r = _radius(circle)
    # the foot of the perpendicular from the centre, then half the chord either side
    t = (cx - px) * dx + (cy - py) * dy
    fx, fy = px + t * dx, py + t * dy
    h2 = r * r - ((cx - fx) ** 2 + (cy - fy) ** 2)
    if h2 < -EPSILON * max(r, 1.0):
        return []
    h = sqrt(max(h2, 0.0))
    return [(fx - h * dx, fy - h * dy), (fx + h * dx, fy + h * dy)]


def _circle_circle(a: PathElement, b: PathElement) -> list[Point]:
    assert a.centre is not None and b.centre is not None
    (ax, ay), (bx, by) = a.centre, b.centre
    ra, rb = _radius(a), _radius(b)
    d = hypot(bx - ax, by - ay)
    if d <= EPSILON:
        return []
    along = (d * d + ra * ra - rb * rb) / (2.0 * d)
    h2 = ra * ra - along * along
    if h2 < -EPSILON * max(ra, 1.0):
        return []
    h = sqrt(max(h2, 0.0))
    ux, uy = (bx - ax) / d, (by - ay) / d
    mx, my = ax + along * ux, ay + along * uy
    return [(mx - h * uy, my + h * ux), (mx + h * uy, my - h * ux)]


def intersections(a: PathElement, b: PathElement) -> list[Point]:
    """Where the whole line or circle of ``a`` crosses that of ``b`` (none, one or two points)."""
    if a.centre is None and b.centre is None:
        return _line_line(a, b)
    if a.centre is None:
        return _line_circle(a, b)
    if b.centre is None:
        return _line_circle(b, a)
    return _circle_circle(a, b)


def _nearest(points: list[Point], to: Point) -> Point | None:
    return min(points, key=lambda q: (q[0] - to[0]) ** 2 + (q[1] - to[1]) ** 2) if points else None


def join(before: PathElement, after: PathElement, d_before: float, d_after: float, outer: str = MEET) -> Corner:
    """How the offsets of ``before`` (by ``d_before``) and ``after`` (by ``d_after``), which meet
    at ``before.end``, are joined. An inside corner (the path turns toward the tool's side) ends
    both at the intersection of their offsets nearest the corner (``NoIntersection`` when they do
    not cross). An outside corner, with ``outer`` ``MEET``: the intersection when the path turns by
    90° or less (an obtuse corner), else the two extension points, each a radius on along the
    offset's tangent past its end (before) and before its start (after); with
    ``PERPENDICULAR_AFTER`` the perpendicular point of ``after``, with ``PERPENDICULAR_BEFORE``
    that of ``before``. A tangent continuation joins at the common perpendicular point."""
    p = before.end
    t1, t2 = end_direction(before), start_direction(after)
    q1, q2 = _shift(p, t1, d_before), _shift(p, t2, d_after)
    cross, dot = t1[0] * t2[1] - t1[1] * t2[0], t1[0] * t2[0] + t1[1] * t2[1]
    side = d_before if d_before else d_after
    if abs(cross) <= 1e-12 and dot > 0.0:  # straight on (or tangent): the offsets touch there
        if hypot(q1[0] - q2[0], q1[1] - q2[1]) <= EPSILON:
            return Corner(q1, (), q1)
        return Corner(q1, (), q2)  # a radius changed on a tangent: straight across
    inner = cross * side > 0.0
    if not inner and outer == PERPENDICULAR_AFTER:
        return Corner(q2, (), q2)
    if not inner and outer == PERPENDICULAR_BEFORE:
        return Corner(q1, (), q1)
    a_off = offset_element(before, d_before)
    b_off = offset_element(after, d_after)
    if inner or dot >= 0.0:
        found = None
        if a_off is not None and b_off is not None:
            found = _nearest(intersections(a_off, b_off), p)
        if found is not None:
            return Corner(found, (), found)
        if inner:
            raise NoIntersection(p)
    # an acute outside corner (or an obtuse one whose offsets do not cross): extension points
    r = abs(side)
    c1 = (q1[0] + t1[0] * r, q1[1] + t1[1] * r)
    c2 = (q2[0] - t2[0] * r, q2[1] - t2[1] * r)
    if before.centre is None and after.centre is None:
        return Corner(c1, (), c2)
    if before.centre is None:
        return Corner(c1, (c2,), q2)
    if after.centre is None:
        return Corner(q1, (c1,), c2)
    return Corner(q1, (c1, c2), q2)


def perpendicular_end(s: PathElement, d: float) -> Point:
    """The point ``d`` to the left of the end of ``s`` (right when negative): where the tool
    stops when nothing follows in the plane."""
    return _shift(s.end, end_direction(s), d)


def sweep(centre: Point, start: Point, end: Point, ccw: bool) -> float:
    """The angle an arc about ``centre`` turns from ``start`` to ``end`` in its sense, in (0, 2π]:
    an arc back to its start is a full circle."""
    a0 = atan2(start[1] - centre[1], start[0] - centre[0])
    a1 = atan2(end[1] - centre[1], end[0] - centre[0])
    s = (a1 - a0) % _TWO_PI if ccw else (a0 - a1) % _TWO_PI
    return _TWO_PI if s <= 1e-12 else s


def centre_segment(programmed: PathElement, start: Point, end: Point) -> PathElement:
    """The tool centre's piece of the offset of ``programmed`` from ``start`` to ``end``."""
    return PathElement(start, end, programmed.centre, programmed.ccw)


def reverses(programmed: PathElement, centre: PathElement) -> bool:
    """Whether the tool centre's piece ``centre`` runs against ``programmed``: a line that
    points backwards (more than 90° off), an arc whose sweep differs from the programmed one by
    more than half a turn (its end overtook its start)."""
    if programmed.centre is None:
        px, py = programmed.end[0] - programmed.start[0], programmed.end[1] - programmed.start[1]
        cx, cy = centre.end[0] - centre.start[0], centre.end[1] - centre.start[1]
        return px * cx + py * cy < -EPSILON * max(hypot(px, py), 1.0)
    assert centre.centre is not None
    full = programmed.start == programmed.end
    wanted = sweep(programmed.centre, programmed.start, programmed.end, programmed.ccw)
    close = hypot(centre.end[0] - centre.start[0], centre.end[1] - centre.start[1]) <= EPSILON
    got = _TWO_PI if close and full else sweep(centre.centre, centre.start, centre.end, centre.ccw)
    if close and not full:
        got = 0.0
    return abs(got - wanted) > pi
