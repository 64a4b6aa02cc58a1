"""Typed syntax tree of one block (one line) of a macro program.

Every node carries ``start`` and ``end``: 0-based columns (code points, end exclusive) in the
line's own text. The line number is not stored in the node: blocks are cached by their text and
shared between lines and documents, so the line is the block's index in its ``Program``.
Nodes are plain slotted dataclasses; once built they are never mutated, because the cache shares
them. Comparison is structural, which the tests use to prove that the fast path and the lark
grammar build the same tree.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, cast

# ---------------------------------------------------------------- expressions


@dataclass(slots=True)
class Number:
    """A numeric literal as written: ``12``, ``-3.5``, ``.5``. ``text`` keeps leading zeros,
    which matter for ``M98 P00020040`` (count and program in one number)."""

    value: float
    text: str
    start: int
    end: int

    @property
    def has_point(self) -> bool:
        return "." in self.text


@dataclass(slots=True)
class Var:
    """``#n`` with a literal number."""

    number: int
    start: int
    end: int


@dataclass(slots=True)
class IndirectVar:
    """``#[expr]``: the variable whose number is the rounded value of ``index``."""

    index: Expr
    start: int
    end: int


@dataclass(slots=True)
class NamedVar:
    """``#_NAME`` or ``#_NAME[n]``: a system variable by its name (FANUC 30i). ``name`` is upper
    case without ``#_``; ``index`` is the bracketed subscript, None when there is none. Which
    number a name stands for is the dialect's business (its ``SYSTEM_VARIABLE_NAMES``)."""

    name: str
    index: Bracket | None
    start: int
    end: int

    @property
    def text(self) -> str:
        """The name as a programmer writes it, without the subscript: ``#_ABSIO``."""
        return f"#_{self.name}"


@dataclass(slots=True)
class Unary:
    """``-x`` or ``+x``."""

    op: str
    operand: Expr
    start: int
    end: int


# AND and OR spelled with symbols (Mazak's EIA/ISO programs: ``[[#1 GT 0] && [#2 LT 5]]``): a
# ``Binary`` keeps the symbol as its op, which means the word it stands for; a control without them
# refuses them (``Dialect.logical_symbols``, docs/semantics.md §3)
LOGICAL_SYMBOLS = {"&&": "AND", "||": "OR"}
# the operators that join bracketed conditions in an IF or WHILE condition
CONDITION_JOINS = frozenset(("AND", "OR", "XOR", *LOGICAL_SYMBOLS))


@dataclass(slots=True)
class Binary:
    """``a op b`` with op one of ``+ - * / AND OR XOR MOD`` (upper case), or ``&&`` / ``||`` as
    written (``LOGICAL_SYMBOLS``: AND and OR spelled as some controls read them)."""

    op: str
    left: Expr
    right: Expr
    start: int
    end: int


@dataclass(slots=True)
class Relation:
    """``a op b`` with op normalised to ``EQ NE GT GE LT LE``; ``spelling`` is the text as
    written (``GT`` or ``>``), so the C-style forms of gsk980tdi can be told apart."""

    op: str
    spelling: str
    left: Expr
    right: Expr
    start: int
    end: int


@dataclass(slots=True)
class Bracket:
    """``[ inner ]``: kept as a node because bracket depth is a rule of the language."""

    inner: Expr
    start: int
    end: int


@dataclass(slots=True)
class FunctionCall:
    """A function call in an expression: ``SIN[x]`` has one argument, ``ATAN[a]/[b]`` two. ``name`` is upper case.
    ``comma`` is True when the first brackets hold two arguments separated by a comma
    (``POW[a,b]``, ``ATAN[a,b]``, ``PRM[n,axis]``); a ``/[b]`` after them adds one more.
    ``bare`` is True when the one argument is a number written without brackets (``SIN30``)."""

    name: str
    args: tuple[Expr, ...]
    start: int
    end: int
    comma: bool = False
    bare: bool = False


Expr = Number | Var | IndirectVar | NamedVar | Unary | Binary | Relation | Bracket | FunctionCall
Variable = Var | IndirectVar | NamedVar

# ---------------------------------------------------------------- words and statements


@dataclass(slots=True)
class Word:
    """An address and its value: ``X-#1``, ``G65``, ``P[CUT]``. ``letter`` is upper case.
    ``value`` is None only when ``name`` holds a bracketed program name (``P[CUT]``)."""

    letter: str
    value: Expr | None
    name: str | None
    start: int
    end: int


@dataclass(slots=True)
class CornerWord:
    """A comma word at the end of a move: ``,C`` a chamfer, ``,R`` a corner radius (FANUC's optional
    chamfering and corner R, Haas corner rounding) or ``,A`` an angle (FANUC direct drawing
    dimension programming). ``letter`` is ``C``, ``R`` or ``A`` (upper case); ``start`` is the
    column of the comma (docs/semantics.md §1)."""

    letter: str
    value: Expr
    start: int
    end: int


@dataclass(slots=True)
class Assign:
    """``#n = expr``. ``message`` is the text of the comment right after it on the block,
    which ``#3000=n(text)`` and ``#3006=n(text)`` show."""

    target: Variable
    value: Expr
    message: str | None
    start: int
    end: int


@dataclass(slots=True)
class If:
    """``IF [cond] GOTO n`` (``goto`` set) or ``IF [cond] THEN statement`` (``then`` set).
    ``implicit_then`` is True when the statement follows the condition without THEN
    (``IF[#1GT10]#2=5``, a form some controls accept, docs/semantics.md §4). ``m99`` holds the
    ``M99`` and ``P`` words of Haas's conditional jump ``[cond] M99 P n``, which is
    ``IF [cond] GOTO n`` written another way: ``goto`` is then the value of that P. With neither
    ``goto`` nor ``then`` the IF governs the rest of its block, the NC words after it or nothing
    (Haas: ``IF [#1 NE #0] G01 X#24``, ``Dialect.if_governs_block``). ``opens_block`` is True for
    ``IF [cond] THEN`` with nothing after THEN: the block form, which runs the blocks up to its
    ``ELSE`` or ``ENDIF`` when the condition holds (Mitsubishi, ``Dialect.block_if``)."""

    condition: Bracket
    goto: Expr | None
    then: Statement | None
    start: int
    end: int
    implicit_then: bool = False
    m99: tuple[Word, Word] | None = None
    opens_block: bool = False


@dataclass(slots=True)
class While:
    """``WHILE [cond] DO m``; ``loop`` is the literal m."""

    condition: Bracket
    loop: Number
    start: int
    end: int


@dataclass(slots=True)
class Do:
    """``DO m`` without WHILE: an endless loop up to ``END m``."""

    loop: Number
    start: int
    end: int


@dataclass(slots=True)
class End:
    """``END m``."""

    loop: Number
    start: int
    end: int


@dataclass(slots=True)
class Else:
    """``ELSE`` of a block ``IF [cond] THEN``: the blocks after it run when the condition did not hold."""

    start: int
    end: int


@dataclass(slots=True)
class EndIf:
    """``ENDIF``: the end of a block ``IF [cond] THEN``."""

    start: int
    end: int


@dataclass(slots=True)
class Goto:
    """``GOTO n``, ``GOTO #i`` or ``GOTO [expr]``."""

    target: Expr
    start: int
    end: int


@dataclass(slots=True)
class OutputPart:
    """One piece of a DPRNT/BPRNT argument: literal ``text`` (``*`` already turned into a
    space) or a variable with its format ``[ab]`` (``digits`` before and ``decimals`` after
    the point; None when not given; BPRNT's ``[c]`` gives ``decimals`` alone)."""

    text: str | None
    variable: Variable | None
    digits: int | None
    decimals: int | None


@dataclass(slots=True)
class Output:
    """External output: ``POPEN``, ``PCLOS``, ``DPRNT[...]`` or ``BPRNT[...]``."""

    command: str
    parts: tuple[OutputPart, ...]
    start: int
    end: int


Statement = Assign | If | While | Do | End | Else | EndIf | Goto | Output
# What a reader takes from a line, in order: NC words, comma words and statements.
Item = Word | CornerWord | Statement

# ---------------------------------------------------------------- the block


@dataclass(slots=True)
class Comment:
    """``( text )``. ``closed`` is False when the line ended before ``)``."""

    text: str
    closed: bool
    start: int
    end: int


def comment_after(comments: tuple[Comment, ...], column: int) -> str | None:
    """The text of the first of ``comments`` that starts at or after ``column``."""
    for c in comments:
        if c.start >= column:
            return c.text
    return None


@dataclass(slots=True, frozen=True)
class Abbreviation:
    """A macro word written shortened (``WH`` for WHILE, keywords.py): its columns, the text as
    written and the whole word."""

    start: int
    end: int
    text: str
    word: str


@dataclass(slots=True)
class Problem:
    """A syntax problem on one block, ready to become a diagnostic. ``alarm`` is the number of
    the alarm a control raises for it (FANUC's, as the interpreter numbers its alarms), kept out
    of ``message``: the analysis and the run name it as the profile shows it (docs/semantics.md
    §6); None where the run stops with its format alarm and the message names none.
    ``without_block_if`` is the message to a control without the block form of IF
    (``Dialect.block_if`` off), where ``message`` suggests that form; ``said`` chooses."""

    message: str
    start: int
    end: int
    severity: str = "error"
    alarm: int | None = None
    without_block_if: str | None = None

    def said(self, block_if: bool) -> str:
        """The message as a control with (``block_if``) or without the block form of IF reads
        it: a line is parsed once for every profile, so the profile chooses here."""
        if block_if or self.without_block_if is None:
            return self.message
        return self.without_block_if


_FIELDS = (
    "label",
    "label_span",
    "program",
    "program_span",
    "title",
    "block_delete",
    "tape",
    "words",
    "corners",
    "statements",
    "comments",
    "problems",
    "structural",
    "abbreviations",
)


class Block:
    """One line of a program.

    ``label`` is the sequence number of a leading ``N`` word; ``program`` the number of a
    leading ``O`` word (the line then starts a program, ``title`` being its first comment).
    ``words`` holds the NC words other than those two, in order; ``statements`` the macro
    statements; ``corners`` the comma words (``,C5.``, ``,R#1``), kept apart from ``words``
    because they are no address of their own (``,R`` is not ``R``). ``block_delete`` is None,
    0 for ``/`` or 1–9 for ``/n``. ``tape`` marks a ``%`` line, or a ``%`` after the code of its
    line (``M30%``, ``code_before_mark``). ``problems`` are the syntax
    errors and warnings of the line; a block with an error has no words or statements.
    ``structural`` is True when the block has a label, O header, ``%`` mark or loop marker (see
    program.py). ``abbreviations`` lists the macro words written shortened (``WH[..]DO1``), in
    column order.

    A line of whitespace-separated address-number words with at most three decimals
    (``G01 X12.5 Y-3.``), most of a CAM program, is kept as its text in ``plain`` and its
    ``words`` are read the first time they are asked for: opening a file then costs one
    pattern match per such line, and the interpreter compiles these lines straight from
    ``plain`` (its ``split()`` is its words). A sequence number followed by such words
    (``N10 G01 X5.``, a line in ten of a CAM program) is a labelled block like any other, with
    the text after its label kept in ``plain_tail`` and its words read from it the first time
    they are asked for; the interpreter and the static checks read that text as they read a
    plain line.
    """

    __slots__ = ("_words", "plain")  # all a plain line's block holds (see ``of_plain``)
    plain: str | None
    _words: tuple[Word, ...] | None
    # the other fields as a plain line's block has them: ``Block(...)`` makes a ``_Block``,
    # which holds each of them itself
    label: int | None = None
    label_span: tuple[int, int] | None = None
    program: int | None = None
    program_span: tuple[int, int] | None = None
    title: str | None = None
    block_delete: int | None = None
    tape: bool = False
    corners: tuple[CornerWord, ...] = ()
    statements: tuple[Statement, ...] = ()
    comments: tuple[Comment, ...] = ()
    problems: tuple[Problem, ...] = ()
    structural: bool = False
    plain_tail: str | None = None
    abbreviations: tuple[Abbreviation, ...] = ()

    def __new__(cls, *args: Any, **kwargs: Any) -> Block:
        return object.__new__(_Block if cls is Block else cls)

    def __init__(
        self,
        label: int | None = None,
        label_span: tuple[int, int] | None = None,
        program: int | None = None,
        program_span: tuple[int, int] | None = None,
        title: str | None = None,
        block_delete: int | None = None,
        tape: bool = False,
        words: tuple[Word, ...] | None = (),
        corners: tuple[CornerWord, ...] = (),
        statements: tuple[Statement, ...] = (),
        comments: tuple[Comment, ...] = (),
        problems: tuple[Problem, ...] = (),
        structural: bool = False,
        plain: str | None = None,
        abbreviations: tuple[Abbreviation, ...] = (),
    ) -> None:
        b = cast("_Block", self)  # ``Block(...)`` makes a ``_Block`` (``__new__``)
        b.label = label
        b.label_span = label_span
        b.program = program
        b.program_span = program_span
        b.title = title
        b.block_delete = block_delete
        b.tape = tape
        b._words = None if plain is not None else words
        b.corners = corners
        b.statements = statements
        b.comments = comments
        b.problems = problems
        b.structural = structural
        b.plain = plain
        b.plain_tail = None
        b.abbreviations = abbreviations

    @property
    def plain_text(self) -> str | None:
        """The text of the line's words when they are plain address-number words, after a label
        or not (``plain``, ``plain_tail``): what a search of a plain line looks at; else None."""
        return self.plain if self.plain is not None else self.plain_tail

    @property
    def words(self) -> tuple[Word, ...]:
        w = self._words
        if w is None:
            from .fastpath import plain_words

            tail = self.plain_tail
            if tail is not None and self.label_span is not None:
                w = self._words = tuple(plain_words(tail, self.label_span[1]) or ())
            else:
                w = self._words = tuple(plain_words(self.plain or "") or ())
        return w

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Block):
            return NotImplemented
        return all(getattr(self, f) == getattr(other, f) for f in _FIELDS)

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        shown = ", ".join(f"{f}={getattr(self, f)!r}" for f in _FIELDS if getattr(self, f) not in (None, (), False))
        return f"Block({shown})"

    @classmethod
    def of_plain(cls, line: str, _new: Any = object.__new__) -> Block:
        """``Block(plain=line)`` without the keyword handling: opening a file makes one for
        nearly every line of a CAM program. It holds its text and, once asked for, its words;
        every other field is the class's (no label, no statement, no problem): two fields made,
        not sixteen, and a third of the memory."""
        b: Block = _new(Block)
        b.plain = line
        b._words = None
        return b

    @classmethod
    def of_labelled(cls, tail: str, label: int, label_span: tuple[int, int], _new: Any = object.__new__) -> Block:
        """The block of a sequence number and plain words (``N10 G01 X5.``): ``label`` written
        at ``label_span``, then ``tail``, the rest of the line, whose words are read when asked for."""
        b: _Block = _new(_Block)
        b.program = b.program_span = b.title = b.block_delete = b._words = b.plain = None
        b.label = label
        b.label_span = label_span
        b.plain_tail = tail
        b.tape = False
        b.structural = True
        b.corners = b.statements = b.comments = b.problems = b.abbreviations = ()
        return b

    @property
    def has_error(self) -> bool:
        return bool(self.problems) and any(p.severity == "error" for p in self.problems)

    @property
    def is_empty(self) -> bool:
        """True for a line that does nothing: blank, comments only, or only ``;``."""
        if self.plain is not None:
            return False
        return (
            self.label is None
            and self.program is None
            and not self.tape
            and not self.words
            and not self.corners
            and not self.statements
            and not self.has_error
        )

    @property
    def code_before_mark(self) -> bool:
        """True for a ``%`` written after code on its line (``M30%``): the code is a block
        that runs, and the mark after it ends the tape (docs/semantics.md §1)."""
        return self.tape and (
            self.label is not None
            or self.program is not None
            or bool(self.words or self.corners or self.statements)
            or self.has_error
        )

    def comment_after(self, column: int) -> str | None:
        """The text of the first comment that starts at or after ``column``: the message of
        ``#3000=n(text)`` (``Assign.message``) and of gsk980tdi ``G65 H99 Pn(/text)``."""
        return comment_after(self.comments, column)

    def word(self, letter: str) -> Word | None:
        """The first NC word with this address letter, if any."""
        for w in self.words:
            if w.letter == letter:
                return w
        return None

    def structure_key(self) -> tuple[object, ...] | None:
        """What this block adds to the cross-line structure (None for most blocks): two
        blocks with equal keys leave a ``Program`` unchanged when one replaces the other."""
        if not self.structural:
            return None
        marker = self.loop_marker()
        loop = (marker[0], marker[1].value) if marker else None
        return (self.label, self.program, self.title, self.tape, loop, self.branch_marker())

    def loop_marker(self) -> tuple[str, Number] | None:
        """``("DO", m)`` for a WHILE..DO or DO block, ``("END", m)`` for END, else None."""
        for s in self.statements:
            if isinstance(s, (While, Do)):
                return ("DO", s.loop)
            if isinstance(s, End):
                return ("END", s.loop)
        return None

    def branch_marker(self) -> str | None:
        """``"IF"`` for a block ``IF [cond] THEN`` (nothing after THEN), ``"ELSE"``, ``"ENDIF"``,
        else None: the markers of the block form of IF (program.py pairs them)."""
        for s in self.statements:
            if s.__class__ is If and s.opens_block:
                return "IF"
            if s.__class__ is Else:
                return "ELSE"
            if s.__class__ is EndIf:
                return "ENDIF"
        return None


class _Block(Block):
    """The block of any line but a plain one (``Block.of_plain``): every field held by itself."""

    __slots__ = (*(f for f in _FIELDS if f != "words"), "plain_tail")
