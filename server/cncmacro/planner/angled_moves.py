"""A straight move given one coordinate of the plane and an angle (FANUC's direct drawing
dimension programming, ``G01 X30. ,A135.``; docs/semantics.md §8, "Chamfer and corner words").

The angle is measured from the plane's first axis toward its second (G17: from +X toward +Y;
G18, a lathe's: from +Z toward +X), counterclockwise as G03 turns. The move's end lies on the
line through the start at that angle: the coordinate the block leaves out is worked out from the
one it names, in radius terms for a diameter axis. A block whose angle runs parallel to the named
axis's line of constant value moves as written.

The GSK980TDi writes the angle as the word Q in 0.001° (§3.13, ``Dialect.drawing_angle``), and
alarms where a line runs within 1° of parallel to where it must go (``one_axis_fault``,
``two_line_fault``: the ``drawing-angle`` finding, and the move drawn as written).

FANUC's two-block form, ``,A1`` alone and then ``X3 Z3 ,A2`` (0i-TF operator's manual, "direct
drawing dimension programming"): the first block's end is the corner where the line through the
start at A1 meets the line through the second block's end at A2 (``corner_point``); the planner
keeps the first angle until the next move (``PENDING_ANGLE``). Without a corner (the second block
names one coordinate or no angle, or the lines run parallel) the tool goes straight to the end.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from ..bilingual import Detail, detail
from .arcs import Plane, plane_scales

_PARALLEL = 1e-9
# the ``codes`` keys of the first block of the two-block form: its angle, and its line
PENDING_ANGLE, PENDING_LINE = ",A pending", ",A pending line"
DRAWING_ANGLE = "drawing-angle"  # the finding where the control alarms on a direct drawing angle


def _off_by(angle: float, towards: float) -> float:
    """How far (degrees, 0 to 90) the line at ``angle`` turns from the line at ``towards``."""
    d = (angle - towards) % 180.0
    return min(d, 180.0 - d)


def one_axis_fault(plane: Plane, names: str, named: set[int], angle: float, tolerance: float) -> Detail | None:
    """Why a block that names one coordinate of ``plane`` (its axis letters ``names``) and
    ``angle`` is one the control alarms on: the line runs within ``tolerance`` of parallel to
    the named axis's line of constant value, so it never reaches it (GSK980TDi §3.13 notes 3, 4);
    None when it does not."""
    a, b = plane[0], plane[1]
    if (a in named) == (b in named):
        return None
    named_letter, along = (names[1], names[0]) if b in named else (names[0], names[1])
    if _off_by(angle, 0.0 if b in named else 90.0) > tolerance:
        return None
    return detail(
        f"{named_letter}_ with the angle {angle:g}°: the line runs within {tolerance:g}° of the {along} axis's "
        f"direction and does not reach the {named_letter} given (GSK980TDi manual §3.13: an alarm); the move is "
        "drawn as written",
        f"{named_letter}_ 与角度 {angle:g}°：直线与 {along} 轴方向的夹角在 {tolerance:g}° 以内，到不了所给的 "
        f"{named_letter}（GSK980TDi 手册 §3.13：报警）；移动按所写绘制",
    )


def two_line_fault(first: float, second: float, tolerance: float) -> Detail | None:
    """Why the two-block form's lines at ``first`` and ``second`` make no corner the control
    accepts: they run within ``tolerance`` of parallel (GSK980TDi §3.13 note 5); None otherwise."""
    if _off_by(first, second) > tolerance:
        return None
    return detail(
        f"the angles {first:g}° and {second:g}° differ by less than {tolerance:g}°: the two lines make no corner "
        "(GSK980TDi manual §3.13: an alarm); the tool is drawn straight to the end point",
        f"角度 {first:g}° 与 {second:g}° 相差不到 {tolerance:g}°：两条直线没有交点（GSK980TDi 手册 §3.13：报警）；"
        "刀具按直线绘制到终点",
    )


def angled_end(
    plane: Plane, diameter: int, start: Sequence[float], target: list[float], named: set[int], angle: float
) -> None:
    """Set, in ``target``, the coordinate of ``plane`` that the block does not name (``named``:
    the axes it names), from the other and ``angle`` in degrees."""
    a, b = plane[0], plane[1]
    if (a in named) == (b in named):
        return
    scale_a, scale_b = plane_scales(plane, diameter)
    cos, sin = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    if a in named:
        if abs(cos) < _PARALLEL:
            return
        target[b] = start[b] + (target[a] - start[a]) * scale_a * sin / cos / scale_b
    else:
        if abs(sin) < _PARALLEL:
            return
        target[a] = start[a] + (target[b] - start[b]) * scale_b * cos / sin / scale_a


def corner_point(
    plane: Plane, diameter: int, start: Sequence[float], end: Sequence[float], first: float, second: float
) -> list[float] | None:
    """Where the line through ``start`` at angle ``first`` meets the line through ``end`` at
    ``second`` (degrees, as ``angled_end`` measures them), in ``plane``; None where they run
    parallel."""
    a, b = plane[0], plane[1]
    scale_a, scale_b = plane_scales(plane, diameter)
    u = (math.cos(math.radians(first)), math.sin(math.radians(first)))
    v = (math.cos(math.radians(second)), math.sin(math.radians(second)))
    cross = u[0] * v[1] - u[1] * v[0]
    if abs(cross) < _PARALLEL:
        return None
    da = (end[a] - start[a]) * scale_a
    db = (end[b] - start[b]) * scale_b
    t = (da * v[1] - db * v[0]) / cross
    corner = list(start)
    corner[a] = start[a] + t * u[0] / scale_a
    corner[b] = start[b] + t * u[1] / scale_b
    return corner
