"""A straight move given one coordinate of the plane and an angle (FANUC's direct drawing
dimension programming, ``G01 X30. ,A135.``; docs/semantics.md §8, "Chamfer and corner words").

The angle is measured from the plane's first axis toward its second (G17: from +X toward +Y;
G18, a lathe's: from +Z toward +X), counterclockwise as G03 turns. The move's end lies on the
line through the start at that angle: the coordinate the block leaves out is worked out from the
one it names, in radius terms for a diameter axis. A block whose angle runs parallel to the named
axis's line of constant value moves as written.

FANUC's two-block form, ``,A1`` alone and then ``X3 Z3 ,A2`` (0i-TF operator's manual, "direct
drawing dimension programming"): the first block's end is the corner where the line through the
start at A1 meets the line through the second block's end at A2 (``corner_point``); the planner
keeps the first angle until the next move (``PENDING_ANGLE``). Without a corner (the second block
names one coordinate or no angle, or the lines run parallel) the tool goes straight to the end.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from .arcs import Plane, plane_scales

_PARALLEL = 1e-9
# the ``codes`` keys of the first block of the two-block form: its angle, and its line
PENDING_ANGLE, PENDING_LINE = ",A pending", ",A pending line"


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
