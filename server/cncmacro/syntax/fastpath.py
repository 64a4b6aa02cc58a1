"""The fast path: a hand-written reader for the common forms of a block.

Plain NC blocks (``G01 X12.5 Y-3. F200``) are nine lines in ten of a CAM program, and most of
the rest are assignments and IF/WHILE/GOTO with ordinary expressions. LALR parsing in Python
costs several microseconds a token, so these forms are read here instead, by a regular
expression for plain words and a small recursive-descent reader for statements.

The contract, held by a property test: for any line this module accepts, it returns exactly
the items that the lark grammar builds; for anything else (a bracketed program name, DPRNT,
an unusual form, every error) it returns None and the grammar decides, so error messages
always come from the grammar.
"""

from __future__ import annotations

import re

from .assemble import Items
from .conditions import MAX_NUMBER_CHARS, RELATION_NAMES, BlockError, check_condition, has_relation
from .keywords import FULL_WORD
from .nodes import (
    Abbreviation,
    Assign,
    Binary,
    Bracket,
    Do,
    End,
    Expr,
    FunctionCall,
    Goto,
    If,
    IndirectVar,
    Item,
    Number,
    Relation,
    Unary,
    Var,
    While,
    Word,
)

_WORDS = re.compile(r"([ \t]*)([A-Za-z])([+-]?(?:\d+\.?\d*|\.\d+))")


def plain_words(code: str, column: int = 0) -> list[Word] | None:
    """The words of ``code`` when it holds only address-number words, else None; ``code``
    starts at ``column`` of its line (after a sequence number, ``Block.plain_tail``).

    ``findall`` skips what it cannot match, so the columns are counted from the matched
    lengths: they reach the end of the line exactly when nothing was skipped.
    """
    words = []
    pos = column
    for gap, letter, text in _WORDS.findall(code):
        if len(text) > MAX_NUMBER_CHARS:
            return None  # the grammar says why
        pos += len(gap)
        end = pos + 1 + len(text)
        words.append(Word(letter.upper(), Number(float(text), text, pos + 1, end), None, pos, end))
        pos = end
    if not words or pos - column != len(code.rstrip(" \t")):
        return None
    return words


# ---------------------------------------------------------------- statements

# A run of two letters or more is one macro word (a value never starts with a letter, so two
# letters are never an address and its value): the word itself or an abbreviation of it
# (keywords.py). Any other run is left to the grammar.
_MACRO_WORDS = {
    **{w: w for w in (
        "ATAN ASIN ACOS SQRT ROUND WHILE GOTO THEN POPEN PCLOS DPRNT BPRNT SIN COS TAN ABS EXP FIX FUP BIN BCD "
        "AND MOD XOR END LN OR EQ NE GT GE LT LE IF DO"
    ).split()},
    **FULL_WORD,
}  # fmt: skip
# a token after the blanks before it: a variable, a number, a macro word, an operator or a letter
_TOKEN = re.compile(
    r"([ \t]*)(?:(#[ \t]*\d+)|(\d+\.?\d*|\.\d+)|([A-Za-z]{2,})|(==|!=|<>|<=|>=|&&|\|\||[-+*/\[\]=<>#])|([A-Za-z]))"
)
_BRACKET_NAME = re.compile(r"\[(?=[^\[\]#()\s]*[^\[\]#()\s\d.+\-*/])(?:[^\[\]#()\s.]|\.(?=[./\\]))[^\[\]#()\s]*\]")
_FUNCS = frozenset("SIN COS TAN ASIN ACOS SQRT ABS LN EXP ROUND FIX FUP BIN BCD".split())
_RELOPS = frozenset("EQ NE GT GE LT LE == != <> <= >= < >".split())
_MULOPS = frozenset(("*", "/", "AND", "MOD", "&&"))
_ADDOPS = frozenset(("+", "-", "OR", "XOR", "||"))
_MAX_TOKENS = 200


_tokens = _TOKEN.findall

# token kinds
_VAR, _NUM, _KW, _OP, _LETTER, _EOF = range(6)


class _Decline(Exception):
    """The line is not one of the forms read here: let the grammar read it."""


def read_items(code: str) -> Items | None:
    """The items of a block of common statement forms, or None to defer to the grammar."""
    if code.count("[") > 12:  # deep nesting is rare; the grammar reads it without recursion
        return None
    shortened: list[Abbreviation] = []
    toks = _tokenize(code, shortened)
    if toks is None:
        return None
    try:
        return Items(_Reader(toks, code).items(), shortened)
    except (_Decline, BlockError):
        return None


def _tokenize(code: str, shortened: list[Abbreviation]) -> list[tuple[int, str, int, int]] | None:
    """The tokens of ``code``; a macro word stands for its whole word, and each one written
    shortened is added to ``shortened``. ``_TOKEN`` reads the blanks before each token and the
    token in a group of its kind, all at once: the columns are counted from the lengths read, so
    they reach the end of the code (its trailing blanks aside) exactly when nothing was skipped."""
    toks: list[tuple[int, str, int, int]] = []
    append = toks.append
    e = 0
    for blanks, var, num, kw, op, letter in _tokens(code):
        s = e + len(blanks)
        if op:
            e = s + len(op)
            append((_OP, op, s, e))
        elif var or num:
            text = var or num
            if len(text) > MAX_NUMBER_CHARS:
                return None  # the grammar says why
            e = s + len(text)
            append((_VAR if var else _NUM, text, s, e))
        elif kw:
            e = s + len(kw)
            up = kw.upper()
            word = _MACRO_WORDS.get(up)
            if word is None:
                return None
            if word != up:
                shortened.append(Abbreviation(s, e, kw, word))
            append((_KW, word, s, e))
        else:
            e = s + 1
            append((_LETTER, letter.upper(), s, e))
    n = len(code)
    if (e != n and e != len(code.rstrip(" \t"))) or len(toks) > _MAX_TOKENS:
        return None
    append((_EOF, "", n, n))
    return toks


class _Reader:
    """Recursive descent over the grammar's common rules, building the grammar's nodes."""

    def __init__(self, toks: list[tuple[int, str, int, int]], code: str) -> None:
        self.toks = toks
        self.code = code
        self.i = 0
        self.relations = 0

    # ---- helpers
    def peek(self) -> tuple[int, str, int, int]:
        return self.toks[self.i]

    def take(self) -> tuple[int, str, int, int]:
        t = self.toks[self.i]
        self.i += 1
        return t

    def expect(self, kind: int, text: str | None = None) -> tuple[int, str, int, int]:
        t = self.toks[self.i]
        if t[0] != kind or (text is not None and t[1] != text):
            raise _Decline
        self.i += 1
        return t

    def number(self) -> Number:
        _k, text, s, e = self.expect(_NUM)
        return Number(float(text), text, s, e)

    # ---- items
    def items(self) -> list[Item]:
        out: list[Item] = []
        while self.peek()[0] != _EOF:
            out.append(self.item())
        return out

    def item(self) -> Item:
        kind, text, s, _e = self.peek()
        if kind == _LETTER:
            return self.word()
        if kind == _VAR or (kind == _OP and text == "#"):
            return self.assign()
        if kind == _KW:
            self.i += 1
            if text == "IF":
                cond = self.condition()
                k2 = self.take()
                if k2[0] == _KW and k2[1] == "GOTO":
                    target = self.target()
                    return If(cond, target, None, s, target.end)
                if k2[0] == _KW and k2[1] == "THEN":
                    then = self.assign()
                    return If(cond, None, then, s, then.end)
                if k2[0] == _VAR or (k2[0] == _OP and k2[1] == "#"):  # THEN left out
                    self.i -= 1
                    then = self.assign()
                    return If(cond, None, then, s, then.end, True)
                raise _Decline
            if text == "WHILE":
                cond = self.condition()
                self.expect(_KW, "DO")
                num = self.number()
                return While(cond, num, s, num.end)
            if text == "DO":
                num = self.number()
                return Do(num, s, num.end)
            if text == "END":
                num = self.number()
                return End(num, s, num.end)
            if text == "GOTO":
                target = self.target()
                return Goto(target, s, target.end)
        raise _Decline

    def word(self) -> Word:
        _k, letter, ls, _le = self.take()
        kind, text, s, e = self.peek()
        if letter == "P" and kind == _OP and text == "[" and _BRACKET_NAME.match(self.code, s):
            raise _Decline
        if kind == _NUM:
            self.i += 1
            value: Expr = Number(float(text), text, s, e)
        elif kind == _OP and text in ("+", "-"):
            self.i += 1
            k2, t2, _s2, e2 = self.peek()
            if k2 == _NUM:
                self.i += 1
                signed = text + t2
                value = Number(float(signed), signed, s, e2)
            else:
                x = self.variable_or_bracket()
                value = Unary(text, x, s, x.end)
        else:
            value = self.variable_or_bracket()
        if self.relations and has_relation(value):
            raise _Decline
        return Word(letter, value, None, ls, value.end)

    def variable_or_bracket(self) -> Var | IndirectVar | Bracket:
        kind, text, _s, _e = self.peek()
        if kind == _VAR or (kind == _OP and text == "#"):
            return self.variable()
        if kind == _OP and text == "[":
            return self.bracket()
        raise _Decline

    def assign(self) -> Assign:
        target = self.variable()
        self.expect(_OP, "=")
        value = self.sum()
        if self.relations and (has_relation(value) or (isinstance(target, IndirectVar) and has_relation(target.index))):
            raise _Decline
        return Assign(target, value, None, target.start, value.end)

    def condition(self) -> Bracket:
        cond = self.bracket()
        check_condition(cond)
        return cond

    def target(self) -> Expr:
        kind, text, s, e = self.peek()
        if kind == _NUM:
            self.i += 1
            return Number(float(text), text, s, e)
        x = self.variable_or_bracket()
        if self.relations and has_relation(x):
            raise _Decline
        return x

    # ---- expressions
    # sum and product are written out alike rather than as one reader of a precedence level: it
    # saves a call per operand on the hot path (benchmarks/parse.py)
    def sum(self) -> Expr:
        left = self.product()
        while True:
            kind, text, _s, _e = self.peek()
            if (kind == _OP or kind == _KW) and text in _ADDOPS:
                self.i += 1
                right = self.product()
                left = Binary(text, left, right, left.start, right.end)
            else:
                return left

    def product(self) -> Expr:
        left = self.unary()
        while True:
            kind, text, _s, _e = self.peek()
            if (kind == _OP or kind == _KW) and text in _MULOPS:
                self.i += 1
                right = self.unary()
                left = Binary(text, left, right, left.start, right.end)
            else:
                return left

    def unary(self) -> Expr:
        kind, text, s, _e = self.peek()
        if kind == _OP and text in ("+", "-"):
            self.i += 1
            x = self.unary()
            return Unary(text, x, s, x.end)
        return self.primary()

    def primary(self) -> Expr:
        kind, text, s, e = self.peek()
        if kind == _NUM:
            self.i += 1
            return Number(float(text), text, s, e)
        if kind == _VAR or (kind == _OP and text == "#"):
            return self.variable()
        if kind == _OP and text == "[":
            return self.bracket()
        if kind == _KW and (text in _FUNCS or text == "ATAN"):
            self.i += 1
            self.expect(_OP, "[")
            arg = self.relexpr()
            close = self.expect(_OP, "]")
            args = [arg]
            if text == "ATAN":
                k2, t2, _s2, _e2 = self.peek()
                k3, t3, _s3, _e3 = self.toks[self.i + 1] if k2 != _EOF else (_EOF, "", 0, 0)
                if k2 == _OP and t2 == "/" and k3 == _OP and t3 == "[":
                    self.i += 2
                    args.append(self.relexpr())
                    close = self.expect(_OP, "]")
            if self.relations and any(has_relation(a) for a in args):
                raise _Decline
            return FunctionCall(text, tuple(args), s, close[3])
        raise _Decline

    def bracket(self) -> Bracket:
        lb = self.expect(_OP, "[")
        inner = self.relexpr()
        rb = self.expect(_OP, "]")
        return Bracket(inner, lb[2], rb[3])

    def relexpr(self) -> Expr:
        left = self.sum()
        kind, text, _s, _e = self.peek()
        if (kind == _OP or kind == _KW) and text in _RELOPS:
            self.i += 1
            right = self.sum()
            self.relations += 1
            if has_relation(left) or has_relation(right):
                raise _Decline
            return Relation(RELATION_NAMES.get(text, text), text, left, right, left.start, right.end)
        return left

    def variable(self) -> Var | IndirectVar:
        kind, text, s, e = self.take()
        if kind == _VAR:
            return Var(int(text[1:].strip()), s, e)
        if kind == _OP and text == "#":
            index = self.bracket()
            return IndirectVar(index, s, index.end)
        raise _Decline
