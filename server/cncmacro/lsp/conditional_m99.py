"""The editor's help with Haas's conditional jump ``[cond] M99 P n`` (docs/semantics.md §4).

Hover on its ``M99`` says what the block does, a jump like ``IF [cond] GOTO n``, rather than what
a plain ``M99`` does (return from a subprogram), and on a profile that does not read the form,
that the control stops there with alarm 114. There a quick fix writes the block as that
``IF [cond] GOTO n``, which every profile reads and which runs the same.
"""

from __future__ import annotations

from ..bilingual import pick
from ..dialects import Dialect
from ..dialects.alarms import FORMAT
from ..syntax.nodes import Block, If
from .texts import t


def if_goto_rewrite(block: Block, text: str, dialect: Dialect) -> tuple[int, int, str] | None:
    """(start, end, new text) that writes the conditional jump of ``block`` (the line ``text``) as
    ``IF [cond] GOTO n``, where ``dialect`` does not read the form; else None."""
    if dialect.conditional_m99:
        return None
    for s in block.statements:
        if s.__class__ is If and s.m99 is not None and s.goto is not None:
            condition = text[s.condition.start : s.condition.end]
            target = text[s.goto.start : s.goto.end]
            # a comment written inside the form (``[#1 GT 2] (NOTE) M99 P10``) stays, after the jump
            inside = "".join(f" {text[c.start : c.end]}" for c in block.comments if s.start <= c.start < s.end)
            return s.start, s.end, f"IF {condition} GOTO {target}{inside}"
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
    head = t("conditional_m99", locale)
    if dialect.conditional_m99:
        return f"{head}\n\n*{dialect.shown_title(locale)}*"
    said = dialect.alarm_said(FORMAT)
    refused = t("conditional_m99_refused", locale, title=dialect.shown_title(locale), alarm=pick(locale, said, said.zh))
    return f"{head}\n\n{refused}"
