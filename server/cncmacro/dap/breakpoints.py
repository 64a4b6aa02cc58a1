"""Where a run stops: line breakpoints (with conditions, hit counts and log messages),
function breakpoints on ``N100`` or ``O9100``, and data breakpoints on ``#`` variables.

A line breakpoint may be set in any program file, also one the run has not loaded yet. It is
verified at the line where the run will really stop: one on a blank or comment line, or on
an O header that holds nothing else, moves to the next block. Conditions and log-message
expressions are macro text, compiled by the interpreter (``machine.evaluate``) once per
machine. ``check`` is asked before each block: it counts hits, writes log messages and says
whether to stop and why.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ..library.files import BinaryFileError, read_program
from ..library.programs import load_text
from ..machine import Machine, MacroAlarm
from ..machine.evaluate import CompiledText, EvaluationError, compile_condition, compile_expression, holds, value_of
from ..syntax.nodes import Block

_HIT = re.compile(r"^\s*(==|>=|<=|>|<|%)?\s*(\d+)\s*$")
_FUNCTION = re.compile(r"^\s*([NnOo])\s*(\d{1,8})\s*$")
_LOG_PART = re.compile(r"\{([^{}]*)\}")


def real_path(path: str) -> str:
    return os.path.normcase(os.path.realpath(path))


def stop_line(blocks: list[Block], line: int) -> int | None:
    """The first line at or after ``line`` (0-based) where a run can stop."""
    for k in range(max(0, line), len(blocks)):
        b = blocks[k]
        if b.is_empty or b.tape:
            continue
        if b.plain is None and b.program is not None and not (b.words or b.statements or b.label is not None):
            continue  # an O header alone: a run starts after it
        return k
    return None


def hit_test(text: str | None) -> Callable[[int], bool] | None:
    """The hit-count condition ``5``, ``>=5``, ``>5``, ``<5``, ``==5`` or ``%5``; ``ValueError``
    for anything else."""
    if text is None or not text.strip():
        return None
    m = _HIT.match(text)
    if m is None:
        raise ValueError(f"hit count '{text}': write a number, or >=N, >N, <N, ==N or %N")
    op, n = m.group(1) or "==", int(m.group(2))
    if op == "%":
        if n == 0:
            raise ValueError("hit count %0: the divisor must be at least 1")
        return lambda hits: hits % n == 0
    return {
        "==": lambda hits: hits == n, ">=": lambda hits: hits >= n, ">": lambda hits: hits > n,
        "<=": lambda hits: hits <= n, "<": lambda hits: hits < n,
    }[op]  # fmt: skip


@dataclass(slots=True)
class Hit:
    """Why the run stops: the DAP reason, the breakpoint ids, and a text to show."""

    reason: str
    ids: list[int]
    description: str | None = None


@dataclass(slots=True)
class Breakpoint:
    """What every kind shares: an id, a condition, a hit count, a log message."""

    id: int
    condition: str | None = None
    hit_condition: str | None = None
    log_message: str | None = None
    hits: int = 0
    message: str | None = None  # why it is not verified
    verified: bool = True
    compiled: CompiledText | None = None
    hit_ok: Callable[[int], bool] | None = None

    def prepare(self) -> None:
        try:
            self.hit_ok = hit_test(self.hit_condition)
        except ValueError as e:
            self.verified, self.message = False, str(e)

    def json(self, **more: Any) -> dict[str, Any]:
        out: dict[str, Any] = {"id": self.id, "verified": self.verified, **more}
        if self.message:
            out["message"] = self.message
        return out


@dataclass(slots=True)
class LineBreakpoint(Breakpoint):
    path: str = ""
    line: int | None = None  # 0-based, where it really stops


@dataclass(slots=True)
class FunctionBreakpoint(Breakpoint):
    letter: str = "N"
    number: int = 0


@dataclass(slots=True)
class DataBreakpoint(Breakpoint):
    number: int = 0
    last: float | None = None
    known: bool = False


@dataclass(slots=True)
class Breakpoints:
    """Every breakpoint of a session, and the decision to stop."""

    lines: dict[str, list[LineBreakpoint]] = field(default_factory=dict)
    functions: list[FunctionBreakpoint] = field(default_factory=list)
    data: list[DataBreakpoint] = field(default_factory=list)
    at: dict[tuple[str, int], list[LineBreakpoint]] = field(default_factory=dict)
    paths: dict[str, str] = field(default_factory=dict)
    next_id: int = 1
    machine: Machine | None = None
    log: Callable[[str], None] = field(default=lambda _text: None)

    @property
    def empty(self) -> bool:
        return not self.at and not self.functions and not self.data

    def _id(self) -> int:
        self.next_id += 1
        return self.next_id - 1

    # ---------------------------------------------------------------- setting
    def set_lines(self, path: str, specs: list[dict[str, Any]]) -> list[LineBreakpoint]:
        """Replace the breakpoints of one file (``specs`` are DAP SourceBreakpoints, 1-based)."""
        key = real_path(path)
        blocks: list[Block] | None = None
        problem = None
        try:
            blocks = load_text(path, read_program(path).text).program.blocks
        except (OSError, BinaryFileError) as e:
            problem = f"cannot read {path}: {e}"
        made = []
        for spec in specs:
            bp = LineBreakpoint(self._id(), spec.get("condition"), spec.get("hitCondition"), spec.get("logMessage"),
                                path=key)  # fmt: skip
            line = spec.get("line")
            if not isinstance(line, int):
                bp.verified, bp.message = False, "a breakpoint needs a line number"
            elif blocks is None:
                bp.verified, bp.message = False, problem
            else:
                bp.line = stop_line(blocks, line - 1)
                if bp.line is None:
                    bp.verified, bp.message = False, "no block to stop at on or after this line"
            bp.prepare()
            self._compile(bp)
            made.append(bp)
        self.lines[key] = made
        self._index()
        return made

    def set_functions(self, specs: list[dict[str, Any]]) -> list[FunctionBreakpoint]:
        made = []
        for spec in specs:
            name = str(spec.get("name", ""))
            bp = FunctionBreakpoint(self._id(), spec.get("condition"), spec.get("hitCondition"))
            m = _FUNCTION.match(name)
            if m is None:
                bp.verified, bp.message = False, f"'{name}': name a sequence number (N100) or a program (O9100)"
            else:
                bp.letter, bp.number = m.group(1).upper(), int(m.group(2))
            bp.prepare()
            self._compile(bp)
            made.append(bp)
        self.functions = [b for b in made if b.verified]
        return made

    def set_data(self, specs: list[dict[str, Any]]) -> list[DataBreakpoint]:
        made = []
        for spec in specs:
            data_id = str(spec.get("dataId", ""))
            bp = DataBreakpoint(self._id(), spec.get("condition"), spec.get("hitCondition"))
            number = data_number(data_id)
            if number is None:
                bp.verified, bp.message = False, f"'{data_id}' is not a variable such as #100"
            else:
                bp.number = number
            bp.prepare()
            self._compile(bp)
            made.append(bp)
        self.data = [b for b in made if b.verified]
        self.prime()
        return made

    def _index(self) -> None:
        self.at = {}
        for bps in self.lines.values():
            for bp in bps:
                if bp.verified and bp.line is not None:
                    self.at.setdefault((bp.path, bp.line), []).append(bp)

    # ---------------------------------------------------------------- a machine to stop
    def bind(self, machine: Machine) -> None:
        """Use these breakpoints with ``machine`` (a new launch or a restart)."""
        self.machine = machine
        for bp in self._all():
            bp.hits = 0
            self._compile(bp)
        self._index()
        self.prime()

    def _all(self) -> list[Breakpoint]:
        return [*(b for bps in self.lines.values() for b in bps), *self.functions, *self.data]

    def _compile(self, bp: Breakpoint) -> None:
        bp.compiled = None
        if self.machine is None or not bp.condition or not bp.condition.strip():
            return
        try:
            bp.compiled = compile_condition(self.machine, bp.condition)
        except EvaluationError as e:
            bp.verified, bp.message = False, f"condition '{bp.condition}': {e}"

    def prime(self) -> None:
        """Remember the values data breakpoints compare against (before a run goes on)."""
        m = self.machine
        if m is None:
            return
        for bp in self.data:
            bp.last, bp.known = _read(m, bp.number)

    # ---------------------------------------------------------------- deciding
    def _passes(self, bp: Breakpoint, m: Machine) -> tuple[bool, str | None]:
        """Whether the condition holds and the hit count is reached (counting this hit)."""
        if bp.compiled is not None:
            try:
                if not holds(m, bp.compiled):
                    return False, None
            except EvaluationError as e:
                return True, f"the condition '{bp.condition}' could not be evaluated: {e}"
        bp.hits += 1
        if bp.hit_ok is not None and not bp.hit_ok(bp.hits):
            return False, None
        return True, None

    def check(self, m: Machine, entered: bool) -> Hit | None:
        """Before the block at the machine's pc runs: stop here? ``entered`` is True right
        after a call opened a new program level."""
        frame = m.frames[-1]
        pc = frame.pc
        raw = frame.file
        key = self.paths.get(raw)
        if key is None:
            key = self.paths[raw] = real_path(raw)
        for bp in self.at.get((key, pc), ()):
            ok, problem = self._passes(bp, m)
            if not ok:
                continue
            if bp.log_message is not None and problem is None:
                self.log(interpolate(m, bp.log_message))
                continue
            return Hit("breakpoint", [bp.id], problem)
        if self.functions:
            blocks = frame.found.file.program.blocks
            label = blocks[pc].label if pc < len(blocks) else None
            for fb in self.functions:
                if (fb.letter == "N" and label == fb.number) or (
                    fb.letter == "O" and entered and frame.found.unit.number == fb.number
                ):
                    ok, problem = self._passes(fb, m)
                    if ok:
                        return Hit("function breakpoint", [fb.id], problem)
        for db in self.data:
            value, known = _read(m, db.number)
            if known and (not db.known or value != db.last):
                before = db.last
                db.last, db.known = value, known
                ok, problem = self._passes(db, m)
                if ok:
                    shown = "vacant" if before is None else f"{before:g}"
                    now = "vacant" if value is None else f"{value:g}"
                    return Hit("data breakpoint", [db.id], problem or f"#{db.number} changed: {shown} -> {now}")
        return None

    def stops_here(self, m: Machine) -> bool:
        """For reverse continue: a line or N breakpoint whose condition holds at this block
        (hit counts and log messages are for forward runs only)."""
        frame = m.frames[-1]
        key = self.paths.get(frame.file) or real_path(frame.file)
        for bp in self.at.get((key, frame.pc), ()):
            if bp.log_message is not None:
                continue
            try:
                if bp.compiled is None or holds(m, bp.compiled):
                    return True
            except EvaluationError:
                return True
        blocks = frame.found.file.program.blocks
        label = blocks[frame.pc].label if frame.pc < len(blocks) else None
        return any(fb.letter == "N" and fb.number == label for fb in self.functions)


def data_number(text: str) -> int | None:
    m = re.match(r"^\s*#\s*(\d{1,5})\b", text)
    return int(m.group(1)) if m else None


def _read(m: Machine, n: int) -> tuple[float | None, bool]:
    try:
        return m.read(float(n)), True
    except MacroAlarm:
        return None, False


def interpolate(m: Machine, message: str) -> str:
    """A log message with each ``{expression}`` replaced by its value."""

    def one(match: re.Match[str]) -> str:
        try:
            v = value_of(m, compile_expression(m, match.group(1)))
        except EvaluationError as e:
            return f"<{e}>"
        return "<vacant>" if v is None else f"{v:g}"

    return _LOG_PART.sub(one, message)
