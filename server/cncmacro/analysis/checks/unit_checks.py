"""Checks of the O programs of a file (docs/semantics.md §1): ``duplicate-program``.

Which copy of a repeated O number the control keeps is decided once, in ``syntax/program.py``
(``ProgramUnit.duplicate``: the first one). Here each header that the control does not keep
earns a warning that points at the program it keeps: nothing calls or runs the copy, so its
blocks are dead text however correct they look.
"""

from __future__ import annotations

from ...bilingual import detail, pick
from ...dialects.alarms import DUPLICATE_PROGRAM
from ...dialects.dialect import Dialect
from ...syntax.program import Program
from ..diagnostics import Diagnostic, Related, diagnostic


def duplicate_program_diagnostics(program: Program, file: str, locale: str, dialect: Dialect) -> list[Diagnostic]:
    """One ``duplicate-program`` warning on each header that repeats an earlier O number; the
    alarm a FANUC control gives when it loads the copy is named with its number only where
    ``dialect`` shows it."""
    out: list[Diagnostic] = []
    if dialect.shown_alarm(DUPLICATE_PROGRAM) is None:
        loading = detail("an alarm", "输入时报警")
    else:
        said = dialect.alarm_said(DUPLICATE_PROGRAM, 3)
        loading = detail(f"FANUC {said}", f"FANUC 输入时{said.zh}")
    for unit in program.units:
        if not unit.duplicate or unit.number is None:
            continue
        kept = program.unit_numbered(unit.number)
        if kept is None:
            continue
        name = f"O{unit.number:04d}"
        block = program.blocks[unit.start]
        start, end = block.program_span or (0, 1)
        en = (
            f"{name} is already the program at line {kept.start + 1}: the control keeps that one and ignores "
            f"this copy (loading it is {loading}), so nothing calls or runs the blocks below"
        )
        zh = (
            f"{name} 与第 {kept.start + 1} 行的程序号重复：系统只保留前一个程序，此处的程序被忽略"
            f"（{loading.zh}），下面的程序段不会被调用或运行"
        )
        kept_span = program.blocks[kept.start].program_span or (0, 1)
        related = (Related(file, kept.start, kept_span[0], kept_span[1],
                           pick(locale, f"the {name} that the control keeps", f"系统保留的 {name}")),)  # fmt: skip
        out.append(diagnostic(file, unit.start, start, unit.start, max(end, start + 1),
                              "duplicate-program", pick(locale, en, zh), related))  # fmt: skip
    return out
