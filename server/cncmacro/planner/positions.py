"""Where the tool is, as the position system variables read it (docs/semantics.md §8): the
program position, the work offset in force (G54–G59, the external one, an extra offset), the
machine position, the skip position and the tool vector. The offsets are the macro machine's
stored variables, read through the planner's host (host.py).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .planner import Planner

WORK_BASE = 5201  # external offset of axis 1; G54 is +20, G55 +40 ... (every profile)


def work_offset_variable(p: Planner, axis: int) -> int:
    """The variable that holds ``axis``'s value of the work offset in force (G54–G59, an extra one)."""
    wcs = p.modal.get("wcs", 54.0)
    if p.extra_wcs and (wcs == 54.1 or wcs in p.extra_codes):
        return p.dialect.extra_offset_variables + 20 * (p.extra_wcs - 1) + axis
    return WORK_BASE + 20 * (int(wcs) - 53) + axis


def work_offset(p: Planner, axis: int) -> float:
    """The work offset of ``axis`` in force: the coordinate system's plus the external."""
    n = work_offset_variable(p, axis)
    return (p.host.stored(n) or 0.0) + (p.host.stored(WORK_BASE + axis) or 0.0)


def machine_position(p: Planner, axis: int) -> float:
    """Where ``axis`` is in machine coordinates: the program position plus the work offset, the
    coordinate shift (G92/G50) and the tool vector."""
    return p.pos[axis] + work_offset(p, axis) + p.shift[axis] + p.tool_vector[axis]


def position_value(p: Planner, which: str, axis: int) -> float | None:
    """Axis ``axis``'s position of a kind (the profile's position rows: the block end point without
    the tool offset, the current position, machine coordinates and the skip position with it, the
    skip position as programmed, the tool vector; docs/semantics.md §8, §10.1). On a lathe X reads
    as a diameter in each of them."""
    if axis >= len(p.pos):
        return 0.0
    if which == "end":  # the programmed end point: without the tool offset
        return p.pos[axis]
    if which == "current":  # where the tool is in work coordinates: with the tool offset
        return p.pos[axis] + p.tool_vector[axis]
    if which == "machine":
        return machine_position(p, axis)
    if which == "skip":  # where a G31 stopped, with the tool offset in force there (FANUC's table: included)
        tool = p.skip_state.tool
        return p.skip_pos[axis] + (tool[axis] if axis < len(tool) else 0.0)
    if which == "skip_programmed":  # the same, the programmed point (Haas, as its #5041 reads)
        return p.skip_pos[axis]
    if which == "tool":
        return p.tool_vector[axis]
    return 0.0
