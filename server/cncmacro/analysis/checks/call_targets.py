"""Finding the programs that calls name, for ``program-not-found`` (docs/semantics.md §5).

A call's literal target is looked up as the interpreter looks it up: among the O programs of
the calling file first, then through the ``ProgramLibrary`` near the file (``find_number``,
and on gsk980tdi ``find_name`` for ``P[CUT]``). Without a library only the file's own programs
are known, so a target that is not among them is left to the run rather than reported.
"""

from __future__ import annotations

from ...bilingual import Detail, pick
from ...dialects.alarms import PROGRAM_NOT_FOUND
from ...dialects.dialect import Dialect
from ...library.programs import FoundProgram, LoadedFile, ProgramLibrary
from ...syntax.program import Program
from ..diagnostics import Diagnostic, diagnostic
from ..indexes.call_sites import CallSite

UNKNOWN = "unknown"


class ProgramFinder:
    """Looks up call targets for one file, each target once."""

    def __init__(self, program: Program, file: str, dialect: Dialect, library: ProgramLibrary | None) -> None:
        self.dialect = dialect
        self.program = program
        self.near = LoadedFile(file, [], program, dialect.name)
        self.library = library
        self._numbers: dict[int, FoundProgram | None] = {}
        self._names: dict[str, FoundProgram | None] = {}

    def find(self, site: CallSite, line: int) -> FoundProgram | str | None:
        """The program ``site`` calls; None when it does not exist; ``UNKNOWN`` when that
        cannot be told without a library."""
        if site.number is None and site.name is None:
            return FoundProgram(self.near, self.program.unit_at(line))  # M98 Q: the current program
        if site.number is not None:
            number = site.number
            if number not in self._numbers:
                unit = self.program.unit_numbered(number)
                if unit is not None:
                    self._numbers[number] = FoundProgram(self.near, unit)
                elif self.library is None:
                    return UNKNOWN
                else:
                    found = self.library.find_number(number, self.near)
                    if found is None and self.dialect.on_control(number):
                        found = self.library.control_program(number)
                    self._numbers[number] = found
            return self._numbers[number]
        name = site.name or ""
        if self.library is None:
            return UNKNOWN
        if name not in self._names:
            self._names[name] = self.library.find_name(name, self.near)
        return self._names[name]

    def unread(self, site: CallSite) -> Detail | None:
        """Why the file named for ``site``'s program could not be read, if that is why it was
        not found."""
        if site.number is None or self.library is None:
            return None
        return self.library.unread_for(site.number, self.near)

    def is_this_file(self, found: FoundProgram) -> bool:
        return found.file is self.near


def not_found(site: CallSite, file: str, line: int, locale: str, dialect: Dialect,
              unread: Detail | None = None) -> Diagnostic:  # fmt: skip
    """The ``program-not-found`` diagnostic of a call whose program does not exist; ``unread``:
    why the file named for it could not be read (``ProgramLibrary.unread_for``)."""
    if site.number is not None:
        what = f"O{site.number:04d}"
    else:
        what = f"[{site.name}]"
    alarm = dialect.alarm_said(PROGRAM_NOT_FOUND)
    if unread is not None:
        message = pick(locale, f"{site.kind} calls {what}, not found: {unread} ({alarm})",
                       f"{site.kind} 调用的程序 {what} 未找到：{unread.zh}（{alarm.zh}）")  # fmt: skip
    else:
        message = pick(
            locale,
            f"{site.kind} calls {what}, which is neither in this file nor found near it ({alarm})",
            f"{site.kind} 调用的程序 {what} 不在本文件中，附近也找不到（{alarm.zh}）",
        )
    end = max(site.end, site.start + 1)
    return diagnostic(file, line, site.start, line, end, "program-not-found", message)
