"""Blocks compiled once into closures that run them (docs/semantics.md §1, §4, §5).

``CompiledFile`` holds, for one program file, a list with one slot per line: the closure that
runs the line, made the first time the line runs. A closure takes the machine and its own
line number and returns the line to run next, or -1 when it changed the frame (a call, a
return, the end). Each closure already knows the next non-empty line, the loop its END
closes, and its literal word values rounded for their address, so running a block does no
lookups in the syntax tree. Jumps are resolved once per (line, label) and cached.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ..bilingual import detail, in_language
from ..dialects.alarms import (
    FORMAT,
    LOOP_NUMBER,
    MAX_VALUE,
    MISSING_END,
    SEQUENCE_NUMBER,
    STATEMENT_FORMAT,
    WRITE_PROTECTED,
)
from ..dialects.dialect import Dialect
from ..library.programs import LoadedFile
from ..planner.alarms import UnknownValue
from ..planner.numbers import format_value, in_least_increments, increment_places, round_half_away, to_increment
from ..syntax.nodes import (
    Assign,
    Block,
    Do,
    Else,
    End,
    EndIf,
    Goto,
    If,
    IndirectVar,
    NamedVar,
    Number,
    Output,
    Statement,
    Var,
    While,
    Word,
)
from ..syntax.program import ProgramUnit
from . import block_roles, jumps
from .alarms import MacroAlarm, raiser
from .binary_output import BPRNT, bprnt_record
from .block_rules import DIALECT_FORMS, first_alarm, validate_block
from .calls import h_code_form
from .corners import with_corners
from .expressions import ExpressionCompiler, Getter
from .guards import LOOP, Passed, alarm_only, alarm_then, unknown_loop_pass
from .variables import out_of_range

if TYPE_CHECKING:
    from .machine import Machine

Runner = Callable[["Machine", int], int]

INTEGER_LETTERS = frozenset("MSTHDNOPLB")
# distances whose letter may also be a whole number elsewhere (M98 Q n, a lathe cycle's P/Q labels):
# a G83 peck Q2.5 or a thread's E11.5 keeps its decimals, never read as increments
DECIMAL_LETTERS = frozenset("QE")
AXIS_LETTERS = frozenset("XYZABCUVWIJKR")
MAX_LOOP_DEPTH = 3


class CompiledFile:
    """The runnable form of one loaded file, for one machine."""

    def __init__(self, machine: Machine, file: LoadedFile) -> None:
        self.machine = machine
        self.file = file
        n = len(file.lines)
        self.code: list[Runner | None] = [None] * (n + 1)
        self.code[n] = _end_of_file
        self.do_end = {p.do_line: p.end_line for p in file.program.loops}
        self.end_do = {p.end_line: p.do_line for p in file.program.loops}
        self.if_blocks, self.branch_ends, self.crossing = _if_blocks(file.program)
        self._jumps: dict[tuple[int, int], tuple[int, int]] = {}
        self._spans: jumps.LoopSpans | None = None  # made at the first jump that is not cached
        self._shared: dict[tuple[str, float | None], nc_blocks.Compiled] = {}  # ``plain_words``
        self.values = ExpressionCompiler(machine.kinds, watch=machine.watching, unknowns=machine.kept_unknown)
        self.addresses = ExpressionCompiler(machine.kinds, in_address=True, watch=machine.watching,
                                            unknowns=machine.kept_unknown)  # fmt: skip

    def reset(self) -> None:
        """Forget every compiled line, loop pair and jump: the file's text changed in place
        (an edit in the editor), so each line is compiled again when it next runs."""
        n = len(self.file.lines)
        self.code = [None] * (n + 1)
        self.code[n] = _end_of_file
        self.do_end = {p.do_line: p.end_line for p in self.file.program.loops}
        self.end_do = {p.end_line: p.do_line for p in self.file.program.loops}
        self.if_blocks, self.branch_ends, self.crossing = _if_blocks(self.file.program)
        self._jumps.clear()
        self._spans = None
        self._shared.clear()

    # ---------------------------------------------------------------- lines
    def skipped(self, block: Block) -> bool:
        """True for a line that does nothing when run (``block_roles.skipped``)."""
        return block_roles.skipped(block, self.machine.settings.block_delete)

    def next_line(self, pc: int) -> int:
        """The next line after ``pc`` that does something (``block_roles.next_line``)."""
        return block_roles.next_line(self.file.program, pc, self.machine.settings.block_delete)

    def entry(self, unit: ProgramUnit) -> int:
        """The first line a program runs (``block_roles.entry``)."""
        return block_roles.entry(self.file.program, unit, self.machine.settings.block_delete)

    def runner(self, pc: int) -> Runner:
        c = self.code[pc]
        if c is None:
            c = self.code[pc] = self.compile(pc)
        return c

    # ---------------------------------------------------------------- jumps
    def jump(self, frame: Any, pc: int, label: float | None, how: str = "GOTO ") -> int:
        """The line a GOTO on line ``pc`` lands on, leaving loops it jumps out of
        (docs/semantics.md §4: forward to the end of the program, then from its start). ``how``
        is what the block writes before the label (``"M99 P"`` for Haas's conditional jump)."""
        if label is None:
            said = how.strip()
            raise MacroAlarm(SEQUENCE_NUMBER, detail(f"{said} to a vacant sequence number", f"{said} 的顺序号为空变量"))
        n = int(round_half_away(label))
        if not 1 <= n <= 99999:
            raise MacroAlarm(
                SEQUENCE_NUMBER,
                detail(f"{how}{n}: a sequence number must be 1 to 99999", f"{how}{n}：顺序号必须在 1～99999 之间"),
                "label-range",
            )
        key = (pc, n)
        hit = self._jumps.get(key)
        if hit is None:
            hit = self._jumps[key] = self._find_jump(frame, pc, n)
        target, keep = hit
        if keep == _INTO_IF:
            raise MacroAlarm(
                STATEMENT_FORMAT,
                detail(
                    f"{how}{n} jumps into a branch of an IF [...] THEN block from outside it",
                    f"{how}{n} 从外部转入 IF [...] THEN 块的分支内",
                ),
                "jump-into-if",
            )
        if keep < 0:
            raise MacroAlarm(
                LOOP_NUMBER,
                detail(
                    f"{how}{n} jumps into a WHILE/DO loop from outside it",
                    f"{how}{n} 从循环外转入 WHILE/DO 循环内",
                ),
                "jump-into-loop",
            )
        del frame.loops[keep:]
        return target

    def jump_target(self, frame: Any, pc: int, label: float | None) -> int | None:
        """The line ``GOTO label`` on line ``pc`` would land on, without jumping; None where the
        jump would alarm (no such label, a label out of range, a jump into a loop or a block IF)."""
        if label is None or label != label:
            return None
        n = int(round_half_away(label))
        if not 1 <= n <= 99999:
            return None
        hit = self._jumps.get((pc, n))
        if hit is None:
            try:
                hit = self._jumps[(pc, n)] = self._find_jump(frame, pc, n)
            except MacroAlarm:
                return None
        return hit[0] if hit[1] >= 0 else None

    def guard_jump(self, m: Machine, pc: int, nxt: int, label: Getter, passed: Passed) -> bool:
        """Whether an analysis run jumps at a branch on line ``pc`` whose condition is unknown
        (``guards.py``): not where the jump lands on the program's own alarm, yes where the block
        after the branch is that alarm; otherwise the path stops there (``UnknownValue``)."""
        try:
            at = self.jump_target(m.frames[-1], pc, label(m))
        except MacroAlarm:  # a label made from an unknown value
            at = None
        blocks, dialect = self.file.program.blocks, self.machine.dialect
        if at is not None and at != nxt:
            to_alarm = alarm_only(blocks[at], dialect)
            next_alarm = 0 <= nxt < len(blocks) and alarm_only(blocks[nxt], dialect)
            if to_alarm != next_alarm:
                passed.record(m, pc, at if to_alarm else nxt)
                return next_alarm
        raise UnknownValue

    def _find_jump(self, frame: Any, pc: int, n: int) -> tuple[int, int]:
        """(target line, loops kept) of ``GOTO n`` on line ``pc``, by the rules of ``jumps``;
        ``loops kept`` is -1 for a jump into a loop from outside."""
        target = jumps.goto_line(self.file.program.label_lines(n, frame.found.unit), pc)
        if target is None:
            raise MacroAlarm(
                SEQUENCE_NUMBER,
                detail(f"N{n} not found in {frame.found.label}", f"{frame.found.label} 中未找到 N{n}"),
            )
        spans = self._spans
        if spans is None:
            spans = self._spans = jumps.LoopSpans(self.do_end)
        if spans.entered(pc, target) is not None:
            return target, -1
        if self.machine.dialect.block_if and jumps.branch_entered(self.file.program.if_blocks, pc, target) is not None:
            return target, _INTO_IF
        return target, spans.kept(pc, target)

    def label_in_caller(self, unit: Any, call_line: int, n: int) -> int:
        """Where ``M99 Pn`` returns in the caller (seed 002): the first Nn after the call
        line, else the last one before it."""
        target = jumps.return_line(self.file.program.label_lines(n, unit), call_line)
        if target is None:
            raise MacroAlarm(
                SEQUENCE_NUMBER,
                detail(f"M99 P{n}: N{n} not found in the calling program", f"M99 P{n}：调用程序中未找到 N{n}"),
            )
        return target

    def label_from_start(self, unit: Any, n: int) -> int:
        """The first Nn of a program (``M98 Q``), searching from its start."""
        target = jumps.first_line(self.file.program.label_lines(n, unit))
        if target is None:
            raise MacroAlarm(
                SEQUENCE_NUMBER,
                detail(f"N{n} not found in the called program", f"被调用的程序中未找到 N{n}"),
            )
        return target

    def local_call_line(self, found: Any, call: str, label: float | None) -> int:
        """The line a local subprogram call (Haas ``M97 P n``) starts at: the first Nn of the
        program that makes the call, searching from its start as ``M98 Q`` does; none is alarm
        128, as for a GOTO."""
        if label is None:
            raise MacroAlarm(
                SEQUENCE_NUMBER, detail(f"{call} needs P: the N line to call", f"{call} 需要用 P 指定调用的 N 程序段")
            )
        n = int(round_half_away(label))
        if not 1 <= n <= 99999:
            raise MacroAlarm(
                SEQUENCE_NUMBER,
                detail(
                    f"{call} P{n}: a sequence number must be 1 to 99999", f"{call} P{n}：顺序号必须在 1～99999 之间"
                ),
                "label-range",
            )
        target = jumps.first_line(self.file.program.label_lines(n, found.unit))
        if target is None:
            raise MacroAlarm(
                SEQUENCE_NUMBER,
                detail(f"{call} P{n}: N{n} not found in {found.label}", f"{call} P{n}：{found.label} 中未找到 N{n}"),
            )
        return target

    # ---------------------------------------------------------------- compiling
    def compile(self, pc: int) -> Runner:
        if not self.machine.watching:
            return self._compile(pc)
        self.values.line = self.addresses.line = pc  # the line the watched reads report
        return self._watched(self.file.program.blocks[pc], self._compile(pc))

    def _watched(self, block: Block, run: Runner) -> Runner:
        """For the analysis: an assignment to a local or common variable (a statement, the
        THEN of an IF when it runs, or a gsk980tdi ``G65 Hm P#n`` arithmetic block) also
        reports the value it left (``RunObserver.wrote``), the value an editor shows beside the
        line; a loop head reports each pass (``RunObserver.loop_pass``: the level, the DO line,
        and whether the loop was already running)."""
        s = block.statements[0] if len(block.statements) == 1 and not block.words else None
        if isinstance(s, (While, Do)):

            def counted(m: Machine, line: int) -> int:
                observer = m.observer
                if observer is not None:
                    loops = m.frames[-1].loops
                    observer.loop_pass(len(m.frames) - 1, line, bool(loops) and loops[-1] == line)
                return run(m, line)

            return counted
        if isinstance(s, Assign):
            return self._reporting(s, run)
        if s is None and self.machine.dialect.h_codes:
            return self._reporting(_h_code_result(block, self.machine.dialect), run)
        return run  # an IF..THEN assignment reports itself, when it runs (``statement``)

    def _reporting(self, written: Assign | int | None, run: Runner) -> Runner:
        """``run``, then the value left in the variable it assigns (an assignment statement,
        or the number of the variable a ``G65 Hm P#n`` writes), for a local or common one."""
        if isinstance(written, Assign):
            written = written.target.number if isinstance(written.target, Var) else None
        if written is None:
            return run
        n = written
        kind = self.machine.kinds.kind(n)
        if kind not in ("local", "common", "persistent"):
            return run
        local = kind == "local"
        path = self.file.path

        def watched(m: Machine, pc: int) -> int:
            nxt = run(m, pc)
            if local:
                m.wrote_local(n)
            observer = m.observer
            if observer is not None:
                observer.wrote(path, pc, n, m.L[n] if local else m.C[n])
            return nxt

        return watched

    def _compile(self, pc: int) -> Runner:
        if pc == self.file.program.read_end:
            return _end_of_file  # the closing '%': the tape ends, what follows is never read
        block = self.file.program.blocks[pc]
        nxt = self.next_line(pc)
        if block.plain is not None:  # most lines of a CAM program: no label, header or error
            return self.plain_words(block.plain, block, nxt)  # what _body does with a plain line
        if self.skipped(block):
            return lambda m, pc: nxt
        if block.has_error:
            problem = next(p for p in block.problems if p.severity == "error")
            number = problem.alarm if problem.alarm is not None else STATEMENT_FORMAT
            said = problem.said(self.machine.dialect.block_if)
            return raiser(
                number,
                detail(f"the block does not parse: {said}", f"程序段无法解析：{in_language(said, True)}"),
            )
        if block.program is not None:
            return self._header(block, pc, nxt)
        return self._body(block, pc, nxt)

    def _header(self, block: Block, pc: int, nxt: int) -> Runner:
        if block_roles.joined_header(block):  # M99O0810: the M99 ends the program above
            end = self._body(block, pc, nxt)

            def joined(m: Machine, pc: int) -> int:
                return end(m, pc) if m.frame.found.unit.start != pc else nxt

            return joined
        rest = None if block_roles.header_only(block) else self._body(block, pc, nxt)

        def header(m: Machine, pc: int) -> int:
            if m.frame.found.unit.start != pc:
                return m.end_of_program(pc)  # ran into the next program's header
            return rest(m, pc) if rest is not None else nxt

        return header

    def _body(self, block: Block, pc: int, nxt: int) -> Runner:
        label = block.label
        if block.statements or block.abbreviations:  # the block rules of a macro statement (block_rules.py)
            problems = validate_block(block, self.machine.dialect)
            problem = first_alarm(problems) if problems else None
            if problem is not None and problem.rule not in DIALECT_FORMS:
                return raiser(problem.alarm, problem.message)
            if len(block.statements) > 1:
                return raiser(STATEMENT_FORMAT, detail("one macro statement per block", "一个程序段只能有一条宏语句"))
            if problem is not None:
                return raiser(problem.alarm, problem.message)
        if block.statements:
            first = block.statements[0]
            if (block.words or block.corners) and first.__class__ is If:  # an IF that governs its block (Haas)
                run = self.governing_if(first, block, pc, nxt)
            else:
                run = self.statement(first, pc, nxt)
        elif block.plain_tail is not None:  # N10 G01 X5.: its words read from the text, as a plain line's
            run = self.plain_words(block.plain_tail, block, nxt)
        elif block.words:
            run = self.nc_block(block, pc, nxt)
        else:
            run = lambda m, pc: nxt  # noqa: E731  (a label alone, or corner words alone)
        if block.corners:
            run = with_corners(self, block, run)
        if label is None:
            return run
        n = float(label)

        def labelled(m: Machine, pc: int) -> int:
            m.planner.codes["N"] = n
            after = run(m, pc)
            if after >= 0 and m.frames[-1].end_line == pc:  # the last block of a lathe cycle's shape
                return m.leave_shape(pc)
            return after

        return labelled

    # ---------------------------------------------------------------- statements
    def statement(self, s: Statement, pc: int, nxt: int) -> Runner:
        if isinstance(s, Assign):
            return self.assign(s, nxt)
        if isinstance(s, If):  # without THEN where THEN is needed: a block rule, raised in _body
            if s.opens_block:
                return self.block_if(s, pc, nxt)
            test = self.values.condition(s.condition)
            if s.goto is not None:  # also Haas's [cond] M99 P n (Dialect.conditional_m99)
                target = self.values.value(s.goto)
                jump = self.jump
                how = "GOTO " if s.m99 is None else "M99 P"

                def if_goto(m: Machine, pc: int) -> int:
                    if test(m):
                        return jump(m.frames[-1], pc, target(m), how)
                    return nxt

                if not self.machine.kept_unknown:
                    return if_goto
                passed, guard = Passed(), self.guard_jump

                def guarded_goto(m: Machine, pc: int) -> int:  # an analysis run (guards.py)
                    try:
                        taken = test(m)
                    except UnknownValue:
                        taken = guard(m, pc, nxt, target, passed)
                    return jump(m.frames[-1], pc, target(m), how) if taken else nxt

                return guarded_goto
            if s.then is None:  # IF [cond] alone (Haas): the condition is worked out, and governs nothing

                def if_alone(m: Machine, pc: int) -> int:
                    test(m)
                    return nxt

                return if_alone
            then = self.statement(s.then, pc, nxt)
            if self.machine.watching and isinstance(s.then, Assign):
                then = self._reporting(s.then, then)

            def if_then(m: Machine, pc: int) -> int:
                return then(m, pc) if test(m) else nxt

            if not (self.machine.kept_unknown and alarm_then(s, self.machine.dialect)):
                return if_then
            passed = Passed()

            def guarded_alarm(m: Machine, pc: int) -> int:  # an analysis run (guards.py)
                try:
                    hit = test(m)
                except UnknownValue:
                    passed.record(m, pc, None)
                    return nxt
                return then(m, pc) if hit else nxt

            return guarded_alarm
        if isinstance(s, Goto):
            target = self.values.value(s.target)
            jump = self.jump
            return lambda m, pc: jump(m.frames[-1], pc, target(m))
        if isinstance(s, (While, Do)):
            return self.loop_head(s, pc, nxt)
        if isinstance(s, End):
            return self.loop_end(s, pc)
        if isinstance(s, Output):
            return self.output(s, nxt)
        if isinstance(s, (Else, EndIf)):
            return self.branch_end(s, pc, nxt)
        return raiser(STATEMENT_FORMAT, detail("unknown statement", "未知的语句"))

    def block_if(self, s: If, pc: int, nxt: int) -> Runner:
        """``IF [cond] THEN`` alone on its line (``Dialect.block_if``): when the condition holds,
        the blocks after it run; when it does not, the run goes on after its ``ELSE``, or after its
        ``ENDIF`` where it has none (docs/semantics.md §4, "Block IF")."""
        pair = self.if_blocks.get(pc)
        if pair is None:
            return raiser(
                STATEMENT_FORMAT, detail("IF [...] THEN has no ENDIF", "IF [...] THEN 没有对应的 ENDIF"), "if-mismatch"
            )
        if pair[2] in self.crossing or pair[1] in self.crossing:
            return _crossing()
        test = self.values.condition(s.condition)
        other = self.next_line(pair[1] if pair[1] is not None else pair[2])

        def if_block(m: Machine, pc: int) -> int:
            return nxt if test(m) else other

        side = self._guarded_side(pair, nxt) if self.machine.kept_unknown else None
        if side is None:
            return if_block
        passed, (go, skipped) = Passed(), side

        def guarded_block(m: Machine, pc: int) -> int:  # an analysis run (guards.py)
            try:
                return nxt if test(m) else other
            except UnknownValue:
                passed.record(m, pc, skipped)
                return go

        return guarded_block

    def _guarded_side(self, pair: tuple[int, int | None, int], nxt: int) -> tuple[int, int] | None:
        """(the line to go on at, the alarm block's line) where one branch of the block IF
        ``pair`` is nothing but the program's own alarm and the other is not (``guards.py``), else None."""
        blocks, dialect = self.file.program.blocks, self.machine.dialect
        _, else_line, endif = pair

        def alone(first: int, end: int) -> bool:  # the branch first..end holds one alarm block
            return first != end and alarm_only(blocks[first], dialect) and self.next_line(first) == end

        then_alarm = alone(nxt, else_line if else_line is not None else endif)
        after_else = self.next_line(else_line) if else_line is not None else None
        else_alarm = after_else is not None and alone(after_else, endif)
        if then_alarm and not else_alarm:
            return (self.next_line(else_line if else_line is not None else endif), nxt)
        if else_alarm and not then_alarm and after_else is not None:
            return (nxt, after_else)
        return None

    def branch_end(self, s: Else | EndIf, pc: int, nxt: int) -> Runner:
        """``ELSE`` reached from the branch before it goes on after its ``ENDIF``; ``ENDIF`` does
        nothing. One without its ``IF [cond] THEN`` stops the run."""
        if pc in self.crossing:
            return _crossing()
        word = "ELSE" if isinstance(s, Else) else "ENDIF"
        endif = self.branch_ends.get(pc)
        if endif is None:
            return raiser(
                STATEMENT_FORMAT,
                detail(f"{word} has no IF [...] THEN before it", f"{word} 之前没有对应的 IF [...] THEN"),
                "if-mismatch",
            )
        if isinstance(s, EndIf):
            return lambda m, pc: nxt
        after = self.next_line(endif)
        return lambda m, pc: after

    def governing_if(self, s: If, block: Block, pc: int, nxt: int) -> Runner:
        """Haas's IF before NC words (``IF [#1 NE #0] G01 X#24``, ``IF [#1 GE 180] #101=0 M99``):
        when the condition holds, its THEN statement (if any) and then the block's words run; when
        it does not, the rest of the block is passed over (``Dialect.if_governs_block``; the block
        rules refuse it elsewhere)."""
        test = self.values.condition(s.condition)
        then = self.statement(s.then, pc, nxt) if s.then is not None else None
        if then is not None and self.machine.watching and isinstance(s.then, Assign):
            then = self._reporting(s.then, then)
        words = self.nc_block(block, pc, nxt) if block.words else None

        def governed(m: Machine, pc: int) -> int:
            if not test(m):
                return nxt
            if then is not None:
                then(m, pc)
            return words(m, pc) if words is not None else nxt

        return governed

    def assign(self, s: Assign, nxt: int) -> Runner:
        value = self.values.value(s.value)
        target = s.target
        message = s.message
        if isinstance(target, Var):
            n = target.number
            kind = self.machine.kinds.kind(n)
            # a local and a common get a closure each, alike but for the store: one lookup less
            # per assignment than VariableAccess.write (benchmarks/interp.py)
            if kind == "local":

                def set_local(m: Machine, pc: int) -> int:
                    v = value(m)
                    if v is not None and not -MAX_VALUE <= v <= MAX_VALUE and v == v:  # NaN: unknown, kept
                        raise out_of_range(n, v)
                    m.L[n] = v
                    return nxt

                return set_local
            if kind in ("common", "persistent"):

                def set_common(m: Machine, pc: int) -> int:
                    v = value(m)
                    if v is not None and not -MAX_VALUE <= v <= MAX_VALUE and v == v:  # NaN: unknown, kept
                        raise out_of_range(n, v)
                    m.C[n] = v
                    return nxt

                return set_common
            if kind == "vacant":
                return raiser(
                    WRITE_PROTECTED,
                    detail("#0 is always vacant and cannot be written", "#0 总是空变量，不能写入"),
                )
            number = float(n)

            def set_other(m: Machine, pc: int) -> int:
                m.write(number, value(m), message)
                return nxt

            return set_other
        if isinstance(target, NamedVar):
            named = self.values.named(target, write=True)

            def set_named(m: Machine, pc: int) -> int:
                m.write(float(named(m)), value(m), message)
                return nxt

            return set_named
        assert isinstance(target, IndirectVar)
        index = self.values.value(target.index)

        def set_indirect(m: Machine, pc: int) -> int:
            m.write(index(m), value(m), message)
            return nxt

        return set_indirect

    def loop_number(self, num: Number) -> int | None:
        v = num.value
        return int(v) if v == int(v) and 1 <= v <= 3 else None

    def loop_head(self, s: While | Do, pc: int, nxt: int) -> Runner:
        number = self.loop_number(s.loop)
        if number is None:
            return _bad_loop_number("DO", s.loop)
        end = self.do_end.get(pc)
        if end is None:
            return self._loop_head_without_end(s, number, nxt)
        after = self.next_line(end)
        test = self.values.condition(s.condition) if isinstance(s, While) else None

        def head(m: Machine, pc: int) -> int:
            loops = m.frames[-1].loops  # ``m.frame`` without the property's call
            if not loops or loops[-1] != pc:
                if len(loops) >= MAX_LOOP_DEPTH:
                    raise MacroAlarm(
                        LOOP_NUMBER,
                        detail(f"loops nested more than {MAX_LOOP_DEPTH} deep", f"循环嵌套超过 {MAX_LOOP_DEPTH} 层"),
                    )
                loops.append(pc)
            if test is None or test(m):
                return nxt
            loops.pop()
            return after

        if test is None or not self.machine.kept_unknown:
            return head
        passed = Passed(LOOP)

        def guarded_head(m: Machine, pc: int) -> int:  # an analysis run: a count the machine has (guards.py)
            loops = m.frames[-1].loops
            entering = not loops or loops[-1] != pc
            try:
                return head(m, pc)
            except UnknownValue:
                passed.record(m, pc, None)
                if unknown_loop_pass(entering):
                    return nxt
                loops.pop()
                return after

        return guarded_head

    def _loop_head_without_end(self, s: While | Do, number: int, nxt: int) -> Runner:
        """A WHILE/DO whose END is not in its program (docs/semantics.md §4): the body runs while the
        condition holds (the program may end or jump away before an END is needed); where it does
        not hold the control looks for END m to go on after it, finds none: alarm 124."""
        missing = detail(f"DO {number} has no END {number}", f"DO {number} 没有对应的 END {number}")
        if not isinstance(s, While):
            return lambda m, pc: nxt
        test = self.values.condition(s.condition)

        def head(m: Machine, pc: int) -> int:
            if test(m):
                return nxt
            raise MacroAlarm(MISSING_END, missing)

        return head

    def loop_end(self, s: End, pc: int) -> Runner:
        number = self.loop_number(s.loop)
        if number is None:
            return _bad_loop_number("END", s.loop)
        do = self.end_do.get(pc)
        if do is None:
            return raiser(
                LOOP_NUMBER,
                detail(f"END {number} has no DO {number} before it", f"END {number} 之前没有对应的 DO {number}"),
            )

        def end(m: Machine, pc: int) -> int:
            loops = m.frames[-1].loops  # ``m.frame`` without the property's call
            if not loops or loops[-1] != do:
                raise MacroAlarm(
                    LOOP_NUMBER,
                    detail(
                        f"END {number} reached outside its loop (loops may not cross)",
                        f"在循环之外执行到 END {number}（循环不能交叉）",
                    ),
                )
            return do

        return end

    def output(self, s: Output, nxt: int) -> Runner:
        if s.command not in ("DPRNT", "BPRNT"):
            return lambda m, pc: nxt
        # the literal text, or the variable's getter with its format
        parts: list[str | tuple[Getter, int | None, int | None]] = []
        dialect = self.machine.dialect
        most, whole_part = dialect.dprnt_places, dialect.dprnt_whole_part
        for p in s.parts:
            if p.variable is not None:
                places = (p.digits or 0) + (p.decimals or 0)
                if most and p.digits is not None and not 0 < places <= most:
                    shown = f"[{p.digits}{p.decimals if p.decimals is not None else ''}]"
                    return raiser(FORMAT, detail(
                        f"DPRNT format {shown}: the places before and after the point must be 1 to {most} in all",
                        f"DPRNT 格式 {shown}：小数点前后的位数合计必须在 1～{most} 之间"))  # fmt: skip
                parts.append((self.values.value(p.variable), p.digits, p.decimals))
            else:
                parts.append(p.text or "")

        if s.command == "BPRNT":  # binary: each value as a 32-bit whole number (binary_output.py)
            return self._bprnt(parts, nxt)

        def dprnt(m: Machine, pc: int) -> int:
            text = "".join(p if isinstance(p, str) else format_value(p[0](m), p[1], p[2], whole_part) for p in parts)
            m.print_line(text, pc)
            return nxt

        return dprnt

    @staticmethod
    def _bprnt(parts: list[str | tuple[Getter, int | None, int | None]], nxt: int) -> Runner:
        """BPRNT's record: the characters, and each variable's value with its decimal places ``[c]``
        (none given: 0)."""

        def bprnt(m: Machine, pc: int) -> int:
            pieces = [p if isinstance(p, str) else (p[0](m), p[2] or 0) for p in parts]
            m.print_line(bprnt_record(pieces), pc, BPRNT)
            return nxt

        return bprnt

    # ---------------------------------------------------------------- NC words
    def word_value(self, w: Word, data: bool = False) -> tuple[bool, Any]:
        """(is_constant, value or getter) for an NC word, rounded for its address. A ``data``
        word (a value ``G10`` writes to an offset) may be unknown: it is written unknown, as an
        assignment writes it (``round_for``)."""
        letter = w.letter
        value = w.value
        if value is None:
            return True, None
        if value.__class__ is Number and letter in AXIS_LETTERS and self.machine.settings.decimal_point != "increment":
            text = value.text
            dot = text.find(".")
            if dot < 0 or len(text) - dot <= 4:  # at most 3 decimals: already on the 0.001 grid
                return True, value.value
        const, v = self.addresses.constant(value)
        point = isinstance(value, Number) and value.has_point
        if const:
            return True, self.round_for(letter, v, literal=True, point=point)
        getter = self.addresses.value(value, letter)
        round_for = self.round_for
        return False, lambda m: round_for(letter, getter(m), literal=False, point=True, data=data)

    def dwell_p_value(self, w: Word) -> tuple[bool, Any]:
        """``word_value`` of a dwell's P (G04's, a drilling cycle's). Where a P written with a
        decimal point counts seconds (``Timing.dwell_p_point_seconds``, Haas: "G04 P10. is a dwell
        of 10 seconds; G04 P10 is 10 milliseconds", docs/semantics.md §9) such a P, and one from a
        variable or an expression (which has no decimal point to read: taken as seconds), is
        given in P's unit (``Timing.dwell_p_unit``) and rounded as P is; a literal without a
        point is P's unit as written."""
        timing = self.machine.dialect.timing
        value = w.value
        if not timing.dwell_p_point_seconds or value is None:
            return self.word_value(w)
        if value.__class__ is Number and not value.has_point:
            return self.word_value(w)
        per_second = 1.0 / timing.dwell_p_unit
        round_for = self.round_for

        def in_units(v: float | None) -> float | None:
            return round_for("P", None if v is None else v * per_second, literal=False, point=True)

        const, v = self.addresses.constant(value)
        if const:
            return True, in_units(v)
        getter = self.addresses.value(value)
        return False, lambda m: in_units(getter(m))

    def round_for(self, letter: str, v: float | None, literal: bool, point: bool, data: bool = False) -> float | None:
        if v is None:
            return 0.0 if self.machine.dialect.vacant_address_is_zero else None
        if v != v:  # an address from an unknown value (machine/unknown_values.py)
            if data:  # a value G10 writes: the offset becomes unknown, the run goes on
                return v
            raise UnknownValue
        if letter == "G":
            return to_increment(v, 1) if v != int(v) else float(v)
        dialect = self.machine.dialect
        if (
            letter in INTEGER_LETTERS
            and not (letter == "D" and dialect.lathe_cycles.one_block)
            and not (dialect.chamfer_words is not None and letter in dialect.chamfer_words)
        ):  # (a lathe whose cycles take D as a depth keeps its decimals, a GSK980TDi's chamfer L and D theirs)
            return round_half_away(v)
        if letter == "F":
            return v
        inch = self.machine.planner.modal.get("units") == 20.0
        if letter in DECIMAL_LETTERS or letter == "D":
            return to_increment(v, 4 if inch else 3)
        if literal and not point and self.machine.settings.decimal_point == "increment":
            v = in_least_increments(letter, v, inch)
        return to_increment(v, increment_places(letter, inch))

    def nc_block(self, block: Block, pc: int, nxt: int) -> Runner:
        return nc_blocks.compile_nc_block(self, block, pc, nxt)

    def plain_words(self, text: str, block: Block, nxt: int) -> Runner:
        """The runner of ``block``, whose words are the literal ``text`` (its ``plain`` or
        ``plain_tail``): plain motion read from the text, else the NC block compiled once for
        every line of this file that holds the same words (a lathe program repeats its cycle
        and shape blocks part after part). A text found in ``_shared`` is not read again.
        ``round_for`` reads the unit in force when a line is compiled, so the unit is part of
        the key."""
        key = (text, self.machine.planner.modal.get("units"))
        found = self._shared.get(key)
        if found is None:
            fast = nc_blocks.compile_plain_line(self, text, nxt)
            if fast is not None:
                return fast
            found = self._shared[key] = nc_blocks.nc_block_of(self, block)
        return found(nxt)


# ``_find_jump``'s count of loops kept for a jump into a branch of a block IF from outside it
_INTO_IF = -2


def _if_blocks(program: Any) -> tuple[dict[int, tuple[int, int | None, int]], dict[int, int], frozenset[int]]:
    """The block IFs of ``program`` by IF line, (IF line, ELSE line or None, ENDIF line), the
    ENDIF line of each paired ELSE and ENDIF line, and the ELSE and ENDIF lines that cross a loop."""
    heads = {f.if_line: (f.if_line, f.else_line, f.endif_line) for f in program.if_blocks}
    ends = {f.endif_line: f.endif_line for f in program.if_blocks}
    ends.update({f.else_line: f.endif_line for f in program.if_blocks if f.else_line is not None})
    return heads, ends, frozenset(p.line for p in program.if_problems if p.kind == "crossing")


def _crossing() -> Runner:
    """The runner of a block IF marker whose branch crosses a WHILE/DO loop."""
    return raiser(
        STATEMENT_FORMAT,
        detail("a block IF [...] THEN and a WHILE/DO loop cross", "块形式 IF [...] THEN 与 WHILE/DO 循环交叉"),
        "if-mismatch",
    )


def _end_of_file(m: Machine, pc: int) -> int:
    return m.end_of_program(pc)


def _bad_loop_number(word: str, loop: Number) -> Runner:
    """The runner of a ``DO`` or ``END`` (``word``) whose number is not 1, 2 or 3: alarm 126."""
    return raiser(
        LOOP_NUMBER,
        detail(f"{word} {loop.text}: the loop number must be 1, 2 or 3", f"{word} {loop.text}：循环号必须为 1、2 或 3"),
    )


# The NC-block compiler imports this module, so it is imported last.
def h_code_destination(block: Block, dialect: Dialect) -> Var | None:
    """The variable ``P#n`` a gsk980tdi ``G65 Hm P#n Q.. R..`` arithmetic block writes (H01, the
    assignment, and every other operation but the jumps and H99), or None (another block, a macro
    call, a jump H code, an indirect P). The one rule of which variable a macro A block sets: the
    run reports it as it reports an assignment, and the check counts it as set by the program
    (analysis/runs/sure_alarms.py)."""
    words = block.words
    if len(words) < 3 or words[0].letter != "G" or not isinstance(words[0].value, Number):
        return None
    if words[0].value.value != 65.0 or not h_code_form(words[1:], dialect):
        return None
    by_letter = {w.letter: w.value for w in words[1:]}
    h, p = by_letter.get("H"), by_letter.get("P")
    if not isinstance(h, Number) or not isinstance(p, Var):
        return None
    return p if int(h.value) in hcodes.ARITHMETIC or int(h.value) == 26 else None


def _h_code_result(block: Block, dialect: Dialect) -> int | None:
    """The number of the variable a ``G65 Hm P#n`` arithmetic block writes, or None."""
    destination = h_code_destination(block, dialect)
    return None if destination is None else destination.number


from . import hcodes, nc_blocks  # noqa: E402
