"""An alarm raised while a block executes: by the macro machine (machine/) or the planner.

It travels as ``MacroAlarm`` (the alarm's number and message) up to the macro machine's run loop,
which turns it into an ``Alarm`` with the file, the line and the call chain (machine/alarms.py).
"""

from __future__ import annotations

from ..bilingual import detail
from ..dialects.alarms import alarm_text


class MacroAlarm(Exception):
    """Raised while a block executes. ``message`` is a ``texts.Detail`` (English, with its
    Chinese) where the interpreter writes it, and defaults to the alarm's standard text."""

    def __init__(self, number: int, message: str | None = None, subject: str | None = None) -> None:
        self.number = number
        self.message = message or detail(alarm_text(number), alarm_text(number, "zh"))
        self.subject = subject  # what the alarm is about where one number covers several things
        super().__init__(f"alarm {number}: {self.message}")
