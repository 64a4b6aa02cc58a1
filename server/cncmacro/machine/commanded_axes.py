"""Which axes a move's text shows: every axis the program has commanded so far.

A machinist reading ``G01  X0.000 Y0.000 Z-2.000 -> X20.000 Y0.000 Z-2.000`` expects the axes
the program named, each with its value even when it is 0, and none that it never mentions (no
``A0.000`` on a three-axis job). A move record (``frames.Move``) holds every axis of the
profile; which ones the program named is read from the move's block: its axis words and, on a
lathe, the incremental letters (``U`` is X, ``W`` is Z). Once named, an axis stays shown. An
axis that moves without being named (a G28 return) is shown too, and a move before any axis
was named or moved (``G70 P.. Q..``, a full circle ``G03 I-10.``) shows the profile's main axes
(X and Z on a lathe, X, Y and Z on a mill), which then stay: never an empty ``->``.
``cncmacro run`` and the debug console's motion echo use this (``Move.text`` takes the list).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from operator import itemgetter
from typing import TYPE_CHECKING

from ..planner.moves import Move

if TYPE_CHECKING:
    from .machine import Machine

_FILE, _LINE = itemgetter(0), itemgetter(1)  # a move's file and line


class CommandedAxes:
    """``shown(move)`` for the moves of one run, in the order they were made."""

    def __init__(self, machine: Machine) -> None:
        self.machine = machine
        dialect = machine.dialect
        index = {a: i for i, a in enumerate(dialect.axes)}
        self.letters = dict(index)
        for letter, axis in dialect.incremental_letters.items():
            if axis in index:
                self.letters[letter] = index[axis]
        main = ("X", "Z") if dialect.lathe else ("X", "Y", "Z")
        self.main = [index[a] for a in main if a in index] or [0]
        self.so_far: set[int] = set()
        self._sorted: list[int] = []
        self._named: dict[tuple[str, int], frozenset[int]] = {}
        self._all = len(dialect.axes)

    def shown(self, mv: Move) -> list[int]:
        """The axes to show for ``mv``, in the profile's order."""
        so_far = self.so_far
        if len(so_far) < self._all:
            before = len(so_far)
            so_far.update(self._block_axes(mv.file, mv.line))
            so_far.update(i for i in range(self._all) if mv.start[i] != mv.end[i])
            if not so_far:
                so_far.update(self.main)
            if len(so_far) != before:
                self._sorted = sorted(so_far)
        return self._sorted

    def absorb(self, moves: Sequence[Move]) -> None:
        """Take in, at once, moves that are not shown (the middle of a long run): their lines are
        looked at only for the letters of axes not yet shown, the plain lines' text searched all
        together (a 100,000-move run's middle took 0.4 s read line by line, most of ``cncmacro
        run``'s time)."""
        so_far = self.so_far
        if len(so_far) >= self._all or not moves:
            return
        wanted = "".join(letter for letter, axis in self.letters.items() if axis not in so_far)
        if wanted:
            files = set(map(_FILE, moves))
            if len(files) == 1:  # one program's moves: its lines, and no pair made a move
                lines = {files.pop(): set(map(_LINE, moves))}
            else:
                lines = {}
                for mv in moves:
                    lines.setdefault(mv.file, set()).add(mv.line)
            for file, numbers in lines.items():
                self._absorb_lines(file, numbers, wanted)
        for i in range(self._all):
            if i not in so_far and any(mv.start[i] != mv.end[i] for mv in moves):
                so_far.add(i)
        if not so_far:
            so_far.update(self.main)
        self._sorted = sorted(so_far)

    def _absorb_lines(self, file: str, numbers: set[int], wanted: str) -> None:
        """The axes the ``numbers`` lines of ``file`` name among the letters ``wanted``."""
        compiled = self.machine.compiled.get(file)
        if compiled is None:
            return
        blocks = compiled.file.program.blocks
        plain: list[str] = []
        for n in numbers:
            if 0 <= n < len(blocks):
                text = blocks[n].plain
                if text is not None:
                    plain.append(text)
                else:
                    self.so_far.update(self._block_axes(file, n))
        if plain:  # a word's first letter, as ``_read`` takes it
            found = re.findall(rf"(?<!\S)[{wanted}]", " ".join(plain), re.IGNORECASE)
            self.so_far.update(self.letters[letter.upper()] for letter in set(found))

    def _block_axes(self, file: str, line: int) -> frozenset[int]:
        key = (file, line)
        named = self._named.get(key)
        if named is None:
            named = self._named[key] = frozenset(self._read(file, line))
        return named

    def _read(self, file: str, line: int) -> list[int]:
        compiled = self.machine.compiled.get(file)
        if compiled is None:
            return []
        blocks = compiled.file.program.blocks
        if not 0 <= line < len(blocks):
            return []
        block = blocks[line]
        letters = self.letters
        if block.plain is not None:  # the words of a plain line, without parsing them
            return [letters[w[0].upper()] for w in block.plain.split() if w[0].upper() in letters]
        return [letters[w.letter] for w in block.words if w.letter in letters]
