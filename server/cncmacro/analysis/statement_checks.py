"""Checks of a block's macro statements (docs/semantics.md §3, §4): what one line decides alone.

A block with a macro statement may hold no NC words (``nc-and-macro``, alarm 127; ``N`` and an O
header are not words). Each statement's expressions go through ``variable_checks``; an
assignment's target through ``check_write``. A literal ``GOTO n`` / ``IF..GOTO n`` target is
rounded as the interpreter rounds it: outside 1–99999 it is ``label-range`` (alarm 128),
otherwise it becomes a ``Jump`` for the cross-line label checks.
"""

from __future__ import annotations

from ..bilingual import in_language, is_chinese, pick
from ..machine.numbers import round_half_away
from ..machine.words import abbreviation_refused, missing_then
from ..syntax.nodes import Assign, Block, Expr, Goto, If, Output, Statement, While
from .line_facts import Jump, LineContext, LineFacts, finding
from .variable_checks import check_write, scan_value

MAX_LABEL = 99999


def check_statements(block: Block, ctx: LineContext, facts: LineFacts) -> None:
    """Findings and jumps of a block that holds macro statements."""
    if block.words or block.corners:
        w = block.words[0] if block.words else block.corners[0]
        letter = w.letter if block.words else f",{w.letter}"
        facts.findings.append(
            finding(
                w.start,
                w.end,
                "nc-and-macro",
                pick(
                    ctx.locale,
                    f"the NC word {letter} and a macro statement in one block (alarm 127); "
                    "only N may precede a macro statement",
                    f"NC代码 {letter} 与宏语句在同一程序段（报警 127）；宏语句之前只允许 N",
                ),
            )
        )
        return
    for s in block.statements:
        _statement(s, ctx, facts)


def _statement(s: Statement, ctx: LineContext, facts: LineFacts) -> None:
    out = facts.findings
    if s.__class__ is Assign:
        check_write(s.target, ctx, out)
        scan_value(s.value, ctx, out)
    elif s.__class__ is If:
        scan_value(s.condition, ctx, out)
        then = s.then
        if s.implicit_then and then is not None and not ctx.dialect.if_without_then:
            message = in_language(missing_then(ctx.dialect), is_chinese(ctx.locale))
            out.append(finding(then.start, then.end, "dialect-feature", message))
        if s.goto is not None:
            scan_value(s.goto, ctx, out)
            literal_jump(s.goto, "GOTO ", ctx, facts)
        elif s.then is not None:
            _statement(s.then, ctx, facts)
    elif s.__class__ is Goto:
        scan_value(s.target, ctx, out)
        literal_jump(s.target, "GOTO ", ctx, facts)
    elif s.__class__ is While:
        scan_value(s.condition, ctx, out)
    elif s.__class__ is Output:
        for part in s.parts:
            if part.variable is not None:
                scan_value(part.variable, ctx, out)


def check_abbreviations(block: Block, ctx: LineContext, facts: LineFacts) -> None:
    """Macro words written shortened (``WH`` for WHILE): a hint with the whole word where the
    dialect reads them (the editor offers to write it out), ``dialect-feature`` where it does not."""
    dialect = ctx.dialect
    for a in block.abbreviations:
        if dialect.keyword_abbreviations:
            message = pick(ctx.locale, f"'{a.text}' is short for {a.word}", f"'{a.text}' 是 {a.word} 的缩写")
            facts.findings.append(finding(a.start, a.end, "keyword-abbreviation", message))
        else:
            refused = in_language(abbreviation_refused(a.text, a.word, dialect), is_chinese(ctx.locale))
            facts.findings.append(finding(a.start, a.end, "dialect-feature", refused))


def literal_jump(target: Expr, how: str, ctx: LineContext, facts: LineFacts) -> None:
    """A jump whose target is a literal: ``label-range`` or a ``Jump`` to judge later.
    ``how`` is what is written before the label (``"GOTO "``, ``"G65 H81 P"``)."""
    is_constant, value = ctx.values.constant(target)
    if not is_constant or value is None:
        return
    n = round_half_away(value) if abs(value) < 1e12 else value
    if not 1 <= n <= MAX_LABEL:
        shown = f"{n:.0f}" if abs(n) < 1e12 else f"{n:g}"
        facts.findings.append(
            finding(
                target.start,
                target.end,
                "label-range",
                pick(
                    ctx.locale,
                    f"{how}{shown}: a sequence number must be 1 to {MAX_LABEL} (alarm 128)",
                    f"{how}{shown}：顺序号必须在 1～{MAX_LABEL} 之间（报警 128）",
                ),
            )
        )
        return
    facts.jumps.append(Jump(int(n), target.start, target.end, how))
