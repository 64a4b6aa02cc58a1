"""The lark LALR parser of one block and the transformer that builds typed nodes while parsing.

The grammar lives in ``block.lark``. Nodes are built inside the parse (lark's inline
transformer), so no intermediate parse tree is made. Rules the language imposes on top of the
grammar (comparisons only in IF/WHILE conditions, ``AND``/``OR`` joining bracketed
conditions, whole loop numbers) raise ``BlockError`` with a plain-words message (English, with
its Chinese beside it).
"""

from __future__ import annotations

import re
from importlib import resources
from typing import TYPE_CHECKING, Any

from lark import Lark, Token, Transformer, Tree
from lark.tree import Meta

from ..bilingual import detail
from .assemble import Items
from .conditions import (
    MAX_NUMBER_CHARS,
    RELATION_NAMES,
    TOO_MANY_DIGITS,
    BlockError,
    check_condition,
    has_relation,
    relation_error,
)
from .keywords import full_word, pattern
from .nodes import (
    Abbreviation,
    Assign,
    Binary,
    Bracket,
    CornerWord,
    Do,
    Else,
    End,
    EndIf,
    Expr,
    FunctionCall,
    Goto,
    If,
    IndirectVar,
    NamedVar,
    Number,
    Output,
    OutputPart,
    Relation,
    Statement,
    Unary,
    Var,
    Variable,
    While,
    Word,
)

if TYPE_CHECKING:

    class _Tok(Token):
        """A token of the lexer, which always sets its positions (lark types them optional)."""

        start_pos: int
        end_pos: int

else:
    _Tok = Token

# A rule's children as lark hands them to its callback: tokens and the nodes its sub-rules
# built, in the grammar's order. Each callback names their types as it takes them apart.
_Children = list[Any]


def _start(x: _Tok | Expr) -> int:
    return x.start_pos if isinstance(x, Token) else x.start


def _end(x: _Tok | Expr) -> int:
    return x.end_pos if isinstance(x, Token) else x.end


def _literal(text: str, start: int, end: int) -> Number:
    digits = sum(ch.isdigit() for ch in text)
    if digits > MAX_NUMBER_CHARS:
        raise BlockError(
            detail(
                f"a number of {digits} digits is too long to read: at most {MAX_NUMBER_CHARS}",
                f"数字有 {digits} 位，太长无法读取：最多 {MAX_NUMBER_CHARS} 位",
            ),
            start,
            end,
            TOO_MANY_DIGITS,
        )
    return Number(float(text), text, start, end)


def _number(tok: _Tok) -> Number:
    return _literal(str(tok), tok.start_pos, tok.end_pos)


def _varnum(tok: _Tok) -> Var:
    digits = tok[1:].strip().rstrip(".")  # ``#504.`` is #504
    _literal(digits, tok.start_pos, tok.end_pos)  # its length is checked
    return Var(int(digits), tok.start_pos, tok.end_pos)


_DPRNT_PIECE = re.compile(r"#[ \t]*(\d+)(?:[ \t]*\[[ \t]*(\d)[ \t]*(\d)[ \t]*\])?|\[|\]|.", re.S)
# BPRNT's ``#b[c]``: one digit, the decimal places (docs/semantics.md §5)
_BPRNT_PIECE = re.compile(r"#[ \t]*(\d+)(?:[ \t]*\[[ \t]*()(\d)[ \t]*\])?|\[|\]|.", re.S)


class _Builder(Transformer[Token, Items]):
    """Lark callbacks: one method per grammar rule, each returning a node.

    ``relations`` counts the comparisons built since ``reset``: while it is 0, no expression
    of the line can hide one, and the checks that walk expressions are skipped.
    ``abbreviations`` collects the macro words written shortened (keywords.py).
    """

    relations = 0
    abbreviations: list[Abbreviation]

    def reset(self) -> None:
        self.relations = 0
        self.abbreviations = []

    def _word(self, tok: _Tok) -> str:
        """The whole word a keyword token stands for; an abbreviation is noted."""
        word = full_word(tok)
        if len(tok) != len(word):
            self.abbreviations.append(Abbreviation(tok.start_pos, tok.end_pos, str(tok), word))
        return word

    def __default__(self, data: str, children: _Children, meta: Meta) -> Tree[Token]:
        return Tree(data, children, meta)  # lark's helper rules (item*) stay trees

    # ---- items
    def start(self, children: _Children) -> Items:
        for k, item in enumerate(children[:-1]):
            if isinstance(item, If) and item.opens_block:  # IF [..] THEN GOTO n: not a statement after THEN
                after = children[k + 1]
                if not isinstance(after, Word | CornerWord):  # NC words after it are judged later (nc-and-macro)
                    raise BlockError(_AFTER_THEN, after.start, after.end, without_block_if=_AFTER_THEN_ONLY)
        return Items(children, self.abbreviations)

    def word(self, c: _Children) -> Word:
        letter: _Tok = c[0]
        value: _Tok | Expr = c[1]
        if isinstance(value, Token):  # BRACKET_NAME
            return Word(letter.upper(), None, value[1:-1], letter.start_pos, value.end_pos)
        if self.relations and has_relation(value):
            raise relation_error(value)
        return Word(letter.upper(), value, None, letter.start_pos, value.end)

    def corner(self, c: _Children) -> CornerWord:
        head: _Tok
        value: Expr
        head, value = c
        if self.relations and has_relation(value):
            raise relation_error(value)
        return CornerWord(head[-1].upper(), value, head.start_pos, value.end)

    def wvalue(self, c: _Children) -> Expr:
        sign: _Tok
        x: _Tok | Expr
        if len(c) == 1:
            x = c[0]
            return _number(x) if isinstance(x, Token) else x
        sign, x = c
        if isinstance(x, Token):  # a signed literal is one number
            text = sign + x
            return _literal(text, sign.start_pos, x.end_pos)
        return Unary(str(sign), x, sign.start_pos, x.end)

    def assign(self, c: _Children) -> Assign:
        target: Variable
        value: Expr
        if len(c) == 5:  # [#_NAME] = value
            lb: _Tok
            lb, target, _rb, _eq, value = c
            if self.relations and has_relation(value):
                raise relation_error(value)
            if self.relations and has_relation(target):
                raise relation_error(target)
            return Assign(target, value, None, lb.start_pos, value.end)
        target, _eq, value = c
        if self.relations and has_relation(value):
            raise relation_error(value)
        if self.relations and isinstance(target, (IndirectVar, NamedVar)) and has_relation(target):
            raise relation_error(target)
        return Assign(target, value, None, target.start, value.end)

    def if_stmt(self, c: _Children) -> If:
        kw: _Tok = c[0]
        cond: Bracket = c[1]
        then: Statement
        if len(c) == 2:  # IF [cond] alone: it governs the rest of the block (words) or nothing
            check_condition(cond)
            return If(cond, None, None, kw.start_pos, cond.end)
        if len(c) == 3 and not isinstance(c[2], Token):  # IF [cond] statement: THEN left out
            then = c[2]
            check_condition(cond)
            return If(cond, None, then, kw.start_pos, then.end, True)
        kw2: _Tok = c[2]
        check_condition(cond)
        self._word(kw2)
        if len(c) == 3:  # IF [cond] THEN alone: the block form, up to ELSE or ENDIF
            return If(cond, None, None, kw.start_pos, kw2.end_pos, opens_block=True)
        if kw2.type == "GOTO":
            goto: Expr = c[3]
            return If(cond, goto, None, kw.start_pos, goto.end)
        then = c[3]
        return If(cond, None, then, kw.start_pos, then.end)

    def m99_jump(self, c: _Children) -> If:
        """Haas's ``[cond] M99 P n``: ``IF [cond] GOTO n`` written another way (docs/semantics.md §4);
        whether the dialect reads it is decided later (``machine/block_rules.py``)."""
        cond: Bracket = c[0]
        m99: Word = c[1]
        if not _is_m99(m99):
            raise BlockError(_BRACKET_STARTS_BLOCK, cond.start, cond.end)
        p: Word | None = c[2] if len(c) > 2 else None
        if p is None or p.letter != "P" or p.value is None:
            where = p if p is not None else m99
            raise BlockError(_M99_NEEDS_P, where.start, where.end)
        check_condition(cond)
        return If(cond, p.value, None, cond.start, p.end, m99=(m99, p))

    def while_stmt(self, c: _Children) -> While:
        kw: _Tok
        cond: Bracket
        num: _Tok
        kw, cond, _do, num = c
        check_condition(cond)
        self._word(kw)
        return While(cond, _number(num), kw.start_pos, num.end_pos)

    def do_stmt(self, c: _Children) -> Do:
        kw: _Tok
        num: _Tok
        kw, num = c
        return Do(_number(num), kw.start_pos, num.end_pos)

    def end_stmt(self, c: _Children) -> End:
        kw: _Tok
        num: _Tok
        kw, num = c
        self._word(kw)
        return End(_number(num), kw.start_pos, num.end_pos)

    def else_stmt(self, c: _Children) -> Else:
        kw: _Tok = c[0]
        return Else(kw.start_pos, kw.end_pos)

    def endif_stmt(self, c: _Children) -> EndIf:
        kw: _Tok = c[0]
        return EndIf(kw.start_pos, kw.end_pos)

    def goto_stmt(self, c: _Children) -> Goto:
        kw: _Tok
        target: Expr
        kw, target = c
        self._word(kw)
        return Goto(target, kw.start_pos, target.end)

    def target(self, c: _Children) -> Expr:
        x: _Tok | Expr = c[0]
        if isinstance(x, Token):
            return _number(x)
        if self.relations and has_relation(x):
            raise relation_error(x)
        return x

    def output_stmt(self, c: _Children) -> Output:
        kw: _Tok = c[0]
        name = self._word(kw)
        if len(c) == 1:
            return Output(name, (), kw.start_pos, kw.end_pos)
        args: _Tok = c[1]
        return Output(name, _output_parts(args, name == "BPRNT"), kw.start_pos, args.end_pos)

    # ---- expressions
    def binary(self, c: _Children) -> Binary:
        left: Expr
        op: _Tok
        right: Expr
        left, op, right = c
        return Binary(self._word(op), left, right, left.start, right.end)

    def unary(self, c: _Children) -> Unary:
        sign: _Tok
        x: Expr
        sign, x = c
        return Unary(str(sign), x, sign.start_pos, x.end)

    def number(self, c: _Children) -> Number:
        return _number(c[0])

    def bracket(self, c: _Children) -> Bracket:
        lb: _Tok
        inner: Expr
        rb: _Tok
        lb, inner, rb = c
        return Bracket(inner, lb.start_pos, rb.end_pos)

    def relation(self, c: _Children) -> Relation:
        left: Expr
        op: _Tok
        right: Expr
        left, op, right = c
        self.relations += 1
        spelling = op.upper()
        for side in (left, right):
            if has_relation(side):
                raise relation_error(side)
        return Relation(RELATION_NAMES.get(spelling, spelling), spelling, left, right, left.start, right.end)

    def named(self, c: _Children) -> NamedVar:
        head: _Tok = c[0]
        name = head[head.index("_") + 1 :].upper()
        index: Bracket | None = c[1] if len(c) > 1 else None
        return NamedVar(name, index, head.start_pos, index.end if index is not None else head.end_pos)

    def variable(self, c: _Children) -> Variable:
        head: _Tok | NamedVar = c[0]
        if isinstance(head, NamedVar):
            return head
        if len(c) == 1:
            return _varnum(head)
        hash_: _Tok
        index: Bracket
        hash_, index = c
        return IndirectVar(index, hash_.start_pos, index.end)

    def call(self, c: _Children) -> FunctionCall:
        head: _Tok = c[0]
        last: _Tok = c[-1]
        name = self._word(head)
        args: tuple[Expr, ...] = tuple(x for x in c[1:] if not isinstance(x, Token))
        if self.relations:
            for a in args:
                if has_relation(a):
                    raise relation_error(a)
        comma = any(isinstance(x, Token) and x.type == "COMMA" for x in c)
        return FunctionCall(name, args, head.start_pos, last.end_pos, comma)

    def bare_call(self, c: _Children) -> FunctionCall:
        head: _Tok
        num: _Tok
        head, num = c
        return FunctionCall(self._word(head), (_number(num),), head.start_pos, num.end_pos, bare=True)


_BRACKET_STARTS_BLOCK = detail(
    "a condition in brackets starts a block only in the conditional jump [cond] M99 P n (Haas); "
    "write IF [cond] GOTO n or IF [cond] THEN <statement>",
    "方括号中的条件只能在条件跳转 [条件] M99 P n（哈斯）中位于程序段开头；"
    "请写作 IF [条件] GOTO n 或 IF [条件] THEN <语句>",
)
_AFTER_THEN = detail(
    "after THEN comes one assignment or output statement (IF [cond] THEN #1=..), or nothing: the block form "
    "IF [cond] THEN, closed by ENDIF on a later line",
    "THEN 之后只能是一条赋值或输出语句（IF [条件] THEN #1=..），或者什么都不写：块形式 IF [条件] THEN，"
    "在后面的程序段以 ENDIF 结束",
)
# the same to a control without the block form of IF (GSK980TDi, FANUC: only IF [cond] GOTO n and
# IF [cond] THEN <statement>): it suggests only those
_AFTER_THEN_ONLY = detail(
    "after THEN comes one assignment or output statement (IF [cond] THEN #1=..); a jump is written "
    "IF [cond] GOTO n, without THEN",
    "THEN 之后只能是一条赋值或输出语句（IF [条件] THEN #1=..）；跳转写作 IF [条件] GOTO n，不写 THEN",
)
_M99_NEEDS_P = detail(
    "the conditional M99 needs P n after it: the sequence number to jump to ([cond] M99 P n)",
    "条件 M99 之后需要 P n：要跳转到的顺序号（[条件] M99 P n）",
)


def _is_m99(w: Word) -> bool:
    """Whether ``w`` is ``M99`` written as a literal (``M99``, ``M099``)."""
    v = w.value
    return w.letter == "M" and isinstance(v, Number) and v.value == 99 and not v.has_point and v.text[0] != "+"


def _output_parts(tok: _Tok, binary: bool = False) -> tuple[OutputPart, ...]:
    """Split ``[X#2[53]**Y#5]`` into literal text and formatted variables; BPRNT's (``binary``)
    ``[X#2[3]]`` gives each variable its decimal places alone."""
    body = str(tok)[1:-1]
    base = tok.start_pos + 1
    parts: list[OutputPart] = []
    text: list[str] = []
    for m in (_BPRNT_PIECE if binary else _DPRNT_PIECE).finditer(body):
        if m.group(1) is not None:
            if text:
                parts.append(OutputPart("".join(text), None, None, None))
                text = []
            var = Var(int(m.group(1)), base + m.start(), base + m.end(1))
            digits = int(m.group(2)) if m.group(2) else None
            decimals = int(m.group(3)) if m.group(3) else None
            parts.append(OutputPart(None, var, digits, decimals))
        else:
            ch = m.group(0)
            if ch == "*":
                text.append(" ")
            elif ch not in " \t":
                text.append(ch)
    if text:
        parts.append(OutputPart("".join(text), None, None, None))
    return tuple(parts)


def _load_grammar() -> str:
    """``block.lark`` with each ``@WORD@`` spelled out as the word or its abbreviations."""
    text = resources.files(__package__).joinpath("block.lark").read_text(encoding="utf-8")
    return re.sub(r"@([A-Z]+)@", lambda m: pattern(m.group(1)), text)


GrammarParser = tuple[Lark, _Builder]


def make_parser() -> GrammarParser:
    """A fresh LALR parser that builds nodes as it parses, and its node builder."""
    builder = _Builder()
    lark = Lark(
        _load_grammar(),
        parser="lalr",
        lexer="contextual",
        transformer=builder,
        maybe_placeholders=False,
    )
    return lark, builder
