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

from ..bilingual import detail
from ..dialects.alarms import POLAR_START
from .alarms import MacroAlarm
from .cutter_stage import LEFT, RIGHT

if TYPE_CHECKING:
    from .planner import Planner

PER_REVOLUTION = 99.0  # a lathe's G99 (system A), the feed group's code

VIRTUAL_PLANE = "virtual plane"  # the ``modal`` key of the mode on (its code), absent when off
CYLINDER = "cylinder radius"  # the ``modal`` key of cylindrical interpolation's radius, while it is on


def refuse_polar_start(p: Planner, g: float, on: bool) -> None:
    """Polar interpolation code ``g`` starting it (``on``) under feed per revolution (G99) or in tool nose
    radius compensation (G41/G42): the control's alarm where the profile has it
    (``Dialect.polar_start_alarm``: GSK980TDi §3.9 note 3, "在C刀补中间或G99状态下不能启动极坐标插补，
    否则报警")."""
    if not on or not p.dialect.polar_start_alarm:
        return
    code = p.modal.get("cutter")
    if code in (LEFT, RIGHT):
        raise MacroAlarm(POLAR_START, detail(
            f"G{g:g} starts polar coordinate interpolation in tool nose radius compensation (G{code:g}): "
            "cancel it with G40 first",
            f"刀尖半径补偿（G{code:g}）中用 G{g:g} 启动极坐标插补：请先用 G40 取消补偿"), "polar-start")  # fmt: skip
    if p.modal.get("feed") == PER_REVOLUTION:
        raise MacroAlarm(POLAR_START, detail(
            f"G{g:g} starts polar coordinate interpolation under feed per revolution (G99): select G98 first",
            f"每转进给（G99）状态下用 G{g:g} 启动极坐标插补：请先指令 G98"), "polar-start")  # fmt: skip


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
