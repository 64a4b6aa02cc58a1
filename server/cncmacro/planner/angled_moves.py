"""A straight move given one coordinate of the plane and an angle (FANUC's direct drawing
dimension programming, ``G01 X30. ,A135.``; docs/semantics.md §8, "Chamfer and corner words").

The angle is measured from the plane's first axis toward its second (G17: from +X toward +Y;
G18, a lathe's: from +Z toward +X), counterclockwise as G03 turns. The move's end lies on the
line through the start at that angle: the coordinate the block leaves out is worked out from the
one it names, in radius terms for a diameter axis. A block that names both coordinates (the
second block of FANUC's two-block form, whose corner is where two such lines meet), or whose
angle runs parallel to the named axis's line of constant value, moves as written.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from .arcs import Plane

_PARALLEL = 1e-9


def angled_end(
    plane: Plane, diameter: int, start: Sequence[float], target: list[float], named: set[int], angle: float
) -> None:
    """Set, in ``target``, the coordinate of ``plane`` that the block does not name (``named``:
    the axes it names), from the other and ``angle`` in degrees."""
    a, b = plane[0], plane[1]
    if (a in named) == (b in named):
        return
    scale_a = 0.5 if a == diameter else 1.0
    scale_b = 0.5 if b == diameter else 1.0
    cos, sin = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    if a in named:
        if abs(cos) < _PARALLEL:
            return
        target[b] = start[b] + (target[a] - start[a]) * scale_a * sin / cos / scale_b
    else:
        if abs(sin) < _PARALLEL:
            return
        target[a] = start[a] + (target[b] - start[b]) * scale_b * cos / sin / scale_a
