"""Cycle-time totals as people read them: a run's time and path, split by tool.

The machine decides the time and length of everything (planner/cycle_time.py) and keeps the
clock, the cut and rapid path so far and, at each tool change, those three as they stood
(``ToolChange``). Here they become totals: the whole run's, and each tool's, from its change
to the next change or the end. ``totals_text`` writes them as the editor's code lens and
``cncmacro run`` show them: ``≈ 3 min 12 s · 1,842 mm cut · 6,300 mm rapid`` (in Chinese
``≈ 3 分 12 秒 · 切削 1,842 mm · 快移 6,300 mm``). The path is kept in mm and shown in the
program's unit: a ``G20`` program's in inches (``72.5 in cut``; planner/units.py).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ...bilingual import is_chinese
from ...planner.units import INCH, MM, length_unit

if TYPE_CHECKING:
    from ...planner.planner import Planner

MM_PER_INCH = 25.4


@dataclass(frozen=True, slots=True)
class Totals:
    """Seconds, and the cut (feed) and rapid path in mm, shown in ``unit`` (``mm`` or ``in``)."""

    seconds: float = 0.0
    cut: float = 0.0
    rapid: float = 0.0
    unit: str = MM

    def __add__(self, other: Totals) -> Totals:
        return Totals(self.seconds + other.seconds, self.cut + other.cut, self.rapid + other.rapid, self.unit)

    def __sub__(self, other: Totals) -> Totals:
        return Totals(self.seconds - other.seconds, self.cut - other.cut, self.rapid - other.rapid, self.unit)

    @property
    def inch(self) -> bool:
        """Whether the program was in inches (G20) at its end."""
        return self.unit == INCH

    def shown(self) -> tuple[float, float]:
        """The cut and rapid path in ``unit``."""
        if self.unit == INCH:
            return self.cut / MM_PER_INCH, self.rapid / MM_PER_INCH
        return self.cut, self.rapid


def end_totals(planner: Planner) -> Totals:
    """A run's totals as its planner ends them, in the unit the program is in at its end."""
    return Totals(planner.clock, planner.cut_length, planner.rapid_length, length_unit(planner.modal.get("units")))


@dataclass(frozen=True, slots=True)
class ToolPart:
    """One tool's part of a run: the change that began it (file, 0-based line), the T in force
    there, and its totals up to the next change or the end."""

    file: str
    line: int
    tool: float | None
    totals: Totals


def tool_parts(changes: Sequence[tuple[str, int, float | None, Totals]], end: Totals) -> list[ToolPart]:
    """Each tool change (file, line, T, the totals before it), in run order, with the run's
    totals at its ``end``: the part from each change to the next."""
    out: list[ToolPart] = []
    for k, (file, line, tool, before) in enumerate(changes):
        after = changes[k + 1][3] if k + 1 < len(changes) else end
        part = after - before
        out.append(ToolPart(file, line, tool, Totals(part.seconds, part.cut, part.rapid, end.unit)))
    return out


def duration_text(seconds: float, locale: str | None = None) -> str:
    """``3 min 12 s``, ``1 h 05 min``, ``4.2 s`` (Chinese: ``3 分 12 秒``)."""
    zh = is_chinese(locale)
    if seconds < 10.0:
        shown = f"{seconds:.1f}"
        return f"{shown} 秒" if zh else f"{shown} s"
    whole = round(seconds)
    h, rest = divmod(whole, 3600)
    m, s = divmod(rest, 60)
    if h:
        return f"{h} 小时 {m:02d} 分" if zh else f"{h} h {m:02d} min"
    if m:
        return f"{m} 分 {s:02d} 秒" if zh else f"{m} min {s:02d} s"
    return f"{s} 秒" if zh else f"{s} s"


def totals_text(t: Totals, locale: str | None = None) -> str:
    """``≈ 3 min 12 s · 1,842 mm cut · 6,300 mm rapid`` (a ``G20`` program's: ``72.5 in cut``)."""
    time = duration_text(t.seconds, locale)
    cut, rapid = t.shown()
    form = ",.1f" if t.unit == INCH else ",.0f"
    if is_chinese(locale):
        return f"≈ {time} · 切削 {cut:{form}} {t.unit} · 快移 {rapid:{form}} {t.unit}"
    return f"≈ {time} · {cut:{form}} {t.unit} cut · {rapid:{form}} {t.unit} rapid"


def tool_name(tool: float | None, lathe: bool = False) -> str:
    """``T1`` on a mill; on a lathe the four digits of tool and offset, ``T0101`` (``T?``
    before any T)."""
    if tool is None:
        return "T?"
    if tool != int(tool):
        return f"T{tool:g}"
    return f"T{int(tool):04d}" if lathe else f"T{int(tool)}"
