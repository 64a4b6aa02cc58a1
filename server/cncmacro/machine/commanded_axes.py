"""Which axes a person is shown for a run's moves: the ones the program has commanded.

A dialect names every axis its control may have (``X Y Z A`` on a FANUC mill), but a
three-axis job never mentions A, and a line of motion that reads ``A0.000`` makes a machinist
wonder where the program turns a rotary table. So a move is shown with every axis the run has
commanded up to and including it: an axis that a moving block names (an absolute letter, or on
a lathe its incremental letter, ``U`` for X), or that a move changed without naming it (a
drilling cycle's retract). Once commanded, an axis stays shown, at 0 too; an axis never
commanded is never shown. Only before any axis is commanded (a full circle ``G02 I-10.`` as the
first move) are all of them shown, so that the move still says where it is.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .frames import Move

if TYPE_CHECKING:
    from ..dialects import Dialect
    from ..library.programs import ProgramLibrary
    from ..syntax.nodes import Block


class CommandedAxes:
    """The axes commanded so far by the moves taken in with ``shown``, as indices in the
    dialect's axis order; the blocks of the moves are read from ``library`` (the run's)."""

    def __init__(self, dialect: Dialect, library: ProgramLibrary) -> None:
        self.axes = dialect.axes
        letters = {a: i for i, a in enumerate(self.axes)}
        for inc, axis in dialect.incremental_letters.items():
            if axis in letters:
                letters[inc] = letters[axis]
        self._letters = letters
        self._library = library
        self.commanded: set[int] = set()
        self._shown: list[int] = []

    def shown(self, mv: Move) -> list[int]:
        """Take in ``mv`` and give the axes to show it with, in the dialect's order."""
        new = {i for i in range(len(self.axes)) if mv.start[i] != mv.end[i]}
        new.update(self._named(mv))
        if not new <= self.commanded:
            self.commanded |= new
            self._shown = sorted(self.commanded)
        return self._shown or list(range(len(self.axes)))

    def _named(self, mv: Move) -> set[int]:
        block = self._block(mv.file, mv.line)
        if block is None:
            return set()
        letters = self._letters
        if block.plain is not None:  # a plain line: its words are its whitespace-separated parts
            found = (letters.get(w[:1].upper()) for w in block.plain.split())
        else:
            found = (letters.get(w.letter) for w in block.words)
        return {i for i in found if i is not None}

    def _block(self, file: str, line: int) -> Block | None:
        loaded = self._library.load(file)  # read once by the run, kept by the library
        if loaded is None or not 0 <= line < len(loaded.program.blocks):
            return None
        return loaded.program.blocks[line]
