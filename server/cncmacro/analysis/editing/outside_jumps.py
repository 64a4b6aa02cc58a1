"""Jumps from other files that land on the labels of a file: ``M98 P.. Q..`` of another file into
one of its programs, and ``M99 P`` of a program in another file that one of its programs calls
(which returns to a label of the caller). An edit of the file's sequence numbers keeps the labels
these name (``sequence_numbers.OutsideJump``); a computed one keeps every label of the program.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from pathlib import Path

from ...dialects.dialect import Dialect
from ...library.machine_file import CallCode
from ...machine.jump_words import RETURN_LABEL as M99
from ...machine.jump_words import SUBPROGRAM_LABEL as Q
from ..indexes.call_sites import calls_on
from ..indexes.sites import computed_jump_sites, jump_sites
from ..indexes.workspace_index import OpenFile, WorkspaceIndex
from .sequence_numbers import OutsideJump

Calls = Mapping[str, CallCode] | None


def outside_jumps(
    index: WorkspaceIndex,
    doc: OpenFile,
    dialect_for: Callable[[list[str], str], Dialect],
    calls_for: Callable[[str], Calls],
) -> list[OutsideJump]:
    """The jumps of other files of the workspace that land on labels of ``doc``."""
    program = doc.parsed.program
    out: list[OutsideJump] = []
    for f in index.loaded_files():
        if f.path == doc.path:
            continue
        dialect = dialect_for(f.lines, f.path)
        calls = calls_for(f.path)
        for i, b, site in calls_on(f.program.blocks, range(f.program.read_end), dialect, calls):
            if site.number is None or f.program.unit_numbered(site.number) is not None:
                continue
            unit = program.unit_numbered(site.number)
            if unit is None:
                continue
            where = f"{Path(f.path).name}:{i + 1}"
            out += [OutsideJump(unit.start, j.label, where) for j in jump_sites(b, dialect, calls) if j.kind == Q]
            computed = computed_jump_sites(b, dialect, calls)
            out += [OutsideJump(unit.start, None, where) for k, _, _ in computed if k == Q]
    dialect = dialect_for(doc.lines, doc.path)
    calls = calls_for(doc.path)
    for i, _, site in calls_on(program.blocks, range(program.read_end), dialect, calls):
        if site.number is not None and program.unit_numbered(site.number) is not None:
            continue
        found = index.find_program(doc, site.number, site.name)
        if found is None or found.file.path == doc.path or found.file.on_control:
            continue
        caller = program.unit_at(i).start
        theirs = dialect_for(found.file.lines, found.file.path)
        their_calls = calls_for(found.file.path)
        for k in range(found.unit.start, min(found.unit.end, len(found.file.program.blocks))):
            fb = found.file.program.blocks[k]
            where = f"{Path(found.file.path).name}:{k + 1}"
            out += [OutsideJump(caller, j.label, where) for j in jump_sites(fb, theirs, their_calls) if j.kind == M99]
            computed = computed_jump_sites(fb, theirs, their_calls)
            out += [OutsideJump(caller, None, where) for kind, _, _ in computed if kind == M99]
    return out
