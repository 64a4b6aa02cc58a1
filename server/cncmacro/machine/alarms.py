"""Alarms as structured results: a number, a message, and where the run was.

Inside the interpreter an alarm travels as ``MacroAlarm`` (number and message: planner/alarms.py,
where the planner raises it too). The run loop
turns it into an ``Alarm`` with the file, the line and the call chain that reached it, which
is what the command line, the diagnostics and the debugger show.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..bilingual import detail, in_language, is_chinese, pick
from ..dialects.alarms import ARGUMENT_RANGE, alarm_words
from ..planner.alarms import MacroAlarm as MacroAlarm

if TYPE_CHECKING:
    from ..dialects.dialect import Dialect


def raiser(number: int, message: str, subject: str | None = None) -> Callable[..., Any]:
    """A closure that raises this alarm whenever it is called: what a block or expression
    compiles to when its text alone decides that it alarms (it may never be reached)."""

    def fail(*_: Any) -> Any:
        raise MacroAlarm(number, message, subject)

    return fail


def macro_alarm_number(n: int, dialect: Dialect, written: str) -> int:
    """The number of the alarm a program raises itself with ``n`` (``written``: ``#3000=n`` or
    gsk980tdi's ``G65 H99 Pn``, docs/semantics.md §6): ``Dialect.macro_alarm_base`` + n. An n
    outside the range the control takes (``Dialect.macro_alarm_numbers``: 0-99 on gsk980tdi, alarms
    5900-5999) raises alarm 119, an argument out of range, instead: the manual gives the range and
    no alarm of its own for a number outside it."""
    base = dialect.macro_alarm_base
    span = dialect.macro_alarm_numbers
    if span is not None and not span[0] <= n <= span[1]:
        low, high = span
        raise MacroAlarm(
            ARGUMENT_RANGE,
            detail(
                f"{written}: the alarm number must be {low} to {high} (alarms {base + low} to {base + high})",
                f"{written}：报警号必须在 {low}～{high} 之间（报警 {base + low}～{base + high}）",
            ),
        )
    return base + n


@dataclass(frozen=True, slots=True)
class CallLevel:
    """One level of a run's call chain (``Alarm.chain``): the program and the line of the call in it."""

    program: str
    file: str
    line: int
    how: str  # "main", "G65", "G66", "M98", or the code that called (e.g. "M50")


CALLED_HOW_ZH = {"main": "主程序"}  # how a program level was called, in Chinese where it is a word


@dataclass(frozen=True, slots=True)
class Alarm:
    """An alarm the run stopped with: ``line`` is 0-based, ``chain`` lists the callers from
    the main program inward."""

    number: int
    message: str
    file: str
    line: int
    chain: tuple[CallLevel, ...] = ()
    subject: str | None = None  # e.g. "repeat-count", "label-range", "jump-into-loop"
    # the number the control shows (``Dialect.shown_alarm``): ``number`` on FANUC and GSK, None
    # on a profile that documents no number for it (Haas); ``number`` stays the interpreter's
    shown: int | None = None

    def words(self, locale: str | None = "en") -> str:
        """ "alarm 128" ("报警 128"), or "alarm" alone where the control documents no number."""
        return alarm_words(self.shown, locale or "en")

    def describe(self) -> str:
        return f"{self.words()}: {self.message}"

    def places(self, locale: str | None, shown: Callable[[str], str] = str) -> list[str]:
        """Where the run stopped and the calls that led there, a line each, in the language of
        ``locale``, each file as ``shown`` writes it: ``  at O1000.nc:30``, ``  called from O1000
        (G65) at MAIN.nc:5`` (``cncmacro run``, the debugger's console)."""
        chinese = is_chinese(locale)
        out = [f"  位置 {shown(self.file)}:{self.line + 1}" if chinese else f"  at {shown(self.file)}:{self.line + 1}"]
        for site in reversed(self.chain[:-1]):
            at = f"{shown(site.file)}:{site.line + 1}"
            how = CALLED_HOW_ZH.get(site.how, site.how)
            out.append(f"  调用自 {site.program}（{how}），位置 {at}" if chinese
                       else f"  called from {site.program} ({site.how}) at {at}")  # fmt: skip
        return out

    def headline(self, locale: str | None) -> str:
        """The alarm as a person reads it where a run stopped, in the language of ``locale``:
        ``ALARM 112: division by zero``, ``报警 112：除数为零`` (``cncmacro run``, the debugger)."""
        text = in_language(self.message, is_chinese(locale))
        return pick(locale, f"{self.words().upper()}: {text}", f"{self.words(locale)}：{text}")


def budget_spent(blocks: int, locale: str | None) -> str:
    """Why a run stopped when its block budget ran out, in the language of ``locale``."""
    return pick(
        locale,
        f"stopped after {blocks} blocks: the block budget ran out (an endless loop?)",
        f"执行 {blocks} 个程序段后停止：已达到程序段数上限（是否有死循环？）",
    )
