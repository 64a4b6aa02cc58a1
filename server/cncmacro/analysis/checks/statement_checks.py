"""Checks of a block's macro statements (docs/semantics.md §3, §4): what one line decides alone.

A block with a macro statement may hold no NC words (``nc-and-macro``, alarm 127; ``N`` and an O
header are not words; on Haas an IF governs the words after it, and an IF with nothing after it
is ``empty-if``), IF needs THEN where the dialect says so, and an abbreviated macro word and
Haas's conditional ``[cond] M99 P n`` are refused where the dialect does not read them: the block
rules of ``machine/block_rules.py``, which the interpreter raises as alarms. Each statement's
expressions go through ``variable_checks``; an assignment's target through ``check_write``. A
literal ``GOTO n`` / ``IF..GOTO n`` / conditional ``M99 P n`` target is rounded as the
interpreter rounds it: outside 1–99999 it is ``label-range`` (alarm 128), otherwise it becomes
a ``Jump`` for the cross-line label checks.
"""

from __future__ import annotations

from ...bilingual import pick
from ...dialects.alarms import SEQUENCE_NUMBER
from ...machine.block_rules import ABBREVIATION, DIALECT_FORMS, NC_AND_STATEMENT, validate_block
from ...planner.numbers import round_half_away
from ...syntax.nodes import Assign, Block, Expr, Goto, If, Output, Statement, While
from .line_facts import Jump, LineContext, LineFacts, alarm_named, block_finding, finding
from .variable_checks import check_write, scan_value

MAX_LABEL = 99999


def check_statements(block: Block, ctx: LineContext, facts: LineFacts) -> None:
    """Findings and jumps of a block that holds macro statements."""
    problems = validate_block(block, ctx.dialect)
    if problems:  # seldom: a block's problems are looked at only when it has some
        nc = next((p for p in problems if p.rule == NC_AND_STATEMENT), None)
        if nc is not None:
            facts.findings.append(block_finding(nc, ctx.locale))
            return
        facts.findings.extend(block_finding(p, ctx.locale) for p in problems if p.rule in DIALECT_FORMS)
    first = block.statements[0]
    if first.__class__ is If and ctx.dialect.if_governs_block and not (block.words or block.corners):
        _empty_if(first, ctx, facts)
    for s in block.statements:
        _statement(s, ctx, facts)


def _statement(s: Statement, ctx: LineContext, facts: LineFacts) -> None:
    out = facts.findings
    if s.__class__ is Assign:
        check_write(s.target, ctx, out)
        scan_value(s.value, ctx, out)
    elif s.__class__ is If:
        scan_value(s.condition, ctx, out)
        if s.goto is not None:
            scan_value(s.goto, ctx, out)
            literal_jump(s.goto, "GOTO " if s.m99 is None else "M99 P", ctx, facts)
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


def _empty_if(s: If, ctx: LineContext, facts: LineFacts) -> None:
    """``IF [..]`` alone where an IF governs the rest of its block (Haas): it governs nothing, so
    the block after it runs whether the condition holds or not, which the writer seldom meant."""
    if s.goto is not None or s.then is not None:
        return
    message = pick(
        ctx.locale,
        "IF [...] with nothing after it: the condition governs only the rest of its own block, so it does "
        "nothing here and the next block runs whether it holds or not; put the words on this line, or jump: "
        "IF [...] GOTO n",
        "IF [...] 之后没有内容：条件只控制同一程序段中其后的代码，此处不起作用，无论条件是否成立下一程序段都会执行；"
        "请把代码写在同一行，或用 IF [...] GOTO n 跳转",
    )
    facts.findings.append(finding(s.start, s.end, "empty-if", message))


def check_abbreviations(block: Block, ctx: LineContext, facts: LineFacts) -> None:
    """Macro words written shortened (``WH`` for WHILE): a hint with the whole word where the
    dialect reads them (the editor offers to write it out), ``dialect-feature`` where it does not."""
    if not ctx.dialect.keyword_abbreviations:  # refused: a block rule
        problems = validate_block(block, ctx.dialect)
        facts.findings.extend(block_finding(p, ctx.locale) for p in problems if p.rule == ABBREVIATION)
        return
    for a in block.abbreviations:
        message = pick(ctx.locale, f"'{a.text}' is short for {a.word}", f"'{a.text}' 是 {a.word} 的缩写")
        facts.findings.append(finding(a.start, a.end, "keyword-abbreviation", message))


def literal_jump(target: Expr, how: str, ctx: LineContext, facts: LineFacts) -> None:
    """A jump whose target is a literal: ``label-range`` or a ``Jump`` to judge later.
    ``how`` is what is written before the label (``"GOTO "``, ``"G65 H81 P"``)."""
    is_constant, value = ctx.values.constant(target)
    if not is_constant or value is None:
        return
    n = round_half_away(value) if abs(value) < 1e12 else value
    if not 1 <= n <= MAX_LABEL:
        shown = f"{n:.0f}" if abs(n) < 1e12 else f"{n:g}"
        en, zh = alarm_named(SEQUENCE_NUMBER, ctx.dialect)
        facts.findings.append(
            finding(
                target.start,
                target.end,
                "label-range",
                pick(
                    ctx.locale,
                    f"{how}{shown}: a sequence number must be 1 to {MAX_LABEL} ({en})",
                    f"{how}{shown}：顺序号必须在 1～{MAX_LABEL} 之间（{zh}）",
                ),
            )
        )
        return
    facts.jumps.append(Jump(int(n), target.start, target.end, how))
