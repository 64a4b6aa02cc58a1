"""docs/debugging.md, exception filters: with "All alarms" off the run does not stop on an alarm,
and the Debug Console's alarm line says where it was raised, as ``cncmacro run`` does: the
headline, ``  at O0001.nc:4``, and for an alarm inside a call each caller's line (``  called from
O0001 (main) at MAIN.nc:3``, the caller named as its stack frame is); in Chinese ``  位置 …`` and ``  调用自 …``."""

from __future__ import annotations

from pathlib import Path

from cncmacro.debugging.breakpoints import Breakpoints
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import CONTINUE, Filters, Stepper
from running import lines, machine

MAIN = lines("O0001", "#1=0", "G65 P9001 A0", "M30")  # the G65 on line 3
MACRO = lines("O9001", "#2=5", "#3=#2/#1", "M99")  # #1 = A = 0: the division on line 3 is alarm 112


def console(tmp_path: Path, text: str, locale: str | None = None) -> list[tuple[str, str]]:
    (tmp_path / "O9001.nc").write_text(MACRO, encoding="utf-8")
    (tmp_path / "MAIN.nc").write_text(text, encoding="utf-8")
    m = machine(text, folder=tmp_path)
    history = History(interval=4)
    history.reset(m)
    said: list[tuple[str, str]] = []
    s = Stepper(m, Breakpoints(), history, lambda t, category: said.append((t, category)), filters=Filters(False))
    s.locale = locale
    stop = s.run(CONTINUE)
    assert stop.reason == "exited"
    return said


def test_an_alarm_not_stopped_at_is_printed_with_its_line(tmp_path: Path) -> None:
    said = console(tmp_path, lines("O0001", "#1=1", "#2=0", "#3=#1/#2", "M30"))  # division by zero, line 4
    assert ("ALARM 112: division by zero\n  at MAIN.nc:4\n", "stderr") in said


def test_an_alarm_in_a_macro_names_the_call_that_reached_it(tmp_path: Path) -> None:
    said = console(tmp_path, MAIN)
    [alarm] = [t for t, category in said if category == "stderr"]
    assert alarm.splitlines()[1:] == ["  at O9001.nc:3", "  called from O0001 (main) at MAIN.nc:3"]


def test_in_chinese(tmp_path: Path) -> None:
    said = console(tmp_path, MAIN, "zh-cn")
    [alarm] = [t for t, category in said if category == "stderr"]
    assert alarm.splitlines()[1:] == ["  位置 O9001.nc:3", "  调用自 O0001（主程序），位置 MAIN.nc:3"]
