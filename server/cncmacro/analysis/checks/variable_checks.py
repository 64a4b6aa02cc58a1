"""Checks of one expression: variable numbers and access, bracket depth, relation spelling.

``scan_value`` walks an expression the way the interpreter compiles it (docs/semantics.md §2, §3):
a literal ``#n`` (or ``#[constant]``) whose number the dialect lacks is ``variable-number``
(alarm 115), reading a write-only system variable is ``write-only``, more than five nested
brackets in what the interpreter compiles as one value is ``bracket-depth`` (alarm 118), and a
C-style relation (``==``, ``<``) where the dialect has none is ``dialect-feature``, and so are
``&&`` and ``||`` where the dialect does not read them for AND and OR (Mazak's), and gsk980tdi's
``#9xxx`` indirection on a dialect without it. A name ``[#_NAME[n]]`` is judged by the
interpreter's ``named_number`` (an unknown name or a bad literal subscript is ``variable-number``,
alarm 1098/1099), and is ``dialect-feature`` where the dialect has no names; a function call by
``call_problem`` (a form no dialect has is ``syntax``, a FANUC 30i function elsewhere
``dialect-feature``, alarm 114).
``check_write`` judges the target of an assignment: ``#0`` and read-only system variables are
``write-protected`` (alarm 116). Variable classes come from the interpreter's ``VariableKinds``
and access rights from the dialect tables, never from a list of our own.
"""

from __future__ import annotations

from ...bilingual import in_language, pick
from ...dialects.alarms import BRACKET_NESTING, FORMAT, VARIABLE_NUMBER, WRITE_PROTECTED
from ...machine.alarms import MacroAlarm
from ...machine.expressions import MAX_BRACKETS, bracket_depth, call_problem
from ...machine.variables import named_number
from ...machine.words import logical_symbol_refused
from ...planner.numbers import round_half_away
from ...syntax.nodes import (
    LOGICAL_SYMBOLS,
    Binary,
    Bracket,
    Expr,
    FunctionCall,
    IndirectVar,
    NamedVar,
    Number,
    Relation,
    Unary,
    Var,
)
from .line_facts import Finding, LineContext, alarm_message, finding


def scan_value(node: Expr, ctx: LineContext, out: list[Finding], depth_checked: bool = True) -> None:
    """Check an expression that the interpreter reads as one value (or condition).
    ``depth_checked`` is False where the interpreter takes a literal without compiling it
    (a constant NC address), so brackets there are not counted."""
    if node.__class__ is Number:
        return
    if depth_checked:
        depth = bracket_depth(node)
        if depth > MAX_BRACKETS:
            out.append(_bracket_finding(node.start, node.end, depth, ctx))
    stack: list[Expr] = [node]
    pop = stack.pop
    push = stack.append
    while stack:
        n = pop()
        if n.__class__ is Number:
            continue
        if n.__class__ is Var:
            _check_read(n.number, n.start, n.end, ctx, out)
        elif n.__class__ is Binary:
            if n.op in LOGICAL_SYMBOLS and not ctx.dialect.logical_symbols:
                _refuse_logical_symbol(n, ctx, out)
            push(n.left)
            push(n.right)
        elif n.__class__ is Bracket:
            push(n.inner)
        elif n.__class__ is FunctionCall:
            _check_call(n, ctx, out)
            stack.extend(n.args)
        elif n.__class__ is Unary:
            push(n.operand)
        elif n.__class__ is IndirectVar:
            number = constant_index(n, ctx)
            if number is not None:
                _check_read(number, n.start, n.end, ctx, out)
            push(n.index)
        elif n.__class__ is Relation:
            _check_relation(n, ctx, out)
            push(n.left)
            push(n.right)
        elif n.__class__ is NamedVar:
            number = named_variable_number(n, ctx, out)
            if number is not None:
                _check_read(number, n.start, n.end, ctx, out)
            if n.index is not None:
                push(n.index)


def constant_index(node: IndirectVar, ctx: LineContext) -> int | None:
    """The variable number of ``#[constant]``, rounded as the interpreter rounds it."""
    is_constant, value = ctx.values.constant(node.index)
    if not is_constant or value is None or abs(value) > 1e9:
        return None
    return int(round_half_away(value))


def named_variable_number(node: NamedVar, ctx: LineContext, out: list[Finding]) -> int | None:
    """The number ``[#_NAME[n]]`` stands for when the text decides it (no subscript, or a literal
    one), else None; a finding when the dialect has no names or the name or subscript is wrong."""
    d = ctx.dialect
    if not d.variable_names:
        other = next((k.dialect for k in ctx.other_kinds if k.dialect.variable_name(node.name) is not None), None)
        feature = f"a {other.title} feature" if other else "not a feature of this control"
        feature_zh = f"是 {other.title} 的功能" if other else "不是本系统的功能"
        out.append(
            finding(
                node.start,
                node.end,
                "dialect-feature",
                pick(
                    ctx.locale,
                    f"{node.text}: system variable names are {feature}; on {d.title} write the variable number "
                    f"({d.alarm_said(FORMAT)})",
                    f"{node.text}：系统变量名{feature_zh}；在 {d.title} 上请写变量号（{d.alarm_said(FORMAT).zh}）",
                ),
            )
        )
        return None
    subscript: float | None = None
    if node.index is not None:
        is_constant, subscript = ctx.values.constant(node.index)
        if not is_constant or subscript is None:
            if d.variable_name(node.name) is not None:
                return None  # the subscript is known when the block runs
            subscript = 1.0  # an unknown name is wrong whatever the subscript
    try:
        return named_number(d, node.name, subscript, node.index is not None)
    except MacroAlarm as alarm:
        out.append(finding(node.start, node.end, "variable-number", alarm_message(alarm, ctx.locale, d)))
        return None


def check_write(target: Var | IndirectVar | NamedVar, ctx: LineContext, out: list[Finding]) -> None:
    """The target of ``#n = ...`` (or a G65 H destination ``P#n``)."""
    if isinstance(target, NamedVar):
        if target.index is not None:
            scan_value(target.index, ctx, out)
        found = named_variable_number(target, ctx, out)
        if found is None:
            return
        number = found
    elif isinstance(target, IndirectVar):
        scan_value(target.index, ctx, out)
        constant = constant_index(target, ctx)
        if constant is None:
            return
        number = constant
    else:
        number = target.number
    kind = ctx.kinds.kind(number)
    if kind != "vacant" and kind != "none" and kind != "system":
        return  # a variable a program may write
    loc = ctx.locale
    protected = ctx.dialect.alarm_said(WRITE_PROTECTED)
    if kind == "vacant":
        vacant = f"#0 恒为空，不能赋值（{protected.zh}）"
        out.append(
            finding(
                target.start,
                target.end,
                "write-protected",
                pick(loc, f"#0 is always vacant and cannot be written ({protected})", vacant),
            )
        )
    elif kind == "none":
        out.append(_missing(number, target.start, target.end, ctx))
    elif kind == "system":
        row = ctx.dialect.system_variable(number)
        if row is not None and row.access == "r":
            out.append(
                finding(
                    target.start,
                    target.end,
                    "write-protected",
                    pick(
                        loc,
                        f"#{number} is a read-only system variable on {ctx.dialect.title}; "
                        f"it cannot be written ({protected})",
                        f"#{number} 在 {ctx.dialect.title} 上为只读系统变量，不能赋值（{protected.zh}）",
                    ),
                )
            )


def _check_read(number: int, start: int, end: int, ctx: LineContext, out: list[Finding]) -> None:
    kind = ctx.kinds.kind(number)
    if kind == "none":
        out.append(_missing(number, start, end, ctx))
    elif kind == "system":
        row = ctx.dialect.system_variable(number)
        if row is not None and row.access == "w":
            alarm = ctx.dialect.alarm_said(VARIABLE_NUMBER)
            out.append(
                finding(
                    start,
                    end,
                    "write-only",
                    pick(
                        ctx.locale,
                        f"#{number} can only be written, not read, on {ctx.dialect.title} ({alarm})",
                        f"#{number} 在 {ctx.dialect.title} 上只能写入，不能读取（{alarm.zh}）",
                    ),
                )
            )


def _missing(number: int, start: int, end: int, ctx: LineContext) -> Finding:
    d = ctx.dialect
    loc = ctx.locale
    alarm = d.alarm_said(VARIABLE_NUMBER)
    other = next((k.dialect for k in ctx.other_kinds if k.kind(number) == "indirect9"), None)
    if other is not None:
        return finding(
            start,
            end,
            "dialect-feature",
            pick(
                loc,
                f"#{number}: indirection by #9 and a common variable number is a {other.title} feature; "
                f"on {d.title} #{number} does not exist ({alarm}), write #[#{number - 9000}]",
                f"#{number}：#9 加公共变量号的变量置换是 {other.title} 的功能；{d.title} 上没有 #{number}"
                f"（{alarm.zh}），请写作 #[#{number - 9000}]",
            ),
        )
    if d.nine_indirection and 9000 <= number <= 9999:
        message = pick(
            loc,
            f"#{number}: on {d.title} #9 followed by a number is indirection through a common "
            f"variable, and #{number - 9000} is not one ({alarm})",
            f"#{number}：在 {d.title} 上 #9 后接公共变量号表示变量置换，而 #{number - 9000} 不是公共变量（{alarm.zh}）",
        )
    else:
        said = d.missing_variable(number)
        message = pick(loc, f"{said} ({alarm})", f"{said.zh}（{alarm.zh}）")
    return finding(start, end, "variable-number", message)


def _check_call(node: FunctionCall, ctx: LineContext, out: list[Finding]) -> None:
    problem = call_problem(node, ctx.dialect)
    if problem is None:
        return
    code, message = problem
    alarm = ctx.dialect.alarm_said(FORMAT)
    out.append(
        finding(
            node.start,
            node.end,
            code,
            pick(ctx.locale, f"{message} ({alarm})", f"{in_language(message, True)}（{alarm.zh}）"),
        )
    )


def _refuse_logical_symbol(node: Binary, ctx: LineContext, out: list[Finding]) -> None:
    """``&&`` or ``||`` on a dialect that does not read them: marked between its two operands."""
    text = logical_symbol_refused(ctx.dialect, node.op)
    out.append(finding(node.left.end, node.right.start, "dialect-feature", pick(ctx.locale, text, text.zh)))


def _check_relation(node: Relation, ctx: LineContext, out: list[Finding]) -> None:
    if node.spelling.isalpha() or ctx.dialect.c_relations:
        return
    alarm = ctx.dialect.alarm_said(FORMAT)
    out.append(
        finding(
            node.start,
            node.end,
            "dialect-feature",
            pick(
                ctx.locale,
                f"'{node.spelling}' is not a relation on {ctx.dialect.title}; write {node.op} ({alarm})",
                f"{ctx.dialect.title} 不支持关系运算符“{node.spelling}”，请写作 {node.op}（{alarm.zh}）",
            ),
        )
    )


def _bracket_finding(start: int, end: int, depth: int, ctx: LineContext) -> Finding:
    alarm = ctx.dialect.alarm_said(BRACKET_NESTING)
    return finding(
        start,
        end,
        "bracket-depth",
        pick(
            ctx.locale,
            f"brackets nested {depth} deep; at most {MAX_BRACKETS} are allowed ({alarm})",
            f"括号嵌套 {depth} 层，最多允许 {MAX_BRACKETS} 层（{alarm.zh}）",
        ),
    )
