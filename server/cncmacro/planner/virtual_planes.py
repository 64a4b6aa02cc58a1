"""Polar coordinate interpolation (FANUC ``G12.1``/``G112``, off with ``G13.1``/``G113``) and
cylindrical interpolation (``G07.1 C_``/``G107``, off with ``C0``) on a turning centre: while one
is on, X and C (polar), or Z and C developed on the cylinder (cylindrical), make the plane in
which arcs and cutter radius compensation act (FANUC 0i-TF operator's manual, "polar coordinate
interpolation", "cylindrical interpolation"; docs/semantics.md §8).

That plane is **not simulated**: a move is drawn and timed as written (C in degrees), an arc as
its chord, and G41/G42 draw the programmed path. What the run must not do is judge the moves in
the plane in force instead (G18's Z and X): an arc in X and C checked there has "its end at its
start", and a compensation started there would push X off the cylinder, then alarm PS0037 at
the G18 that follows ``G07.1 C0``. The mode is kept with the modal codes (``VIRTUAL_PLANE``), so
that a snapshot keeps it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .planner import Planner

VIRTUAL_PLANE = "virtual plane"  # the ``modal`` key of the mode on (its code), absent when off


def switch_virtual_plane(p: Planner, g: float, on: bool) -> None:
    """Code ``g`` turns polar or cylindrical interpolation on (``on``) or off."""
    if on:
        p.modal[VIRTUAL_PLANE] = g
    else:
        p.modal.pop(VIRTUAL_PLANE, None)


def in_virtual_plane(p: Planner) -> bool:
    """Whether polar or cylindrical interpolation is on."""
    return VIRTUAL_PLANE in p.modal
