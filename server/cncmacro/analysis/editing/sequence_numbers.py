"""Editing N labels so that every jump still lands where it landed: renumbering the labels of a
file or of some of its lines with a step, adding sequence numbers to the blocks without one and
removing the ones nothing jumps to (docs/editor.md "Sequence numbers").

Where each literal jump lands is decided by the interpreter's rules (``machine.jumps``:
``GOTO``/``IF..GOTO``/``G65 H80–H86`` search forward from the jump, then from the program's
start; ``M98 Q`` and a local call ``M97 P`` take the first label of the program; ``M99 P``
returns into each caller in the file, or in a main program takes its first label), so a jump to
one of two ``N10`` is rewritten to the new number of the one it lands on. A jump whose label the
run computes (``GOTO #1``, ``M99 P#2``, ``G65 H81 P#3``) may land on any label of the programs it
can reach; an edit that changes one of those labels is refused with the jump's line named
(``Blocker``), unless the caller asks to keep those labels as they are. Labels that jumps from
other files land on (``OutsideJump``: ``M98 P.. Q..`` into a program of this file, ``M99 P`` of a
program it calls) are always kept, and so is ``Nn`` for an ``M99 Pn`` of a file's only program
that nothing in the file calls (run as a main program it jumps there; called, it returns to the
caller). New numbers never take a number that a label kept in the same
program, or a jump that finds no label there, already uses: a jump that stopped the run with
alarm 128 must not start landing.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

from ...bilingual import pick
from ...dialects.dialect import Dialect
from ...library.machine_file import CallCode
from ...machine.block_roles import passed_over
from ...machine.jumps import first_line, goto_line, return_line
from ...syntax.nodes import Block, Word
from ...syntax.program import Program, ProgramUnit
from ..indexes.call_sites import call_site
from ..indexes.sites import computed_jump_sites, jump_sites, starts_from_the_top

MAX_SEQUENCE_NUMBER = 99999  # N1 to N99999 (docs/semantics.md §4, alarm 128 beyond)


@dataclass(frozen=True, slots=True)
class TextChange:
    """Replace columns ``start``..``end`` of ``line`` (code points) with ``text``."""

    line: int
    start: int
    end: int
    text: str


@dataclass(frozen=True, slots=True)
class Blocker:
    """A jump the edit cannot keep landing where it landed: one whose label the run computes and
    that could land on a label the edit changes, or an ``M99 P`` whose callers' labels would get
    different numbers."""

    line: int
    start: int
    end: int
    message: str
    keepable: bool = True  # False: keeping the labels computed jumps reach does not help


@dataclass(frozen=True, slots=True)
class OutsideJump:
    """A jump from another file onto a program of this one: ``unit_start`` is the program's
    first line, ``label`` the literal label (None when computed), ``where`` names the jump."""

    unit_start: int
    label: int | None
    where: str


@dataclass(slots=True)
class SequencePlan:
    """What an edit of sequence numbers does: its text changes, or the blockers that refuse it;
    ``kept`` are label lines left as they are (computed or outside jumps may land there)."""

    changes: list[TextChange] = field(default_factory=list)
    blockers: list[Blocker] = field(default_factory=list)
    kept: list[int] = field(default_factory=list)
    error: str | None = None


@dataclass(frozen=True, slots=True)
class _Jump:
    """A literal jump: the label lines it lands on (one per caller for ``M99 P``)."""

    line: int
    start: int
    end: int
    label: int
    targets: tuple[int, ...]
    units: tuple[int, ...]  # first lines of the programs it searches


@dataclass(frozen=True, slots=True)
class _Computed:
    line: int
    start: int
    end: int
    kind: str
    units: tuple[int, ...]


class _FileJumps:
    """Every jump of one file, resolved by the interpreter's rules to the lines it lands on."""

    def __init__(self, program: Program, dialect: Dialect, calls: Mapping[str, CallCode] | None) -> None:
        self.program = program
        self.units = {u.start: u for u in program.units}
        self.literal: list[_Jump] = []
        self.computed: list[_Computed] = []
        blocks = program.blocks
        self.ambiguous: set[tuple[int, int]] = set()  # (unit start, label) an M99 P may mean here or not
        self.callers: dict[int, list[int]] = {}  # unit start -> call lines of it in this file
        self.called: dict[int, int] = {}  # call line -> unit start of the program it calls
        for i in range(program.read_end):
            site = call_site(blocks[i], dialect, calls)
            if site is not None and site.number is not None:
                unit = program.unit_numbered(site.number)
                if unit is not None:
                    self.callers.setdefault(unit.start, []).append(i)
                    self.called[i] = unit.start
        for i in range(program.read_end):
            b = blocks[i]
            for j in jump_sites(b, dialect, calls):
                units = self._searched(i, j.kind)
                if j.kind == "M98 Q" and not units:  # M98 P#1 Q10: the program is computed, maybe this one
                    self.computed.append(_Computed(i, j.start, j.end, "M98 P", tuple(self.units)))
                    continue
                if j.kind == "M99" and self._alone(i):  # a main program's jump, or a return to a caller elsewhere
                    self.ambiguous.add((self.program.unit_at(i).start, j.label))
                    continue
                targets = {t for u in units for t in self._lands(i, j.kind, j.label, u)}
                self.literal.append(_Jump(i, j.start, j.end, j.label, tuple(sorted(targets)), units))
            for kind, start, end in computed_jump_sites(b, dialect, calls):
                self.computed.append(_Computed(i, start, end, kind, self._searched(i, kind)))

    def _alone(self, line: int) -> bool:
        """Whether ``line`` is in the only program of the file and nothing in the file calls it:
        run as a main program, its ``M99 P`` jumps to its own label; called from another file,
        it returns to a label of the caller."""
        units = self.program.units
        return len(units) == 1 and not self.callers.get(units[0].start)

    def _searched(self, line: int, kind: str) -> tuple[int, ...]:
        """The programs of this file (by first line) a jump of ``kind`` on ``line`` looks in."""
        unit = self.program.unit_at(line)
        if kind == "M99":
            lines = self.callers.get(unit.start)
            if lines:
                return tuple(sorted({self.program.unit_at(c).start for c in lines}))
            return (unit.start,) if unit is self.program.units[0] else ()
        if kind == "M98 Q":
            if line in self.called:
                return (self.called[line],)
            names_one = any(w.letter == "P" for w in self.program.blocks[line].words)
            return () if names_one else (unit.start,)  # P of another file or computed: not here
        return (unit.start,)

    def _lands(self, line: int, kind: str, label: int, unit_start: int) -> list[int]:
        lines = self.program.label_lines(label, self.units[unit_start])
        own = self.program.unit_at(line).start
        if kind == "M99" and own != unit_start:  # back into a caller, after its call line
            calls = [c for c in self.callers.get(own, []) if self.program.unit_at(c).start == unit_start]
            return [t for c in calls if (t := return_line(lines, c)) is not None]
        t = first_line(lines) if kind == "M99" or starts_from_the_top(kind) else goto_line(lines, line)
        return [] if t is None else [t]


def _unit_name(unit: ProgramUnit, locale: str) -> str:
    return f"O{unit.number:04d}" if unit.number is not None else pick(locale, "this program", "本程序")


class _Plan:
    """What the three edits share: the file's jumps, the lines asked for, the labels kept."""

    def __init__(
        self,
        program: Program,
        dialect: Dialect,
        lines: range | None,
        locale: str,
        calls: Mapping[str, CallCode] | None,
        outside: Iterable[OutsideJump],
    ) -> None:
        self.program = program
        self.locale = locale
        end = program.read_end
        self.lines = range(0, end) if lines is None else range(max(0, lines.start), min(lines.stop, end))
        self.jumps = _FileJumps(program, dialect, calls)
        self.landed = {t for j in self.jumps.literal for t in j.targets}
        self.outside_labels: dict[int, set[int]] = {}
        for unit, label in self.jumps.ambiguous:
            self.outside_labels.setdefault(unit, set()).add(label)
        self.outside_any: set[int] = set()
        for o in outside:
            if o.label is None:
                self.outside_any.add(o.unit_start)
            else:
                self.outside_labels.setdefault(o.unit_start, set()).add(o.label)

    def label_lines(self) -> list[int]:
        blocks = self.program.blocks
        return [i for i in self.lines if blocks[i].label is not None and blocks[i].label_span is not None]

    def unit_of(self, line: int) -> int:
        return self.program.unit_at(line).start

    def outside_reaches(self, line: int) -> bool:
        """Whether a jump from another file may land on the label of ``line``."""
        unit = self.unit_of(line)
        label = self.program.blocks[line].label
        return unit in self.outside_any or label in self.outside_labels.get(unit, ())

    def blockers(self, units: set[int], en: str, zh: str) -> tuple[list[Blocker], set[int]]:
        """The computed jumps that could land in one of ``units`` (programs whose labels the
        edit changes), and the programs they reach."""
        out: list[Blocker] = []
        reached: set[int] = set()
        for c in self.jumps.computed:
            hit = [u for u in c.units if u in units]
            if not hit:
                continue
            reached.update(hit)
            name = _unit_name(self.jumps.units[hit[0]], self.locale)
            message = pick(
                self.locale,
                f"line {c.line + 1}: the label of this {c.kind} is computed when it runs; it could land on a "
                f"label of {name} that {en}",
                f"第 {c.line + 1} 行：此 {c.kind} 的顺序号在运行时算出，可能落在 {name} 中{zh}的顺序号上",
            )
            out.append(Blocker(c.line, c.start, c.end, message))
        return out, reached

    def numbers_in_use(self, unit: int, moving: set[int]) -> set[int]:
        """Label numbers a new number must not take in program ``unit``: labels that stay, labels
        jumps of other files name, and labels that jumps there name but do not find."""
        program = self.program
        u = self.jumps.units[unit]
        used = {
            b.label for i in range(u.start, min(u.end, len(program.blocks)))
            if (b := program.blocks[i]).label is not None and i not in moving
        }  # fmt: skip
        used |= self.outside_labels.get(unit, set())
        used |= {j.label for j in self.jumps.literal if unit in j.units and not j.targets}
        return used

    def rewrite_jumps(self, new: Mapping[int, int]) -> tuple[list[TextChange], list[Blocker]]:
        """The jumps that land on a label line given a new number (``new``), rewritten to it;
        an ``M99 P`` whose callers' labels would part ways is a blocker."""
        out: list[TextChange] = []
        split: list[Blocker] = []
        for j in self.jumps.literal:
            if not any(t in new for t in j.targets):
                continue
            numbers = {new.get(t, j.label) for t in j.targets}
            if len(numbers) > 1:
                split.append(Blocker(j.line, j.start, j.end, pick(
                    self.locale,
                    f"line {j.line + 1}: M99 P{j.label} returns to N{j.label} in more than one caller, and "
                    f"those labels would get different numbers",
                    f"第 {j.line + 1} 行：M99 P{j.label} 返回到多个调用者中的 N{j.label}，这些顺序号会被改成不同的号",
                ), keepable=False))  # fmt: skip
            elif (n := numbers.pop()) != j.label:
                out.append(TextChange(j.line, j.start, j.end, str(n)))
        return out, split


def _refused(
    plan: _Plan, touched: list[int], keep_computed: bool, en: str, zh: str
) -> tuple[SequencePlan | None, set[int]]:
    units = {plan.unit_of(i) for i in touched}
    blockers, reached = plan.blockers(units, en, zh)
    if blockers and not keep_computed:
        return SequencePlan(blockers=blockers), reached
    return None, reached


def renumber(
    program: Program,
    dialect: Dialect,
    *,
    step: int,
    start: int | None = None,
    lines: range | None = None,
    keep_computed: bool = False,
    locale: str = "en",
    calls: Mapping[str, CallCode] | None = None,
    outside: Iterable[OutsideJump] = (),
) -> SequencePlan:
    """Number the labels on ``lines`` (the whole file when None) ``start``, ``start + step``, …
    in each program, and rewrite every literal jump that lands on one of them."""
    first = step if start is None else start
    if step < 1 or not 1 <= first <= MAX_SEQUENCE_NUMBER:
        return SequencePlan(error=pick(locale, "the step and the first number must be 1 or more",
                                       "步长和起始号必须不小于 1"))  # fmt: skip
    plan = _Plan(program, dialect, lines, locale, calls, outside)
    labelled = plan.label_lines()
    refused, reached = _refused(plan, labelled, keep_computed, "this renumbering changes", "本次重新编号要改变")
    if refused is not None:
        return refused
    kept = [i for i in labelled if plan.unit_of(i) in reached or plan.outside_reaches(i)]
    moving = [i for i in labelled if i not in kept]
    new: dict[int, int] = {}
    by_unit: dict[int, list[int]] = {}
    for i in moving:
        by_unit.setdefault(plan.unit_of(i), []).append(i)
    for unit, label_lines in by_unit.items():
        used = plan.numbers_in_use(unit, set(label_lines))
        n = first
        for i in label_lines:
            while n in used:
                n += step
            if n > MAX_SEQUENCE_NUMBER:
                return SequencePlan(error=_too_high(locale))
            new[i] = n
            n += step
    changes: list[TextChange] = []
    for i, n in new.items():
        b = program.blocks[i]
        assert b.label_span is not None
        if n != b.label:
            changes.append(TextChange(i, b.label_span[0], b.label_span[1], f"N{n}"))
    jumps, split = plan.rewrite_jumps(new)
    if split:
        return SequencePlan(blockers=split)
    changes += jumps
    return SequencePlan(changes=_sorted(changes), kept=kept)


def add_sequence_numbers(
    program: Program,
    dialect: Dialect,
    *,
    step: int,
    lines: range | None = None,
    keep_computed: bool = False,
    locale: str = "en",
    calls: Mapping[str, CallCode] | None = None,
    outside: Iterable[OutsideJump] = (),
) -> SequencePlan:
    """Give each block on ``lines`` that runs and has no sequence number one: the next multiple
    of ``step`` after the label before it in its program that no label or jump there uses.
    Labels already written stay, so no jump changes where it lands. A block IF's ``ELSE`` and
    ``ENDIF`` get none: they mark where a branch ends, and a label there would be a jump target
    inside the branch (docs/editor.md "Sequence numbers")."""
    if step < 1:
        return SequencePlan(error=pick(locale, "the step must be 1 or more", "步长必须不小于 1"))
    plan = _Plan(program, dialect, lines, locale, calls, outside)
    blocks = program.blocks
    bare = [
        i for i in plan.lines
        if blocks[i].label is None and not passed_over(blocks[i], False) and not _has_errors(blocks[i])
        and blocks[i].program is None and blocks[i].branch_marker() not in ("ELSE", "ENDIF")
    ]  # fmt: skip
    refused, reached = _refused(plan, bare, keep_computed, "these new numbers could create",
                                "新加的顺序号可能产生")  # fmt: skip
    if refused is not None:
        return refused
    changes: list[TextChange] = []
    used_by_unit: dict[int, set[int]] = {}
    previous: dict[int, int] = {}
    numbered = set(bare)  # asked for once per line: a long program must not cost the square
    for i in plan.lines:
        unit = plan.unit_of(i)
        if unit in reached:
            continue
        used = used_by_unit.get(unit)
        if used is None:
            used = used_by_unit[unit] = plan.numbers_in_use(unit, set())
        label = blocks[i].label
        if label is not None:
            previous[unit] = label
            continue
        if i not in numbered:
            continue
        n = (previous.get(unit, 0) // step + 1) * step
        while n in used:
            n += step
        if n > MAX_SEQUENCE_NUMBER:
            return SequencePlan(error=_too_high(locale))
        used.add(n)
        previous[unit] = n
        at = _code_start(blocks[i])
        changes.append(TextChange(i, at, at, f"N{n} "))
    return SequencePlan(changes=changes)


def remove_unused_sequence_numbers(
    program: Program,
    dialect: Dialect,
    *,
    lines: range | None = None,
    keep_computed: bool = False,
    locale: str = "en",
    calls: Mapping[str, CallCode] | None = None,
    outside: Iterable[OutsideJump] = (),
) -> SequencePlan:
    """Take out the labels on ``lines`` that no jump lands on (by the interpreter's rules), nor a
    jump of another file names; a label a computed jump could reach refuses the edit, or is
    kept when ``keep_computed``."""
    plan = _Plan(program, dialect, lines, locale, calls, outside)
    unused = [i for i in plan.label_lines() if i not in plan.landed and not plan.outside_reaches(i)]
    refused, reached = _refused(plan, unused, keep_computed, "this edit removes", "本次编辑要删除")
    if refused is not None:
        return refused
    kept = [i for i in unused if plan.unit_of(i) in reached]
    changes: list[TextChange] = []
    for i in unused:
        if i in kept:
            continue
        b = program.blocks[i]
        assert b.label_span is not None
        start, end = b.label_span
        after = [x for x in (*b.words, *b.statements, *b.corners)]
        first = min(after, key=lambda x: x.start) if after else None
        if isinstance(first, Word) and first.letter == "N":  # N10 N20: without N10, N20 would be the label
            continue
        changes.append(TextChange(i, start, first.start if first is not None else end, ""))
    return SequencePlan(changes=changes, kept=kept)


def _too_high(locale: str) -> str:
    return pick(
        locale,
        f"the new numbers would pass N{MAX_SEQUENCE_NUMBER}: take a smaller step",
        f"新顺序号会超过 N{MAX_SEQUENCE_NUMBER}，请用更小的步长",
    )


def _has_errors(block: Block) -> bool:
    return any(p.severity == "error" for p in block.problems)


def _code_start(block: Block) -> int:
    """The column of the first word or statement of a block."""
    starts = [x.start for x in (*block.words, *block.statements, *block.corners)]
    return min(starts) if starts else 0


def _sorted(changes: list[TextChange]) -> list[TextChange]:
    return sorted(changes, key=lambda c: (c.line, c.start))
