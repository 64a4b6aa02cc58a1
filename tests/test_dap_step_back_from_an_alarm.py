"""docs/debugging.md, going back from an alarm: the alarm's block never ran to its end, so step
back from an alarm goes back over it to the block before, and the stack shows the line before
the alarm's (it stayed on the alarm's line with the same values, only the alarm cleared). A step
forward from there comes back to the alarm's line with the values it had, where a value can be
set before the block runs again."""

from __future__ import annotations

from pathlib import Path

from cncmacro.debugging.breakpoints import Breakpoints
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import CONTINUE, STEP_OVER, Stepper
from cncmacro.machine.evaluate import set_variable
from running import lines, machine

DIVIDE = lines("O0001", "#1=5", "#2=0", "#3=10/#2", "#4=1", "M30")  # 10/#2 on line 4: alarm 112
MAIN = lines("O0001", "#100=1", "G65 P9001 A0", "M30")  # the G65 on line 3
MACRO = lines("O9001", "#2=5/#1", "M99")  # #1 = A = 0: alarm 112 on the macro's first block


def stepper(tmp_path: Path, text: str) -> Stepper:
    (tmp_path / "O9001.nc").write_text(MACRO, encoding="utf-8")
    (tmp_path / "MAIN.nc").write_text(text, encoding="utf-8")
    m = machine(text, folder=tmp_path)
    history = History(interval=2)
    history.reset(m)
    s = Stepper(m, Breakpoints(), history, lambda _text, _category: None)
    s.stop_at_end = True
    return s


def test_step_back_from_an_alarm_goes_to_the_block_before_the_alarms(tmp_path: Path) -> None:
    s = stepper(tmp_path, DIVIDE)
    m = s.machine
    stop = s.run(CONTINUE)
    # blocks #1=5 (1), #2=0 (2), #3=10/#2 (3, the alarm) on line 4
    assert (stop.reason, stop.text, m.blocks, m.frames[-1].pc + 1) == (
        "exception", "ALARM 112: division by zero", 3, 4,
    )  # fmt: skip
    stop = s.step_back()
    # back over the alarm's block and #2=0: before line 3, after #1=5 (block 1), #2 not yet set
    assert (stop.reason, m.status, m.alarm, m.blocks, m.frames[-1].pc + 1) == ("step", "paused", None, 1, 3)
    assert (m.L[1], m.L[2], m.L[3]) == (5.0, None, None)
    # a step runs #2=0 and stands on the alarm's line again, which has not run
    assert s.run(STEP_OVER).reason == "step"
    assert (m.blocks, m.frames[-1].pc + 1, m.L[2], m.alarm) == (2, 4, 0.0, None)
    set_variable(m, 2, "4", 0)  # fixed by hand: 10/4 = 2.5
    s.history.mark(m)
    s.run(STEP_OVER)
    assert (m.frames[-1].pc + 1, m.L[3]) == (5, 2.5)


def test_an_alarm_on_a_macros_first_block_steps_back_to_its_call(tmp_path: Path) -> None:
    s = stepper(tmp_path, MAIN)
    m = s.machine
    stop = s.run(CONTINUE)
    # blocks #100=1 (1), G65 (2), #2=5/#1 (3, the alarm, in O9001 at its line 2)
    assert (stop.reason, len(m.frames), m.frames[-1].pc + 1, m.blocks) == ("exception", 2, 2, 3)
    s.step_back()
    # before the G65 (block 1 run): the main program on line 3, #100 = 1
    assert (len(m.frames), m.frames[-1].pc + 1, m.blocks, m.C[100], m.alarm) == (1, 3, 1, 1.0, None)


def test_an_alarm_on_the_first_block_steps_back_to_the_start(tmp_path: Path) -> None:
    s = stepper(tmp_path, lines("O0001", "#3=1/0", "M30"))
    m = s.machine
    assert s.run(CONTINUE).reason == "exception"
    stop = s.step_back()
    # no block before the alarm's: the start of the kept history, the alarm's line not run
    assert (stop.reason, stop.description, m.blocks, m.frames[-1].pc + 1, m.alarm) == (
        "entry", "the start of the kept history", 0, 2, None,
    )  # fmt: skip
