"""Turning the items read from a line (words and macro statements) into a ``Block``.

Both the lark grammar and the fast path for plain NC blocks end here, so whatever reads the
line, a leading ``O`` word becomes the program header, a leading ``N`` word the sequence
number, and a comment right after ``#3000=n`` its message (``nodes.comment_after``, which also
finds the text of a gsk980tdi ``G65 H99 Pn(/text)``) in exactly the same way.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import cast

from ..bilingual import Detail, detail
from .lines import Prepared
from .nodes import (
    Abbreviation,
    Assign,
    Block,
    Comment,
    CornerWord,
    Do,
    Else,
    End,
    EndIf,
    If,
    Item,
    Number,
    Problem,
    Statement,
    While,
    Word,
    comment_after,
)


class Items(list[Item]):
    """The items read from a line, with the macro words written shortened among them (both
    readers, the grammar and the fast path, hand them over so)."""

    __slots__ = ("abbreviations",)

    def __init__(self, items: Sequence[Item], abbreviations: Sequence[Abbreviation]) -> None:
        super().__init__(items)
        self.abbreviations = tuple(sorted(abbreviations, key=_start)) if abbreviations else ()


def _start(a: Abbreviation) -> int:
    return a.start


def assemble(items: Sequence[Item], prep: Prepared) -> Block:
    """Build the block of a line from its items, in the order they were written."""
    if len(items) == 1 and not (prep.problems or prep.comments or prep.tape):
        s = items[0]
        if s.__class__ is not Word and s.__class__ is not CornerWord:  # one statement, the commonest macro line
            statement = cast(Statement, s)
            return Block(
                block_delete=prep.block_delete,
                statements=(statement,),
                structural=_marks_structure(statement),
                abbreviations=getattr(items, "abbreviations", ()),
            )
    problems = list(prep.problems)
    program: int | None = None
    program_span: tuple[int, int] | None = None
    label: int | None = None
    label_span: tuple[int, int] | None = None
    title = None
    i = 0
    n = len(items)
    if n:
        w = items[0]
        if isinstance(w, Word) and w.letter == "O":
            number = _whole_literal(w, *_PROGRAM_NUMBER, problems)
            if number is not None:
                program, program_span = number, (w.start, w.end)
                title = _first_comment_text(prep.comments)
            i = 1
    if i < n:
        w = items[i]
        if isinstance(w, Word) and w.letter == "N":
            number = _whole_literal(w, *_SEQUENCE_NUMBER, problems)
            if number is not None:
                label, label_span = number, (w.start, w.end)
            i += 1
    words: list[Word] = []
    corners: list[CornerWord] = []
    statements: list[Statement] = []
    for item in items[i:]:
        if isinstance(item, Word):
            words.append(item)
        elif isinstance(item, CornerWord):
            corners.append(item)
        else:
            if prep.comments:
                target = item.then if isinstance(item, If) else item
                if isinstance(target, Assign):
                    target.message = comment_after(prep.comments, target.end)
            statements.append(item)
    if program is None and not statements and len(words) > 1 and words[-1].letter == "O" and _ends_program(words[-2]):
        w = words[-1]  # M99O0810: one program's end and the next one's number on one line (a dump file)
        number = _whole_literal(w, *_PROGRAM_NUMBER, problems)
        if number is not None:
            program, program_span = number, (w.start, w.end)
            title = comment_after(prep.comments, w.end)
            words.pop()
    stmts = tuple(statements)
    structural = label is not None or program is not None or prep.tape or any(_marks_structure(s) for s in stmts)
    return Block(
        label=label,
        label_span=label_span,
        program=program,
        program_span=program_span,
        title=title,
        block_delete=prep.block_delete,
        tape=prep.tape,
        words=tuple(words),
        corners=tuple(corners),
        statements=stmts,
        comments=prep.comments,
        problems=tuple(problems),
        structural=structural,
        abbreviations=getattr(items, "abbreviations", ()),
    )


def assemble_words(words: list[Word], prep: Prepared) -> Block:
    """``assemble`` for a line of NC words only (the fast path's plain blocks)."""
    first = words[0].letter if words else ""
    if first == "O" or first == "N" or prep.problems or prep.comments or prep.tape or words[-1].letter == "O":
        return assemble(words, prep)
    return Block(block_delete=prep.block_delete, words=tuple(words))


_PROGRAM_NUMBER = (
    detail(
        "a program number must be written as a number, not a variable or expression",
        "程序号必须直接写成数字，不能使用变量或表达式",
    ),
    detail("a program number must be a whole number written without a decimal point", "程序号必须是不带小数点的整数"),
)
_SEQUENCE_NUMBER = (
    detail(
        "a sequence number must be written as a number, not a variable or expression",
        "顺序号必须直接写成数字，不能使用变量或表达式",
    ),
    detail("a sequence number must be a whole number written without a decimal point", "顺序号必须是不带小数点的整数"),
)


def _whole_literal(w: Word, not_literal: Detail, not_whole: Detail, problems: list[Problem]) -> int | None:
    """The value of an O or N word, which must be a whole literal number written without a
    decimal point (``O1234.`` as ``O12.34``: an address that takes no decimal point, FANUC alarm
    007); what to say when it is not a literal, and when it is not whole."""
    v = w.value
    if not isinstance(v, Number):
        problems.append(Problem(not_literal, w.start, w.end))
        return None
    if v.has_point or v.value != int(v.value) or v.value < 0:
        problems.append(Problem(not_whole, w.start, w.end))
        return None
    return int(v.value)


def _ends_program(w: Word) -> bool:
    """``M99``, ``M30`` or ``M02`` written as a literal: a word after which an O word starts the
    next program (docs/semantics.md §1)."""
    v = w.value
    return w.letter == "M" and isinstance(v, Number) and not v.has_point and v.value in (99.0, 30.0, 2.0)


def _marks_structure(s: Statement) -> bool:
    """Whether a statement is a marker the program's structure is made of: a loop's head or end,
    or a block IF's IF, ELSE or ENDIF (program.py)."""
    return isinstance(s, (While, Do, End, Else, EndIf)) or (s.__class__ is If and s.opens_block)


def _first_comment_text(comments: tuple[Comment, ...]) -> str | None:
    return comments[0].text.strip() if comments else None
