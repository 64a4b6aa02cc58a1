"""A lathe's turning cycle as the legs it is drawn and timed by (docs/semantics.md §9).

A single fixed cycle (G90, G92, G94: ``Dialect.single_cycles``, dialects/turning_cycles.py) goes
in along its first axis at rapid, cuts along the other to the end point, comes back out along
the first (at the feed, or at rapid for a thread's pull-out) and returns at rapid to where it
started. Any other turning cycle (G70–G76 so far) is one cut from where it starts to its end
point, until its passes are planned.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from .moves import Leg

if TYPE_CHECKING:
    from ..dialects.turning_cycles import SingleCycle


def turning_legs(
    cycle: SingleCycle | None, axis_index: Mapping[str, int], start: Sequence[float], end: Sequence[float]
) -> tuple[Leg, ...]:
    """The legs of a turning cycle from ``start`` to its end point ``end`` (module docstring)."""
    first = None if cycle is None else axis_index.get(cycle.first)
    if cycle is None or first is None:
        return (Leg(False, tuple(end)),)
    inside = list(start)
    inside[first] = end[first]
    out = list(end)
    out[first] = start[first]
    return (
        Leg(True, tuple(inside)),
        Leg(False, tuple(end)),
        Leg(cycle.rapid_out, tuple(out)),
        Leg(True, tuple(start)),
    )
