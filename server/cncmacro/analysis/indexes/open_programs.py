"""The programs of the open files, and which of them another program calls.

Every O program of the open files that the control would run (but a repeated O number's later
copy, which the control does not keep: ``ProgramUnit.duplicate``) is listed with whether a
program calls it with a literal target: by its number (G65/G66/M98/call codes), a file's first
program also by the number or the name of its file. A program that only calls itself still
runs on its own. The analysis runs each one nothing calls; a called one is analysed through
its callers (``workspace.py``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from pathlib import Path

from ...library.files import o_number
from ...library.programs import FoundProgram
from ...machine import block_roles
from ..workspace_documents import WorkspaceDocument

RunKey = tuple[str, int]  # a program's file and its place among the file's units
OpenProgram = tuple[RunKey, FoundProgram, bool]  # the key, the program, whether another program calls it
CallSites = Iterable[tuple[int, int | None, str | None]]  # (line, program number, program name) of each literal call


def open_programs(
    docs: Mapping[str, WorkspaceDocument], call_sites: Callable[[WorkspaceDocument], CallSites], block_delete: bool
) -> list[OpenProgram]:
    """Every runnable O program of ``docs``, in the order of their paths and then of their
    files; ``call_sites`` gives the literal calls of a document."""
    by_number: dict[int, list[tuple[str, int]]] = {}
    by_name: dict[str, list[tuple[str, int]]] = {}
    for path, d in docs.items():
        ignored = [u for u in d.doc.program.units if u.duplicate]
        for line, number, name in call_sites(d):
            if ignored and any(line in u for u in ignored):
                continue  # a copy the control does not keep calls nothing
            if number is not None:
                by_number.setdefault(number, []).append((path, line))
            elif name is not None:
                by_name.setdefault(name, []).append((path, line))
    out = []
    for path in sorted(docs):
        d = docs[path]
        program = d.doc.program
        stem = Path(path).stem
        named = o_number(stem, bare=True)  # the number a call finds this file by
        first = program.named_units()[0]  # what a call by the file's name runs
        for k, unit in enumerate(program.units):
            if unit.duplicate or not block_roles.runnable(program, unit, block_delete):
                continue
            sites = list(by_number.get(unit.number, ())) if unit.number is not None else []
            if unit.number is None and k == 0:
                sites = list(by_number.get(named, ())) if named is not None else []
            if unit is first:
                sites += by_name.get(stem.lower(), ())
            called = any(p != path or not unit.start <= line < unit.end for p, line in sites)
            out.append(((path, k), FoundProgram(d.loaded, unit), called))
    return out
