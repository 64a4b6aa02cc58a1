"""The geometry of a chamfer or a corner rounding between two moves, in one plane (docs/semantics.md
§8, "Chamfer and corner words").

Pure functions of points in the plane's two axes, after offset_geometry.py's ``PathElement`` (a
line, or an arc about its centre in its sense): nothing here knows of G codes or controls. Two
elements meet at the corner ``before.end`` (= ``after.start``).

- ``chamfer``: the straight line between the point of ``before`` and the point of ``after`` that are
  each ``d`` from the corner (FANUC's ``,C``: "the distance from the virtual corner"; on an arc the
  point of the arc that distance from the corner in a straight line).
- ``chamfer_of_length``: the same chamfer whose own length is ``length`` (the GSK980TDi's ``L``, type
  I): the two points at one distance from the corner, found by halving.
- ``rounding``: the arc of radius ``r`` tangent to both (FANUC's ``,R``, the GSK980TDi's ``D``): its
  centre is where the two elements, each offset by ``r`` toward the side the path turns to, cross
  nearest the corner, and it touches each element at the foot of that centre.

``None`` where nothing is inserted: two lines on one line (and, for a rounding, any two elements
already tangent at the corner: GSK980TDi manual §3.11.3; a chamfer between an arc and a line
tangent to it is cut). ``NoFit`` where the element does not fit:
its reason is ``SHORT`` (a point off its move: the move is too short), ``LONG`` (a chamfer of type I
longer than the third side of the triangle the two moves make) or ``RADIUS`` (no tangent arc of that
radius on the two moves).
"""

from __future__ import annotations

from math import hypot, pi
from typing import NamedTuple

from .offset_geometry import (
    EPSILON,
    PathElement,
    end_direction,
    intersections,
    offset_element,
    start_direction,
    sweep,
)

Point = tuple[float, float]
SHORT, LONG, RADIUS = "short", "long", "radius"
_TANGENT = 1e-9  # |sin| of the turn below which two elements go straight on


class NoFit(ValueError):
    """The chamfer or rounding does not fit the two moves (``reason``: module docstring)."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


class Inserted(NamedTuple):
    """What goes between the two moves: ``before`` now ends at ``start``, ``after`` starts at
    ``end``, and the tool goes from one to the other straight (``centre`` None) or along an arc
    about ``centre``, counterclockwise when ``ccw``."""

    start: Point
    end: Point
    centre: Point | None = None
    ccw: bool = False


def _turn(before: PathElement, after: PathElement) -> tuple[float, float]:
    """The sine and cosine of the turn from ``before``'s end direction to ``after``'s start one."""
    t1, t2 = end_direction(before), start_direction(after)
    return t1[0] * t2[1] - t1[1] * t2[0], t1[0] * t2[0] + t1[1] * t2[1]


def _one_line(before: PathElement, after: PathElement) -> bool:
    """Whether two lines go straight on, one after the other (§3.11.3 情形 1)."""
    if before.centre is not None or after.centre is not None:
        return False
    cross, dot = _turn(before, after)
    return abs(cross) <= _TANGENT and dot > 0.0


def _on_arc(s: PathElement, q: Point) -> float | None:
    """How far round ``s`` (an arc) ``q`` is from its start, in radians; None past its end."""
    assert s.centre is not None
    total = sweep(s.centre, s.start, s.end, s.ccw)
    if hypot(q[0] - s.start[0], q[1] - s.start[1]) <= EPSILON:
        return 0.0
    got = sweep(s.centre, s.start, q, s.ccw)
    return got if got <= total + 1e-12 else None


def _at_distance(s: PathElement, d: float, from_end: bool) -> Point:
    """The point of ``s`` ``d`` from its end (``from_end``) or its start in a straight line, the
    nearest such along ``s`` to that end; ``NoFit(SHORT)`` when there is none."""
    corner = s.end if from_end else s.start
    if s.centre is None:
        n = hypot(s.end[0] - s.start[0], s.end[1] - s.start[1])
        if d > n + EPSILON:
            raise NoFit(SHORT)
        t = start_direction(s)
        k = -d if from_end else d
        return corner[0] + t[0] * k, corner[1] + t[1] * k
    circle = PathElement((corner[0] + d, corner[1]), (corner[0] + d, corner[1]), corner)
    found = [(a, q) for q in intersections(s, circle) if (a := _on_arc(s, q)) is not None]
    if not found:
        raise NoFit(SHORT)
    pick = max if from_end else min
    return pick(found)[1]


def chamfer(before: PathElement, after: PathElement, d: float) -> Inserted | None:
    """The chamfer ``d`` from the corner along each move (module docstring)."""
    if _one_line(before, after):
        return None
    return Inserted(_at_distance(before, d, True), _at_distance(after, d, False))


def _reach(s: PathElement, from_end: bool) -> float:
    """The farthest a point of ``s`` is from its corner end, in a straight line (a bound)."""
    if s.centre is None or sweep(s.centre, s.start, s.end, s.ccw) <= pi:
        return hypot(s.end[0] - s.start[0], s.end[1] - s.start[1])
    return 2.0 * hypot(s.start[0] - s.centre[0], s.start[1] - s.centre[1])


def chamfer_of_length(before: PathElement, after: PathElement, length: float) -> Inserted | None:
    """The chamfer ``length`` long whose ends are at one distance from the corner (type I)."""
    if _one_line(before, after):
        return None
    far = hypot(after.end[0] - before.start[0], after.end[1] - before.start[1])
    if length > far + EPSILON:  # longer than the triangle's third side (§3.11.3 情形 2)
        raise NoFit(LONG)
    top = min(_reach(before, True), _reach(after, False))

    def span(d: float) -> float:
        a, b = _at_distance(before, d, True), _at_distance(after, d, False)
        return hypot(b[0] - a[0], b[1] - a[1])

    if span(top) < length - EPSILON:  # an end off its move (§3.11.3 情形 3)
        raise NoFit(SHORT)
    lo, hi = 0.0, top
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if span(mid) < length:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-13 * max(top, 1.0):
            break
    return chamfer(before, after, hi)


def _foot(s: PathElement, q: Point) -> Point:
    """The point of ``s``'s line or circle nearest ``q``."""
    if s.centre is None:
        t = start_direction(s)
        k = (q[0] - s.start[0]) * t[0] + (q[1] - s.start[1]) * t[1]
        return s.start[0] + t[0] * k, s.start[1] + t[1] * k
    cx, cy = s.centre
    r = 0.5 * (hypot(s.start[0] - cx, s.start[1] - cy) + hypot(s.end[0] - cx, s.end[1] - cy))
    n = hypot(q[0] - cx, q[1] - cy)
    if n <= EPSILON:
        raise NoFit(RADIUS)
    return cx + (q[0] - cx) * r / n, cy + (q[1] - cy) * r / n


def _within(s: PathElement, q: Point) -> bool:
    """Whether ``q``, a point of ``s``'s line or circle, lies on ``s`` itself."""
    if s.centre is None:
        dx, dy = s.end[0] - s.start[0], s.end[1] - s.start[1]
        n = hypot(dx, dy)
        k = ((q[0] - s.start[0]) * dx + (q[1] - s.start[1]) * dy) / n if n > EPSILON else 0.0
        return -EPSILON <= k <= n + EPSILON
    return _on_arc(s, q) is not None


def rounding(before: PathElement, after: PathElement, r: float) -> Inserted | None:
    """The arc of radius ``r`` tangent to both moves (module docstring)."""
    cross, dot = _turn(before, after)
    if abs(cross) <= _TANGENT and dot > 0.0:  # already tangent (or on one line): nothing
        return None
    if abs(cross) <= _TANGENT:  # the path turns straight back: no arc touches both
        raise NoFit(RADIUS)
    d = r if cross > 0.0 else -r  # the side the path turns to: left when counterclockwise
    a, b = offset_element(before, d), offset_element(after, d)
    if a is None or b is None:
        raise NoFit(RADIUS)
    corner = before.end
    found = intersections(a, b)
    if not found:
        raise NoFit(RADIUS)
    centre = min(found, key=lambda q: (q[0] - corner[0]) ** 2 + (q[1] - corner[1]) ** 2)
    t1, t2 = _foot(before, centre), _foot(after, centre)
    if not _within(before, t1) or not _within(after, t2):
        raise NoFit(RADIUS)
    return Inserted(t1, t2, centre, cross > 0.0)
