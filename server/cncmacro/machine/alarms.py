"""Alarms as structured results: a number, a message, and where the run was.

Inside the interpreter an alarm travels as ``MacroAlarm`` (number and message: planner/alarms.py,
where the planner raises it too). The run loop
turns it into an ``Alarm`` with the file, the line and the call chain that reached it, which
is what the command line, the diagnostics and the debugger show.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ..dialects.alarms import alarm_words
from ..planner.alarms import MacroAlarm as MacroAlarm


def raiser(number: int, message: str, subject: str | None = None) -> Callable[..., Any]:
    """A closure that raises this alarm whenever it is called: what a block or expression
    compiles to when its text alone decides that it alarms (it may never be reached)."""

    def fail(*_: Any) -> Any:
        raise MacroAlarm(number, message, subject)

    return fail


@dataclass(frozen=True, slots=True)
class CallLevel:
    """One level of a run's call chain (``Alarm.chain``): the program and the line of the call in it."""

    program: str
    file: str
    line: int
    how: str  # "main", "G65", "G66", "M98", or the code that called (e.g. "M50")


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
