"""Macro text typed by a person while a run is stopped: expressions, conditions, assignments.

The debugger's watch, hover and console, conditional breakpoints (``#1 GT 5``) and log points
all hand the interpreter a piece of macro text. It is read with the same block grammar as a
program line (an expression as the right side of ``#1=``, a condition inside ``IF[...]``),
compiled with the same expression compiler, and run against the machine as it stands, in the
locals of the program level the person selected. Nothing is evaluated as Python. A mistake in
the text is an ``EvaluationError`` whose message says what is wrong; an alarm the text raises
(``#1/0``, ``#3000=1``) is one too, and leaves the run as it was.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import TYPE_CHECKING, TypeVar

from ..bilingual import Detail, detail, in_language
from ..syntax.block_parser import parse_block
from ..syntax.nodes import Assign, Block, If, NamedVar, Var
from .alarms import MacroAlarm
from .expressions import ExpressionCompiler, Getter, Test
from .variables import StopRequest

if TYPE_CHECKING:
    from .machine import Machine

_T = TypeVar("_T")

Value = float | None

_COLUMN = re.compile(r"column (\d+)")
_COLUMN_ZH = re.compile(r"第 (\d+) 列")
_WANTED_MORE = re.compile(r"; expected (?!'\]')")  # the parser wanted more than ']' (syntax/messages.py)
_ASSIGNMENT = re.compile(r"^\s*#[^=]*?(?<![=!<>])=(?!=)")
MAX_TEXT = 1000


class EvaluationError(ValueError):
    """The text does not read as macro syntax, or running it raised an alarm."""


@dataclass(frozen=True, slots=True)
class CompiledText:
    """Text compiled once for a machine's dialect, to run many times (a breakpoint condition)."""

    text: str
    value: Getter | None = None
    test: Test | None = None


def _block(text: str, prefix: str, suffix: str) -> Block:
    if len(text) > MAX_TEXT:
        raise EvaluationError(
            detail(
                f"the text is too long ({len(text)} characters, at most {MAX_TEXT})",
                f"文本过长（{len(text)} 个字符，最多 {MAX_TEXT} 个）",
            )
        )
    if "\n" in text or "\r" in text:
        raise EvaluationError(detail("one line of macro text only", "只能输入一行宏语句"))
    block = parse_block(prefix + text + suffix)
    error = next((p for p in block.problems if p.severity == "error"), None)
    if error is not None:
        message = error.message
        if suffix and error.start >= len(prefix) + len(text) and _WANTED_MORE.search(message):
            raise EvaluationError(_ended_early(text, message))  # at what was put around the text
        raise EvaluationError(_shifted(error.message, len(prefix)))
    return block


def _ended_early(text: str, message: str) -> Detail:
    """The text stops before it is complete (``#4 GT``): the parser's complaint is about what
    was put after it (the ``]`` of ``IF[...]``), which the person never typed; what it expected
    there (``; expected a value``, syntax/messages.py) is kept."""
    zh = getattr(message, "zh", message)
    en_tail = message[message.find("; expected") :]
    zh_tail = zh[zh.find("；应为") :] if "；应为" in zh else ""
    return Detail(f"'{text}' is not complete{en_tail}", f"'{text}' 不完整{zh_tail}")


def _shifted(message: str, shift: int) -> str:
    """A syntax message about the line built around the text, with its columns counted from
    the text as typed, in both languages."""
    en = _COLUMN.sub(lambda m: f"column {max(1, int(m.group(1)) - shift)}", message)
    zh = getattr(message, "zh", None)
    if zh is None:
        return en
    return Detail(en, _COLUMN_ZH.sub(lambda m: f"第 {max(1, int(m.group(1)) - shift)} 列", zh))


def is_assignment(text: str) -> bool:
    """True for text of the form ``#100=5`` (``#1 EQ 2`` and ``#1==2`` are not)."""
    return _ASSIGNMENT.match(text) is not None


def compile_expression(machine: Machine, text: str) -> CompiledText:
    """``text`` as a value (``#1+#2*2``, ``#[#100]``, ``SIN[30]``)."""
    block = _block(text.strip(), "#1=", "")
    if len(block.statements) != 1 or block.words or block.corners or not isinstance(block.statements[0], Assign):
        raise EvaluationError(detail(f"'{text.strip()}' is not an expression", f"'{text.strip()}' 不是表达式"))
    compiler = ExpressionCompiler(machine.kinds)
    value = compiler.value(block.statements[0].value)
    _refused(machine, compiler)
    return CompiledText(text, value=value)


def compile_condition(machine: Machine, text: str) -> CompiledText:
    """``text`` as a condition (``#1 GT 5``, ``[#1 EQ #0] OR [#2 LT 0]``)."""
    stripped = text.strip()
    try:
        block = _block(stripped, "IF[", "]GOTO1")
    except EvaluationError:
        if not (stripped.startswith("[") and stripped.endswith("]")):
            raise
        block = _block(stripped, "IF", "GOTO1")
    statement = block.statements[0] if len(block.statements) == 1 else None
    if not isinstance(statement, If) or block.words or block.corners:
        raise EvaluationError(detail(f"'{stripped}' is not a condition", f"'{stripped}' 不是条件"))
    compiler = ExpressionCompiler(machine.kinds)
    test = compiler.condition(statement.condition)
    _refused(machine, compiler)
    return CompiledText(text, test=test)


def _refused(machine: Machine, compiler: ExpressionCompiler) -> None:
    """Raise, as running it would, the alarm the compiled text alone decides (``'=='`` where
    the control reads only EQ, ``#9999``): text kept to run later is refused when it is given."""
    alarm = compiler.refusal
    if alarm is not None:
        said = machine.dialect.alarm_said(alarm.number)
        raise EvaluationError(detail(f"{said}: {alarm.message}", f"{said.zh}：{in_language(alarm.message, True)}"))


@contextmanager
def in_level(machine: Machine, level: int | None) -> Iterator[None]:
    """Run with the locals of program level ``level`` (0 is the main program) in force."""
    saved = machine.L
    if level is not None and 0 <= level < len(machine.frames):
        machine.L = machine.frames[level].locals
    try:
        yield
    finally:
        machine.L = saved


def _guarded(machine: Machine, level: int | None, action: Callable[[], _T]) -> _T:
    with in_level(machine, level):
        try:
            return action()
        except MacroAlarm as e:
            said = machine.dialect.alarm_said(e.number)
            raise EvaluationError(
                detail(f"{said}: {e.message}", f"{said.zh}：{in_language(e.message, True)}")
            ) from None
        except StopRequest as e:
            raise EvaluationError(
                detail(
                    f"the text stops the run ({e.message}); it was not run",
                    f"这段文本会停止运行（{in_language(e.message, True)}），未执行",
                )
            ) from None


def value_of(machine: Machine, compiled: CompiledText, level: int | None = None) -> Value:
    """The value of a compiled expression at this moment."""
    assert compiled.value is not None
    getter = compiled.value
    return _guarded(machine, level, lambda: getter(machine))


def holds(machine: Machine, compiled: CompiledText, level: int | None = None) -> bool:
    """Whether a compiled condition holds at this moment."""
    assert compiled.test is not None
    test = compiled.test
    return bool(_guarded(machine, level, lambda: test(machine)))


def evaluate(machine: Machine, text: str, level: int | None = None) -> Value:
    """The value of the expression ``text`` in program level ``level`` (the innermost by default)."""
    return value_of(machine, compile_expression(machine, text), level)


def assign(machine: Machine, text: str, level: int | None = None) -> tuple[int, Value]:
    """Run the assignment ``text`` (``#100=5``, ``#[#1]=#2``) with every check a program
    line gets; returns the variable number written and its new value."""
    block = _block(text.strip(), "", "")
    statement = block.statements[0] if len(block.statements) == 1 else None
    if not isinstance(statement, Assign) or block.words or block.corners or block.label is not None:
        raise EvaluationError(
            detail(
                f"'{text.strip()}' is not an assignment such as #100=5",
                f"'{text.strip()}' 不是赋值语句（例如 #100=5）",
            )
        )
    compiler = ExpressionCompiler(machine.kinds)
    value = compiler.value(statement.value)
    target = statement.target
    index: Getter
    if isinstance(target, Var):
        number = float(target.number)
        index = lambda m: number  # noqa: E731
    elif isinstance(target, NamedVar):  # [#_NAME[n]]: the number the name stands for, as a program line takes it
        named = compiler.named(target, write=True)
        index = lambda m: float(named(m))  # noqa: E731
    else:
        index = compiler.value(target.index)

    def run() -> tuple[int, Value]:
        n = machine.variable_number(index(machine))
        v = value(machine)
        machine.write(float(n), v, statement.message)
        return n, machine.read(float(n)) if machine.kinds.kind(n) != "none" else v

    return _guarded(machine, level, run)


def set_variable(machine: Machine, number: int, text: str, level: int | None = None) -> Value:
    """Set ``#number`` to the value of the expression ``text`` (empty or ``#0`` for vacant)."""
    value = evaluate(machine, text, level) if text.strip() else None

    def run() -> Value:
        machine.write(float(number), value)
        return machine.read(float(number))

    return _guarded(machine, level, run)
