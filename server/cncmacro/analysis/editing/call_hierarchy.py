"""Who calls whom, program by program, across the workspace: the callers and callees of an O
program for the editor's call hierarchy. A call is what ``call_sites.call_site`` says a block
calls (``G65``/``G66 P``, ``M98 P``, ``M198``, the machine file's call codes such as ``G100``),
resolved as a run resolves it (``ProgramLibrary``: the caller's own file first, then its folder
and the workspace folders); a local subprogram call (Haas ``M97 P n``) calls the label ``Nn`` of
its own program, which lands as ``M98 Q`` does (``machine.jumps.first_line``).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path

from ...dialects.dialect import Dialect
from ...library.file_cache import LoadedFile
from ...library.machine_file import CallCode
from ...library.programs import FoundProgram, ProgramLibrary
from ...machine.jump_words import local_call_kind
from ...machine.jumps import first_line
from ...syntax.program import ProgramUnit
from ..indexes.call_sites import CallSite, calls_on
from ..indexes.sites import jump_sites

Calls = Mapping[str, CallCode] | None
Span = tuple[int, int, int]  # line, start, end


@dataclass(frozen=True, slots=True)
class CallTarget:
    """A program (``label`` None) or the label a local subprogram call enters: its file, its
    lines (``start``..``end``, end exclusive) and the columns that name it on ``start``."""

    path: str
    start: int
    end: int
    number: int | None
    label: int | None
    title: str | None
    span: tuple[int, int]

    @property
    def name(self) -> str:
        program = f"O{self.number:04d}" if self.number is not None else Path(self.path).stem
        return program if self.label is None else f"N{self.label} ({program})"


def program_item(f: LoadedFile, unit: ProgramUnit) -> CallTarget:
    b = f.program.blocks[unit.start] if unit.start < len(f.program.blocks) else None
    span = b.program_span if b is not None and b.program_span else (0, 0)
    return CallTarget(f.path, unit.start, unit.end, unit.number, None, unit.title, span)


def label_item(f: LoadedFile, unit: ProgramUnit, label: int) -> CallTarget | None:
    line = first_line(f.program.label_lines(label, unit))
    if line is None:
        return None
    b = f.program.blocks[line]
    span = b.label_span or (0, 0)
    return CallTarget(f.path, line, line + 1, unit.number, label, unit.title, span)


def _local_calls(f: LoadedFile, unit: ProgramUnit, dialect: Dialect, calls: Calls) -> list[tuple[int, int, int, int]]:
    """(line, start, end, label) of the local subprogram calls of ``unit``."""
    code = dialect.local_subprogram_code
    if code is None:
        return []
    kind = local_call_kind(code)
    blocks = f.program.blocks
    return [
        (i, j.start, j.end, j.label)
        for i in range(unit.start, min(unit.end, f.program.read_end))
        for j in jump_sites(blocks[i], dialect, calls)
        if j.kind == kind
    ]


def outgoing(
    library: ProgramLibrary, f: LoadedFile, item: CallTarget, dialect: Dialect, calls: Calls
) -> list[tuple[CallTarget, list[Span]]]:
    """The programs (and local labels) ``item`` calls, each with the spans of its calls."""
    unit = f.program.unit_at(item.start)
    lines = range(item.start, min(item.end if item.label is None else unit.end, f.program.read_end))
    out: dict[CallTarget, list[Span]] = {}
    for i, _, site in calls_on(f.program.blocks, lines, dialect, calls):
        found = _called(library, site, f)
        if found is None or found.file.on_control:
            continue
        out.setdefault(program_item(found.file, found.unit), []).append((i, site.target.start, site.target.end))
    for i, start, end, label in _local_calls(f, unit, dialect, calls):
        if i in lines and (target := label_item(f, unit, label)) is not None:
            out.setdefault(target, []).append((i, start, end))
    return list(out.items())


def incoming(
    library: ProgramLibrary,
    files: list[LoadedFile],
    item: CallTarget,
    dialect_for: Callable[[list[str], str], Dialect],
    calls_for: Callable[[str], Calls],
) -> list[tuple[CallTarget, list[Span]]]:
    """The programs that call ``item``, each with the spans of its calls."""
    out: dict[CallTarget, list[Span]] = {}
    if item.label is not None:
        f = next((x for x in files if x.path == item.path), None)
        if f is None:
            return []
        unit = f.program.unit_at(item.start)
        for i, start, end, label in _local_calls(f, unit, dialect_for(f.lines, f.path), calls_for(f.path)):
            if label == item.label and label_item(f, unit, label) == item:
                caller = program_item(f, f.program.unit_at(i))
                out.setdefault(caller, []).append((i, start, end))
        return list(out.items())
    stem = Path(item.path).stem.upper()
    for f in files:
        dialect = dialect_for(f.lines, f.path)
        calls = calls_for(f.path)
        for i, _, site in calls_on(f.program.blocks, range(f.program.read_end), dialect, calls):
            if site.number is not None and site.number != item.number:
                continue
            if site.name is not None and site.name.upper() not in (stem, f"O{item.number}" if item.number else stem):
                continue
            found = _called(library, site, f)
            if found is None or found.file.path != item.path or found.unit.start != item.start:
                continue
            caller = program_item(f, f.program.unit_at(i))
            out.setdefault(caller, []).append((i, site.target.start, site.target.end))
    return list(out.items())


def _called(library: ProgramLibrary, site: CallSite, f: LoadedFile) -> FoundProgram | None:
    """The program ``site`` (a call in ``f``) runs, as the library finds it."""
    if site.name is not None:
        return library.find_name(site.name, f)
    return library.find_number(site.number, f) if site.number is not None else None
