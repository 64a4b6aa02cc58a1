"""A lathe's spindle between constant surface speed (G96) and constant speed (G97): what S is
when a G97 or a G96 block gives none (docs/semantics.md §10.4).

GSK980TDi manual §3.25 note 4: "从 G96 状态变为 G97 状态时，G97 程序段如果没有 S 代码（r/min），那么 G96
状态的最后转速作为 G97 状态的 S 代码使用，即此时主轴转速不变" (a G97 without S keeps the speed the
spindle turned at under G96, at the diameter where the tool is, within the G50 S clamp); note 1:
"在 G96 状态中，被指令的 S 值，即使在 G97 状态中也保持着。当返回到 G96 状态时，其值恢复" (the surface speed
comes back with a G96 without S). FANUC 0i-TF, "constant surface speed control", alike. Before,
the surface speed's number became the spindle speed: G96 S150 then G97 turned at 150 rev/min.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .cycle_time import INCH, SPEED_CLAMP

if TYPE_CHECKING:
    from .planner import Planner

SURFACE_SPEED = "G96 S"  # the ``codes`` key of the surface speed kept through G97


def spindle_mode(p: Planner, g: float, other: dict[str, float]) -> None:
    """G96 or G97 (``g``) in a block with the words ``other``, before its S is set."""
    before = p.modal.get("spindle")
    codes = p.codes
    if g == 97.0 and before == 96.0:
        surface = codes.get("S") or 0.0
        codes[SURFACE_SPEED] = surface
        if "S" not in other:
            codes["S"] = _turning_at(p, surface)
    elif g == 96.0 and before != 96.0 and "S" not in other and codes.get(SURFACE_SPEED) is not None:
        codes["S"] = codes[SURFACE_SPEED]


def _turning_at(p: Planner, surface: float) -> float:
    """The speed (rev/min) the spindle turns at under G96 ``surface`` where the tool is: at its
    diameter, never above the G50 S clamp nor the spindle's top speed."""
    times = p.times
    top = min(times.top_speed, times.timing.max_spindle_speed, codes_clamp(p))
    x = p.axis_index.get("X")
    unit = INCH if p.modal.get("units") == 20.0 else 1.0
    diameter = abs(p.pos[x]) * unit if x is not None else 0.0
    per_minute = (304.8 if unit != 1.0 else 1000.0) * surface
    return top if diameter <= 0.0 else min(per_minute / (math.pi * diameter), top)


def codes_clamp(p: Planner) -> float:
    """The G50 S clamp in force (infinite without one)."""
    clamp = p.codes.get(SPEED_CLAMP)
    return math.inf if clamp is None else clamp
