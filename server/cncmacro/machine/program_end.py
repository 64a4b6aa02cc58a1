"""Which M codes end a program (docs/semantics.md §5), the same on every profile.

``M30`` and ``M02`` end the run (``END_CODES``: ``Machine.end_program``, which also cancels the
modal calls); ``M99`` (``RETURN_CODE``) ends a called program, returning to its caller, and
ends a main program where the run is told to (``Machine.m99_ends_main``), else runs it again.
A code is read as the interpreter rounds an M word (``M2.`` is M02, ``M030`` is M30).

The interpreter dispatches on these codes (``nc_blocks.py``) and keeps the one that ended a run
(``Machine.ended_with``, which the debugger names: ``debugging/stepping.py``); the editor folds
an O program up to its last end (``ide/folding.py``) by ``end_code``, the same rule read from the
block's text.
"""

from __future__ import annotations

from ..syntax.fastpath import plain_words
from ..syntax.nodes import Block
from .calls import code_value

END_CODES = frozenset((30.0, 2.0))  # M30, M02: the run ends
RETURN_CODE = 99.0  # M99: a called program returns (a main program ends or runs again)


def end_code(block: Block) -> float | None:
    """The literal M code of ``block`` that ends the program it stands in: M30 or M02 (the
    run), or M99 (a called program; a main program where ``m99_ends_main``); None when it has
    none. M99 comes first, as in the interpreter. A code written from a variable (``M#1``) is
    known only when the block runs."""
    plain = block.plain
    if plain is not None:
        if "M" not in plain and "m" not in plain:  # nearly every line of a CAM program
            return None
        words = plain_words(plain) or []  # not kept on the block: plain lines are many
    else:
        words = list(block.words)
    codes = [code_value(w) for w in words if w.letter == "M"]
    if RETURN_CODE in codes:  # the interpreter returns before it would end
        return RETURN_CODE
    return next((c for c in codes if c in END_CODES), None)
