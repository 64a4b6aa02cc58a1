"""GSK980TDi's ellipse (``G6.2``/``G6.3``) and parabola (``G7.2``/``G7.3``) moves: the points the
tool passes through from the start to the block's end (docs/semantics.md §8, "Conic moves").

GSK980TDi manual §3.6, ``G6.2 X(U) Z(W) A B Q``: A and B are the half axes (their signs ignored),
Q the angle of the long axis in 0.001° (its sign ignored, taken modulo 180°; Q180. is 0.18°): the
plane's first axis (Z in G18, X in G17, Y in G19) turned clockwise seen from the plane's positive
normal, the sense of G02. G6.2 goes round clockwise in that sense, as G02; G6.3 as G03. Of the two
ellipses through the start and the end, the control cuts the one on which the way round is at most
180°. The control alarms where A or B is 0 or left out, and where the end is farther from the start
than the long axis reaches.

§3.7, ``G7.2 X(U) Z(W) P Q``: the parabola y² = 2Px, P in least input increments (its sign
ignored), its axis at Q as the ellipse's. Of the two parabolas with that axis through the start
and the end, G7.2 is the one that turns clockwise from the start to the end, G7.3 the other. The
control alarms where P is 0 or left out, and where the line from the start to the end is parallel
to the axis.

Both work in the plane in force, X as a radius where it is programmed as a diameter; an axis off
the plane moves in proportion. The curve is cut as short straight pieces, each turning at most
``STEP_DEGREES``; they are recorded and timed as the block's move.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from math import atan2, ceil, cos, radians, sin, sqrt, tau

from ..bilingual import Detail, detail
from .arcs import Plane, plane_scales

CURVE_FAULT = "curve-fault"  # the finding where the control alarms on a conic move or a three-point arc
STEP_DEGREES = 2.0  # the most a piece of the curve turns (an ellipse's of radius 50: 0.008 mm off it)
_STEP = radians(STEP_DEGREES)
_MAX_PIECES = 720


def conic_points(
    parabola: bool,
    clockwise: bool,
    plane: Plane,
    diameter: int,
    start: Sequence[float],
    end: Sequence[float],
    words: Mapping[str, float],
    increment: float,
) -> list[tuple[float, ...]] | Detail:
    """The points after ``start`` up to ``end`` (program coordinates) of the block's ellipse (or
    ``parabola``) in ``plane``; ``diameter`` is the index of the axis programmed as a diameter,
    ``increment`` the program unit's least input increment (a parabola's P). Where the control
    alarms, why (in English and Chinese)."""
    a, b = plane[0], plane[1]
    scale_a, scale_b = plane_scales(plane, diameter)
    angle = radians((abs(words.get("Q", 0.0)) / 1000.0) % 180.0)
    ua, ub = cos(angle), -sin(angle)  # the axis, the plane's first axis turned clockwise by Q
    wa, wb = -ub, ua  # across it, a quarter turn counterclockwise
    sa, sb = start[a] * scale_a, start[b] * scale_b
    ea, eb = end[a] * scale_a, end[b] * scale_b
    s = (sa * ua + sb * ub, sa * wa + sb * wb)
    e = (ea * ua + eb * ub, ea * wa + eb * wb)
    found = (
        _parabola(clockwise, s, e, abs(words.get("P", 0.0)) * increment)
        if parabola
        else _ellipse(clockwise, s, e, abs(words.get("A", 0.0)), abs(words.get("B", 0.0)))
    )
    if not isinstance(found, list):
        return found
    points = []
    count = len(found)
    for k, (u, w) in enumerate(found, start=1):
        if k == count:
            points.append(tuple(end))
            break
        at = [x + (y - x) * k / count for x, y in zip(start, end, strict=True)]  # an axis off the plane
        at[a] = (u * ua + w * wa) / scale_a
        at[b] = (u * ub + w * wb) / scale_b
        points.append(tuple(at))
    return points


def _ellipse(
    clockwise: bool, s: tuple[float, float], e: tuple[float, float], half_long: float, half_short: float
) -> list[tuple[float, float]] | Detail:
    """The points of the ellipse from ``s`` to ``e`` (along and across its long axis): squeezed
    across by ``half_long / half_short`` it is a circle of radius ``half_long``, on which the way
    round is found as a G02/G03 arc's with R."""
    if half_long == 0.0 or half_short == 0.0:
        return detail(
            "an ellipse needs both half axes: A and B must not be 0 or left out (GSK980TDi manual §3.6); "
            "the control stops with an alarm, the run draws the move straight",
            "椭圆需要两个半轴：A、B 不能为 0 或省略（GSK980TDi 手册 §3.6）；系统报警，本次运行按直线绘制",
        )
    squeeze = half_long / half_short
    su, sw = s[0], s[1] * squeeze
    eu, ew = e[0], e[1] * squeeze
    du, dw = eu - su, ew - sw
    d2 = du * du + dw * dw
    if d2 > 4.0 * half_long * half_long * (1.0 + 1e-9):
        return detail(
            f"the end point is farther from the start than the ellipse's long axis reaches (A{half_long:g}, "
            f"B{half_short:g}; GSK980TDi manual §3.6): the control stops with an alarm, the run draws the move "
            "straight",
            f"终点与起点的距离超出椭圆长轴所及（A{half_long:g}、B{half_short:g}；GSK980TDi 手册 §3.6）："
            "系统报警，本次运行按直线绘制",
        )
    k2 = half_long * half_long / d2 - 0.25 if d2 > 0.0 else 0.0
    k = sqrt(k2) if k2 > 0.0 else 0.0
    if not clockwise:
        k = -k
    cu, cw = su + 0.5 * du + k * dw, sw + 0.5 * dw - k * du
    first = atan2(sw - cw, su - cu)
    sweep = (atan2(ew - cw, eu - cu) - first) % tau  # counterclockwise
    if clockwise and sweep > 0.0:
        sweep -= tau
    pieces = min(_MAX_PIECES, max(1, ceil(abs(sweep) / _STEP)))
    return [
        (cu + half_long * cos(first + sweep * i / pieces), (cw + half_long * sin(first + sweep * i / pieces)) / squeeze)
        for i in range(1, pieces + 1)
    ]


def _parabola(
    clockwise: bool, s: tuple[float, float], e: tuple[float, float], p: float
) -> list[tuple[float, float]] | Detail:
    """The points of the parabola u - c = σ (w - d)² / 2p from ``s`` to ``e`` (along and across
    its axis): σ, the side it opens to, is the one on which it turns the block's way round."""
    if p == 0.0:
        return detail(
            "a parabola needs its P: it must not be 0 or left out (GSK980TDi manual §3.7); the control stops "
            "with an alarm, the run draws the move straight",
            "抛物线需要 P：不能为 0 或省略（GSK980TDi 手册 §3.7）；系统报警，本次运行按直线绘制",
        )
    across = e[1] - s[1]
    if abs(across) < 1e-9:
        return detail(
            "the line from the start to the end point is parallel to the parabola's axis (GSK980TDi manual §3.7): "
            "the control stops with an alarm, the run draws the move straight",
            "起点到终点的连线与抛物线的对称轴平行（GSK980TDi 手册 §3.7）：系统报警，本次运行按直线绘制",
        )
    # opening towards +u it turns clockwise while w grows (the curve's tangent turns that way)
    side = 1.0 if (across > 0.0) == clockwise else -1.0
    d = 0.5 * (e[1] + s[1]) - p * side * (e[0] - s[0]) / across
    c = s[0] - side * (s[1] - d) ** 2 / (2.0 * p)
    turned = abs(atan2(e[1] - d, p) - atan2(s[1] - d, p))  # the tangent's turn from the start to the end
    pieces = min(_MAX_PIECES, max(1, ceil(turned / _STEP)))
    out = []
    for i in range(1, pieces + 1):
        w = s[1] + across * i / pieces
        out.append((c + side * (w - d) ** 2 / (2.0 * p), w))
    return out
