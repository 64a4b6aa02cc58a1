"""Checks of the comma words ``,C``, ``,R`` and ``,A`` on a block (docs/semantics.md §1, §8).

Their values are checked as any address value is (``variable_checks``). A ``corner-word`` warning
says what the block alone shows wrong with them: one written where no G01/G02/G03 move can take
it (a literal G00, or no axis word: ``machine/corners.py`` decides), or one on a profile whose
manual does not document them (``Dialect.corner_words``: gsk980tdi writes its chamfers with L and
D). A control's own alarms on the move after a corner are not checked (none is documented well
enough here).
"""

from __future__ import annotations

from ...bilingual import in_language, is_chinese
from ...machine.corners import NAMES, no_move
from ...syntax.nodes import Block
from .line_facts import LineContext, LineFacts, finding
from .variable_checks import scan_value


def check_corners(block: Block, ctx: LineContext, facts: LineFacts) -> None:
    """Findings of the corner words of a block of NC words."""
    out = facts.findings
    dialect = ctx.dialect
    axes = frozenset((*dialect.axes, *dialect.incremental_letters))
    zh = is_chinese(ctx.locale)
    for c in block.corners:
        scan_value(c.value, ctx, out, depth_checked=not ctx.values.constant(c.value)[0])
        if not dialect.corner_words:
            name = NAMES[c.letter]
            drawing = dialect.drawing_angle
            if c.letter == "A" and drawing is not None:  # GSK980TDi §3.13: G01 X_ Q_, Q in 0.001°
                letter, unit = drawing[0], f"{drawing[1]:g}°"
                own = f"it writes the angle of a line as {letter} (G01 X_ {letter}_, in {unit})"
                own_zh = f"其直线角度写作 {letter}（G01 X_ {letter}_，单位 {unit}）"
            else:
                own = "it writes a chamfer as L and a corner arc as D on G01/G02/G03"
                own_zh = "其倒角在 G01/G02/G03 中写作 L（直线倒角）和 D（圆弧倒角）"
            message = (
                f"{dialect.title}'s manual does not document ,{c.letter} ({name}); {own}. Read and run as on FANUC "
                "(the move as written); to confirm on the control"
            )
            message_zh = (
                f"{dialect.title} 的说明书中没有 ,{c.letter}（{name.zh}）；{own_zh}。"
                "此处按 FANUC 读取并运行（按所写移动）；请在机床上确认"
            )
            out.append(finding(c.start, c.end, "corner-word", message_zh if zh else message))
            continue
        why = no_move(c, block, axes)
        if why is not None:
            out.append(finding(c.start, c.end, "corner-word", in_language(why, zh)))
