"""Polar coordinate interpolation (FANUC ``G12.1``/``G112``, off with ``G13.1``/``G113``) and
cylindrical interpolation (``G07.1 C_``/``G107``, off with ``C0``) on a turning centre: while one
is on, X and C (polar), or Z and C developed on the cylinder (cylindrical), make the plane in
which arcs and cutter radius compensation act (FANUC 0i-TF operator's manual, "polar coordinate
interpolation", "cylindrical interpolation"; docs/semantics.md §8).

That plane is **not simulated**: a move is drawn as written, an arc as its chord, and G41/G42 draw
the programmed path. A cut's length under cylindrical interpolation takes C's degrees on the
cylinder's surface, radius times angle (``surface_length``): C in degrees as millimetres made a
slot on a 10 mm radius 5.7 times too long. What the run must not do is judge the moves in
the plane in force instead (G18's Z and X): an arc in X and C checked there has "its end at its
start", and a compensation started there would push X off the cylinder, then alarm PS0037 at
the G18 that follows ``G07.1 C0``. The mode is kept with the modal codes (``VIRTUAL_PLANE``), so
that a snapshot keeps it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .planner import Planner

VIRTUAL_PLANE = "virtual plane"  # the ``modal`` key of the mode on (its code), absent when off
CYLINDER = "cylinder radius"  # the ``modal`` key of cylindrical interpolation's radius, while it is on


def switch_virtual_plane(p: Planner, g: float, on: bool, radius: float | None = None) -> None:
    """Code ``g`` turns polar or cylindrical interpolation (the cylinder's ``radius``) on
    (``on``) or off."""
    p.modal.pop(CYLINDER, None)
    if on:
        p.modal[VIRTUAL_PLANE] = g
        if radius:
            p.modal[CYLINDER] = abs(radius)
    else:
        p.modal.pop(VIRTUAL_PLANE, None)


def surface_length(p: Planner, start: Sequence[float], end: Sequence[float], length: float) -> float:
    """A straight cut's ``length`` (``MoveTimes.distance``, C's degrees counted as millimetres)
    with C's turn taken on the cylinder's surface instead: radius × angle in radians."""
    radius = p.modal.get(CYLINDER)
    c = p.axis_index.get("C")
    if radius is None or c is None or start[c] == end[c]:
        return length
    turn = end[c] - start[c]
    on_surface = radius * math.radians(turn)
    return math.sqrt(max(length * length - turn * turn, 0.0) + on_surface * on_surface)


def in_virtual_plane(p: Planner) -> bool:
    """Whether polar or cylindrical interpolation is on."""
    return VIRTUAL_PLANE in p.modal
