"""The codes that act once, in the block that names them (docs/semantics.md §8): G04 dwell, G10
offsets, G28/G30 through the intermediate point to the reference point (on Haas a G28 alone
homes every axis, and G28 cancels the tool length offset), G31 skip (probing.py),
G53 in machine coordinates, G52's local coordinate system, coordinate setting (G92 on a mill,
G50 on a lathe), a lathe's turning cycles (turning_cycles.py), cylindrical interpolation's
``G07.1 C_`` (a radius, not a move), the workpiece coordinate system preset (``G92.1 IP0``), and
any other one-shot code with axis words, which moves in the modal mode. ``G10`` writes the offset
tables through the planner's host (host.py). On FANUC (``Dialect.reference_in_cycle_alarm``) a
G27-G30 while a drilling canned cycle is in force is alarm PS0044 (docs/semantics.md §9).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..bilingual import detail
from ..dialects.alarms import ARGUMENT_RANGE, REFERENCE_IN_CYCLE
from .alarms import MacroAlarm
from .cutter_stage import frame_moved
from .lathe_cycles import ShapeCall, lathe_cycle
from .machine_limits import g53_bounds, leaves_travel
from .offset_travel import keep_machine_position, work_offsets
from .positions import WORK_BASE, work_offset
from .probing import skip_block
from .reciprocating_feed import reciprocating_feed
from .virtual_planes import refuse_polar_start, switch_virtual_plane
from .whereabouts import coordinates_set, home_known, lose, placed, referenced, shift_cancelled

if TYPE_CHECKING:
    from .planner import Planner

REFERENCE_CODES = (27.0, 28.0, 29.0, 30.0)  # reference position check, return, return from, 2nd-4th
LOCAL_ORIGIN = "G52-"  # the ``codes`` key of G52's origin on an axis, with the axis's index after it


def one_shot(
    p: Planner, g: float, axes: dict[int, float], inc: dict[int, float], other: dict[str, float], file: str, line: int
) -> tuple[bool, ShapeCall | None]:
    """Carry out one-shot code ``g`` with the block's words: (moved, the shape a lathe cycle
    names), as ``Planner.execute_nc`` returns them."""
    if g in REFERENCE_CODES and p.dialect.reference_in_cycle_alarm and p.drills and p.modal.get("canned", 80.0) != 80.0:
        # FANUC PS0044 "G27-G30 NOT ALLOWED IN FIXED CYC": "One of G27 to G30 is commanded in canned
        # cycle mode" (docs/semantics.md §9)
        canned = p.modal["canned"]
        raise MacroAlarm(REFERENCE_IN_CYCLE, detail(
            f"G{g:g} in canned cycle mode (G{canned:g} in force): cancel the cycle with G80 first",
            f"固定循环方式中（G{canned:g} 有效）指令了 G{g:g}：须先用 G80 取消循环"))  # fmt: skip
    if g == 4.0:  # dwell: P in the profile's unit, X or U in seconds (cycle_time.py); X before U
        p.clock += p.times.dwell_seconds(other, next(iter({**inc, **axes}.values()), None))
        return False, None
    if g == 10.0:
        g10(p, axes, inc, other)
        return False, None
    if g in p.dialect.unsimulated_codes:  # its words are the cycle's; the tool is left where it began
        if axes or inc or not other.keys() <= {"R"}:  # not the GSK's first block, its R alone
            p.host.note("simulation", detail(
                f"G{g:g} is not simulated: the cycle's passes are not drawn or timed, and the tool is left at its "
                "start point",
                f"G{g:g} 未模拟：不绘制也不计时该循环的走刀，刀具留在其起点"),
                line, "not-simulated")  # fmt: skip
        return False, None
    if g == p.dialect.reciprocating_feed_code:  # GSK's G86 (reciprocating_feed.py)
        return reciprocating_feed(p, axes, other, file, line), None
    if g in (28.0, 30.0):  # through the intermediate point to the reference point
        return reference_return(p, g, axes, inc, file, line), None
    if g in p.dialect.skip_codes:  # skip (G31; a multi-step skip's G31.1-G31.3): probing.py
        skip_block(p, p.target(axes, inc), file, line)
        return True, None
    if g == 53.0:
        target = list(p.pos)
        for i, v in axes.items():
            target[i] = v - (work_offset(p, i) + p.shift[i] + p.tool_vector[i])
        # at rapid whatever the motion in force, which stays (GSK980TDi §3.20: "刀具快速定位到该位置，
        # 速度及运动方式与快速定位 G00 相同"; FANUC: machine coordinate system selection)
        mode = 0.0
        if p.travel is not None:  # machine coordinates: checked whether the offsets are known or not
            here = tuple(p.pos)
            stop = leaves_travel(p, g53_bounds(p, list(axes)), mode, 17.0, here, tuple(target), None, None)
            if stop is not None:
                p.move(file, line, mode, list(stop[0]))
                raise stop[1]
        p.move(file, line, mode, target, end_unknown=not home_known(p, axes))
        referenced(p, axes)  # at a machine position the run knows (whereabouts.py)
        return bool(axes), None
    if g == p.dialect.local_coordinate_code:  # U, W as X, Z: "绝对代码或相对代码指定时执行的结果一样" (GSK §3.19)
        local_coordinates(p, {**inc, **axes})
        return False, None
    if g == p.dialect.coordinate_setting_code:
        # X, Z: the present position's new coordinates; U, W: its new coordinates less the old
        # (GSK980TDi §3.18: "当前位置新的 X 轴绝对坐标与执行代码前的绝对坐标的差值"; FANUC G92/G50 IP_ in
        # increments), bar work's G50 W15. shifting the part for the next one. The tool stays
        setting = {**{i: p.pos[i] + d for i, d in inc.items()}, **axes}
        coordinates_set(p, setting)  # a frame known where the machine position was (whereabouts.py)
        change: dict[int, float] = {}
        for i, v in setting.items():
            p.shift[i] += p.pos[i] - v
            change[i] = v - p.pos[i]
            p.pos[i] = v
        if p.cutter is not None:  # in offset mode: the corner in one frame (cutter_stage.py)
            frame_moved(p, change)
        return False, None
    if p.dialect.lathe and g in p.dialect.cycle_codes:
        return lathe_cycle(p, g, axes, inc, other, file, line)
    if g in p.dialect.axis_value_codes:  # G07.1 C_: the cylinder's radius (Dialect.axis_value_codes), C0 off
        radius = next(iter({**axes, **inc}.values()), 0.0)
        switch_virtual_plane(p, g, bool(radius), radius)
        return False, None
    polar = p.dialect.polar_interpolation_codes.get(g)
    if polar is not None:  # G12.1 / G13.1 (virtual_planes.py)
        refuse_polar_start(p, g, polar)
        switch_virtual_plane(p, g, polar)
        return False, None
    if g in p.dialect.preset_codes:  # G92.1 IP0: the shift of the named axes cancelled, no move
        change = {i: p.shift[i] for i in set(axes) | set(inc)}
        for i in change:
            p.pos[i] += p.shift[i]
            p.shift[i] = 0.0
            p.codes.pop(f"{LOCAL_ORIGIN}{i}", None)
        shift_cancelled(p, set(change))
        if p.cutter is not None:
            frame_moved(p, change)
        return False, None
    if axes or inc:  # any other one-shot code with axis words: move in the modal mode
        mode = _one_shot_mode(p, g, line)
        target = p.target(axes, inc)
        if p.lathe or p.modal.get("distance", 90.0) == 90.0:
            placed(p, axes)
        p.move(file, line, mode, target, p.block_arc(mode, target, other, line))
        return True, None
    return False, None


def reference_return(p: Planner, g: float, axes: dict[int, float], inc: dict[int, float], file: str, line: int) -> bool:
    """G28/G30: at rapid to the intermediate point the axis words name, then each named axis to
    the reference point, machine 0 (on Haas a G28 alone names them all); whether it moved."""
    dialect = p.dialect
    named = set(axes) | set(inc)
    if not named and g == 28.0 and dialect.reference_return_all_axes:  # Haas: G28 alone homes them all
        named = set(range(len(p.pos)))
    if not named:
        return False
    if axes or inc:
        p.move(file, line, 0.0, p.target(axes, inc))
        if p.lathe or p.modal.get("distance", 90.0) == 90.0:
            placed(p, axes)  # at the intermediate point
    if dialect.reference_return_cancels_tool_offset:
        if p.lathe:
            p.tool_vector = [0.0] * len(p.pos)  # off at the reference point (docs/semantics.md §10.1)
        else:
            cancel_length_offset(p)
    home = list(p.pos)
    for i in named:
        home[i] = 0.0 - (work_offset(p, i) + p.shift[i] + p.tool_vector[i]) + 0.0
    # to a point on the drawing only where its offsets are given; a G30's is the machine builder's (whereabouts.py)
    p.move(file, line, 0.0, home, end_unknown=not home_known(p, named, g == 28.0))
    if g == 28.0:
        referenced(p, named)
    else:  # the 2nd reference position is the machine builder's (FANUC parameter 1241): not known here
        lose(p, named)
    return True


def cancel_length_offset(p: Planner) -> None:
    """A mill's G28 that cancels the tool length offset (``Dialect.reference_return_cancels_tool_offset``,
    Haas: "for the following lines of code"): group 08 reads G49 and the Z vector is 0; the tool
    does not move for it, so Z's program position takes the vector up (the reference point's move
    then homes Z without it, when the block names Z)."""
    p.modal["length"] = 49.0
    z = p.axis_index.get("Z")
    if z is not None:
        p.pos[z] += p.tool_vector[z]
        p.tool_vector[z] = 0.0


def local_coordinates(p: Planner, axes: dict[int, float]) -> None:
    """G52: the local coordinate system's origin on each named axis is its value in the work
    coordinate system (0 cancels it). The tool does not move: the program position moves by the
    change, the coordinate shift takes it up, so the machine position (positions.py) stays. The
    origin is kept with the codes, as a snapshot keeps them."""
    moved: dict[int, float] = {}
    for i, v in axes.items():
        key = f"{LOCAL_ORIGIN}{i}"
        change = v - (p.codes.get(key) or 0.0)
        p.codes[key] = v
        p.shift[i] += change
        p.pos[i] -= change
        moved[i] = -change
    if p.cutter is not None:  # in offset mode: the corner in one frame (cutter_stage.py)
        frame_moved(p, moved)


def g10(p: Planner, axes: dict[int, float], inc: dict[int, float], other: dict[str, float]) -> None:
    """G10: L2 Pn a work offset (P0 the external one), L20 Pn an extra work offset, on a lathe
    P a tool offset (P < 10000 wear, 10000 + n geometry; R the nose radius, C added to it), on a
    mill L10–L13 P R a tool offset (and the L numbers ``Dialect.g10_tool_l_aliases`` gives as one
    of them, Haas's L1)."""
    host = p.host
    l_value = other.get("L")
    number = int(other.get("P", 0.0))
    absolute = p.dialect.lathe or p.modal.get("distance", 90.0) == 90.0
    shift = l_value is None and number == 0 and p.dialect.lathe and p.dialect.lathe_offsets.p0_work_shift
    if l_value in (2.0, 20.0) or shift:  # a lathe's G10 P0: the workpiece shift, the external offset
        base = _work_offset_base(p, 2.0, 0) if shift else _work_offset_base(p, l_value or 2.0, number)
        before = work_offsets(p)  # the offset in force may be the one written: the tool stays (offset_travel.py)
        for i, v in axes.items():
            if absolute:
                host.store(base + i, v)
            else:
                host.store_added(base + i, v)
        for i, v in inc.items():
            host.store_added(base + i, v)
        moved = keep_machine_position(p, before)
        if moved and p.cutter is not None:
            frame_moved(p, moved)
        return
    if p.dialect.lathe:
        geometry = number >= 10000
        n = number % 10000
        offsets = p.dialect.lathe_offsets
        for letter, g_base, w_base in offsets.axes:
            axis = p.axis_index.get(letter)
            if axis is None:
                continue
            num = (g_base if geometry else w_base) + n
            if axis in axes:
                host.store(num, axes[axis])
            if axis in inc:
                host.store_added(num, inc[axis])
        radius = offsets.radius[0 if geometry else 1] + n
        if "R" in other:
            host.store(radius, other["R"])
        # C adds to the nose radius as U and W add to X and Z ("G10 P_ X(U)_ Z(W)_ R(C)_ Q_"), a C
        # axis's word included
        c_axis = p.axis_index.get("C")
        more = axes.get(c_axis) if c_axis is not None else other.get("C")
        if more is not None:
            host.store_added(radius, more)
        if "Q" in other:
            host.store(offsets.tip + n, other["Q"])
        return
    bases = dict(zip((10.0, 11.0, 12.0, 13.0), p.dialect.tool_offset_bases, strict=True))
    for alias, same in p.dialect.g10_tool_l_aliases:  # Haas L1 = L11
        bases[alias] = bases[same]
    if l_value in bases and "R" in other:
        num = bases[l_value] + number
        if absolute:
            host.store(num, other["R"])
        else:
            host.store_added(num, other["R"])


def _work_offset_base(p: Planner, l_value: float, number: int) -> int:
    """The variable of axis 1 of the work offset ``G10 L2 P`` or ``L20 P`` names; alarm 119 for a
    P outside the offsets the control has."""
    if l_value == 2.0:
        if not 0 <= number <= 6:
            raise MacroAlarm(
                ARGUMENT_RANGE,
                detail(f"G10 L2 P{number}: P must be 0 (external) to 6 (G59)",
                       f"G10 L2 P{number}：P 必须为 0（外部偏置）～6（G59）"),
            )  # fmt: skip
        return WORK_BASE + 20 * number
    count = p.dialect.extra_offset_count
    if not 1 <= number <= count:
        raise MacroAlarm(
            ARGUMENT_RANGE,
            detail(f"G10 L20 P{number}: P must be 1 to {count}", f"G10 L20 P{number}：P 必须在 1～{count} 之间"),
        )
    return p.dialect.extra_offset_variables + 20 * (number - 1)


def _one_shot_mode(p: Planner, g: float, line: int) -> float:
    """The mode a move of one-shot code ``g`` on ``line`` is made in: the motion in force, but at
    rapid for an automatic tool offset measurement (``Dialect.tool_measure_codes``: GSK980TDi §3.17,
    "在执行程序段 G36 X__(或 G37 Z__)时，刀具首先快速移动到代码的测量位置", the tool first goes to the
    measuring position at rapid), whose measurement is noted as not simulated."""
    if g not in p.dialect.tool_measure_codes:
        return p.modal.get("motion", 0.0)
    p.host.note("simulation", detail(
        f"G{g:g} is not simulated beyond its move: the tool goes to the measuring position at rapid (the last "
        "stretch at the measuring feed, parameter No.141, is timed at rapid too) and the tool offset is left as "
        "it was, as if the measuring signal came exactly there",
        f"G{g:g} 仅模拟其移动：刀具以快速移动速度到达测量位置（最后一段按参数№.141 的测量速度移动，也按快速移动计时），"
        "刀具偏置值保持不变，视为测量到达信号恰在该位置发出"),
        line, "not-simulated")  # fmt: skip
    return 0.0
