"""Cycle-time totals as people read them: a run's time and path, split by tool.

The machine decides the time and length of everything (planner/cycle_time.py) and keeps the
clock, the cut and rapid path so far and, at each tool change, those three as they stood
(``ToolChange``). Here they become totals: the whole run's, and each tool's, from its change
to the next change or the end. ``totals_text`` writes them as the editor's code lens and
``cncmacro run`` show them: ``≈ 3 min 12 s · 1,842 mm cut · 6,300 mm rapid`` (in Chinese
``≈ 3 分 12 秒 · 切削 1,842 mm · 快移 6,300 mm``).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from ...bilingual import is_chinese


@dataclass(frozen=True, slots=True)
class Totals:
    """Seconds, and the cut (feed) and rapid path in mm."""

    seconds: float = 0.0
    cut: float = 0.0
    rapid: float = 0.0

    def __add__(self, other: Totals) -> Totals:
        return Totals(self.seconds + other.seconds, self.cut + other.cut, self.rapid + other.rapid)

    def __sub__(self, other: Totals) -> Totals:
        return Totals(self.seconds - other.seconds, self.cut - other.cut, self.rapid - other.rapid)


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
        out.append(ToolPart(file, line, tool, after - before))
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
    """``≈ 3 min 12 s · 1,842 mm cut · 6,300 mm rapid``."""
    time = duration_text(t.seconds, locale)
    if is_chinese(locale):
        return f"≈ {time} · 切削 {t.cut:,.0f} mm · 快移 {t.rapid:,.0f} mm"
    return f"≈ {time} · {t.cut:,.0f} mm cut · {t.rapid:,.0f} mm rapid"


def tool_name(tool: float | None, lathe: bool = False) -> str:
    """``T1`` on a mill; on a lathe the four digits of tool and offset, ``T0101`` (``T?``
    before any T)."""
    if tool is None:
        return "T?"
    if tool != int(tool):
        return f"T{tool:g}"
    return f"T{int(tool):04d}" if lathe else f"T{int(tool)}"
