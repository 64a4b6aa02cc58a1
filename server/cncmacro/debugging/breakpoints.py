"""Where a run stops: line breakpoints (with conditions, hit counts and log messages),
function breakpoints on ``N100``, ``O9100`` or a code (``M06``, ``T``, ``G81``: see
``code_breakpoints``), and data breakpoints on ``#`` variables.

A line breakpoint may be set in any program file of the launch's folders (``scope``, as
``library.files.ReadScope`` decides), also one the run has not loaded yet; before the launch,
the file's own folder stands in for them, and at the launch every file is read and placed
again, so one outside the launch's folders is then unverified, saying why. A file that cannot
be read (a pipe, a device, a link leading out) is never waited on: its breakpoints are
unverified with the reason. A breakpoint is verified at the line where the run will really
stop (``machine.block_roles.stop_line``, the interpreter's own rule): one on a blank or comment
line, a ``%`` mark, or an O header that holds nothing else moves to the next block, and one on
an O line that also holds a sequence number (``O100 N5``) stays there, where a run starts and a
``GOTO 5`` lands; one on a ``/`` block while the machine's block delete switch is on is not
verified (the run skips that block). Conditions and log-message expressions are macro text, compiled
by the interpreter (``machine.evaluate``) once per machine. ``check`` is asked before each
block: it counts hits, writes log messages and says whether to stop and why. A breakpoint is
asked for as an ``Asked`` (where, and its conditions); the front end turns its protocol's
requests into these and the breakpoints it gets back into its protocol's answers.

A hit is a visit at which the condition holds: the run arriving at the breakpoint's block
(a line or ``N`` breakpoint), entering the program (``O``), or a block changing the variable
(a data breakpoint, met right after that block). Every visit is counted, also those a step
arrives at, from the moment the breakpoint was set (``since``; at a launch, from the first
block). For going backwards, ``look`` tells which breakpoints an earlier point of the run
visits, ``stop_back`` whether the forward run stopped (or would have stopped) there, and
``rewind`` sets the counts back: the hit number of a visit is the count the forward run had
just after it, that is the count now less the visits after it.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from dataclasses import dataclass, field

from ..bilingual import in_language, is_chinese, pick
from ..library.files import ReadScope, SkippedFileError
from ..library.programs import load_text
from ..machine import Machine, MacroAlarm
from ..machine.block_roles import stop_line
from ..machine.evaluate import CompiledText, EvaluationError, compile_condition, compile_expression, holds, value_of
from ..planner.numbers import format_plain, shown_value
from ..syntax.program import Program
from .code_breakpoints import CodeName, codes_of, looks_like_code, matches, read_code_name

_HIT = re.compile(r"^\s*(==|>=|<=|>|<|%)?\s*(\d+)\s*$")
_FUNCTION = re.compile(r"^\s*([NnOo])\s*(\d{1,8})\s*$")
_LOG_PART = re.compile(r"\{([^{}]*)\}")
_DATA_LEVEL = re.compile(r"@\s*(\d{1,3})\s*$")
LOCALS = 33  # #1–#33: each macro level has its own


def real_path(path: str) -> str:
    return os.path.normcase(os.path.realpath(path))


def place(program: Program, line: int, block_delete: bool, locale: str | None) -> tuple[int | None, str | None]:
    """Where a breakpoint asked for on ``line`` (0-based) stops, or why it never can."""
    blocks = program.blocks
    if block_delete and 0 <= line < program.read_end and blocks[line].block_delete is not None:
        return None, pick(locale, "this block is skipped: block delete is on", "此程序段会被跳过：跳段开关已打开")
    k = stop_line(program, line, block_delete)
    if k is None:
        return None, pick(locale, "no block to stop at on or after this line", "此行及其后没有可停止的程序段")
    return k, None


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


@dataclass(frozen=True, slots=True)
class Asked:
    """A breakpoint as a person asked for it: ``place`` is the 0-based line of a line breakpoint
    (None when none was given), the ``N100`` or ``O9100`` of a function breakpoint, or the
    ``#100`` of a data breakpoint; only a line breakpoint writes a log message."""

    place: int | str | None = None
    condition: str | None = None
    hit_condition: str | None = None
    log_message: str | None = None


@dataclass(slots=True)
class Hit:
    """Why the run stops: ``breakpoint``, ``function breakpoint`` or ``data breakpoint``, the
    breakpoint ids, and a text to show."""

    reason: str
    ids: list[int]
    description: str | None = None


@dataclass(slots=True)
class Visit:
    """The breakpoints one earlier point of the run visits (for going backwards): each with
    None when its condition held (a hit), or the reason it could not be evaluated."""

    block: int
    met: list[tuple[Breakpoint, str | None]]
    changes: dict[int, str] = field(default_factory=dict)  # data breakpoint id -> what changed


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
    since: int = -1  # hits count the visits after this block count

    reason = "breakpoint"

    def prepare(self) -> None:
        try:
            self.hit_ok = hit_test(self.hit_condition)
        except ValueError as e:
            self.verified, self.message = False, str(e)

    def same(self, other: Breakpoint) -> bool:
        """The same breakpoint asked for again (its count goes on)."""
        return (self.condition, self.hit_condition, self.log_message) == (
            other.condition, other.hit_condition, other.log_message)  # fmt: skip


@dataclass(slots=True)
class LineBreakpoint(Breakpoint):
    path: str = ""
    line: int | None = None  # 0-based, where it really stops
    asked: int | None = None  # 0-based, where it was set
    shown_path: str = ""  # the path as the client gave it
    placement: str | None = None  # why it cannot stop where it was set

    def same(self, other: Breakpoint) -> bool:
        return isinstance(other, LineBreakpoint) and other.asked == self.asked and Breakpoint.same(self, other)


@dataclass(slots=True)
class FunctionBreakpoint(Breakpoint):
    letter: str = "N"
    number: int = 0
    name: str = ""  # as asked for
    code: CodeName | None = None  # a G, M or T code to stop before

    reason = "function breakpoint"

    def same(self, other: Breakpoint) -> bool:
        return isinstance(other, FunctionBreakpoint) and (other.letter, other.number, other.code) == (
            self.letter, self.number, self.code) and Breakpoint.same(self, other)  # fmt: skip

    def meets(
        self, m: Machine, block_label: int | None, arrival: bool, opened: bool, codes: list[tuple[str, float]]
    ) -> bool:
        """Whether the run visits this breakpoint: arriving at its ``N`` block or at a block with
        its code, or entering its ``O`` program."""
        if self.code is not None:
            return arrival and matches(self.code, codes)
        if self.letter == "N":
            return arrival and block_label == self.number
        return opened and m.frames[-1].found.unit.number == self.number


@dataclass(slots=True)
class DataBreakpoint(Breakpoint):
    number: int = 0
    level: int | None = None  # a local's (#1–#33) macro level: 0 the main program's
    last: float | None = None
    known: bool = False

    reason = "data breakpoint"

    def same(self, other: Breakpoint) -> bool:
        return (
            isinstance(other, DataBreakpoint)
            and (other.number, other.level) == (self.number, self.level)
            and Breakpoint.same(self, other)
        )


@dataclass(slots=True)
class Breakpoints:
    """Every breakpoint of a session, and the decision to stop."""

    lines: dict[str, list[LineBreakpoint]] = field(default_factory=dict)
    functions: list[FunctionBreakpoint] = field(default_factory=list)  # the verified ones
    asked_functions: list[FunctionBreakpoint] = field(default_factory=list)
    renamed: list[FunctionBreakpoint] = field(default_factory=list)  # verified otherwise by the last bind
    data: list[DataBreakpoint] = field(default_factory=list)
    at: dict[tuple[str, int], list[LineBreakpoint]] = field(default_factory=dict)
    paths: dict[str, str] = field(default_factory=dict)
    next_id: int = 1
    machine: Machine | None = None
    log: Callable[[str], None] = field(default=lambda _text: None)
    locale: str | None = None
    block_delete: bool = False  # the switch the line breakpoints were placed for
    scope: ReadScope | None = None  # the launch's folders (None before a launch)
    counted_to: int = -1  # the visits up to this block count are counted

    @property
    def empty(self) -> bool:
        return not self.at and not self.functions and not self.data

    def _id(self) -> int:
        self.next_id += 1
        return self.next_id - 1

    def _carry(self, bp: Breakpoint, old: list[Breakpoint]) -> None:
        """A new breakpoint counts from now, one asked for again goes on counting."""
        bp.since = self.counted_to
        for was in old:
            if bp.same(was):
                bp.hits, bp.since = was.hits, was.since
                return

    # ---------------------------------------------------------------- setting
    def set_lines(self, path: str, specs: list[Asked]) -> list[LineBreakpoint]:
        """Replace the breakpoints of one file (each ``place`` a 0-based line)."""
        key = real_path(path)
        program = self._read(path)
        old: list[Breakpoint] = list(self.lines.get(key, ()))
        made = []
        for spec in specs:
            bp = LineBreakpoint(self._id(), spec.condition, spec.hit_condition, spec.log_message,
                                path=key, shown_path=path)  # fmt: skip
            if isinstance(spec.place, int):
                bp.asked = spec.place
            self._place(bp, program)
            self._carry(bp, old)
            made.append(bp)
        self.lines[key] = made
        self._index()
        return made

    def read_scope(self, path: str) -> ReadScope:
        """Where ``path`` may be read from: the launch's folders, or before a launch its own folder."""
        return self.scope if self.scope is not None else ReadScope.of([os.path.dirname(path) or "."])

    def _read(self, path: str) -> Program | str:
        """The program in the file at ``path``, or why it cannot be read."""
        try:
            return load_text(path, self.read_scope(path).read(path).text).program
        except SkippedFileError as e:
            return in_language(e.message, is_chinese(self.locale))  # the path, and why it is not read
        except OSError as e:
            why = e.strerror or str(e)
            return pick(self.locale, f"cannot read {path}: {why}", f"无法读取 {path}：{why}")

    def _place(self, bp: LineBreakpoint, program: Program | str) -> None:
        """Place ``bp`` in its file's ``program`` (or say why not) and check its conditions."""
        bp.line = bp.placement = None
        if bp.asked is None:
            bp.verified, bp.message = False, "a breakpoint needs a line number"
        elif isinstance(program, str):
            bp.verified, bp.message = False, program
        else:
            bp.line, bp.placement = place(program, bp.asked, self.block_delete, self.locale)
            bp.message, bp.verified = bp.placement, bp.line is not None
        bp.prepare()
        self._compile(bp)

    def set_functions(self, specs: list[Asked]) -> list[FunctionBreakpoint]:
        """Replace the function breakpoints (each ``place`` a name such as ``N100`` or ``O9100``)."""
        made = []
        old: list[Breakpoint] = list(self.functions)
        for spec in specs:
            name = str(spec.place)
            bp = FunctionBreakpoint(self._id(), spec.condition, spec.hit_condition, name=name)
            self._name(bp)
            bp.prepare()
            self._compile(bp)
            self._carry(bp, old)
            made.append(bp)
        self.asked_functions = made
        self.functions = [b for b in made if b.verified]
        return made

    def _name(self, bp: FunctionBreakpoint) -> None:
        """Read the breakpoint's name: ``N100``, ``O9100`` or a code (checked against the
        machine's dialect once there is one)."""
        name = bp.name
        bp.code, bp.verified, bp.message = None, True, None
        m = _FUNCTION.match(name)
        if m is not None:
            bp.letter, bp.number = m.group(1).upper(), int(m.group(2))
            return
        if looks_like_code(name):
            code = read_code_name(name, self.machine)
            if isinstance(code, CodeName):
                bp.code = code
                return
            bp.verified, bp.message = False, in_language(code, is_chinese(self.locale))
            return
        bp.verified = False
        bp.message = pick(
            self.locale,
            f"'{name}': name a sequence number (N100), a program (O9100) or a G, M or T code (M06, T, M00, G81)",
            f"'{name}'：请写顺序号（N100）、程序号（O9100）或 G、M、T 代码（M06、T、M00、G81）",
        )

    def set_data(self, specs: list[Asked]) -> list[DataBreakpoint]:
        """Replace the data breakpoints (each ``place`` a variable such as ``#100``)."""
        made = []
        old: list[Breakpoint] = list(self.data)
        for spec in specs:
            data_id = str(spec.place)
            bp = DataBreakpoint(self._id(), spec.condition, spec.hit_condition)
            number = data_number(data_id)
            if number is None:
                bp.verified, bp.message = False, f"'{data_id}' is not a variable such as #100"
            else:
                bp.number, bp.level = number, data_level(data_id)
            bp.prepare()
            self._compile(bp)
            self._carry(bp, old)
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
    def bind(self, machine: Machine, scope: ReadScope | None = None) -> list[LineBreakpoint]:
        """Use these breakpoints with ``machine`` (a new launch or a restart) and the launch's
        folders ``scope`` (when given); the line breakpoints that this changed (placed again
        for the machine's block delete switch, or unverified in a file outside the folders)."""
        self.machine = machine
        self.counted_to = -1
        self.block_delete = bool(machine.settings.block_delete)
        if scope is not None:
            self.scope = scope
        before = {bp.id: (bp.verified, bp.line, bp.message) for bps in self.lines.values() for bp in bps}
        for bps in self.lines.values():
            if bps:
                program = self._read(bps[0].shown_path)
                for bp in bps:
                    self._place(bp, program)
        named = {fb.id: (fb.verified, fb.message) for fb in self.asked_functions}
        for fb in self.asked_functions:  # a code is checked against this launch's dialect
            self._name(fb)
            fb.prepare()
        self.renamed = [fb for fb in self.asked_functions if (fb.verified, fb.message) != named[fb.id]]
        self.functions = [b for b in self.asked_functions if b.verified]
        for b in self._all():
            b.hits, b.since = 0, -1
            if not isinstance(b, LineBreakpoint):  # placed (and compiled) above
                self._compile(b)
        self._index()
        self.prime()
        return [bp for bps in self.lines.values() for bp in bps if (bp.verified, bp.line, bp.message) != before[bp.id]]

    def _all(self) -> list[Breakpoint]:
        return [*(b for bps in self.lines.values() for b in bps), *self.functions, *self.data]

    def _compile(self, bp: Breakpoint) -> None:
        bp.compiled = None
        if self.machine is None or not bp.condition or not bp.condition.strip():
            return
        try:
            bp.compiled = compile_condition(self.machine, bp.condition)
        except EvaluationError as e:
            bp.verified, bp.message = (
                False,
                pick(
                    self.locale,
                    f"condition '{bp.condition}': {e}",
                    f"条件 '{bp.condition}'：{in_language(e.args[0], True)}",
                ),
            )

    def _unevaluated(self, bp: Breakpoint, e: EvaluationError) -> str:
        """Why a breakpoint stopped although its condition could not be evaluated."""
        return pick(
            self.locale,
            f"the condition '{bp.condition}' could not be evaluated: {e}",
            f"条件 '{bp.condition}' 无法求值：{in_language(e.args[0], True)}",
        )

    def prime(self) -> None:
        """Remember the values data breakpoints compare against (before a run goes on)."""
        m = self.machine
        if m is None:
            return
        for bp in self.data:
            bp.last, bp.known = _watched(m, bp)
            bp.known = bp.known or bp.level is not None  # a level not running yet: its locals start vacant

    # ---------------------------------------------------------------- deciding
    def _passes(self, bp: Breakpoint, m: Machine) -> tuple[bool, str | None]:
        """Whether the condition holds and the hit count is reached (counting this hit)."""
        if bp.compiled is not None:
            try:
                if not holds(m, bp.compiled):
                    return False, None
            except EvaluationError as e:
                return True, self._unevaluated(bp, e)
        bp.hits += 1
        if bp.hit_ok is not None and not bp.hit_ok(bp.hits):
            return False, None
        return True, None

    def _key(self, raw: str) -> str:
        key = self.paths.get(raw)
        if key is None:
            key = self.paths[raw] = real_path(raw)
        return key

    def check(self, m: Machine, entered: bool) -> Hit | None:
        """Before the block at the machine's pc runs: stop here? ``entered`` is True right
        after a call opened a new program level. Every visit is counted, whatever the answer."""
        self.counted_to = m.blocks
        frame = m.frames[-1]
        pc = frame.pc
        stop: Hit | None = None
        for bp in self.at.get((self._key(frame.file), pc), ()):
            ok, problem = self._passes(bp, m)
            if not ok:
                continue
            if bp.log_message is not None and problem is None:
                self.log(interpolate(m, bp.log_message, self.locale))
                continue
            stop = stop or Hit("breakpoint", [bp.id], problem)
        if self.functions:
            label, codes = self._block_facts(m)
            for fb in self.functions:
                if fb.meets(m, label, True, entered, codes):
                    ok, problem = self._passes(fb, m)
                    if ok:
                        stop = stop or Hit("function breakpoint", [fb.id], problem)
        for db in self.data:
            changed = _watch(m, db)
            if changed is not None:
                ok, problem = self._passes(db, m)
                if ok:
                    stop = stop or Hit("data breakpoint", [db.id], problem or _change(db.number, *changed))
        return stop

    def _block_facts(self, m: Machine) -> tuple[int | None, list[tuple[str, float]]]:
        """The sequence number of the block at the machine's pc, and its codes when a code
        breakpoint asks for them."""
        frame = m.frames[-1]
        blocks = frame.found.file.program.blocks
        block = blocks[frame.pc] if frame.pc < len(blocks) else None
        if block is None:
            return None, []
        codes = codes_of(m, block) if any(fb.code is not None for fb in self.functions) else []
        return block.label, codes

    # ---------------------------------------------------------------- going backwards
    def look(self, m: Machine, first: bool, arrival: bool, change: bool, entered: bool) -> Visit | None:
        """Which breakpoints this earlier point of the run visits, without counting. The
        history replays a stretch of the past block by block: ``first`` at its start (data
        breakpoints take their values from there), ``arrival`` where the run arrives at the
        block (line, ``N``), ``change`` where the block before it belongs to the stretch
        (data, ``O``: ``entered`` when that block opened a program level)."""
        if first:
            self.prime()
        if m.finished:
            return None
        met: list[tuple[Breakpoint, str | None]] = []
        changes: dict[int, str] = {}
        frame = m.frames[-1]
        pc = frame.pc
        if arrival:
            for bp in self.at.get((self._key(frame.file), pc), ()):
                self._meet(bp, m, met)
        if self.functions:
            label, codes = self._block_facts(m)
            opened = entered and (change or (arrival and m.blocks == 0))
            for fb in self.functions:
                if fb.meets(m, label, arrival, opened, codes):
                    self._meet(fb, m, met)
        if change:
            for db in self.data:
                changed = _watch(m, db)
                if changed is not None:
                    changes[db.id] = _change(db.number, *changed)
                    self._meet(db, m, met)
        return Visit(m.blocks, met, changes) if met else None

    def _meet(self, bp: Breakpoint, m: Machine, met: list[tuple[Breakpoint, str | None]]) -> None:
        if bp.compiled is None:
            met.append((bp, None))
            return
        try:
            if holds(m, bp.compiled):
                met.append((bp, None))
        except EvaluationError as e:
            met.append((bp, self._unevaluated(bp, e)))

    def stop_back(self, visit: Visit, after: dict[int, int]) -> Hit | None:
        """Whether the forward run stopped (or would have stopped) at this earlier visit;
        ``after`` counts each breakpoint's hits between it and now. A visit from before a
        breakpoint with a hit count was set has no number, so it is no stop for it."""
        for bp, problem in visit.met:
            if problem is not None:
                return Hit(bp.reason, [bp.id], problem)
            if bp.log_message is not None:
                continue
            if bp.hit_ok is None or (visit.block > bp.since and bp.hit_ok(bp.hits - after.get(bp.id, 0))):
                return Hit(bp.reason, [bp.id], visit.changes.get(bp.id))
        return None

    def count(self, visit: Visit, after: dict[int, int]) -> None:
        """Add this visit's hits to ``after`` (walking backwards)."""
        for bp, problem in visit.met:
            if problem is None and visit.block > bp.since:
                after[bp.id] = after.get(bp.id, 0) + 1

    def rewind(self, block: int, after: dict[int, int]) -> None:
        """The run went back to ``block``: take away the hits it had after it."""
        for bp in self._all():
            bp.hits = max(0, bp.hits - after.get(bp.id, 0))
            bp.since = min(bp.since, block)
        self.counted_to = block


def _change(number: int, before: float | None, now: float | None) -> str:
    shown = "vacant" if before is None else format_plain(before)
    after = "vacant" if now is None else format_plain(now)
    return f"#{number} changed: {shown} -> {after}"


def data_number(text: str) -> int | None:
    m = re.match(r"^\s*#\s*(\d{1,5})\b", text)
    return int(m.group(1)) if m else None


def data_level(data_id: str) -> int | None:
    """The macro level whose local a data breakpoint watches: ``#1@2`` watches #1 of level 2,
    a local without a level (``#1``) the main program's; None for any other variable (it is
    one for the whole run)."""
    number = data_number(data_id)
    if number is None or not 1 <= number <= LOCALS:
        return None
    m = _DATA_LEVEL.search(data_id)
    return int(m.group(1)) if m else 0


def data_id(number: int, level: int | None) -> str:
    """The data breakpoint id of ``#number`` (of macro ``level`` for a local)."""
    return f"#{number}@{level}" if level is not None and 1 <= number <= LOCALS else f"#{number}"


def _watch(m: Machine, bp: DataBreakpoint) -> tuple[float | None, float | None] | None:
    """The watched value's change since it was last seen (before, now), None when it did not
    change; what is seen is kept. While the watched local's level is not running nothing is
    seen, and the next call of that level starts with vacant locals."""
    value, known = _watched(m, bp)
    if not known:
        if bp.level is not None:
            bp.last, bp.known = None, True
        return None
    if bp.known and value == bp.last:
        return None
    before = bp.last
    bp.last, bp.known = value, True
    return before, value


def _watched(m: Machine, bp: DataBreakpoint) -> tuple[float | None, bool]:
    """The value a data breakpoint watches, and whether there is one: a local of a macro
    level that is not running now (not called yet, or returned) has none, so a call or a
    return that only switches levels is no change."""
    if bp.level is None:
        return _read(m, bp.number)
    for f in m.frames:
        if f.macro_level == bp.level:
            return f.locals[bp.number], True
    return None, False


def _read(m: Machine, n: int) -> tuple[float | None, bool]:
    try:
        return m.read(float(n)), True
    except MacroAlarm:
        return None, False


def interpolate(m: Machine, message: str, locale: str | None = None) -> str:
    """A log message with each ``{expression}`` replaced by its value, shown as the Variables
    view shows it (``shown_value``: ``21.650635``, not ``21.6506``; ``0`` for 3.06e-15)."""

    def one(match: re.Match[str]) -> str:
        try:
            v = value_of(m, compile_expression(m, match.group(1)))
        except EvaluationError as e:
            return f"<{e}>"
        return shown_value(v, locale)

    return _LOG_PART.sub(one, message)
