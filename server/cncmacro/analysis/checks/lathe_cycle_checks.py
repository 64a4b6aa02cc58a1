"""The findings of a lathe's multiple repetitive cycles that the text alone shows
(docs/semantics.md §10.5): a G70–G76 block's literal words and its shape blocks N(P)…N(Q), read
without running the program.

The rules are ``planner/cycle_rules.py``'s (the run calls the same ones for values that come
from variables): this module only gathers what the text says, in text order within each O
program: the position the tool is at (from literal X/Z, U/W words; unknown after a call, a
reference return or a word from a variable), the motion mode in force, the last first block of
each cycle. A finding about the cycle block marks its word (or the block); one about the shape's
geometry marks the block N(Q) where it is an error (the run stops there, when the shape has been
read) and the cycle block where it is a warning (the run notes it there); a command not allowed
in the shape marks that command. Findings only the text decides: the block N(P) or N(Q) not in the program
(PS0063), a label of the shape used twice (``duplicate-label``), M98/M99/G65/G66 in the shape
(PS0325), a G code outside GSK's list, a chamfer or corner R ending the shape (PS0069) or in a
thread block (PS0050), more blocks than GSK's 200. Nothing here runs on a profile without
``Dialect.cycle_rules`` (a mill's G73/G74/G76 are drilling cycles).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ...bilingual import Detail, detail, pick
from ...dialects import alarms as A
from ...dialects import lathe_cycle_rules as K
from ...dialects.lathe_cycle_rules import LatheCycleRules
from ...planner.cycle_rules import CycleFinding, Step, block_findings, is_second_block, shape_findings
from ...syntax.nodes import Assign, Block, CornerWord, Word
from ...syntax.program import Program, ProgramUnit
from ..diagnostics import Diagnostic, diagnostic
from .line_facts import LineContext

CYCLES = frozenset({70.0, 71.0, 72.0, 73.0, 74.0, 75.0, 76.0})
SHAPES = frozenset({70.0, 71.0, 72.0, 73.0})
MOTION = frozenset({0.0, 1.0, 2.0, 3.0, 32.0, 34.0, 90.0, 92.0, 94.0})
# codes after which the position is not known from the text (returns, coordinate changes)
_LOSES_POSITION = frozenset({27.0, 28.0, 29.0, 30.0, 53.0, 54.0, 55.0, 56.0, 57.0, 58.0, 59.0, 65.0, 66.0})


@dataclass(slots=True)
class _Read:
    """A block's words as the text gives them: the literal values by letter (the last of a
    letter), the letters with values not known, the G codes. Never changed once read: the
    lines of the same plain text share one (``_Unit.read``)."""

    values: dict[str, float] = field(default_factory=dict)
    unknown: set[str] = field(default_factory=set)
    gs: list[float] = field(default_factory=list)
    g_unknown: bool = False


_PLAIN_WORD = re.compile(r"([A-Za-z])([+-]?(?:\d+\.?\d*|\.\d+))")


def _read(block: Block, ctx: LineContext) -> _Read:
    r = _Read()
    plain = block.plain
    if plain is not None:  # literal words only (``Block.plain``): read from the text, no nodes built
        values, gs = r.values, r.gs
        for letter, text in _PLAIN_WORD.findall(plain):
            if letter == "G" or letter == "g":
                gs.append(float(text))
            else:
                values[letter.upper()] = float(text)
        return r
    for w in block.words:
        known, value = (False, None) if w.value is None else ctx.values.constant(w.value)
        if w.letter == "G":
            if known and value is not None:
                r.gs.append(value)
            else:
                r.g_unknown = True
        elif known and value is not None:
            r.values[w.letter] = value
            r.unknown.discard(w.letter)
        else:
            r.unknown.add(w.letter)
            r.values.pop(w.letter, None)
    return r


@dataclass(slots=True)
class _State:
    """What the text says of the machine so far in one O program."""

    x: float | None = None
    z: float | None = None
    mode: float | None = None
    firsts: dict[float, dict[str, float]] = field(default_factory=dict)

    def moved(self, r: _Read) -> None:
        """Follow a block that is not a cycle: its motion mode and where it sends the tool."""
        for g in r.gs:
            if g in MOTION:
                self.mode = g
        if r.g_unknown:
            self.mode = None
        if any(g in _LOSES_POSITION for g in r.gs) or r.values.get("M") == 98.0:
            self.x = self.z = None
            return
        self.x = _next(self.x, r, "X", "U")
        self.z = _next(self.z, r, "Z", "W")


def _next(at: float | None, r: _Read, absolute: str, incremental: str) -> float | None:
    if absolute in r.unknown or incremental in r.unknown:
        return None
    if absolute in r.values:
        at = r.values[absolute]
    if incremental in r.values:
        at = None if at is None else at + r.values[incremental]
    return at


def lathe_cycle_diagnostics(program: Program, file: str, ctx: LineContext) -> list[Diagnostic]:
    """Every finding of the lathe cycles of ``program`` (module docstring)."""
    rules = ctx.dialect.cycle_rules
    if rules is None:
        return []
    out: list[Diagnostic] = []
    plain_reads: dict[str, _Read] = {}
    for unit in program.units:
        if unit.duplicate:
            continue
        _Unit(program, unit, file, ctx, rules, out, plain_reads).run()
    return out


class _Unit:
    """The lathe cycles of one O program."""

    def __init__(self, program: Program, unit: ProgramUnit, file: str, ctx: LineContext, rules: LatheCycleRules,
                 out: list[Diagnostic], plain_reads: dict[str, _Read]) -> None:  # fmt: skip
        self.program, self.unit, self.file, self.ctx, self.rules, self.out = program, unit, file, ctx, rules, out
        self.state = _State()
        self.reads: dict[int, _Read] = {}
        self.plain_reads = plain_reads  # a plain line's reading by its text: a lathe program repeats its lines

    def read(self, line: int) -> _Read:
        r = self.reads.get(line)
        if r is None:
            block = self.program.blocks[line]
            plain = block.plain
            if plain is None:
                r = _read(block, self.ctx)
            else:
                r = self.plain_reads.get(plain)
                if r is None:
                    r = self.plain_reads[plain] = _read(block, self.ctx)
            self.reads[line] = r
        return r

    def run(self) -> None:
        end = min(self.unit.end, self.program.read_end)
        for line in range(self.unit.start, end):
            block = self.program.blocks[line]
            if block.problems and block.has_error:
                continue
            if block.plain is None and not block.words and not block.corners:  # a plain line has words
                continue
            r = self.read(line)
            self.thread_corners(line, block, r)
            cycle = next((g for g in r.gs if g in CYCLES), None)
            if cycle is None:
                self.state.moved(r)
            else:
                self.cycle(line, block, cycle, r)

    # ------------------------------------------------------------ marking
    def add(self, line: int, start: int, end: int, code: str, message: Detail, alarm: int | None, sure: bool) -> None:
        text = pick(self.ctx.locale, str(message), message.zh)
        if alarm is not None:
            said = self.ctx.dialect.alarm_said(alarm)
            text += pick(self.ctx.locale, f" ({said})", f"（{said.zh}）")
        self.out.append(diagnostic(self.file, line, start, line, max(end, start + 1), code, text, milder=not sure))

    def whole(self, block: Block) -> tuple[int, int]:
        items: list[Word | CornerWord] = [*block.words, *block.corners]
        if not items:
            return 0, 1
        return min(i.start for i in items), max(i.end for i in items)

    def mark(self, line: int, block: Block, r: _Read, f: CycleFinding, code: str) -> None:
        w = block.word(f.letter) if f.letter else None
        start, end = (w.start, w.end) if w is not None else self.whole(block)
        self.add(line, start, end, code, f.message, f.alarm, f.sure)

    # ------------------------------------------------------------ the checks
    def thread_corners(self, line: int, block: Block, r: _Read) -> None:
        """PS0050: a chamfer or corner R in a thread cutting block."""
        if not block.corners or not any(g in self.rules.thread_codes for g in r.gs):
            return
        g = next(g for g in r.gs if g in self.rules.thread_codes)
        for c in block.corners:
            if c.letter in ("C", "R"):
                message = detail(f"G{g:g}: a chamfer or corner R (,{c.letter}) in a thread cutting block",
                                 f"G{g:g}：螺纹切削程序段中有倒角或拐角 R（,{c.letter}）")  # fmt: skip
                self.add(line, c.start, c.end, "cycle-block", message, A.THREAD_CORNER,
                         K.THREAD_CORNER in self.rules.surely)  # fmt: skip

    def cycle(self, line: int, block: Block, g: float, r: _Read) -> None:
        state = self.state
        present = frozenset(r.values) | frozenset(r.unknown)
        second = is_second_block(g, present)
        travel: dict[str, float | None] = {
            "X": _travel(state.x, r, "X", "U"),
            "Z": _travel(state.z, r, "Z", "W"),
        }
        first = state.firsts.get(g)
        for f in block_findings(self.rules, g, r.values, first, travel, frozenset(r.unknown)):
            self.mark(line, block, r, f, "cycle-block")
        if not second:
            state.firsts[g] = dict(r.values)
            return
        if g in SHAPES:
            self.shape(line, block, g, r)

    def shape(self, line: int, block: Block, g: float, r: _Read) -> None:
        p, q = r.values.get("P"), r.values.get("Q")
        if p is None or q is None:
            return
        program, unit = self.program, self.unit
        firsts = program.label_lines(int(p), unit)
        first = next((x for x in firsts if x > line), firsts[0] if firsts else None)
        lasts = [] if first is None else [x for x in program.label_lines(int(q), unit) if x >= first]
        if first is None or not lasts:
            letter, label = ("P", p) if first is None else ("Q", q)
            w = _word(block, letter)
            message = detail(f"G{g:g}: no block N{label:g} in this program for its {letter}",
                             f"G{g:g}：本程序中没有其 {letter} 指定的程序段 N{label:g}")  # fmt: skip
            self.add(line, w.start, w.end, "cycle-shape", message, A.CYCLE_BLOCK_NOT_FOUND,
                     K.LABEL_NOT_FOUND in self.rules.surely)  # fmt: skip
            return
        last = lasts[0]
        for letter, label in (("P", p), ("Q", q)):
            count = len(program.label_lines(int(label), unit))
            if count > 1:
                w = _word(block, letter)
                message = detail(f"G{g:g}: N{label:g} labels {count} blocks of this program; the shape's {letter} "
                                 "should name one (the GSK980TDi manual forbids it; FANUC takes the first after "
                                 "the cycle block)",
                                 f"G{g:g}：本程序中有 {count} 个程序段标为 N{label:g}；形状的 {letter} 应只对应一个"
                                 "（GSK980TDi 说明书不允许；FANUC 取循环程序段之后的第一个）")  # fmt: skip
                self.out.append(diagnostic(self.file, line, w.start, line, w.end, "duplicate-label",
                                           pick(self.ctx.locale, str(message), message.zh)))  # fmt: skip
        self.shape_blocks(line, block, g, r, first, last)

    def shape_blocks(self, line: int, block: Block, g: float, r: _Read, first: int, last: int) -> None:
        """The blocks N(P)…N(Q): what may not be in them, and their geometry for the rules."""
        rules = self.rules
        program = self.program
        steps: list[Step] = []
        exact = True  # every move of the shape is known from the text
        mode = self.state.mode
        x, z = self.state.x, self.state.z
        start = None if x is None or z is None else (x, z)
        named: frozenset[str] | None = None
        count = 0
        for at in range(first, last + 1):
            b = program.blocks[at]
            if b.problems and b.has_error:
                exact = False
                continue
            if b.statements:
                count += 1
                if any(not isinstance(s, Assign) for s in b.statements):
                    exact = False  # a jump or loop: the text's order is not the run's
                continue
            if b.plain is None and not b.words and not b.corners:
                continue
            count += 1
            sr = self.read(at)
            self.shape_commands(at, g, sr)
            if at == last:
                self.last_block(at, g, b)
            for code in sr.gs:
                if code in MOTION:
                    mode = code
            if sr.g_unknown:
                mode = None
            axes = {a for a in ("X", "Z", "U", "W") if a in sr.values or a in sr.unknown}
            if not axes:
                continue
            if named is None:
                named = frozenset(axes)
            nx, nz = _next(x, sr, "X", "U"), _next(z, sr, "Z", "W")
            if mode is None or nx is None or nz is None:
                if not steps and mode is not None:
                    steps.append((mode, float("nan"), float("nan")))  # the first move's mode is still known
                exact = False
                break
            steps.append((mode, nx, nz))
            x, z = nx, nz
        if rules.shape_blocks is not None and count > rules.shape_blocks:
            limit = rules.shape_blocks
            message = detail(f"G{g:g}: the shape holds {count} blocks, more than the {limit} the control takes",
                             f"G{g:g}：形状程序有 {count} 个程序段，超过系统允许的 {limit} 个")  # fmt: skip
            s, e = self.whole(block)
            self.add(line, s, e, "cycle-shape", message, None, K.SHAPE_BLOCKS in rules.surely)
        if g == 70.0 or not steps:
            return  # the run judges a shape only when a roughing cycle reads it
        type_two = named is not None and bool(named & {"X", "U"}) and bool(named & {"Z", "W"})
        known_steps = steps if exact else steps[:1]
        for f in shape_findings(rules, g, r.values, start if exact else None, known_steps, type_two,
                                self.ctx.settings.shape_monotone_check):  # fmt: skip
            if f.sure:  # where the run stops: the block N(Q), when the shape has been read
                s, e = self.whole(program.blocks[last])
                self.add(last, s, e, "cycle-shape", f.message, f.alarm, True)
            else:  # where the run notes it: the cycle block
                self.mark(line, block, r, f, "cycle-shape")

    def shape_commands(self, at: int, g: float, r: _Read) -> None:
        """PS0325: a call or return in the shape; on GSK a G code outside its list (a warning)."""
        rules = self.rules
        calls = [("G", c) for c in r.gs if c in (65.0, 66.0)]
        m = r.values.get("M")
        if m in (98.0, 99.0):
            calls.append(("M", m))
        block = self.program.blocks[at]
        for letter, c in calls:
            w = _word(block, letter)
            message = detail(f"{letter}{c:02g} in the shape of G{g:g}: M98, M99, G65 and G66 are not allowed there",
                             f"G{g:g} 的形状程序中有 {letter}{c:02g}：其中不允许 M98、M99、G65、G66")  # fmt: skip
            self.add(at, w.start, w.end, "cycle-shape", message, A.SHAPE_COMMAND, K.SHAPE_COMMAND in rules.surely)
        allowed = rules.shape_g_codes
        if allowed is None:
            return
        for c in r.gs:
            if c in allowed or c in (65.0, 66.0):
                continue
            w = _word(block, "G")
            message = detail(f"G{c:02g} in the shape of G{g:g}: the manual allows only G00-G05, G6.2, G6.3, G7.2, "
                             "G7.3, G40-G42 and G96-G99 there",
                             f"G{g:g} 的形状程序中有 G{c:02g}：说明书规定其中只能有 G00-G05、G6.2、G6.3、G7.2、G7.3、"
                             "G40-G42、G96-G99")  # fmt: skip
            self.add(at, w.start, w.end, "cycle-shape", message, A.SHAPE_COMMAND, K.SHAPE_G_CODE in rules.surely)

    def last_block(self, at: int, g: float, b: Block) -> None:
        """PS0069: the shape's last block ends in a chamfer or corner R."""
        for c in b.corners:
            if c.letter in ("C", "R"):
                message = detail(f"G{g:g}: the last block of the shape ends in a chamfer or corner R (,{c.letter}), "
                                 "which has no next move to meet",
                                 f"G{g:g}：形状程序的最后一段以倒角或拐角 R（,{c.letter}）结束，"
                                 "没有下一个移动与之相接")  # fmt: skip
                self.add(at, c.start, c.end, "cycle-shape", message, A.SHAPE_LAST_BLOCK,
                         K.LAST_BLOCK in self.rules.surely)  # fmt: skip


def _word(block: Block, letter: str) -> Word:
    """The first word of ``letter`` in ``block``, which the block's reading found there."""
    w = block.word(letter)
    assert w is not None
    return w


def _travel(at: float | None, r: _Read, absolute: str, incremental: str) -> float | None:
    """How far a cycle block's end point is from the start along one axis (None: not known)."""
    if absolute in r.unknown or incremental in r.unknown:
        return None
    if absolute in r.values:
        return None if at is None else r.values[absolute] - at
    return r.values.get(incremental, 0.0)
