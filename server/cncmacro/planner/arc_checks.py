"""What the run says of an arc the control cannot cut as written (docs/semantics.md §8, "Arcs").

``arcs.arc_fault`` finds the fault, once for every path an arc block takes (the general path,
a plain line's plan, a run of plain lines: machine/straight_runs.py declines such a line to
them); here it becomes the control's answer. I, J, K whose end is off the start's circle by
more than the tolerance is FANUC's alarm PS0020 "over tolerance of radius" where the profile
documents it (``Dialect.arc_radius_alarm``: the run stops there); elsewhere, and for an R
shorter than half the chord or an R arc with its end at its start (which no manual at hand
gives an alarm for), the run notes it (kind ``arc``, the fault as subject) and goes on. An arc
that moves in its plane with neither R nor I, J, K is FANUC's alarm PS0022 "R or I, J, K command
not found" (``Dialect.arc_centre_alarm``; ``no_centre``); elsewhere it is cut as a straight line.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..bilingual import Detail, detail
from ..dialects.alarms import ARC_NO_CENTRE, ARC_RADIUS
from .alarms import MacroAlarm
from .arcs import RADIUS_MISMATCH, SHORT_RADIUS, Plane, moves_in_plane

NO_CENTRE = "arc-centre"  # the subject of PS0022

if TYPE_CHECKING:
    from .planner import Planner


def arc_message(fault: tuple[str, float, float], tolerance: float) -> Detail:
    """The finding's text for a machinist, in English and Chinese (numbers in the program's unit)."""
    kind, first, second = fault
    if kind == RADIUS_MISMATCH:
        off = abs(second - first)
        return detail(
            f"the arc's end point is {off:.3f} off its circle: the start is {first:.3f} from the centre I, J, K "
            f"give, the end {second:.3f} (more apart than the tolerance {tolerance:.3f}, FANUC parameter 3410); "
            "check the end point and I, J, K",
            f"圆弧终点偏离圆周 {off:.3f}：起点到 I、J、K 所定圆心的距离为 {first:.3f}，终点为 {second:.3f}"
            f"（相差超过允差 {tolerance:.3f}，FANUC 参数 3410）；请检查终点和 I、J、K",
        )
    if kind == SHORT_RADIUS:
        return detail(
            f"R{first:g} is shorter than half the chord ({second:.3f}): no arc of that radius reaches the end point; "
            f"the run draws a half circle of radius {second:.3f}; check R or the end point",
            f"R{first:g} 小于弦长的一半（{second:.3f}）：该半径的圆弧到不了终点；"
            f"本次运行按半径 {second:.3f} 的半圆绘制；请检查 R 或终点",
        )
    return detail(
        f"R{first:g} with the end point at the start: the control makes no move (an arc of 0°); "
        "a full circle is written with I, J or K",
        f"R{first:g} 的终点与起点相同：系统不移动（0° 圆弧）；整圆须用 I、J 或 K 指令",
    )


def arc_finding(p: Planner, fault: tuple[str, float, float], line: int) -> None:
    """The control's answer to ``fault`` (``arcs.arc_fault``) on ``line``: alarm PS0020 where the
    profile documents it for I, J, K off the circle, else a note the run goes past."""
    tolerance = p.arc_tolerance / 25.4 if p.modal.get("units") == 20.0 else p.arc_tolerance
    message = arc_message(fault, tolerance)
    if fault[0] == RADIUS_MISMATCH and p.dialect.arc_radius_alarm:
        raise MacroAlarm(ARC_RADIUS, message, RADIUS_MISMATCH)
    p.host.note("arc", message, line, fault[0])


def no_centre(p: Planner, mode: float, plane: Plane, start: Sequence[float], end: Sequence[float]) -> None:
    """An arc ``mode`` (G02/G03) from ``start`` to ``end`` in ``plane`` whose block names neither R
    nor an offset word of the plane: where the profile has FANUC's PS0022
    (``Dialect.arc_centre_alarm``) and the move goes somewhere in the plane, the run stops with it;
    else the move is cut as a straight line."""
    if not p.dialect.arc_centre_alarm or not moves_in_plane(plane, start, end):
        return
    _, _, off_a, off_b = plane
    g = f"G{mode:02g}"
    raise MacroAlarm(ARC_NO_CENTRE, detail(
        f"{g} moves in the plane but gives neither R nor {off_a}, {off_b}: the control cannot find the arc's centre",
        f"{g} 在平面内移动，但既未指令 R 也未指令 {off_a}、{off_b}：系统无法确定圆弧的圆心"), NO_CENTRE)  # fmt: skip
