"""docs/debugging.md, "Conditions": a breakpoint's condition is read as the condition of
``IF[...]`` and refused, with the reason, when it is set. A condition typed unfinished (``#4 GT``)
is said to be incomplete, with what is missing, and not blamed on the ``]`` the debugger puts
around it; a relation the control does not read (``==`` or ``>`` on a FANUC, alarm 114) and a
variable the control does not have (``#9999``, alarm 115) are refused when the breakpoint is set,
as a program line with them alarms, rather than when it is first reached. A program line
``IF[#4 GT]GOTO1`` has its ``]``, which does close a ``[``, said to come before the value."""

from __future__ import annotations

from pathlib import Path

import pytest

from cncmacro.debugging.breakpoints import Asked, Breakpoints
from cncmacro.syntax.block_parser import parse_block
from running import lines, machine


def condition_message(tmp_path: Path, condition: str, locale: str | None = None) -> tuple[bool, str | None]:
    path = tmp_path / "O0001.nc"
    path.write_text(lines("O0001", "#4=1", "#5=2", "M30"), encoding="utf-8")
    bps = Breakpoints()
    bps.locale = locale
    bps.bind(machine(path.read_text(encoding="utf-8")))
    [bp] = bps.set_lines(str(path), [Asked(2, condition)])
    return bp.verified, bp.message


@pytest.mark.parametrize(
    ("condition", "said"),
    [
        ("#4 GT", "condition '#4 GT': '#4 GT' is not complete; expected a value (a number, #variable or [expression])"),
        ("#4 GT 3 AND", "'#4 GT 3 AND' is not complete; expected a value"),
        ("#4 == 3", "condition '#4 == 3': alarm 114: '==' is not a relation on FANUC 0i Custom Macro B; write EQ"),
        ("#4>2", "alarm 114: '>' is not a relation on FANUC 0i Custom Macro B; write GT"),
        ("#9999 GT 1", "alarm 115: #9999 does not exist"),
        ("[#4 GT 3", "expected ']' to close the '[' at column 1"),  # a bracket the person did type
    ],
)
def test_a_condition_that_cannot_be_read_is_refused_when_set_with_its_reason(
    tmp_path: Path, condition: str, said: str
) -> None:
    verified, message = condition_message(tmp_path, condition)
    assert not verified
    assert message is not None and said in message
    assert "without a matching" not in message


def test_an_unfinished_condition_in_chinese(tmp_path: Path) -> None:
    _, message = condition_message(tmp_path, "#4 GT", "zh-cn")
    assert message == "条件 '#4 GT'：'#4 GT' 不完整；应为数值（数字、#变量或 [表达式]）"


def test_a_good_condition_is_verified(tmp_path: Path) -> None:
    assert condition_message(tmp_path, "[#4 GT 0] AND [#5 EQ 2]") == (True, None)


def test_a_program_line_whose_bracket_closes_before_the_value_says_so() -> None:
    # "IF[#4 GT]GOTO1": the ']' at column 9 closes the '[' at column 3; what is wrong is the
    # value missing before it (it said "']' without a matching '['")
    [problem] = [p for p in parse_block("IF[#4 GT]GOTO1").problems if p.severity == "error"]
    assert problem.message == "unexpected ']'; expected a value (a number, #variable or [expression])"
    assert problem.message.zh == "此处不应出现 ']'；应为数值（数字、#变量或 [表达式]）"  # type: ignore[attr-defined]
    assert (problem.start, problem.end) == (8, 9)
    # a ']' that closes nothing is still said so
    [extra] = [p for p in parse_block("#2=1+2]").problems if p.severity == "error"]
    assert extra.message == "']' without a matching '['"
