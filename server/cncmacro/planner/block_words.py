"""What a block's words set before it moves (docs/semantics.md §8): the modal groups of its G
codes (a G00–G03 cancels a mill's drilling cycle, G54.1 P and Haas G154 P / G110–G129 select an
extra work offset), and F, S, D, H, B, T and M: their last values, a tool change and its time, a
tool length offset (tool_offsets.py); an M code's time (``m_code_time``) and a tool change
(``tool_change``: where a tool's part of the run starts, told to the host, then its time).
``set_modal`` returns the block's one-shot code, which ``Planner.execute_nc`` then carries out
(one_shot.py).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..bilingual import detail
from ..dialects.alarms import ARGUMENT_RANGE
from .alarms import MacroAlarm
from .cutter_stage import cutter_code, frame_moved
from .drill_cycles import CYCLE_P, CYCLE_Q, R_GIVEN, Z_GIVEN
from .machine_limits import lathe_offset, offset_number, spindle_speed, tool_number
from .moves import ToolChange
from .offset_travel import keep_machine_position, vector_changing, work_offsets
from .spindle_modes import spindle_mode
from .tool_offsets import apply_length_offset, same_station, select_tool
from .turning_cycles import forget_single_cycle
from .units import UNITS_GROUP, unit_change
from .virtual_planes import in_virtual_plane

if TYPE_CHECKING:
    from .planner import Planner


def set_modal(p: Planner, gs: list[float], other: dict[str, float], line: int) -> float | None:
    """Set the modal groups of the block's G codes (on ``line``); returns its one-shot code, if any."""
    one_shot_code: float | None = None
    before: list[float] | None = None
    groups = [p.g_groups.get(g) for g in gs]
    if "wcs" in groups and p.dialect.coordinate_setting_voids_wcs and p.dialect.coordinate_setting_code in gs:
        kept = [(g, group) for g, group in zip(gs, groups, strict=True) if group != "wcs"]  # G55 G50: G50 alone
        gs, groups = [g for g, _ in kept], [group for _, group in kept]
    if "motion" in groups and p.dialect.drills and ("canned" not in groups or p.dialect.motion_cancels_cycle_in_block):
        p.modal["canned"] = 80.0  # G00-G03 cancel a drilling cycle, as G80 does
        if "canned" in groups:  # G00 G81 in one block: the G00 runs, the cycle is cancelled (Mitsubishi)
            kept = [(g, group) for g, group in zip(gs, groups, strict=True) if group != "canned"]
            gs, groups = [g for g, _ in kept], [group for _, group in kept]
    for g, group in zip(gs, groups, strict=True):
        if not group:
            one_shot_code = g
        elif group != "macro":  # G66/G67 are the macro machine's
            if group == UNITS_GROUP:
                unit_change(p, g, line)  # units.py
            elif group == "spindle" and p.lathe:
                spindle_mode(p, g, other)  # spindle_modes.py: S across G96 and G97
            elif (group == "cutter" and not in_virtual_plane(p)) or (group == "plane" and p.cutter is not None):
                cutter_code(p, group, g, line)  # cutter_stage.py; not in polar or cylindrical interpolation
            if group == "wcs" and g == 54.0 and "P" in other and p.dialect.extra_offset_by_g54_p:
                g = 54.1  # G54 Pn is G54.1 Pn (FANUC)
            if group == "wcs" and before is None:
                before = work_offsets(p)  # the tool stays on the machine (offset_travel.py)
            if group == "canned" and g != 80.0:
                cycle_named(p, p.modal.get(group, 80.0), g)
            p.modal[group] = g
            if group == "motion" and g not in p.dialect.single_cycles:
                forget_single_cycle(p)  # a single cycle's modal words (turning_cycles.py)
            if group == "wcs" and g == 54.1:
                p.extra_wcs = int(other.get("P", 1))
            elif group == "wcs" and g in p.extra_codes:
                p.extra_wcs = _extra_offset(p, g, other)
    if before is not None:
        moved = keep_machine_position(p, before)
        if moved and p.cutter is not None:  # in offset mode: the corner in one frame (cutter_stage.py)
            frame_moved(p, moved)
    return one_shot_code


def cycle_named(p: Planner, before: float, g: float) -> None:
    """Drilling canned cycle ``g`` is named with ``before`` in force (80: none). The initial level
    is taken again (``Planner.cycle_start_z``, at the next hole) only where the canned cycle mode
    begins, after G80 or a G00-G03 (FANUC 0i-MF: "the absolute Z position when the canned cycle
    mode is entered"), or where a lathe's cycle drills along another axis (G83 on the face, G87
    on the side); and there, where FANUC clears the hole data (``Dialect.peck_q_alarm``), a peck's
    Q from the cycle mode before is no longer in force, nor, where the control resets it
    (``Dialect.cycle_cancel_clears_dwell``), its dwell P."""
    if before == 80.0:
        p.cycle_start_z = None
        if p.dialect.peck_q_alarm:
            p.codes.pop(CYCLE_Q, None)
            p.codes.pop(Z_GIVEN, None)  # Z and R from before are kept, with a warning (drill_cycles.py)
            p.codes.pop(R_GIVEN, None)
        if p.dialect.cycle_cancel_clears_dwell:
            p.codes.pop(CYCLE_P, None)
        return
    drilling = p.dialect.lathe_drilling
    if drilling is not None:
        old, new = drilling.cycles.get(before), drilling.cycles.get(g)
        if old is None or new is None or old.axis != new.axis:
            p.cycle_start_z = None


def set_codes(p: Planner, other: dict[str, float], file: str, line: int) -> None:
    """F, S, D, H, B, T and M: their last values, a tool change, a tool length offset."""
    for letter in ("F", "S", "D", "H", "B"):
        if letter in other:
            p.codes[letter] = other[letter]
    if "T" in other and p.lathe:  # an offset number the control does not have (machine_limits.py)
        lathe_offset(p, other["T"])
    if p.settings.limits is not None:  # the machine's spindle, tools and offsets (machine_limits.py)
        machine_limits(p, other, file, line)
    if "T" in other:
        before = p.codes.get("T")
        select_tool(p, other["T"])
        # a lathe's turret indexes to another station only: T0100 after T0101 changes the offset
        if p.times.tool_change_t and not (p.lathe and before is not None and same_station(before, other["T"])):
            tool_change(p, file, line)
    if "M" in other:
        p.codes["M"] = other["M"]
        m_code_time(p, other["M"], file, line)  # after T: T1 M06 changes to T1
    if "H" in other and p.modal.get("length") in (43.0, 44.0):
        apply_length_offset(p, other["H"])
    elif not p.lathe and p.modal.get("length") == 49.0 and "Z" in p.axis_index:
        if p.tool_vector[p.axis_index["Z"]]:
            vector_changing(p)
            p.tool_vector[p.axis_index["Z"]] = 0.0


def machine_limits(p: Planner, other: dict[str, float], file: str, line: int) -> None:
    """What the machine file's ``[limits]`` says of a block's S, T, D and H (machine_limits.py)."""
    if "S" in other:
        spindle_speed(p, other["S"], line, file)
    if "T" in other:
        tool_number(p, other["T"], line)
    for letter in ("D", "H") if not p.lathe else ():  # a lathe's offset is its T's (a D there may be a cycle's)
        if letter in other:
            offset_number(p, letter, other[letter], int(other[letter]))


def _extra_offset(p: Planner, g: float, other: dict[str, float]) -> int:
    """The extra work offset a Haas ``G154 Pn`` (P1 when P is left out) or ``G110``–``G129``
    selects; a P outside the offsets the control has is alarm 119."""
    if g != p.dialect.extra_offset_code:
        return p.dialect.extra_offset_aliases.index(g) + 1
    number = int(other.get("P", 1.0))
    count = p.dialect.extra_offset_count
    if not 1 <= number <= count:
        raise MacroAlarm(
            ARGUMENT_RANGE,
            detail(f"G{g:g} P{number}: P must be 1 to {count}", f"G{g:g} P{number}：P 必须在 1～{count} 之间"),
        )
    return number


def m_code_time(p: Planner, m: float, file: str, line: int) -> None:
    """The time of M code ``m``: a tool change (``tool_change``) or the machine file's."""
    if m == p.times.tool_change_m:
        tool_change(p, file, line)
    else:
        p.clock += p.times.m_seconds(m)


def tool_change(p: Planner, file: str, line: int) -> None:
    """A tool change on ``line``: where a tool's part of the run starts (kept while moves
    are recorded, told to the host), then its time."""
    if p.record_moves:
        tool = p.codes.get("T")
        p.tool_changes.append(ToolChange(file, line, tool, p.clock, p.cut_length, p.rapid_length))
    p.host.tool_changed(file, line)
    p.clock += p.times.timing.tool_change_seconds
