"""The machine's limits as a run meets them (the machine file's ``[limits]``,
library/limits_settings.py; docs/semantics.md §11).

- **Travel.** A move that leaves an axis's travel (its soft limits, in machine coordinates) stops
  where it crosses the limit with the control's over-travel alarm (FANUC OT0500 on the + side,
  OT0501 on the − side), naming the axis and how far past the limit the move was going. Machine
  coordinates are the program position plus the work offset in force, the coordinate shift
  (G92, G52, a lathe's G50) and the tool offset (positions.py); an axis is checked only while the
  run knows its machine position (whereabouts.py, the rule the position variables follow too):
  the work offset's variable given (the machine file's ``[variables]``, the persistent file,
  ``G10`` or the program) or a G92/G50 made at a known position, a tool length or lathe tool
  offset in force given too, and no G30 since the axis's last absolute move. The external offset
  counts as 0 unless given. A ``G53`` move names machine
  coordinates itself, so it is always checked. ``program_bounds`` turns the travel into the
  program's coordinates once for a run of moves made under the same offsets. Under cutter radius
  compensation the machine follows the tool centre (a lathe's imaginary tool nose beside its nose
  centre): cutter_stage.py checks its path (``path_leaves_travel``) once it is settled.
- **Units.** The travel is in mm whatever G20/G21 says, a rotary axis's (A, B, C) in degrees: under
  G20 a linear axis's inches are taken times 25.4 and a rotary axis's degrees as they are
  (``axis_unit``).
- **Spindle.** An S above the top speed under G97 is a warning; the spindle turns at its top
  speed (cycle_time.py times a feed per revolution with it).
- **Tools.** A T whose tool (a lathe's: the digits before the offset number) the machine does not
  have is an error note; a D or H, or a lathe's offset number, the control does not have is
  alarm PS0030. A lathe's T is held to the profile's offset table where ``[limits]`` gives no
  offsets (GSK980TDi: 1–32), with or without a machine file.

The cutting feed's clamp is ``MoveTimes.top_feed`` (cycle_time.py), the rapid rate the timing's.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..bilingual import detail
from ..dialects.alarms import OFFSET_NUMBER, OVERTRAVEL_MINUS, OVERTRAVEL_PLUS
from ..dialects.describe import ROTARY_AXES
from .alarms import MacroAlarm
from .arcs import ARC_MODES
from .moves import CentrePath
from .tool_offsets import lathe_offset_number
from .whereabouts import frame_offset, machine_known

if TYPE_CHECKING:
    from .moves import CentrePiece, Leg
    from .planner import Planner

# (axis index, lowest, highest, offset): an axis's travel in program coordinates and the offset
# from program to machine coordinates, both in program units
Bounds = tuple[tuple[int, float, float, float], ...]
_EPS = 1e-9  # a point on the limit is inside
_ARC_SAMPLES = 256  # where an arc first leaves the travel is looked for among this many points, then halved
SPINDLE_NOTE = "spindle-limit"  # the note subjects (the analysis's codes)
TOOL_NOTE = "unknown-tool"


def axis_unit(p: Planner, i: int) -> float:
    """mm (degrees) per program unit of axis ``i``: 25.4 under G20 for a linear axis; a rotary
    axis is in degrees in either unit (FANUC: "The unit of data input for degrees remains
    unchanged"), ``MoveTimes.inch_scale``."""
    return p.times.inch_scale[i] if p.modal.get("units") == 20.0 else 1.0


def program_bounds(p: Planner) -> Bounds:
    """Each limited axis whose machine position is known, with its travel in program coordinates
    under the offsets in force (module docstring)."""
    travel = p.travel
    if travel is None:
        return ()
    out = []
    for i, low, high in travel:
        if machine_known(p, i):
            unit = axis_unit(p, i)
            offset = frame_offset(p, i)
            out.append((i, low / unit - offset, high / unit - offset, offset))
    return tuple(out)


def g53_bounds(p: Planner, named: Sequence[int]) -> Bounds:
    """The travel of the axes a G53 block names, in the program coordinates its target was worked
    out in (one_shot.py): machine coordinates need no offset to be known there."""
    if p.travel is None:
        return ()
    out = []
    for i, low, high in p.travel:
        if i in named:
            unit = axis_unit(p, i)
            offset = frame_offset(p, i)
            out.append((i, low / unit - offset, high / unit - offset, offset))
    return tuple(out)


def outside(bounds: Bounds, start: Sequence[float], end: Sequence[float]) -> bool:
    """Whether a straight move from ``start`` to ``end`` goes out of ``bounds`` (an axis moving
    further out than it already is counts; one coming back in does not)."""
    for i, low, high, _ in bounds:
        e = end[i]
        if (e > high + _EPS and e > start[i]) or (e < low - _EPS and e < start[i]):
            return True
    return False


def leaves_travel(
    p: Planner,
    bounds: Bounds,
    mode: float,
    plane: float,
    start: tuple[float, ...],
    end: tuple[float, ...],
    centre: tuple[float, ...] | None,
    legs: tuple[Leg, ...] | None,
) -> tuple[tuple[float, ...], MacroAlarm] | None:
    """Where a move (an arc about ``centre``, a cycle made of ``legs``) first leaves ``bounds``
    and the over-travel alarm it stops with; None when it stays inside. A cycle stops at its end
    (it is drawn whole)."""
    if legs is not None:
        at = start
        for leg in legs:
            found = _straight(bounds, at, leg.end)
            if found is not None:
                return end, _alarm(p, bounds, found)
            at = leg.end
        return None
    if centre is not None and mode in ARC_MODES:
        return _arc(p, bounds, mode, plane, start, end, centre)
    found = _straight(bounds, start, end)
    if found is None:
        return None
    t = found[0]
    point = tuple(s + (e - s) * t for s, e in zip(start, end, strict=True))
    return point, _alarm(p, bounds, found)


def path_leaves_travel(
    p: Planner, bounds: Bounds, plane: float, path: CentrePath
) -> tuple[CentrePath, MacroAlarm] | None:
    """Where a tool centre path (cutter radius compensation, cutter_stage.py: the machine position
    follows the tool centre, not the programmed point) first leaves ``bounds``, piece by piece as
    ``leaves_travel`` looks at a move: the path up to there and the alarm; None when it stays inside."""
    at = path.start
    kept: list[CentrePiece] = []
    for piece in path.pieces:
        mode = 1.0 if piece.centre is None else (2.0 if piece.clockwise else 3.0)
        stop = leaves_travel(p, bounds, mode, plane, at, piece.end, piece.centre, None)
        if stop is not None:
            kept.append(piece._replace(end=stop[0]))
            return CentrePath(path.start, tuple(kept)), stop[1]
        kept.append(piece)
        at = piece.end
    return None


# (where along the move it leaves, 0 to 1; the axis's row in the bounds; +1 or -1; the farthest
# value the move was going to on that axis, program coordinates)
_Leaving = tuple[float, int, int, float]


def _straight(bounds: Bounds, start: Sequence[float], end: Sequence[float]) -> _Leaving | None:
    first: _Leaving | None = None
    for k, (i, low, high, _) in enumerate(bounds):
        s, e = start[i], end[i]
        if e > high + _EPS and e > s:
            t, side = max(0.0, (high - s) / (e - s)), 1
        elif e < low - _EPS and e < s:
            t, side = max(0.0, (low - s) / (e - s)), -1
        else:
            continue
        if first is None or t < first[0]:
            first = (t, k, side, e)
    return first


def _arc(
    p: Planner,
    bounds: Bounds,
    mode: float,
    plane: float,
    start: tuple[float, ...],
    end: tuple[float, ...],
    centre: tuple[float, ...],
) -> tuple[tuple[float, ...], MacroAlarm] | None:
    """An arc: its points are looked at along the sweep; the first one out of the travel is
    narrowed down to where the arc crosses the limit."""
    axes = p.times.planes.get(plane)
    if axes is None:
        found = _straight(bounds, start, end)
        return None if found is None else (end, _alarm(p, bounds, found))
    a, b, ka, kb = axes
    sa, sb = (start[a] - centre[a]) * ka, (start[b] - centre[b]) * kb
    ea, eb = (end[a] - centre[a]) * ka, (end[b] - centre[b]) * kb
    r0, r1 = math.hypot(sa, sb), math.hypot(ea, eb)
    a0 = math.atan2(sb, sa)
    sweep = (math.atan2(eb, ea) - a0) % (2.0 * math.pi)
    if mode == 2.0:
        sweep = sweep - 2.0 * math.pi if sweep else 0.0
    if sweep == 0.0 and start[a] == end[a] and start[b] == end[b]:
        sweep = -2.0 * math.pi if mode == 2.0 else 2.0 * math.pi

    def point(f: float) -> tuple[float, ...]:
        angle, r = a0 + sweep * f, r0 + (r1 - r0) * f
        out = [s + (e - s) * f for s, e in zip(start, end, strict=True)]  # the helix's other axes
        out[a] = centre[a] + r * math.cos(angle) / ka
        out[b] = centre[b] + r * math.sin(angle) / kb
        return tuple(out)

    # the farthest each axis goes: the most outward sample, per side
    worst: _Leaving | None = None
    previous = 0.0
    first_out: float | None = None
    for n in range(1, _ARC_SAMPLES + 1):
        f = n / _ARC_SAMPLES
        here = point(f)
        found = _straight(bounds, start, here)
        if found is not None:
            if first_out is None:
                first_out = previous
            if worst is None or _beyond(bounds, found) > _beyond(bounds, worst):
                worst = found
        elif first_out is None:
            previous = f
    if worst is None or first_out is None:
        return None
    low, high = first_out, first_out + 1.0 / _ARC_SAMPLES
    for _ in range(40):  # halve the step until it is far below a micrometre
        mid = 0.5 * (low + high)
        if _straight(bounds, start, point(mid)) is None:
            low = mid
        else:
            high = mid
    return point(low), _alarm(p, bounds, worst)


def _beyond(bounds: Bounds, found: _Leaving) -> float:
    """How far past its limit a leaving goes (program units)."""
    _, k, side, value = found
    _, low, high, _ = bounds[k]
    return value - high if side > 0 else low - value


def _alarm(p: Planner, bounds: Bounds, found: _Leaving) -> MacroAlarm:
    """The over-travel alarm of a leaving: the axis, the side, where the move was going in machine
    coordinates and how far past the limit, in mm."""
    _, k, side, value = found
    i, low, high, offset = bounds[k]
    unit = axis_unit(p, i)
    axis = p.dialect.axes[i]
    limit = (high if side > 0 else low) + offset
    machine = (value + offset) * unit
    past = _beyond(bounds, found) * unit
    sign = "+" if side > 0 else "-"
    number = OVERTRAVEL_PLUS if side > 0 else OVERTRAVEL_MINUS
    measure = "deg" if axis in ROTARY_AXES else "mm"
    return MacroAlarm(number, detail(
        f"{axis}{sign} over travel: the move goes to machine {axis}{machine:.3f}, {past:.3f} {measure} past the "
        f"{sign} limit {axis}{limit * unit:.3f} ([limits] travel); the axis stops at the limit",
        f"{axis} 轴{sign}向超程：该移动要到达机床坐标 {axis}{machine:.3f}，超出{sign}向限位 "
        f"{axis}{limit * unit:.3f}（[limits] travel）{past:.3f} {measure}；轴停在限位处"))  # fmt: skip


# ---------------------------------------------------------------- spindle and tools
def spindle_speed(p: Planner, s: float, line: int, file: str) -> None:
    """An S above the machine's top speed under G97: a warning, once per line (the spindle turns
    at the top speed: ``MoveTimes.per_rev_minutes``)."""
    top = p.spindle_top
    if top is None or s <= top or p.modal.get("spindle") == 96.0:
        return
    key = f"{SPINDLE_NOTE}:{file}:{line}"
    if key in p.codes:
        return
    p.codes[key] = 1.0
    p.host.note("limits", detail(
        f"S{s:g} is above the spindle's top speed {top:g} rev/min ([limits] spindle): the control turns it "
        f"at {top:g}",
        f"S{s:g} 超过主轴最高转速 {top:g} r/min（[limits] spindle）：系统以 {top:g} r/min 旋转"),
        line, SPINDLE_NOTE)  # fmt: skip


def _listed(ranges: tuple[tuple[int, int], ...]) -> str:
    return ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in ranges)


def _has(ranges: tuple[tuple[int, int], ...], n: int) -> bool:
    return any(a <= n <= b for a, b in ranges)


def tool_number(p: Planner, t: float, line: int) -> None:
    """T: a tool the machine does not have is an error note (once per line); a lathe's offset
    number the control does not have is alarm PS0030 (``lathe_offset``, called for every T)."""
    limits = p.settings.limits
    if limits is None:
        return
    n = int(t)
    tool = (n // 100 if n >= 100 else n // 10) if p.lathe else n
    tools = limits.tools
    if tools is None or not tool or _has(tools, tool):
        return
    key = f"{TOOL_NOTE}:{line}"
    if key in p.codes:
        return
    p.codes[key] = 1.0
    shown = _listed(tools)
    p.host.note("limits", detail(
        f"T{t:g}: the machine has no tool {tool} (its tools: {shown}, [limits] tools)",
        f"T{t:g}：机床没有 {tool} 号刀（可用刀号：{shown}，[limits] tools）"), line, TOOL_NOTE)  # fmt: skip


def lathe_offset(p: Planner, t: float) -> None:
    """A lathe's T whose offset number (its last two digits) the control does not have: alarm
    PS0030. The offsets it has are the machine file's ``[limits] offsets`` where it gives them,
    else those of the profile's tables (``table_offsets``)."""
    offset = lathe_offset_number(t)
    if not offset:
        return
    limits = p.settings.limits
    if limits is not None and limits.offsets is not None:
        offset_number(p, "T", t, offset)
        return
    ranges = table_offsets(p)
    if ranges is None or _has(ranges, offset):
        return
    shown = _listed(ranges)
    raise MacroAlarm(OFFSET_NUMBER, detail(
        f"T{t:g}: offset number {offset} is not one of the control's ({shown})",
        f"T{t:g}：刀补号 {offset} 不在系统的刀补号之内（{shown}）"))  # fmt: skip


def table_offsets(p: Planner) -> tuple[tuple[int, int], ...] | None:
    """The lathe offset numbers the profile's tables hold: 1 to the last of the row of offset 1's
    X geometry (GSK980TDi #2701–#2732: 1–32; FANUC 0i-TF #15001–#15400: 1–400); None where the
    table has no such row."""
    axes = p.dialect.lathe_offsets.axes
    if not axes:
        return None
    base = axes[0][1]
    row = p.dialect.system_variable(base + 1)
    return None if row is None else ((1, row.last - base),)


def offset_number(p: Planner, letter: str, value: float, n: int) -> None:
    """A D, H or lathe offset number ``n`` the control does not have: alarm PS0030."""
    limits = p.settings.limits
    if limits is None or limits.offsets is None or not n or _has(limits.offsets, n):
        return
    shown = _listed(limits.offsets)
    raise MacroAlarm(OFFSET_NUMBER, detail(
        f"{letter}{value:g}: offset number {n} is not one of the control's ({shown}, [limits] offsets)",
        f"{letter}{value:g}：刀补号 {n} 不在系统的刀补号之内（{shown}，[limits] offsets）"))  # fmt: skip
