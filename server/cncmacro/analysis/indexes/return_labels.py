"""Where ``M99 P n`` lands, for the editor's hover, go to definition and references, across the
workspace's files (docs/semantics.md §4, docs/editor.md "Navigation").

``M99 P n`` at the end of a subprogram returns to ``Nn`` of the program that called it: in each
caller, the first ``Nn`` after the call line, else the last one before it
(``machine.jumps.return_line``, the interpreter's rule). The callers are the programs of the
workspace's files, the open documents as the editor has them, whose literal call reaches the
subprogram (``callers``: a call in the subprogram's own file finds a program of that file first,
one in another file is found as the program library finds it, ``caller_entries.call_identity``
naming the numbers and file names a call may use). A program that nothing calls and that is the
first of its file is a main program: its ``M99 P n`` goes on from its own first ``Nn``. Anywhere
else the callers are unknown, and the editor says so.

The other way round, ``returns_onto`` gives the ``M99 P n`` of the programs a program calls that
land on one of its labels: what a label's hover and references list beside its own jumps.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import cast

from ...library.machine_file import CallCode
from ...library.programs import FoundProgram, LoadedFile
from ...machine.calls import call_word_pattern
from ...machine.jump_words import RETURN_LABEL
from ...machine.jumps import first_line, return_line
from ...syntax.program import ProgramUnit
from .call_sites import CallSite, calls_on
from .caller_entries import call_identity
from .sites import JumpSite, jump_sites
from .workspace_index import OpenFile, WorkspaceIndex


@dataclass(frozen=True, slots=True)
class Caller:
    """A call that reaches a subprogram: the calling file, its program and the call's line."""

    file: LoadedFile
    unit: ProgramUnit
    line: int
    site: CallSite

    @property
    def name(self) -> str:
        """The calling program as a person names it (``O6001``, or its file's name)."""
        return FoundProgram(self.file, self.unit).label


@dataclass(frozen=True, slots=True)
class Landing:
    """Where one caller's return lands: the ``Nn`` line in ``caller.file`` (None: the caller
    has no ``Nn``, alarm 128 when the run returns there)."""

    caller: Caller
    line: int | None


@dataclass(frozen=True, slots=True)
class Returns:
    """Where an ``M99 P n`` lands: one ``Landing`` per call that reaches its program, or, for a
    main program (``main``), its own first ``Nn`` (``own``; None when it has none). Neither
    callers nor ``main``: the callers are unknown."""

    landings: tuple[Landing, ...]
    main: bool = False
    own: int | None = None


@dataclass(frozen=True, slots=True)
class CalleeReturn:
    """An ``M99 P n`` of a called program (in ``file``, on ``line``) that lands on a label."""

    file: LoadedFile
    line: int
    site: JumpSite


def callers(index: WorkspaceIndex, doc: OpenFile, unit: ProgramUnit) -> list[Caller]:
    """Every literal call in the workspace's files that reaches ``unit`` of ``doc``."""
    here = doc.as_loaded()
    numbers, names = call_identity(FoundProgram(here, unit))
    library = None
    out: list[Caller] = []
    for f in index.loaded_files():
        own = f.path == doc.path
        program = f.program
        dialect, calls = index.dialect_for(f.lines, f.path), _codes(index, f.path)
        word = re.compile(call_word_pattern(calls or {})).search  # a line without one calls nothing
        lines = [i for i in range(min(program.read_end, len(program.blocks), len(f.lines))) if word(f.lines[i])]
        for i, _, site in calls_on(program.blocks, lines, dialect, calls):
            if site.number is not None and site.number not in numbers:
                continue
            if site.number is None and (site.name is None or site.name.strip().lower() not in names):
                continue
            if own and site.number is not None and program.unit_numbered(site.number) is not None:
                # a program of the calling file is found first (``ProgramLibrary.find_number``)
                if program.unit_numbered(site.number) is unit:
                    out.append(Caller(f, program.unit_at(i), i, site))
                continue
            if library is None:
                library = index.library(None)
            if site.number is not None:
                found = library.find_number(site.number, f)
            else:
                found = library.find_name(site.name or "", f)
            if found is not None and found.file.path == doc.path and found.unit.start == unit.start:
                out.append(Caller(f, program.unit_at(i), i, site))
    return out


def return_landings(index: WorkspaceIndex, doc: OpenFile, line: int, label: int) -> Returns:
    """Where the ``M99 P{label}`` on ``line`` of ``doc`` lands (see the module docstring)."""
    program = doc.parsed.program
    unit = program.unit_at(line)
    found = callers(index, doc, unit)
    if found:
        return Returns(tuple(Landing(c, return_line(c.file.program.label_lines(label, c.unit), c.line)) for c in found))
    if unit is program.named_units()[0]:
        return Returns((), main=True, own=first_line(program.label_lines(label, unit)))
    return Returns(())


def returns_onto(index: WorkspaceIndex, doc: OpenFile, line: int, label: int) -> list[CalleeReturn]:
    """The ``M99 P{label}`` of the programs that the program holding ``line`` of ``doc`` calls,
    which return to the ``N{label}`` on ``line``."""
    program = doc.parsed.program
    unit = program.unit_at(line)
    lines = program.label_lines(label, unit)
    if line not in lines:
        return []
    dialect, calls = index.dialect_for(doc.lines, doc.path), _codes(index, doc.path)
    out: list[CalleeReturn] = []
    seen: set[tuple[str, int]] = set()
    end = min(unit.end, program.read_end, len(program.blocks))
    for call_line, _, site in calls_on(program.blocks, range(unit.start, end), dialect, calls):
        if return_line(lines, call_line) != line:
            continue
        found = index.find_program(doc, site.number, site.name)
        if found is None:
            continue
        f = found.file
        theirs, their_calls = index.dialect_for(f.lines, f.path), index.calls_for(f.path)
        blocks = f.program.blocks
        for i in range(found.unit.start, min(found.unit.end, f.program.read_end, len(blocks))):
            for j in jump_sites(blocks[i], theirs, their_calls):
                if j.kind == RETURN_LABEL and j.label == label and (f.path, i) not in seen:
                    seen.add((f.path, i))
                    out.append(CalleeReturn(f, i, j))
    return out


def _codes(index: WorkspaceIndex, path: str) -> Mapping[str, CallCode] | None:
    """The machine file's call codes for ``path`` (the index keeps them untyped)."""
    return cast("Mapping[str, CallCode] | None", index.calls_for(path))
