"""Turning the items read from a line (words and macro statements) into a ``Block``.

Both the lark grammar and the fast path for plain NC blocks end here, so whatever reads the
line, a leading ``O`` word becomes the program header, a leading ``N`` word the sequence
number, and a comment right after ``#3000=n`` its message in exactly the same way.
"""

from __future__ import annotations

from collections.abc import Sequence

from .lines import Prepared
from .nodes import Assign, Block, Comment, Do, End, If, Number, Problem, While, Word


def assemble(items: Sequence[object], prep: Prepared) -> Block:
    """Build the block of a line from its items, in the order they were written."""
    problems = list(prep.problems)
    program = program_span = label = label_span = None
    title = None
    i = 0
    n = len(items)
    if n and _is_word(items[0], "O"):
        w = items[0]
        number = _whole_literal(w, "a program number", problems)  # type: ignore[arg-type]
        if number is not None:
            program, program_span = number, (w.start, w.end)  # type: ignore[union-attr]
            title = _first_comment_text(prep.comments)
        i = 1
    if i < n and _is_word(items[i], "N"):
        w = items[i]
        number = _whole_literal(w, "a sequence number", problems)  # type: ignore[arg-type]
        if number is not None:
            label, label_span = number, (w.start, w.end)  # type: ignore[union-attr]
        i += 1
    words: list[Word] = []
    statements: list[object] = []
    for item in items[i:]:
        if isinstance(item, Word):
            words.append(item)
        else:
            if prep.comments:
                target = item.then if isinstance(item, If) else item
                if isinstance(target, Assign):
                    target.message = _comment_after(prep.comments, target.end)
            statements.append(item)
    stmts = tuple(statements)
    structural = (
        label is not None
        or program is not None
        or prep.tape
        or any(isinstance(s, (While, Do, End)) for s in stmts)
    )
    return Block(
        label=label,
        label_span=label_span,
        program=program,
        program_span=program_span,
        title=title,
        block_delete=prep.block_delete,
        tape=prep.tape,
        words=tuple(words),
        statements=stmts,  # type: ignore[arg-type]
        comments=prep.comments,
        problems=tuple(problems),
        structural=structural,
    )


def assemble_words(words: list[Word], prep: Prepared) -> Block:
    """``assemble`` for a line of NC words only (the fast path's plain blocks)."""
    first = words[0].letter if words else ""
    if first == "O" or first == "N" or prep.problems or prep.comments or prep.tape:
        return assemble(words, prep)
    return Block(block_delete=prep.block_delete, words=tuple(words))


def _is_word(item: object, letter: str) -> bool:
    return isinstance(item, Word) and item.letter == letter


def _whole_literal(w: Word, what: str, problems: list[Problem]) -> int | None:
    """The value of an O or N word, which must be a whole literal number."""
    v = w.value
    if not isinstance(v, Number):
        problems.append(Problem(f"{what} must be written as a number, not a variable or expression", w.start, w.end))
        return None
    if v.value != int(v.value) or v.value < 0:
        problems.append(Problem(f"{what} must be a whole number", w.start, w.end))
        return None
    return int(v.value)


def _first_comment_text(comments: tuple[Comment, ...]) -> str | None:
    return comments[0].text.strip() if comments else None


def _comment_after(comments: tuple[Comment, ...], column: int) -> str | None:
    """The text of the first comment that starts at or after ``column``."""
    for c in comments:
        if c.start >= column:
            return c.text
    return None
