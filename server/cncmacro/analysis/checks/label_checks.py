"""Label checks across lines (docs/semantics.md §4, §5): where jumps, ``M98 Q`` and ``M99 P`` land.

A literal ``GOTO n`` (also ``IF..GOTO`` and gsk980tdi ``G65 H80–H86 P n``) looks for ``Nn`` in its
own O program, forward from the jump and then from the program's start, as the interpreter's
``CompiledFile.jump`` does: no such label is ``undefined-label`` (alarm 128), a label inside a
loop that the jump is not in is ``jump-into-loop``, and one inside a branch of a block IF that the
jump is not in is ``jump-into-if``. ``M98 Q n`` looks in the called program, a
local subprogram call (Haas ``M97 P n``) in its own.
``M99 P n`` of a program called from this file looks in each caller; in a file's first program,
when nothing in the file calls it and other programs follow it (the main program), in itself;
anywhere else it is left to the run. A label used more than once where a jump goes to it is
``duplicate-label`` (a warning: the search rule still picks one).
"""

from __future__ import annotations

from bisect import bisect_right

from ...bilingual import pick
from ...dialects import Dialect
from ...dialects.alarms import SEQUENCE_NUMBER, STATEMENT_FORMAT
from ...machine.jumps import LoopSpans, branch_entered, goto_line
from ...syntax.program import LoopPair, Program, ProgramUnit
from ..diagnostics import Diagnostic, Related, diagnostic
from ..indexes.call_sites import CallSite
from .call_targets import UNKNOWN, ProgramFinder, not_found
from .line_facts import LineFacts


def _unit_name(unit: ProgramUnit, locale: str) -> str:
    if unit.number is not None:
        return f"O{unit.number:04d}"
    return pick(locale, "this program", "本程序")


class LabelChecker:
    """The cross-line label and call checks of one file."""

    def __init__(self, program: Program, file: str, finder: ProgramFinder, locale: str, dialect: Dialect) -> None:
        self.program = program
        # "alarm 128" as the control shows it ("alarm" alone where it documents no number)
        said = dialect.alarm_said(SEQUENCE_NUMBER)
        self._alarm, self._alarm_zh = str(said), said.zh
        self.file = file
        self.finder = finder
        self.locale = locale
        self.dialect = dialect
        self.out: list[Diagnostic] = []
        self._starts = [u.start for u in program.units]
        self._duplicates: dict[tuple[int, int], ProgramUnit] = {}  # (unit start, label) -> unit
        self._callers: dict[int, list[tuple[int, CallSite]]] = {}  # unit start -> [(call line, call)]
        self._spans: LoopSpans | None = None  # the program's loops, made at the first jump
        self._loops: dict[int, LoopPair] = {}  # by DO line

    def unit_of(self, line: int) -> ProgramUnit:
        units = self.program.units
        return units[max(0, bisect_right(self._starts, line) - 1)]

    def run(self, facts: list[tuple[int, LineFacts]]) -> list[Diagnostic]:
        for line, f in facts:
            for jump in f.jumps:
                self._jump(line, jump.label, jump.start, jump.end, jump.how)
            for site in f.calls:
                self._call(line, site)
        for line, f in facts:
            for r in f.returns:
                self._return(line, r.label, r.start, r.end)
        for (_, label), unit in self._duplicates.items():
            self._duplicate(unit, label)
        return self.out

    def _loop_entered(self, line: int, target: int) -> LoopPair | None:
        """The loop that a jump from ``line`` to ``target`` enters from outside, if any (the
        interpreter's rule, ``machine.jumps.LoopSpans``)."""
        if self._spans is None:
            self._loops = {p.do_line: p for p in self.program.loops}
            self._spans = LoopSpans({do: p.end_line for do, p in self._loops.items()})
        do = self._spans.entered(line, target)
        return None if do is None else self._loops[do]

    # ---------------------------------------------------------------- GOTO and H80-H86
    def _jump(self, line: int, label: int, start: int, end: int, how: str) -> None:
        unit = self.unit_of(line)
        lines = self.program.label_lines(label, unit)
        loc = self.locale
        if not lines:
            self._missing(line, start, end, label, unit,
                          pick(loc, f"{how}{label}: there is no N{label} in {_unit_name(unit, loc)} ({self._alarm})",
                               f"{how}{label}：{_unit_name(unit, loc)} 中没有 N{label}"
                               f"（{self._alarm_zh}）"))  # fmt: skip
            return
        if len(lines) > 1:
            self._duplicates[(unit.start, label)] = unit
        target = goto_line(lines, line)
        assert target is not None
        loop = self._loop_entered(line, target)
        if loop is not None:
            span = _label_span(self.program, loop.do_line)
            self.out.append(
                diagnostic(self.file, line, start, line, max(end, start + 1), "jump-into-loop",
                           pick(loc, f"{how}{label} jumps into the loop DO {loop.number} (lines {loop.do_line + 1}–"
                                     f"{loop.end_line + 1}) from outside it",
                                f"{how}{label} 从循环外跳入 DO {loop.number} 循环（第 {loop.do_line + 1}～"
                                f"{loop.end_line + 1} 行）"),
                           (Related(self.file, target, *_label_span(self.program, target),
                                    pick(loc, f"N{label}, inside the loop", f"N{label}，位于循环内")),
                            Related(self.file, loop.do_line, *span, pick(loc, "the loop starts here", "循环从此开始"))))
            )  # fmt: skip
            return
        branch = branch_entered(self.program.if_blocks, line, target) if self.dialect.block_if else None
        if branch is not None:
            first, last = branch
            alarm = self.dialect.alarm_said(STATEMENT_FORMAT)
            self.out.append(
                diagnostic(self.file, line, start, line, max(end, start + 1), "jump-into-if",
                           pick(loc, f"{how}{label} jumps into a branch of the IF [...] THEN block (lines {first + 1}–"
                                     f"{last + 1}) from outside it ({alarm})",
                                f"{how}{label} 从外部跳入 IF [...] THEN 块的分支（第 {first + 1}～{last + 1} 行）"
                                f"（{alarm.zh}）"),
                           (Related(self.file, target, *_label_span(self.program, target),
                                    pick(loc, f"N{label}, inside the branch", f"N{label}，位于分支内")),
                            Related(self.file, first, *_label_span(self.program, first),
                                    pick(loc, "the branch starts here", "分支从此开始"))))
            )  # fmt: skip

    def _missing(self, line: int, start: int, end: int, label: int, unit: ProgramUnit, message: str,
                 related: tuple[Related, ...] = ()) -> None:  # fmt: skip
        self.out.append(
            diagnostic(self.file, line, start, line, max(end, start + 1), "undefined-label", message, related)
        )

    # ---------------------------------------------------------------- calls, M98 Q and M97 P
    def _call(self, line: int, site: CallSite) -> None:
        found = self.finder.find(site, line)
        if found == UNKNOWN:
            return
        if found is None:
            self.out.append(not_found(site, self.file, line, self.locale, self.dialect, self.finder.unread(site)))
            return
        assert not isinstance(found, str)
        here = self.finder.is_this_file(found)
        if here and site.number is not None:
            self._callers.setdefault(found.unit.start, []).append((line, site))
        if site.label is None:
            return
        q = site.label
        lines = found.file.program.label_lines(q, found.unit)
        loc = self.locale
        if not lines:
            where = _unit_name(found.unit, loc) if found.unit.number is not None else found.label
            self._missing(line, site.label_span[0], site.label_span[1], q, found.unit,
                          pick(loc, f"{site.kind} {site.label_letter}{q}: there is no N{q} in {where} ({self._alarm})",
                               f"{site.kind} {site.label_letter}{q}：{where} 中没有 N{q}"
                               f"（{self._alarm_zh}）"))  # fmt: skip
        elif len(lines) > 1 and here:
            self._duplicates[(found.unit.start, q)] = found.unit

    # ---------------------------------------------------------------- M99 P
    def _return(self, line: int, label: int, start: int, end: int) -> None:
        unit = self.unit_of(line)
        callers = self._callers.get(unit.start)
        loc = self.locale
        if callers:
            for call_line, site in callers:
                caller = self.unit_of(call_line)
                lines = self.program.label_lines(label, caller)
                if not lines:
                    name = _unit_name(caller, loc)
                    message = pick(
                        loc,
                        f"M99 P{label}: the caller {name} has no N{label} to return to ({self._alarm})",
                        f"M99 P{label}：调用者 {name} 中没有可返回的 N{label}（{self._alarm_zh}）",
                    )
                    call = Related(self.file, call_line, site.start, site.end,
                                   pick(loc, f"the {site.kind} call", f"{site.kind} 调用"))  # fmt: skip
                    self._missing(line, start, end, label, caller, message, (call,))
                    return
                if len(lines) > 1:
                    self._duplicates[(caller.start, label)] = caller
            return
        units = self.program.units
        if unit is units[0] and len(units) > 1:  # the main program: M99 P jumps in itself
            lines = self.program.label_lines(label, unit)
            if not lines:
                name = _unit_name(unit, loc)
                message = pick(
                    loc,
                    f"M99 P{label} in the main program jumps to N{label}, which is not in {name} ({self._alarm})",
                    f"主程序中的 M99 P{label} 跳转到 N{label}，但 {name} 中没有（{self._alarm_zh}）",
                )
                self._missing(line, start, end, label, unit, message)
            elif len(lines) > 1:
                self._duplicates[(unit.start, label)] = unit

    # ---------------------------------------------------------------- duplicates
    def _duplicate(self, unit: ProgramUnit, label: int) -> None:
        lines = self.program.label_lines(label, unit)
        loc = self.locale
        first = lines[0]
        f_start, f_end = _label_span(self.program, first)
        for line in lines[1:]:
            start, end = _label_span(self.program, line)
            self.out.append(
                diagnostic(self.file, line, start, line, end, "duplicate-label",
                           pick(loc, f"N{label} is used {len(lines)} times in {_unit_name(unit, loc)} and a jump "
                                     "goes to it: the control takes the first one it finds",
                                f"N{label} 在 {_unit_name(unit, loc)} 中出现 {len(lines)} 次且是跳转目标："
                                "系统只会转到最先找到的那一个"),
                           (Related(self.file, first, f_start, f_end, pick(loc, f"the first N{label}",
                                                                             f"第一个 N{label}")),))
            )  # fmt: skip


def _label_span(program: Program, line: int) -> tuple[int, int]:
    b = program.blocks[line]
    if b.label_span is not None:
        return b.label_span
    for s in b.statements:
        return s.start, s.end
    return 0, 1
