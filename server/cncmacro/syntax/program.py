"""The cross-line structure of a document: O programs, N labels, DO/END pairs, the blocks of a
block IF (``IF [cond] THEN`` .. ``ELSE`` .. ``ENDIF``) and the tape's end.

A ``Program`` is built from the blocks of a whole file by one linear pass that visits only
the blocks marked ``structural`` (a label, an O header, a ``%`` mark, a WHILE/DO/END, a block
IF's IF/ELSE/ENDIF), so that
rebuilding it after an edit costs time in proportion to those blocks, not to the file.
The pass finds facts; judging them (a duplicate label, a DO without END) is the analysis
layer's job.

The tape ends at its closing ``%`` (docs/semantics.md §1): a ``%`` line before any program text
starts the tape, the next one ends it, and a ``%`` after program text ends it at once (a line
that starts with the DOS end-of-file character reads as such a mark). What follows the end
(``tape_end``) is not part of the program: no unit, loop or tape mark is taken from it, and
every layer above passes it over. A ``%`` written after the code of its line (``M30%``) is
always a closing mark, and that code is read: reading ends after that line. Otherwise reading
ends at the closing ``%`` itself (``Program.read_end``,
the one answer to where a file's text ends for the run, the checks and the editor): a control
reads the mark and stops, so nothing on that line after the ``%`` is read either (the parser
keeps no block there), and running into it ends the program like the end of the file. The
last O program still holds the line of its closing ``%`` (``ProgramUnit.end``), as the first
holds the ``%`` that starts the tape.
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right, insort
from dataclasses import dataclass, field
from itertools import compress, islice

from .nodes import Block


@dataclass(slots=True)
class LoopPair:
    """A ``WHILE..DO m`` or ``DO m`` line and the ``END m`` line that closes it."""

    number: int
    do_line: int
    end_line: int


@dataclass(slots=True)
class LoopProblem:
    """A loop marker that does not pair: ``kind`` is ``do-without-end``, ``end-without-do``
    or ``crossing`` (an END that closes a DO while an inner loop is still open, whose DO is
    ``other_line``)."""

    kind: str
    line: int
    number: int
    other_line: int | None = None


@dataclass(slots=True)
class IfBlock:
    """A block ``IF [cond] THEN`` line, its ``ELSE`` line (None without one) and the ``ENDIF``
    line that closes it. Block IFs nest; they pair within one O program, apart from DO loops."""

    if_line: int
    else_line: int | None
    endif_line: int

    @property
    def spans(self) -> tuple[tuple[int, int], ...]:
        """The branches as (first marker line, last line it holds): the THEN branch from the IF
        up to its ELSE (or ENDIF), and the ELSE branch from the ELSE up to the ENDIF."""
        if self.else_line is None:
            return ((self.if_line, self.endif_line),)
        return ((self.if_line, self.else_line), (self.else_line, self.endif_line))


@dataclass(slots=True)
class IfProblem:
    """A block IF marker that does not pair: ``kind`` is ``if-without-endif``,
    ``else-without-if``, ``endif-without-if``, ``second-else`` (an ELSE after the ELSE of its IF,
    whose line is ``other_line``) or ``crossing`` (an ELSE or ENDIF reached while a loop opened
    inside the branch it ends is still open, or after a loop that was open at its IF has ended:
    a block IF and a loop may not cross; ``other_line`` is the loop's DO line when it is known)."""

    kind: str
    line: int
    other_line: int | None = None


@dataclass(slots=True)
class ProgramUnit:
    """One O program in a file, from its header line up to (not including) ``end``.

    A file that does not start with an O header has a first unit with ``number`` None
    covering the lines before the first header (GSK programs are often named by their
    file).

    ``duplicate`` marks a header that repeats the number of an earlier program in the same
    file. The control keeps one program per number, the first one it reads (loading the second
    copy is FANUC alarm 073, docs/semantics.md §1), so nothing calls or runs a duplicate: every
    lookup of a number (``Program.unit_numbered``) and every choice of programs to run skips it.
    """

    number: int | None
    title: str | None
    start: int
    end: int
    duplicate: bool = False

    def __contains__(self, line: int) -> bool:
        return self.start <= line < self.end


@dataclass(slots=True)
class Program:
    """A parsed file: its blocks (one per line) and what connects them."""

    blocks: list[Block]
    units: list[ProgramUnit]
    labels: dict[int, list[int]]
    loops: list[LoopPair]
    loop_problems: list[LoopProblem]
    tape_marks: list[int]
    markers: list[int]  # lines with an O header, a '%', a loop marker or a block IF marker, in order
    tape_end: int | None = None  # the line of the closing '%': the lines after it are not read
    if_blocks: list[IfBlock] = field(default_factory=list)
    if_problems: list[IfProblem] = field(default_factory=list)

    @property
    def read_end(self) -> int:
        """The line at which reading ends: the closing ``%``, else the file's end
        (``len(blocks)``). The lines before it are the program's text; the ``%`` line holds no
        block and ends a run that reaches it (see the module docstring)."""
        end = self.tape_end
        if end is None:
            return len(self.blocks)
        return end + 1 if self.blocks[end].code_before_mark else end  # ``M30%``: its M30 is read

    def after_tape(self, line: int) -> bool:
        """True for a line after the closing ``%`` (not part of the program)."""
        return self.tape_end is not None and line > self.tape_end

    def shift(self, at: int, delta: int) -> None:
        """Move the line numbers of units, loops and tape marks at or after ``at`` by
        ``delta`` (labels and markers are moved by ``update_program``)."""
        for u in self.units:
            if u.start >= at:
                u.start += delta
            if u.end >= at:
                u.end += delta
        for p in self.loops:
            if p.do_line >= at:
                p.do_line += delta
            if p.end_line >= at:
                p.end_line += delta
        problems: list[LoopProblem | IfProblem] = [*self.loop_problems, *self.if_problems]
        for q in problems:
            if q.line >= at:
                q.line += delta
            if q.other_line is not None and q.other_line >= at:
                q.other_line += delta
        for f in self.if_blocks:
            if f.if_line >= at:
                f.if_line += delta
            if f.else_line is not None and f.else_line >= at:
                f.else_line += delta
            if f.endif_line >= at:
                f.endif_line += delta
        self.tape_marks = [x + delta if x >= at else x for x in self.tape_marks]
        if self.tape_end is not None and self.tape_end >= at:
            self.tape_end += delta

    def label_lines(self, label: int, unit: ProgramUnit | None = None) -> list[int]:
        """The lines labelled N``label``, in order (duplicates kept), optionally only those
        inside ``unit``."""
        lines = self.labels.get(label, [])
        if unit is None:
            return list(lines)
        return [i for i in lines if unit.start <= i < unit.end]

    def unit_at(self, line: int) -> ProgramUnit:
        """The O program that holds ``line``."""
        starts = [u.start for u in self.units]
        return self.units[max(0, bisect_right(starts, line) - 1)]

    def unit_numbered(self, number: int) -> ProgramUnit | None:
        """The program ``O<number>`` of the file, if it has one: the first unit with that
        header (a later one is a ``duplicate`` that the control does not keep)."""
        for u in self.units:
            if u.number == number and not u.duplicate:
                return u
        return None

    def named_units(self) -> list[ProgramUnit]:
        """The programs a person names: every unit, except a first one without header that
        holds no program text when an O header follows it. Such lines (a ``%``, the
        ``(cncmacro: dialect=...)`` comment, a heading in comments) are the first program's
        lead-in, not a program named by its file; the machine starts the file at that O line."""
        units = self.units
        if len(units) > 1 and units[0].number is None and self.text_free(units[0]):
            return units[1:]
        return units

    def text_free(self, unit: ProgramUnit) -> bool:
        """True when ``unit`` holds nothing the control runs: only blank lines, comments and
        ``%`` marks (the scan stops at the first line with program text)."""
        return all(b.is_empty or b.tape for b in islice(self.blocks, unit.start, unit.end))

    def loop_at(self, do_line: int) -> LoopPair | None:
        for p in self.loops:
            if p.do_line == do_line:
                return p
        return None


def _is_marker(b: Block) -> bool:
    return (
        b.program is not None
        or b.tape
        or (bool(b.statements) and (b.loop_marker() is not None or b.branch_marker() is not None))
    )


def build_program(blocks: list[Block], structural: list[bool] | None = None) -> Program:
    """Find the units, labels and loop pairs of ``blocks``.

    ``structural`` may be given as the list of each block's ``structural`` flag, kept up to
    date by the caller, so that the blocks without structure are never visited here.
    """
    if structural is None:
        structural = [b.structural for b in blocks]
    labels: dict[int, list[int]] = {}
    markers: list[int] = []
    for i in compress(range(len(blocks)), structural):
        b = blocks[i]
        lab = b.label
        if lab is not None:
            lines = labels.get(lab)
            if lines is None:
                labels[lab] = [i]
            else:
                lines.append(i)
        if b.program is not None or b.tape or b.statements:
            if _is_marker(b):
                markers.append(i)
    program = Program(blocks, [], labels, [], [], [], markers)
    _derive_from_markers(program)
    return program


def update_program(program: Program, start: int, old_blocks: list[Block], new_blocks: list[Block]) -> None:
    """Patch ``program`` after ``old_blocks`` at ``start`` were replaced by ``new_blocks``
    (``program.blocks`` already holds the new list). Costs a look at each label and each
    marker, never a pass over the blocks; the result equals ``build_program``."""
    end = start + len(old_blocks)
    delta = len(new_blocks) - len(old_blocks)
    labels = program.labels
    for k, b in enumerate(old_blocks):
        if b.label is not None:
            lines = labels[b.label]
            lines.remove(start + k)
            if not lines:
                del labels[b.label]
    if delta:
        for lines in labels.values():
            if lines[-1] >= end:
                for j, x in enumerate(lines):
                    if x >= end:
                        lines[j] = x + delta
    for k, b in enumerate(new_blocks):
        if b.label is not None:
            found = labels.get(b.label)
            if found is None:
                labels[b.label] = [start + k]
            else:
                insort(found, start + k)

    markers = program.markers
    lo = bisect_left(markers, start)
    hi = bisect_left(markers, end)
    changed = hi > lo
    new_markers = [start + k for k, b in enumerate(new_blocks) if b.structural and _is_marker(b)]
    markers[lo:hi] = new_markers
    if delta:
        for j in range(lo + len(new_markers), len(markers)):
            markers[j] += delta
    if changed or new_markers or first_mark_turned(program, start, delta):
        _derive_from_markers(program)
    elif delta:
        program.shift(end, delta)
    else:  # the last program holds its closing '%', as _derive_from_markers ends it
        program.units[-1].end = len(program.blocks) if program.tape_end is None else program.tape_end + 1


def _derive_from_markers(program: Program) -> None:
    """Units, loop pairs and tape marks from the marker lines alone."""
    blocks = program.blocks
    n = len(blocks)
    units: list[ProgramUnit] = [ProgramUnit(None, None, 0, n)]
    loops: list[LoopPair] = []
    problems: list[LoopProblem] = []
    tape_marks: list[int] = []
    open_loops: list[tuple[int, int]] = []  # (number, DO line)
    if_blocks: list[IfBlock] = []
    if_problems: list[IfProblem] = []
    open_ifs: list[list[int | None]] = []  # [IF line, ELSE line or None, loops open at the IF]
    numbers: set[int] = set()
    unit = units[0]
    tape_end = None
    for i in program.markers:
        b = blocks[i]
        if b.tape:
            tape_marks.append(i)
            if len(tape_marks) > 1 or b.code_before_mark or _text_before(blocks, i):
                tape_end = i  # the closing '%': reading ends here (``read_end``)
                unit.end = i + 1  # the last program holds the line of its closing '%'
                break
        if b.program is not None:
            _close_unit(open_loops, problems)
            _close_ifs(open_ifs, if_problems)
            if unit.start == i:  # the header is the file's first line: replace the implicit unit
                units.pop()
            else:
                unit.end = i
            unit = ProgramUnit(b.program, b.title, i, n, b.program in numbers)
            numbers.add(b.program)
            units.append(unit)
        marker = b.loop_marker() if b.statements else None
        if marker is not None:
            kind, num = marker
            number = int(num.value) if num.value == int(num.value) else -1
            if kind == "DO":
                open_loops.append((number, i))
            else:
                _close_loop(number, i, open_loops, loops, problems)
        branch = b.branch_marker() if b.statements else None
        if branch is not None:
            _branch(branch, i, open_ifs, if_blocks, if_problems, open_loops)
    _close_unit(open_loops, problems)
    _close_ifs(open_ifs, if_problems)
    program.units = units
    program.loops = loops
    program.loop_problems = problems
    program.if_blocks = sorted(if_blocks, key=lambda f: f.if_line)
    program.if_problems = if_problems
    program.tape_marks = tape_marks
    program.tape_end = tape_end


def first_mark_turned(program: Program, start: int, delta: int) -> bool:
    """Whether an edit at ``start`` (no marker changed) turned the first '%' from the tape's start
    into its end or back: text was added before it where there was none, or the last removed."""
    marks = program.tape_marks
    if not marks or start > marks[0]:
        return False
    was_end = program.tape_end == marks[0]
    return was_end != _text_before(program.blocks, marks[0] + delta)


def _text_before(blocks: list[Block], line: int) -> bool:
    """Whether any line before ``line`` holds program text (the first '%' after program text
    ends the tape rather than starting it). Stops at the first such line: near the top."""
    return any(not (b.is_empty or b.tape) for b in islice(blocks, line))


def _close_loop(
    number: int,
    line: int,
    open_loops: list[tuple[int, int]],
    loops: list[LoopPair],
    problems: list[LoopProblem],
) -> None:
    if open_loops and open_loops[-1][0] == number:
        loops.append(LoopPair(number, open_loops.pop()[1], line))
        return
    for k in range(len(open_loops) - 1, -1, -1):
        if open_loops[k][0] == number:
            inner = open_loops[-1]
            problems.append(LoopProblem("crossing", line, number, inner[1]))
            loops.append(LoopPair(number, open_loops.pop(k)[1], line))
            return
    problems.append(LoopProblem("end-without-do", line, number))


def _branch(
    kind: str,
    line: int,
    open_ifs: list[list[int | None]],
    blocks: list[IfBlock],
    problems: list[IfProblem],
    open_loops: list[tuple[int, int]],
) -> None:
    """One block IF marker: an IF opens a block, an ELSE marks the innermost open one's second
    branch, an ENDIF closes it. A branch ends with as many loops open as at its IF, or it crosses one."""
    if kind == "IF":
        open_ifs.append([line, None, len(open_loops)])
        return
    if not open_ifs:
        problems.append(IfProblem("else-without-if" if kind == "ELSE" else "endif-without-if", line))
        return
    top = open_ifs[-1]
    if top[2] != len(open_loops):
        inside = open_loops[-1][1] if top[2] is not None and len(open_loops) > top[2] else None
        problems.append(IfProblem("crossing", line, inside))
    if kind == "ELSE":
        if top[1] is not None:
            problems.append(IfProblem("second-else", line, top[1]))
        else:
            top[1] = line
        return
    first, other, _ = open_ifs.pop()
    assert first is not None
    blocks.append(IfBlock(first, other, line))


def _close_ifs(open_ifs: list[list[int | None]], problems: list[IfProblem]) -> None:
    for first, *_ in open_ifs:
        assert first is not None
        problems.append(IfProblem("if-without-endif", first))
    open_ifs.clear()


def _close_unit(open_loops: list[tuple[int, int]], problems: list[LoopProblem]) -> None:
    for number, line in open_loops:
        problems.append(LoopProblem("do-without-end", line, number))
    open_loops.clear()
