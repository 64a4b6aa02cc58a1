"""Which words of a block of NC words name a label the run jumps to (docs/semantics.md §4, §5),
as the interpreter reads them, for the editor's searches (``analysis/indexes/sites.py``: go to
definition, references, rename, renumbering) and the static checks of ``M99 P``.

Which call a block makes is ``recognise_call``'s (``calls.py``), and a word is a jump only where
the run jumps by it:

- the Q of a subprogram call ``M98``/``M198`` (the last Q, as ``nc_blocks.py`` reads it): the
  called program starts at its Nn (kind ``M98 Q``, M198's too: it lands by the same rule);
- the P of the dialect's local subprogram call (Haas ``M97 P n``, ``local_call_kind``), a label
  of the program itself;
- the P of gsk980tdi's ``G65 H80``–``H86`` branches (``BlockCall.arithmetic``; the last H and P, as
  ``hcodes.py`` reads them; kind ``H8x``). Where the control has no macro A, ``G65 H81 P1000``
  calls O1000 with the argument H and jumps nowhere;
- the P of ``M99`` in a block that makes no call (the first P, as ``nc_blocks.py`` reads it;
  ``return_word``): a return to a label of the caller, or in a main program on from its own;
- on a lathe, the P and Q of a ``G70``–``G73`` block that has both (kind ``G71 P``, ``G71 Q``):
  the first and last blocks of the cycle's finishing shape, which the run runs
  (``planner/lathe_cycles.py``; found as ``call_stack.enter_shape`` finds them).

A block that makes any other call jumps by none of its words: a G65/G66 macro call's M99 and Q
are its arguments M and Q, and a code the machine file's ``[calls]`` makes a call (``M97 = 9097``
on a Haas) is that call, whose P is no label. ``GOTO n`` and ``IF [..] GOTO n`` (Haas's
conditional ``[cond] M99 P n`` among them) are statements, not words: ``analysis/indexes/sites.py``
reads them from the syntax.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from ..dialects.dialect import Dialect
from ..planner.lathe_cycles import SHAPE_CODES
from ..syntax.nodes import Number, Word
from .calls import code_value, last_word, recognise_call
from .hcodes import BRANCHES
from .program_end import RETURN_CODE

SUBPROGRAM_LABEL = "M98 Q"  # the Q of M98/M198: the first Nn of the called program
RETURN_LABEL = "M99"  # the P of M99: a label of the caller
BRANCH_LABEL = "H8x"  # the P of G65 H80-H86 (gsk980tdi macro A)


def local_call_kind(code: float) -> str:
    """The kind of the jump of a local subprogram call with M code ``code`` (``M97 P``)."""
    return f"M{code:g} P"


def may_hold_jump(text: str) -> bool:
    """Whether a plain line (``Block.plain``, address-number words only) may hold a jump word:
    every one needs an M word (M98, M198, M99, the local call), an H word (G65 H8x) or, a
    lathe cycle's shape, a P and a Q. Lines without them, nearly every line of a CAM program,
    are passed over at once."""
    return (
        "M" in text
        or "m" in text
        or "H" in text
        or "h" in text
        or (("P" in text or "p" in text) and ("Q" in text or "q" in text))
    )


def jump_words(
    words: Sequence[Word], dialect: Dialect, calls: Mapping[str, object] | None = None
) -> list[tuple[str, Word]]:
    """(kind, word) for each word of ``words`` that names a label the run jumps to, literal or
    computed (see the module docstring); ``calls`` are the machine file's call codes."""
    shape = _shape_words(words, dialect)
    if shape:
        return shape
    if not any(w.letter == "M" or w.letter == "H" for w in words):
        return []
    found = _jump_word(words, dialect, calls)
    return [] if found is None or found[1].value is None else [found]  # P[NAME] names no label


def _jump_word(words: Sequence[Word], dialect: Dialect, calls: Mapping[str, object] | None) -> tuple[str, Word] | None:
    call = recognise_call(words, dialect, calls)
    if call is None:
        if any(w.letter == "M" and code_value(w) == RETURN_CODE for w in words):
            p = return_word(words)
            return None if p is None else (RETURN_LABEL, p)
        return None
    if call.arithmetic:
        h = last_word(words, "H")
        p = last_word(words, "P")
        v = h.value if h is not None else None
        if p is not None and isinstance(v, Number) and int(v.value) in BRANCHES:
            return BRANCH_LABEL, p
        return None
    if call.local:
        return None if call.target is None else (f"{call.kind} P", call.target)  # local_call_kind
    if call.kind in ("M98", "M198"):
        q = last_word(words, "Q")
        return None if q is None else (SUBPROGRAM_LABEL, q)
    return None


def _shape_words(words: Sequence[Word], dialect: Dialect) -> list[tuple[str, Word]]:
    """The P and Q of a lathe's ``G70``–``G73`` block with both (the last of each, as the
    block's words are read), or none."""
    if not dialect.lathe:
        return []
    code = next((code_value(w) for w in words if w.letter == "G" and code_value(w) in SHAPE_CODES), None)
    if code is None or code not in dialect.cycle_codes:
        return []
    p, q = last_word(words, "P"), last_word(words, "Q")
    if p is None or q is None or p.value is None or q.value is None:
        return []
    return [(f"G{code:g} P", p), (f"G{code:g} Q", q)]


def return_word(words: Sequence[Word]) -> Word | None:
    """The P word of an ``M99`` block that names the caller's label it returns to: the first."""
    return next((w for w in words if w.letter == "P"), None)
