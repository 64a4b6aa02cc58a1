"""The files of one ``cncmacro check`` split into groups that can be checked one after another.

A file's findings depend only on the files its programs call and the files that call them
(callers of callers too), so files that no call connects can be analysed in separate
workspaces, one after the other (or side by side, ``check --jobs``), and each group's findings
printed as soon as it is done: memory then follows the largest group, not the folder.
``file_keys`` looks at one file: what it names (its file name as a number and as a bracketed
name, with or without its ending, and its O numbers) and the programs its calls name
(``machine.calls.recognise_call``, as the interpreter reads a call). Only a file whose text
holds a call word is parsed for that; of any other, the numbers its O words may spell are
noted from the text (every ``O`` followed by digits, a superset of the parser's program
numbers), and the file is parsed for its exact O numbers (``exact_names``) only when one of
those is a number that some call names. ``join_groups`` then joins into one group every file
with the files that may hold what it calls, among the files read in its profile: a call finds
only a program of its own machine (``ProgramLibrary.on_machine``), so a FANUC file and a
GSK980TDi-marked file beside it are never joined by a call. Within one profile it errs on the side
of joining: a number held by several files joins them all, and a file whose call names its
program by a value only a run knows (``G65 P#1``) joins every file of its profile, so that no run
can reach a file that is not open beside it (``library/programs.py`` decides which file a call
reaches). Both are given texts, not
paths, so that the work can be spread over processes (``check_work.py``).
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from pathlib import Path
from typing import NamedTuple

from ..library.file_cache import load_text
from ..library.files import o_number
from ..library.machine_file import MachineSettings
from ..library.profiles import file_profile
from ..machine.calls import call_word_pattern, recognise_call

Key = tuple[str, int | str]  # ("n", a program number) or ("s", a lower-case file stem or bracketed name)
ANY: Key = ("*", 0)  # a call whose program only a run knows: it may reach any file

# an O word as written anywhere in a text (spaces or a sign between the O and its digits, as
# the parser reads ``O 1234`` and ``O+1234``): every program number of the file is among these
_O_DIGITS = re.compile(r"[Oo][ \t]*\+?[ \t]*(\d+)")


class FileKeys(NamedTuple):
    """What ``file_keys`` found in one file. ``maybe`` is None when ``names`` holds the file's
    exact O numbers, else the numbers its O words may spell (``exact_names`` tells which);
    ``profile`` is the name of the profile the file is read in (``file_profile``)."""

    names: frozenset[Key]
    calls: frozenset[Key]
    maybe: frozenset[int] | None
    profile: str


def file_keys(path: Path, text: str, settings: MachineSettings, dialect: str | None) -> FileKeys:
    """What a call may name to reach ``path`` and what the calls in its ``text`` name."""
    names = _file_names(path)
    word = re.compile(call_word_pattern(settings.calls)).search
    if word(text) is None:  # no call: the file is read for its O numbers only if a call names one
        maybe = frozenset(int(m) for m in _O_DIGITS.findall(text))
        return FileKeys(frozenset(names), frozenset(), maybe, file_profile(text, settings, dialect).name)
    loaded = load_text(str(path), text)
    names.update(("n", u.number) for u in loaded.program.units if u.number is not None)
    calls: set[Key] = set()
    profile = file_profile(loaded.lines, settings, dialect)
    blocks = loaded.program.blocks
    for line, text_line in enumerate(loaded.lines):
        if line >= len(blocks) or word(text_line) is None:
            continue
        call = recognise_call(blocks[line].words, profile, settings.calls)
        if call is None or call.arithmetic or call.local or call.label is not None:
            continue
        if call.number is not None:
            calls.add(("n", call.number))
        if call.name is not None:
            name = call.name.strip().lower()
            calls.add(("s", name))
            named = o_number(name)
            if named is not None:
                calls.add(("n", named))
        if call.number is None and call.name is None and call.target is not None:
            calls.add(ANY)
    return FileKeys(frozenset(names), frozenset(calls), None, profile.name)


def exact_names(path: Path, text: str) -> frozenset[Key]:
    """What a call may name to reach ``path``, its O numbers read by the parser."""
    names = _file_names(path)
    names.update(("n", u.number) for u in load_text(str(path), text).program.units if u.number is not None)
    return frozenset(names)


def _file_names(path: Path) -> set[Key]:
    """What a call may name to reach ``path`` by its file name alone."""
    names: set[Key] = {("s", path.stem.lower()), ("s", path.name.lower())}  # P[CUT] and P[CUT.CNC]
    number = o_number(path.stem, bare=True)
    if number is not None:
        names.add(("n", number))
    return names


def to_read_exactly(keys: list[FileKeys]) -> list[int]:
    """Which of the files of ``keys`` must be parsed for their exact O numbers: those whose O
    words may spell a number that a call names."""
    wanted = {key[1] for k in keys for key in k.calls if key[0] == "n"}
    if not wanted or any(ANY in k.calls for k in keys):  # no call by number, or every file joined anyway
        return []
    return [i for i, k in enumerate(keys) if k.maybe is not None and not k.maybe.isdisjoint(wanted)]


def join_groups(paths: list[Path], keys: list[FileKeys]) -> list[list[Path]]:
    """``paths`` (each with its ``keys``, exact where ``to_read_exactly`` asked) in groups of
    files that calls may connect (a call, the files of its own file's profile only), each group
    in the order of ``paths``, the groups in the order of their first file."""
    holders: dict[Key, list[int]] = {}
    for i, k in enumerate(keys):
        for key in k.names:
            holders.setdefault(key, []).append(i)
    parent = list(range(len(paths)))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    def join(i: int, others: Iterable[int]) -> None:
        for j in others:
            a, b = root(i), root(j)
            if a != b:
                parent[max(a, b)] = min(a, b)

    of_profile: dict[str, list[int]] = {}
    for i, k in enumerate(keys):
        of_profile.setdefault(k.profile, []).append(i)
    for i, k in enumerate(keys):
        if ANY in k.calls:
            join(i, of_profile[k.profile])
        for key in k.calls:
            join(i, (j for j in holders.get(key, ()) if keys[j].profile == k.profile))
    groups: dict[int, list[Path]] = {}
    for i, path in enumerate(paths):
        groups.setdefault(root(i), []).append(path)
    return list(groups.values())
