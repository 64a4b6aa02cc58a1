"""A three-point arc (GSK980TDi ``G05``, ``G05.1``): the circle through the start, a point on the
arc and the end, cut from the start through that point to the end (docs/semantics.md §8).

GSK980TDi manual §3.5: ``G05 X(U) Z(W) I K F`` gives the point on the arc relative to the start
(I along X as a radius value, K along Z, both signed, "类似于 G02/G03 代码中 … I、K"); ``G05.1``
gives it in absolute coordinates (I an X diameter, K a Z). Both are modal. I or K left out is 0
there. The arc is the one of the two about the circle's centre that passes through the point, so
it is a G02 or a G03 arc, and the planner records and times it as one. Where the control alarms
(the three points on one line, I and K both left out; "G05 cannot cut a full circle") there is no
circle: the caller is told why, gives the finding (``curve-fault``: the manual gives the alarm no
number) and cuts the move straight."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

from ..bilingual import Detail, detail
from .arcs import Plane, plane_scales

NO_POINT = detail(
    "a three-point arc needs its point on the arc: I and K must not both be left out (GSK980TDi manual §3.5); "
    "the control stops with an alarm, the run draws the move straight",
    "三点圆弧需要圆弧上的中间点：I、K 不能同时省略（GSK980TDi 手册 §3.5）；系统报警，本次运行按直线绘制",
)
ON_ONE_LINE = detail(
    "the start, the point on the arc (I, K) and the end point are on one line, or two of them are the same "
    "(a full circle): no arc passes through them (GSK980TDi manual §3.5); the control stops with an alarm, the "
    "run draws the move straight",
    "起点、中间点（I、K）和终点共线，或其中两点重合（整圆）：不能构成圆弧（GSK980TDi 手册 §3.5）；"
    "系统报警，本次运行按直线绘制",
)


def three_point_arc(
    absolute: bool,
    plane: Plane,
    diameter: int,
    start: Sequence[float],
    end: Sequence[float],
    words: Mapping[str, float],
    arc_length: Callable[[float, Sequence[float], Sequence[float], Sequence[float]], float],
) -> tuple[float, tuple[float, ...]] | Detail:
    """(2.0 or 3.0, the centre) of the arc from ``start`` through the block's point on the arc
    (its plane's offset ``words``: relative to the start, or in program coordinates when
    ``absolute``) to ``end`` in ``plane``; ``diameter`` is the index of the axis programmed as a
    diameter; ``arc_length(mode, start, end, centre)`` measures an arc as the clock does. Where
    there is no such circle, why."""
    a, b, off_a, off_b = plane
    if off_a not in words and off_b not in words:
        return NO_POINT
    scale_a, scale_b = plane_scales(plane, diameter)
    sa, sb = start[a] * scale_a, start[b] * scale_b
    ea, eb = end[a] * scale_a, end[b] * scale_b
    wa, wb = words.get(off_a, 0.0), words.get(off_b, 0.0)
    if absolute:  # the point in program coordinates: X a diameter
        ma, mb = wa * scale_a, wb * scale_b
    else:  # relative to the start, X a radius value, as G02/G03's I
        ma, mb = sa + wa, sb + wb
    # the circumcentre of (s, m, e), worked from s
    ba, bb = ma - sa, mb - sb
    ca, cb = ea - sa, eb - sb
    d = 2.0 * (ba * cb - bb * ca)
    if abs(d) < 1e-12:  # on one line, or two of the points the same
        return ON_ONE_LINE
    b2, c2 = ba * ba + bb * bb, ca * ca + cb * cb
    ua = sa + (cb * b2 - bb * c2) / d
    ub = sb + (ba * c2 - ca * b2) / d
    centre = list(start)
    centre[a] = ua / scale_a
    centre[b] = ub / scale_b
    middle = list(start)
    middle[a] = ma / scale_a
    middle[b] = mb / scale_b
    # the arc that reaches the point before it reaches the end is the one through it
    mode = 2.0 if arc_length(2.0, start, middle, centre) < arc_length(2.0, start, end, centre) else 3.0
    return mode, tuple(centre)
