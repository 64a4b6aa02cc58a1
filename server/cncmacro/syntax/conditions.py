"""The rules of the language that both readers of a block apply to what they read.

The lark grammar (``grammar.py``) and the hand-written fast path (``fastpath.py``) build the
same nodes; what the grammar accepts but the language does not (a comparison outside an IF or
WHILE condition, conditions joined without brackets, a number too long to read) is decided
here, once, and raised as ``BlockError`` with a plain-words message (English, with its Chinese
beside it). Nothing here needs the grammar, so a file that the fast path reads whole never
loads it.
"""

from __future__ import annotations

from ..bilingual import Detail, detail
from .nodes import (
    CONDITION_JOINS,
    Binary,
    Bracket,
    Expr,
    FunctionCall,
    IndirectVar,
    NamedVar,
    Relation,
    Unary,
)

RELATION_NAMES = {"==": "EQ", "!=": "NE", "<>": "NE", ">": "GT", ">=": "GE", "<": "LT", "<=": "LE"}


class BlockError(Exception):
    """A rule of the language broken by a line that the grammar itself accepts."""

    def __init__(
        self, message: Detail, start: int, end: int, alarm: int | None = None, without_block_if: Detail | None = None
    ) -> None:
        super().__init__(message)
        self.message = message
        self.start = start
        self.end = end
        self.alarm = alarm  # the alarm's number, named by whoever shows the message (``Problem.alarm``)
        self.without_block_if = without_block_if  # the message where the profile has no block IF


# No control reads a number this long (FANUC: alarm 003, too many digits), and a float cannot
# hold one of 309 digits: the line is not read.
MAX_NUMBER_CHARS = 24
# the alarms of the two rules below (FANUC's numbers, dialects/alarms.py's, which this layer does
# not import): too many digits, and a comparison outside a condition
TOO_MANY_DIGITS = 3
ILLEGAL_FORMAT = 114


def has_relation(expr: Expr) -> bool:
    """True when a comparison hides anywhere inside ``expr``."""
    return _first_relation(expr) is not None


def _first_relation(expr: Expr) -> Relation | None:
    """The first comparison inside ``expr`` (walked without recursion), None for none."""
    stack: list[object] = [expr]
    while stack:
        e = stack.pop()
        if isinstance(e, Relation):
            return e
        if isinstance(e, Binary):
            stack.append(e.left)
            stack.append(e.right)
        elif isinstance(e, Bracket):
            stack.append(e.inner)
        elif isinstance(e, Unary):
            stack.append(e.operand)
        elif isinstance(e, FunctionCall):
            stack.extend(e.args)
        elif isinstance(e, IndirectVar):
            stack.append(e.index)
        elif isinstance(e, NamedVar) and e.index is not None:
            stack.append(e.index)
    return None


def relation_error(expr: Expr) -> BlockError:
    rel = _first_relation(expr)
    assert rel is not None  # only called after has_relation
    return BlockError(
        detail(
            f"the comparison '{rel.spelling}' is allowed only in an IF or WHILE condition",
            f"关系运算符 '{rel.spelling}' 只能用在 IF 或 WHILE 的条件中",
        ),
        rel.start,
        rel.end,
        ILLEGAL_FORMAT,
    )


def check_condition(cond: Bracket) -> None:
    """A condition is ``[a op b]`` or bracketed conditions joined by AND, OR or XOR, as many as
    the line holds (``[[a] AND [b] AND [c]]`` is read left to right, as every other operator)."""
    stack: list[Bracket] = [cond]
    while stack:
        b = stack.pop()
        inner = b.inner
        if isinstance(inner, Relation):
            continue
        sides = _joined_conditions(inner)
        if sides is not None:
            stack.extend(sides)
            continue
        if has_relation(inner):
            raise BlockError(
                detail(
                    "conditions are joined with AND/OR only when each side is bracketed: [[#1 EQ 0] OR [#2 LT 0]]",
                    "用 AND/OR 连接条件时，每个条件都要加方括号：[[#1 EQ 0] OR [#2 LT 0]]",
                ),
                b.start,
                b.end,
            )
        raise BlockError(
            detail(
                "the condition needs a comparison such as [#1 GT 0] (EQ NE GT GE LT LE)",
                "条件中需要关系运算，例如 [#1 GT 0]（EQ NE GT GE LT LE）",
            ),
            b.start,
            b.end,
        )


def _joined_conditions(e: Expr) -> list[Bracket] | None:
    """The bracketed conditions that AND, OR and XOR (or ``&&``, ``||``) join in ``e`` (``[a] AND [b] OR [c]``), or
    None when ``e`` is not such a chain. A loop, not recursion: a chain may be long."""
    out: list[Bracket] = []
    pending: list[Expr] = [e]
    while pending:
        x = pending.pop()
        if isinstance(x, Binary) and x.op in CONDITION_JOINS:
            for side in (x.right, x.left):
                if isinstance(side, Bracket) and _is_bracketed_condition(side):
                    out.append(side)
                elif isinstance(side, Binary) and side.op in CONDITION_JOINS:
                    pending.append(side)
                else:
                    return None
        else:
            return None
    return out


def _is_bracketed_condition(e: Expr) -> bool:
    """A bracket whose content can be a condition; its details are checked in turn."""
    if not isinstance(e, Bracket):
        return False
    inner = e.inner
    return isinstance(inner, Relation) or (isinstance(inner, Binary) and inner.op in CONDITION_JOINS)
