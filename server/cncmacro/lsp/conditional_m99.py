"""The editor's help with Haas's conditional jump ``[cond] M99 P n`` (docs/semantics.md §4).

Hover on its ``M99`` says what the block does, a jump like ``IF [cond] GOTO n``, rather than what
a plain ``M99`` does (return from a subprogram), and on a profile that does not read the form,
that the control stops there with alarm 114. There a quick fix writes the block as that
``IF [cond] GOTO n``, which every profile reads and which runs the same.
"""

from __future__ import annotations

from ..bilingual import pick
from ..dialects import Dialect
from ..syntax.nodes import Block, If


def if_goto_rewrite(block: Block, text: str, dialect: Dialect) -> tuple[int, int, str] | None:
    """(start, end, new text) that writes the conditional jump of ``block`` (the line ``text``) as
    ``IF [cond] GOTO n``, where ``dialect`` does not read the form; else None."""
    if dialect.conditional_m99:
        return None
    for s in block.statements:
        if s.__class__ is If and s.m99 is not None and s.goto is not None:
            condition = text[s.condition.start : s.condition.end]
            target = text[s.goto.start : s.goto.end]
            return s.start, s.end, f"IF {condition} GOTO {target}"
    return None


def conditional_m99_hover(block: Block, column: int, dialect: Dialect, locale: str) -> tuple[str, int, int] | None:
    """The Markdown for ``column`` when it is on the ``M99`` of a conditional jump, and its range."""
    for s in block.statements:
        if s.__class__ is If and s.m99 is not None:
            m99 = s.m99[0]
            if m99.start <= column <= m99.end:
                return _text(dialect, locale), m99.start, m99.end
    return None


def _text(dialect: Dialect, locale: str) -> str:
    head = pick(
        locale,
        "**[cond] M99 P n** — Conditional jump (Haas): to block Nn when the condition holds, otherwise on to "
        "the next block; the same as IF [cond] GOTO n",
        "**[条件] M99 P n** — 条件跳转（哈斯）：条件成立时转到 Nn 程序段，否则继续执行下一段；等同于 IF [条件] GOTO n",
    )
    if dialect.conditional_m99:
        return f"{head}\n\n*{dialect.title}*"
    refused = pick(
        locale,
        f"{dialect.title} does not read it: the control stops at this block with alarm 114",
        f"{dialect.title} 不接受这种写法：执行到此程序段时报警 114",
    )
    return f"{head}\n\n{refused}"
