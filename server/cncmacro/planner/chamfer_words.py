"""A control's own chamfer and corner rounding words on a move: the GSK980TDi's ``L`` (a straight
chamfer) and ``D`` (a rounding arc) in a G01, G02 or G03 block (its manual §3.11 "倒角功能",
``Dialect.chamfer_words``; docs/semantics.md §10.1).

Like FANUC's ``,C`` and ``,R`` (machine/corners.py) they are **not simulated**: the move runs as
written and the toolpath keeps the sharp corner. The run says so once per block, so that a
program's chamfer is not dropped in silence, and names what is not looked for.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..bilingual import detail

if TYPE_CHECKING:
    from .planner import Planner

CUTTING_MODES = (1.0, 2.0, 3.0)  # "倒角必须在 G01、G02 或 G03 代码段中使用"


def note_chamfer(p: Planner, mode: float, other: dict[str, float], line: int) -> None:
    """Note a chamfer or rounding word of ``other`` in a block of ``mode`` on ``line``."""
    words = p.dialect.chamfer_words
    if words is None or mode not in CUTTING_MODES:
        return
    chamfer, rounding = words
    if chamfer not in other and rounding not in other:
        return
    if chamfer in other:
        en, zh = f"the chamfer {chamfer}{other[chamfer]:g}", f"直线倒角 {chamfer}{other[chamfer]:g}"
    else:
        en, zh = f"the corner rounding {rounding}{other[rounding]:g}", f"圆弧倒角 {rounding}{other[rounding]:g}"
    p.host.note("simulation", detail(
        f"{en} between this move and the next is not simulated: the toolpath keeps the sharp corner and the "
        "time counts none, and the control's alarms for it (a chamfer too long, a move too short, a radius too "
        "large) are not looked for",
        f"本段与下一段之间的{zh}未模拟：刀具轨迹保留尖角，时间中不计入，系统对此的报警（倒角过长、程序段过短、"
        "半径过大）也不检查"),
        line, "not-simulated")  # fmt: skip
