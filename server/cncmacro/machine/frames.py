"""The records the macro machine keeps while it runs: call frames, modal calls, notes (a
run's moves are the planner's: planner/moves.py).

A ``Frame`` is one program level: the main program, or a program entered by G65, G66,
M98 or a call code, or a lathe cycle's finishing shape (G70–G73 P Q: the blocks N(P) to N(Q)
of the program running, ended by ``end_line``). Macro calls (G65, G66, call codes) own a fresh set of locals
``#1–#33``; a subprogram (M98) shares its caller's. Frames are small and copied whole by
snapshots, so everything in them is a plain value or a list the snapshot copies.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from ..library.programs import FoundProgram
from .alarms import CallLevel

if TYPE_CHECKING:
    from .blocks import CompiledFile


@dataclass(slots=True)
class Frame:
    """One program level. ``pc`` is the 0-based line about to run; ``return_pc`` the caller's
    line to continue at; ``loops`` the DO lines of the loops that are running, innermost last."""

    found: FoundProgram
    code: CompiledFile
    pc: int
    kind: str  # "main", "G65", "G66", "M98", the calling code ("M50", "G100", "T") or a shape cycle ("G71")
    locals: list[float | None]
    macro_level: int
    call_line: int = -1  # the caller's line that made the call
    return_pc: int = -1
    repeats: int = 1  # how many more times the program runs after this pass
    start_pc: int = 0  # where each pass starts (M98 Q starts at a label)
    arguments: dict[int, float | None] = field(default_factory=dict)
    letters: dict[int, str] = field(default_factory=dict)  # local number -> argument letter
    loops: list[int] = field(default_factory=list)
    modal: ModalCall | None = None  # the ModalCall that made this frame, if a G66 did
    written: set[int] | None = None  # analysis runs: the locals this macro level assigned itself
    end_line: int = -1  # a shape cycle's frame: the line of its block N(Q), after which it ends
    increments: dict[int, float] = field(default_factory=dict)  # ``Arguments.increments``
    passes: int = 1  # how many times the call runs the program in all (its L): the debugger's "pass 2 of 3"

    @property
    def file(self) -> str:
        return self.found.file.path

    @property
    def name(self) -> str:
        return self.found.label

    def copy(self, locals_copy: list[float | None]) -> Frame:
        f = Frame(
            self.found, self.code, self.pc, self.kind, locals_copy, self.macro_level, self.call_line, self.return_pc,
            self.repeats, self.start_pc, self.arguments, self.letters, list(self.loops), self.modal,
            None if self.written is None else set(self.written), self.end_line,
        )  # fmt: skip
        f.passes = self.passes
        return f


@dataclass(frozen=True, slots=True)
class ModalCall:
    """A G66 in force: the program, its arguments and count, and the level that set it."""

    found: FoundProgram
    arguments: tuple[tuple[int, float | None], ...]
    letters: tuple[tuple[int, str], ...]
    repeats: int
    level: int
    increments: tuple[tuple[int, float], ...] = ()  # ``Arguments.increments``


@dataclass(frozen=True, slots=True)
class Note:
    """Something a run noticed that is not an alarm (a clamped L, arguments out of order, a
    DPRNT line, a #3006 message): ``kind`` names it for the analysis and the debugger."""

    kind: str
    message: str
    file: str
    line: int
    subject: str | None = None  # e.g. "repeat-count" for a clamped L
    chain: tuple[CallLevel, ...] = ()  # the calls that led there, main program first
    # a guard the analysis run went past (machine/guards.py): the line of the alarm block it did not run
    skipped: int | None = None
