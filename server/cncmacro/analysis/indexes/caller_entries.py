"""The programs on disk through which an open program is analysed (docs/design.md "Entry points").

An open program that no open file calls may still be called from a file on disk in the
workspace folders, and through it from that file's callers: a main program that calls a macro
that calls this one. ``CallerSearch.roots`` climbs from the program to its callers on disk,
level by level, until it reaches programs that nothing calls; those are the entry programs
whose runs reach it, with their arguments. Which file a call reaches is decided by the
library's lookup from the calling file (``ProgramLibrary.find_number``/``find_name``), so a
call that the control would resolve to another file with the same number does not count. A
program on disk that an open file names is left to that file's run. Open files are never
taken from disk: their text is the editor's.
"""

from __future__ import annotations

import os
from collections.abc import Container
from pathlib import Path

from ...library.programs import FoundProgram, ProgramLibrary
from .call_index import CallIndex

MAX_LEVELS = 16  # callers of callers looked for, at most (the controls nest at most 12 levels)
_Key = tuple[str, int]  # (file, index of the O program in it)


class CallerSearch:
    """See the module docstring. ``open_paths`` maps the open documents' paths to their
    paths with links resolved."""

    def __init__(self, library: ProgramLibrary, index: CallIndex, open_paths: dict[str, str]) -> None:
        self.library = library
        self.index = index
        self.open_paths = set(open_paths)
        self.open_real = set(open_paths.values())
        self._callers: dict[_Key, list[tuple[_Key, FoundProgram]]] = {}

    def roots(
        self, found: FoundProgram, numbers: Container[int], names: Container[str]
    ) -> dict[_Key, FoundProgram] | None:
        """The entry programs on disk whose runs reach ``found``: None when nothing on disk
        calls it, or when its callers only call each other (no program that nothing calls
        reaches it). ``numbers`` and ``names`` are what the other open files' calls name: a
        program they name is reached by an open file's run, and no entry is looked for above it
        (the result may then be empty)."""
        first = self._disk_callers(found)
        if not first:
            return None
        roots: dict[_Key, FoundProgram] = {}
        by_open = False
        seen: set[_Key] = {_key_of(found)}
        frontier = first
        for _ in range(MAX_LEVELS):
            above: list[tuple[_Key, FoundProgram]] = []
            for key, caller in frontier:
                if key in seen:
                    continue
                seen.add(key)
                if _named(caller, numbers, names):
                    by_open = True
                    continue
                callers = self._disk_callers(caller)
                if callers:
                    above.extend(callers)
                else:
                    roots[key] = caller
            if not above:
                break
            frontier = above
        return roots if roots or by_open else None

    def callers(self, found: FoundProgram) -> list[FoundProgram]:
        """The programs of files on disk that call ``found`` with a literal target reaching it
        (each calling program once, by file and O program): ``cncmacro run`` names them for a
        subprogram run on its own."""
        return [caller for _key, caller in self._disk_callers(found)]

    def _disk_callers(self, target: FoundProgram) -> list[tuple[_Key, FoundProgram]]:
        """The programs of files on disk (not open) with a literal call that reaches ``target``."""
        key = _key_of(target)
        cached = self._callers.get(key)
        if cached is not None:
            return cached
        path = target.file.path
        units = target.file.program.units
        k = key[1]
        numbers, names = call_identity(target)
        candidates: set[str] = set()
        for n in numbers:
            candidates.update(self.index.callers(n, None))
        for name in names:
            candidates.update(self.index.callers(None, name))
        out: list[tuple[_Key, FoundProgram]] = []
        for cpath in sorted(candidates):
            if cpath == path or cpath in self.open_paths or os.path.realpath(cpath) in self.open_real:
                continue
            loaded = self.library.load(cpath)
            if loaded is None:
                continue
            for call in self.index.calls_of(cpath):
                if call.number not in numbers and call.name not in names:
                    continue
                if call.number is not None:
                    found = self.library.find_number(call.number, loaded)
                else:
                    found = self.library.find_name(call.name or "", loaded)
                if found is None or not _same_file(found.file.path, path):
                    continue
                if found.unit.start != units[k].start or call.unit >= len(loaded.program.units):
                    continue
                caller = FoundProgram(loaded, loaded.program.units[call.unit])
                if all(c[0] != (cpath, call.unit) for c in out):
                    out.append(((cpath, call.unit), caller))
        self._callers[key] = out
        return out


def _key_of(found: FoundProgram) -> _Key:
    return (found.file.path, found.file.program.units.index(found.unit))


def call_identity(found: FoundProgram) -> tuple[set[int], set[str]]:
    """The numbers and bracketed names a call may use for ``found``: its O number; for a
    file's first program (after a lead-in of comments, ``Program.named_units``) also the file
    name (``9100.nc``, ``CUT.CNC``)."""
    numbers: set[int] = set()
    names: set[str] = set()
    if found.unit.number is not None:
        numbers.add(found.unit.number)
    if found.unit is found.file.program.named_units()[0]:
        p = Path(found.file.path)
        stem = p.stem.lower() if p.suffix else p.name.lower()
        digits = stem[1:] if stem[:1] == "o" else stem
        if found.unit.number is None and digits.isdigit() and len(digits) <= 8:
            numbers.add(int(digits))
        names.update({stem, p.name.lower()})
    return numbers, names


def _named(found: FoundProgram, numbers: Container[int], names: Container[str]) -> bool:
    """Whether an open file's literal calls name ``found`` (then an open file's run reaches it)."""
    own_numbers, own_names = call_identity(found)
    return any(n in numbers for n in own_numbers) or any(x in names for x in own_names)


def _same_file(a: str, b: str) -> bool:
    return a == b or os.path.realpath(a) == os.path.realpath(b)
