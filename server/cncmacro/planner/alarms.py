"""An alarm raised while a block executes: by the macro machine (machine/) or the planner.

It travels as ``MacroAlarm`` (the alarm's number and message) up to the macro machine's run loop,
which turns it into an ``Alarm`` with the file, the line and the call chain (machine/alarms.py).
"""

from __future__ import annotations

from collections.abc import Callable

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


class AlarmBeforeMove(MacroAlarm):
    """An alarm the control raises while it reads ahead, before an earlier block than the one
    read has moved (FANUC's interference check: "the tool stops and an alarm is displayed" at the
    end of the block before the one that would be cut backwards). The planner has already made
    that block's move; ``take_back`` undoes it, once, when the run ends on this alarm (a run of
    plain lines that meets it runs the line again the general way, which raises it anew). ``at``
    (file, 0-based line) is the block the alarm stands on when it is not the one read: a stroke
    limit the tool centre crosses on a block whose path was settled by the next one (cutter_stage.py)."""

    def __init__(
        self, number: int, message: str, subject: str | None, take_back: Callable[[], None],
        at: tuple[str, int] | None = None,
    ) -> None:  # fmt: skip
        super().__init__(number, message, subject)
        self.take_back = take_back
        self.at = at


UNKNOWN_VALUE = "unknown-value"  # the subject of ``UnknownValue``


class UnknownValue(MacroAlarm):
    """An analysis run reached a block whose outcome depends on a value the machine has and the
    folder does not (a common kept at power-off, an offset: machine/unknown_values.py): a branch
    on it, an address or variable number made from it. The control decides with its value; the
    run stops that path there, with a note rather than an alarm (docs/semantics.md §2, "Unknown, not vacant")."""

    def __init__(self) -> None:
        super().__init__(
            0,
            detail("this block depends on a value only the machine has", "本程序段取决于只有机床上才有的数值"),
            UNKNOWN_VALUE,
        )


def is_unknown(v: float | None) -> bool:
    """Whether ``v`` is unknown (NaN: the machine has a value, the folder does not)."""
    return v is not None and v != v
