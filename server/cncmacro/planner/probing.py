"""G31, the skip function, on the simulated machine (docs/semantics.md §8, docs/machine-file.md
"Probing: the [skip] table").

A G31 block is a straight feed move from where the tool is to the block's end point that stops
where the skip signal comes on. The machine file's ``[skip]`` table (``library/skip_model.py``)
says where that is: the next unused contact point of its sequence, else the first surface of
its model the move reaches (the smallest fraction of the way along it; surfaces at the same
place in the order they are written). When nothing is hit the move runs to its end point and
the signal stays off, as on the control. Either way #5061… (``Planner.skip_pos``, read through
the profile's skip position rows) hold where the move ended, in work coordinates, with the tool
offset in force there where the profile's row says so (``positions.position_value``): seed 003
§4.9, "在G31(跳转功能)程序段中跳转信号接通时的刀具位置储存在变量#5061到#5064中。当G31程序段中
的跳转信号未接通时，这些变量中储存的是指令的程序段终点值". A control that stores it in common
variables instead (``Dialect.skip_commons``: the GSK980TDi's #995–#999, §3.16.2, "跳转信号变为"1"
时绝对坐标位置被存储在用户宏变量中") has them written where the signal came on, in the program's
coordinates (X a diameter on a lathe), through the planner's host; a G31 that ends without the
signal leaves them as they were, of which the manual says nothing.

Each G31 of a run that keeps its moves leaves a ``Probe`` (for the toolpath: ``cncmacro run
--json`` marks the move's ``skip``) and a ``skip`` note (for people: the run's text output and
the debugger's console) saying where it stopped and why.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

from ..bilingual import Detail, detail
from ..library.skip_model import Circle, SkipModel
from .cycle_time import SKIP_MODE
from .numbers import format_plain

if TYPE_CHECKING:
    from .planner import Planner

_EDGE = 1e-9  # a touch this close outside the move's ends (rounding) still counts, at the end
_SHAPE_NAMES = {"bore": detail("bore", "孔"), "boss": detail("boss", "凸台")}


@dataclass(frozen=True, slots=True)
class SkipState:
    """How many contact points of the machine file's sequence the run's G31 blocks have taken,
    and the tool offset (the tool vector) in force where the last G31 stopped (part of a
    snapshot: going back gives them back)."""

    contacts_used: int = 0
    tool: tuple[float, ...] = ()


class Probe(NamedTuple):
    """One G31: where (file, 0-based line), the index of its move in ``Planner.moves``, where it
    stopped (work coordinates, one value per axis) and whether the skip signal came on there."""

    file: str
    line: int
    move: int
    end: tuple[float, ...]
    hit: bool


def skip_block(m: Planner, target: list[float], file: str, line: int) -> None:
    """Carry out a G31 to ``target``: move until the skip signal comes on (or to ``target``),
    set the skip position, and record the probe and its note."""
    start = list(m.pos)
    end, what = skip_end(m.settings.skip, m.axis_index, start, target, m.skip_state.contacts_used)
    used = m.skip_state.contacts_used + (m.skip_state.contacts_used < len(m.settings.skip.contacts))
    if m.record_moves:  # a run for its diagnostics keeps neither moves nor these
        m.probes.append(Probe(file, line, len(m.moves), tuple(end), what is not None))
        m.host.note("skip", _note(m, start, end, what), line)
    m.move(file, line, SKIP_MODE, end)
    m.skip_pos = list(m.pos)
    m.skip_state = SkipState(used, tuple(m.tool_vector))  # the offset the "skip" rows add (positions.py)
    if m.dialect.skip_commons:  # the GSK980TDi's #995…: where the signal came on, as the program writes it
        index = m.axis_index
        stored = [(n, m.pos[index[a]]) for a, n in m.dialect.skip_commons if a in index]
        m.host.probed(stored, what is not None)


def skip_end(
    model: SkipModel, axis_index: dict[str, int], start: Sequence[float], target: Sequence[float], used: int
) -> tuple[list[float], Detail | None]:
    """Where a G31 from ``start`` to ``target`` stops, and what it touched (None: nothing, it
    ends at ``target``), with ``used`` contact points of the sequence already taken."""
    if used < len(model.contacts):
        contact = model.contacts[used]
        end = list(target)
        if not contact.hit:
            return end, None
        for letter, v in contact.point:
            j = axis_index.get(letter)
            if j is not None:
                end[j] = v
        return end, detail(f"contact point {used + 1} of the machine file", f"机床设置文件的第 {used + 1} 个接触点")
    best: tuple[float, Detail] | None = None
    for plane in model.planes:
        j = axis_index.get(plane.axis)
        if j is None or start[j] == target[j] or not min(start[j], target[j]) <= plane.at <= max(start[j], target[j]):
            continue
        t = (plane.at - start[j]) / (target[j] - start[j])
        if best is None or t < best[0]:
            best = (t, detail(f"the plane {plane.axis}{plane.at:g}", f"平面 {plane.axis}{plane.at:g}"))
    for circle in model.circles:
        t_circle = _circle_hit(circle, axis_index, start, target)
        if t_circle is not None and (best is None or t_circle < best[0]):
            name = _SHAPE_NAMES[circle.kind]
            at = " ".join(f"{a}{v:g}" for a, v in circle.centre)
            best = (
                t_circle,
                detail(f"the {name} D{circle.diameter:g} at {at}", f"{name.zh} D{circle.diameter:g}（圆心 {at}）"),
            )
    if best is None:
        return list(target), None
    t = best[0]
    end = [a + (b - a) * t for a, b in zip(start, target, strict=True)]
    for k, (a, b) in enumerate(zip(start, target, strict=True)):
        if a == b:
            end[k] = a  # an axis that does not move keeps its value exactly
    return end, best[1]


def _circle_hit(
    circle: Circle, axis_index: dict[str, int], start: Sequence[float], target: Sequence[float]
) -> float | None:
    """How far along the move (0 to 1) it reaches the circle's wall: where it leaves a bore or
    comes into a boss; None when it does not, or the control lacks one of the circle's axes."""
    (a, ca), (b, cb) = circle.centre
    i, j = axis_index.get(a), axis_index.get(b)
    if i is None or j is None:
        return None
    sx, sy = start[i] - ca, start[j] - cb
    dx, dy = target[i] - start[i], target[j] - start[j]
    qa = dx * dx + dy * dy
    if qa == 0.0:
        return None  # the move runs along the wall's direction: it never crosses it
    r = circle.diameter / 2
    qb = 2 * (sx * dx + sy * dy)
    qc = sx * sx + sy * sy - r * r
    disc = qb * qb - 4 * qa * qc
    if disc < 0:
        return None
    root = math.sqrt(disc)
    t = (-qb + root) / (2 * qa) if circle.kind == "bore" else (-qb - root) / (2 * qa)
    if not -_EDGE <= t <= 1 + _EDGE:
        return None
    return min(max(t, 0.0), 1.0)


def _note(m: Planner, start: Sequence[float], end: Sequence[float], what: Detail | None) -> Detail:
    """``G31 stopped at X25 Y0: the skip signal came on (the bore D50 at X0 Y0)``."""
    axes = m.dialect.axes
    moved = [k for k in range(len(axes)) if start[k] != end[k]] or list(range(len(axes)))
    at = " ".join(f"{axes[k]}{format_plain(round(end[k], 4))}" for k in moved)
    if what is None:
        return detail(f"G31 reached its end point {at}: the skip signal did not come on",
                      f"G31 到达终点 {at}：跳转信号未接通")  # fmt: skip
    return detail(f"G31 stopped at {at}: the skip signal came on ({what})",
                  f"G31 停在 {at}：跳转信号接通（{what.zh}）")  # fmt: skip
