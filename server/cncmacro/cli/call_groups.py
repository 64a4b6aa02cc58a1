"""The files of one ``cncmacro check`` split into groups that can be checked one after another.

A file's findings depend only on the files its programs call and the files that call them
(callers of callers too), so files that no call connects can be analysed in separate
workspaces, one after the other, and each group's findings printed as soon as it is done:
memory then follows the largest group, not the folder. ``call_groups`` reads each file once,
notes what it names (its O numbers, its file name as a number and as a bracketed name, with or
without its ending) and the programs its calls name (``machine.calls.recognise_call``, as the
interpreter reads a call), and joins into one group every file with the files that may hold
what it calls. It errs on the side of joining: a number held by several files joins them all,
and a file whose call names its program by a value only a run knows (``G65 P#1``) joins every
file, so that no run can reach a file that is not open beside it (``library/programs.py``
decides which file a call reaches).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from pathlib import Path

from ..library.file_cache import load_text
from ..library.files import o_number
from ..library.machine_file import MachineSettings
from ..library.profiles import file_profile
from ..machine.calls import call_word_pattern, recognise_call

Key = tuple[str, int | str]  # ("n", a program number) or ("s", a lower-case file stem or bracketed name)
ANY: Key = ("*", 0)  # a call whose program only a run knows: it may reach any file


def call_groups(
    paths: list[Path], read: Callable[[Path], str | None], settings: MachineSettings, dialect: str | None
) -> list[list[Path]]:
    """``paths`` (those ``read`` gives a text for) in groups of files that calls may connect,
    each group in the order of ``paths``, the groups in the order of their first file."""
    word = re.compile(call_word_pattern(settings.calls)).search
    readable: list[Path] = []
    holders: dict[Key, list[int]] = {}
    wants: list[set[Key]] = []
    for path in paths:
        text = read(path)
        if text is None:
            continue
        i = len(readable)
        readable.append(path)
        names, calls = _names_and_calls(path, text, word, settings, dialect)
        for key in names:
            holders.setdefault(key, []).append(i)
        wants.append(calls)
    parent = list(range(len(readable)))

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

    for i, calls in enumerate(wants):
        if ANY in calls:
            join(i, range(len(readable)))
        for key in calls:
            join(i, holders.get(key, ()))
    groups: dict[int, list[Path]] = {}
    for i, path in enumerate(readable):
        groups.setdefault(root(i), []).append(path)
    return list(groups.values())


def _names_and_calls(
    path: Path, text: str, word: Callable[[str], object], settings: MachineSettings, dialect: str | None
) -> tuple[set[Key], set[Key]]:
    """What a call may name to reach ``path`` and what the calls in its text name."""
    names: set[Key] = {("s", path.stem.lower()), ("s", path.name.lower())}  # P[CUT] and P[CUT.CNC]
    number = o_number(path.stem, bare=True)
    if number is not None:
        names.add(("n", number))
    loaded = load_text(str(path), text)
    names.update(("n", u.number) for u in loaded.program.units if u.number is not None)
    calls: set[Key] = set()
    if word(text) is None:
        return names, calls
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
    return names, calls
