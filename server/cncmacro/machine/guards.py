"""A program's own guard on a value only the machine has: which side the analysis run follows
(docs/semantics.md §2, "Unknown, not vacant", the guard of a production program).

A production program often tests a value the machine keeps before it cuts, and raises its own
macro alarm when the test fails: ``IF [#3901 GE #3902] THEN #3000=1 (BATCH COMPLETE)``,
``IF [#500 EQ 0] GOTO 999`` … ``N999 #3000=2 (SET THE OFFSET)``. The analysis run has no value
for #3901 or #500 (``unknown_values.py``) and would stop there, leaving the rest of the program
unchecked. The control passes its own guard on every production cycle (the program runs every
day), so where one side of a branch on an unknown is nothing but the program's own alarm, the
analysis run follows the other side and says so with a note (kind ``"unknown"``, subject
``"guard"``, ``skipped`` the line of the alarm block it did not run). A branch whose sides are
anything else still stops the path, as before. A guard on a random number (GSK980TDi's
``RAND``, ``SRAND``) is passed the same way, though the control takes either side as the draw
falls: the other side is one the control takes, and the analysis says so
(``analysis/runs/unknown_stops.py``). A ``WHILE`` whose condition is unknown is gone
through once and then left (``unknown_loop_pass``, a note of subject ``"loop"``), so that its
body and what follows are checked. Only an analysis run meets an unknown:
``cncmacro run`` and the debugger read these values as vacant and decide as the control with
those values would.

One rule says what an alarm block is, ``alarm_only``: a block that holds nothing but an
assignment to the profile's macro-alarm variable (the system variable whose source is
``"alarm"``: FANUC, Haas and GSK ``#3000``) or, on a control with macro A, ``G65 H99 Pn``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..bilingual import detail
from ..syntax.nodes import Assign, Block, If, Number, Var
from .frames import Note

if TYPE_CHECKING:
    from ..dialects.dialect import Dialect
    from .machine import Machine

GUARD = "guard"  # the subject of the note a guard passed leaves
LOOP = "loop"  # the subject of the note a WHILE on an unknown leaves (one pass, then out)
UNKNOWN_NOTE = "unknown"  # the kind of those notes


def alarm_only(block: Block, dialect: Dialect) -> bool:
    """Whether ``block`` does nothing but raise the program's own macro alarm: ``#3000=n``
    (the profile's variable of source ``"alarm"``), or ``G65 H99 Pn`` where the profile has macro A
    (a sequence number and comments aside)."""
    if block.program is not None or block.corners or block.has_error:
        return False
    statements, words = block.statements, block.words
    if statements:
        return not words and len(statements) == 1 and alarm_statement(statements[0], dialect)
    if not dialect.h_codes or len(words) != 3:
        return False
    g, h = words[0], words[1]
    return (
        g.letter == "G"
        and isinstance(g.value, Number)
        and g.value.value == 65.0
        and h.letter == "H"
        and isinstance(h.value, Number)
        and h.value.value == 99.0
        and words[2].letter == "P"
    )


def alarm_statement(s: object, dialect: Dialect) -> bool:
    """Whether the statement ``s`` is an assignment to the profile's macro-alarm variable."""
    if not isinstance(s, Assign) or not isinstance(s.target, Var):
        return False
    row = dialect.system_variable(s.target.number)
    return row is not None and row.source == "alarm"


def alarm_then(s: If, dialect: Dialect) -> bool:
    """Whether ``IF [..] THEN`` statement ``s`` raises the macro alarm and nothing else."""
    return s.goto is None and s.then is not None and alarm_statement(s.then, dialect)


def unknown_loop_pass(entering: bool) -> bool:
    """Whether an analysis run goes (again) through a ``WHILE`` loop whose condition is unknown
    (docs/semantics.md §2, a loop on a value only the machine has): once, on entering it, so that
    its body is checked; coming back from its ``END``, it leaves the loop, so that what follows
    is checked too. The machine runs it as many times as its value says, which the folder lacks;
    one pass is the fewest that checks every block of it."""
    return entering


class Passed:
    """The note a guard (or a loop on an unknown, ``subject`` LOOP) leaves, once for each time a
    run goes past it: a closure keeps one and adds it again only when the run no longer holds it
    (a restore to a snapshot before it)."""

    __slots__ = ("at", "note", "subject")

    def __init__(self, subject: str = GUARD) -> None:
        self.note: Note | None = None
        self.at = -1
        self.subject = subject

    def record(self, m: Machine, pc: int, skipped: int | None) -> None:
        """Say that the run went past the guard on line ``pc`` (``skipped``: the alarm block's
        line it did not run, None for an alarm on the guard's own line)."""
        held = self.note
        if held is not None and self.at < len(m.notes) and m.notes[self.at] is held:
            return
        f = m.frames[-1]
        message = (
            detail(
                "the analysis run goes on past this guard, as the machine passes it in production",
                "分析运行越过此保护判断继续，机床在生产中通过该判断",
            )
            if self.subject == GUARD
            else detail(
                "the analysis run goes through this loop once and leaves it: its condition is unknown",
                "分析运行执行此循环一次后离开：其条件未知",
            )
        )
        note = Note(
            UNKNOWN_NOTE,
            message,
            f.file,
            pc,
            self.subject,
            m.chain(pc),
            skipped,
        )
        self.at = len(m.notes)
        self.note = note
        m.notes.append(note)
