"""Tool offsets as the planner applies them (docs/semantics.md §8, §10.1): a lathe's T code
selects an offset whose geometry and wear shift X, Z and Y; a mill's G43/G44 H offsets Z by the
tool length. Either sets the tool vector, which the machine position (#5021…) and the current
position (#5041…) include and the programmed path (the moves, #5001…) does not. The values are
the macro machine's offset variables (where the profile keeps them: ``Dialect.lathe_offsets``,
``Dialect.tool_offset_bases``), read through the planner's host (host.py).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .offset_travel import vector_changing

if TYPE_CHECKING:
    from .planner import Planner


def select_tool(p: Planner, t: float) -> None:
    """T: the tool in force; on a lathe its offset number (the last two digits from T100 up, else
    the last digit) sets the tool vector from the geometry and wear tables, and offset 0 (T0100)
    cancels it."""
    p.codes["T"] = t
    if not p.dialect.lathe:
        return
    offset = lathe_offset_number(t)
    vec = [0.0] * len(p.pos)
    if offset:
        stored = p.host.stored
        for axis, geometry, wear in p.dialect.lathe_offsets.axes:
            if axis in p.axis_index:
                vec[p.axis_index[axis]] = (stored(geometry + offset) or 0.0) + (stored(wear + offset) or 0.0)
    p.tool_vector = vec


def same_station(before: float, t: float) -> bool:
    """Whether lathe T codes ``before`` and ``t`` name the same tool station (their digits before
    the offset number's: T0101 and T0100 both station 1)."""
    return station_number(before) == station_number(t)


def station_number(t: float) -> int:
    """The tool station of a lathe's T code: its digits before the offset number's (T0101: 1)."""
    n = int(t)
    return n // 100 if n >= 100 else n // 10


def lathe_offset_number(t: float) -> int:
    """The offset number of a lathe's T code: its last two digits from T100 up (T0101: 1), else its
    last digit (T11: 1)."""
    n = int(t)
    return n % 100 if n >= 100 else n % 10


def apply_length_offset(p: Planner, h: float) -> None:
    """G43/G44 H: the Z tool vector is offset H's geometry plus wear (negated under G44)."""
    n = int(h)
    value = 0.0
    if n:
        geometry, wear = p.dialect.tool_offset_bases[:2]
        value = (p.host.stored(geometry + n) or 0.0) + (p.host.stored(wear + n) or 0.0)
    if p.modal.get("length") == 44.0:
        value = -value
    if "Z" in p.axis_index:
        if p.tool_vector[p.axis_index["Z"]] != value:
            vector_changing(p)
        p.tool_vector[p.axis_index["Z"]] = value
