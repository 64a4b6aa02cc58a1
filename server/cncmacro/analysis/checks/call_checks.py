"""Checks of a block of NC words (docs/semantics.md §5, §7): calls, returns and their words.

Which call a block makes is ``machine.calls.recognise_call``'s, and what the block may not
contain (words beside G65/G66: ``g65-nc-words``, a G argument, a call without P, an unknown G
code, an M code with a decimal point) ``machine/block_rules.py``'s, the rules the interpreter
raises as alarms: each problem is a finding here (``block_finding``). On gsk980tdi a G65 whose
first P or H word is H is the macro A form (``h_code_form``); otherwise a code that the machine
settings configure as a call, then ``M98``/``M198``, the dialect's local subprogram call (Haas
``M97 P n``: its P is a label of the same program, judged like ``M98 Q``) and ``M99``. What
depends on values is decided by the interpreter's own helpers in ``machine/calls.py``
(``map_arguments`` for argument letters, ``repeat_count``, ``program_and_count`` and
``count_in_p_and_l`` for counts, ``macro_program_number`` for P), run on the literal values: an
alarm they raise becomes an error here, a note a warning. Calls with a literal target become ``CallSite`` facts for
``program-not-found``; literal ``H80–H86 P`` targets ``Jump`` facts; ``M99 Pn`` a ``ReturnJump``.
"""

from __future__ import annotations

from ...bilingual import in_language, pick
from ...dialects.alarms import FORMAT, P_VALUE_RANGE, PROGRAM_NOT_FOUND, SEQUENCE_NUMBER
from ...library.programs import is_program_name
from ...machine.alarms import MacroAlarm
from ...machine.block_rules import (
    BEFORE_CALL,
    CALL_WITHOUT_P,
    CALL_WORD_ORDER,
    G_AFTER_CALL,
    O_WITH_CALL,
    BlockProblem,
    validate_block,
)
from ...machine.calls import (
    SUBPROGRAM_CALLS,
    BlockCall,
    argument_targets,
    bad_name_detail,
    call_words,
    code_value,
    count_in_p_and_l,
    macro_program_number,
    map_arguments,
    program_and_count,
    recognise_call,
    repeat_count,
)
from ...machine.hcodes import ARITHMETIC, BRANCHES
from ...machine.jump_words import return_word
from ...machine.program_end import RETURN_CODE
from ...machine.word_sets import WordSet
from ...machine.words import refused_words
from ...planner.numbers import round_half_away
from ...syntax.nodes import Block, Bracket, IndirectVar, Number, Var, Word
from ..indexes.call_sites import CallSite
from .lathe_signs import block_signs, sign_words
from .line_facts import LineContext, LineFacts, ReturnJump, alarm_message, alarm_named, block_finding, finding
from .statement_checks import literal_jump
from .variable_checks import check_write, scan_value

H_OPERATIONS = frozenset((*ARITHMETIC, *BRANCHES, 26, 99))


def words_looked_at(ctx: LineContext) -> tuple[WordSet, ...]:
    """The words ``check_words`` looks at (``machine/word_sets.py``); every other word of a block
    it passes over, so a plain line without one of these is not looked at (``static_checks``):
    the call words (``recognise_call``'s), the words a control may refuse (``validate_block``'s),
    M99 (a return, whose P is a label), the other profiles' local call codes and, under a mill
    profile, the words that show a lathe program (signs of the profile the program was written
    for: ``lathe_signs.py``). A check of another word is added here with it."""
    return (
        *call_words(ctx.dialect, ctx.calls),
        *refused_words(ctx.dialect, ctx.calls),
        WordSet("M", frozenset((RETURN_CODE,))),
        *((WordSet("M", frozenset(ctx.foreign_local)),) if ctx.foreign_local else ()),
        *sign_words(ctx.dialect),
    )


def check_words(block: Block, ctx: LineContext, facts: LineFacts) -> None:
    """Findings and facts of a block of NC words (no macro statement)."""
    call = recognise_call(block.words, ctx.dialect, ctx.calls)
    problems = validate_block(block, ctx.dialect, ctx.calls, call=call)
    if call is not None and call.kind in ("G65", "G66"):
        _macro_call(block.words, call, problems, ctx, facts)
        return
    _nc_block(block.words, call, problems, ctx, facts)
    if call is None:
        facts.lathe_signs.extend(block_signs(block.words, ctx.dialect))


def _literal(w: Word) -> float | None:
    v = w.value
    return v.value if v.__class__ is Number else None


def _constant(w: Word | None, ctx: LineContext) -> float | None:
    if w is None or w.value is None:
        return None
    is_constant, value = ctx.values.constant(w.value)
    return value if is_constant else None


def _add(facts: LineFacts, w: Word, code: str, en: str, zh: str, ctx: LineContext, *, milder: bool = False) -> None:
    """A finding of ``code`` on the word ``w``; ``milder`` where the control is lenient (``codes.py``)."""
    facts.findings.append(finding(w.start, w.end, code, pick(ctx.locale, en, zh), milder=milder))


def _add_alarm(facts: LineFacts, w: Word, code: str, alarm: MacroAlarm, ctx: LineContext) -> None:
    """A finding of ``code`` on the word ``w``: the alarm the interpreter raises for it."""
    facts.findings.append(finding(w.start, w.end, code, alarm_message(alarm, ctx.locale, ctx.dialect)))


# ---------------------------------------------------------------- G65 / G66


def _macro_call(
    words: tuple[Word, ...], call: BlockCall, problems: list[BlockProblem], ctx: LineContext, facts: LineFacts
) -> None:
    name = call.kind
    rule = {p.rule: p for p in problems}
    for stop in (BEFORE_CALL, O_WITH_CALL):  # the words G65/G66 may not share its block with
        problem = rule.get(stop)
        if problem is not None:
            facts.findings.append(block_finding(problem, ctx.locale))
            if problem.stops:
                return
    order = rule.get(CALL_WORD_ORDER)  # a word other than P or H right after the call (a warning)
    if order is not None:
        facts.findings.append(block_finding(order, ctx.locale))
    after = words[call.at + 1 :]
    dialect = ctx.dialect
    if call.arithmetic:
        _h_code(words[call.at], after, ctx, facts)
        return
    if name == "G65" and not dialect.h_codes and not any(w.letter == "L" for w in after) and _looks_like_h_code(after):
        h = after[0]
        _add(facts, h, "dialect-feature",
             f"G65 H{_literal(h):02.0f} (macro A arithmetic and branches) does not exist on {dialect.title}; "
             "write it as a macro statement",
             f"{dialect.title} 没有 G65 H{_literal(h):02.0f}（宏程序 A 形式的运算与转移），请改写为宏语句",
             ctx)  # fmt: skip
        return
    for w in after:
        if w.value is not None:
            scan_value(w.value, ctx, facts.findings)
    g_argument = rule.get(G_AFTER_CALL)
    if g_argument is not None:
        facts.findings.append(block_finding(g_argument, ctx.locale))
    else:
        _check_arguments(list(call.arguments), ctx, facts)
    _macro_target(call, rule.get(CALL_WITHOUT_P), ctx, facts)
    if call.count is not None:
        _check_count(call.count, ctx, facts)


def _looks_like_h_code(after: tuple[Word, ...]) -> bool:
    """``G65 H01 P#100 Q..`` written for a control with macro A, read on one without it: H
    right after G65 with an operation number, and P a variable or H a branch or alarm."""
    h = after[0] if after else None
    if h is None or h.letter != "H":
        return False
    value = _literal(h)
    if value is None or value != int(value) or int(value) not in H_OPERATIONS:
        return False
    p = next((w for w in after if w.letter == "P"), None)
    p_is_variable = p is not None and isinstance(p.value, (Var, IndirectVar))
    return p_is_variable or int(value) in BRANCHES or int(value) == 99


def _check_arguments(args: list[Word], ctx: LineContext, facts: LineFacts) -> None:
    """Argument letters through the interpreter's ``map_arguments`` (values do not matter to
    what it refuses or remarks on, so each is given as 0): an alarm is an ``argument-address``
    error, a remark (I, J, K out of order on fanuc) an ``argument-order`` warning on the first
    word out of order."""
    try:
        mapped = map_arguments([(w.letter, 0.0) for w in args], ctx.dialect)
    except MacroAlarm as alarm:
        bad = _first_refused(args, ctx)
        _add_alarm(facts, bad, "argument-address", alarm, ctx)
        return
    if mapped.remarks:
        k = next(k for k in range(1, len(args) + 1) if map_arguments([(w.letter, 0.0) for w in args[:k]],
                                                                      ctx.dialect).remarks)  # fmt: skip
        w = args[k - 1]
        before = next(a.letter for a in reversed(args[: k - 1]) if a.letter in "IJK")
        n = argument_targets([a.letter for a in args[:k]])[-1]
        remark = mapped.remarks[0]
        _add(facts, w, "argument-order",
             f"{w.letter} after {before} in its set: {in_language(remark, False)}; the control still puts it in #{n}",
             f"{w.letter} 写在同组的 {before} 之后：{in_language(remark, True)}；系统仍把它赋给 #{n}",
             ctx)  # fmt: skip


def _first_refused(args: list[Word], ctx: LineContext) -> Word:
    for k in range(1, len(args) + 1):
        try:
            map_arguments([(w.letter, 0.0) for w in args[:k]], ctx.dialect)
        except MacroAlarm:
            return args[k - 1]
    return args[-1]


def _macro_target(call: BlockCall, missing: BlockProblem | None, ctx: LineContext, facts: LineFacts) -> None:
    dialect = ctx.dialect
    p_word = call.target
    if p_word is None:
        assert missing is not None  # block_rules.py's CALL_WITHOUT_P
        facts.findings.append(block_finding(missing, ctx.locale))
        return
    if p_word.name is not None:
        _named_target(p_word, call, ctx, facts)
        return
    value = p_word.value
    if isinstance(value, Bracket) and dialect.bracket_names and isinstance(value.inner, Var):
        return  # P[#100]: the program is known only when the block runs
    number = _constant(p_word, ctx)
    if number is None:
        return
    try:
        program = macro_program_number(number, dialect)
    except MacroAlarm as alarm:
        _add(facts, p_word, "program-number",
             f"{alarm.message} on {dialect.title} ({alarm_named(alarm.number, dialect)[0]})",
             f"{in_language(alarm.message, True)}（{dialect.title}，{alarm_named(alarm.number, dialect)[1]}）",
             ctx)  # fmt: skip
        return
    facts.calls.append(CallSite(call.kind, program, None, p_word, call.code, call.arguments))


def _named_target(p_word: Word, call: BlockCall, ctx: LineContext, facts: LineFacts) -> bool:
    """``P[CUT]``: a dialect without bracketed names, or a name the control refuses, is an
    error (False); otherwise the name is for ``program-not-found`` to look up (True)."""
    dialect = ctx.dialect
    name = p_word.name or ""
    if not dialect.bracket_names:
        _add(facts, p_word, "dialect-feature",
             f"P[{name}]: {dialect.title} names programs only by number, e.g. P1234",
             f"P[{name}]：{dialect.title} 只能用程序号指定程序，例如 P1234", ctx)  # fmt: skip
        return False
    if not is_program_name(name):
        text = bad_name_detail(name)
        _add(facts, p_word, "program-number",
             f"{in_language(text, False)} ({dialect.alarm_said(P_VALUE_RANGE)})",
             f"{in_language(text, True)}（{dialect.alarm_said(P_VALUE_RANGE).zh}）", ctx)  # fmt: skip
        return False
    facts.calls.append(CallSite(call.kind, None, name, p_word, call.code, call.arguments))
    return True


def _check_count(l_word: Word, ctx: LineContext, facts: LineFacts) -> None:
    """A literal L through ``repeat_count``: an alarm is an error, a clamp a warning."""
    value = _constant(l_word, ctx)
    if value is None:
        return
    notes: list[str] = []
    try:
        repeat_count(value, ctx.dialect, notes)
    except MacroAlarm as alarm:
        _add_alarm(facts, l_word, "repeat-count-range", alarm, ctx)
        return
    if notes:
        _add(facts, l_word, "repeat-count-range", in_language(notes[0], False), in_language(notes[0], True), ctx,
             milder=True)  # fmt: skip


# ---------------------------------------------------------------- G65 H (macro A, gsk980tdi)


def _h_code(g65: Word, after: tuple[Word, ...], ctx: LineContext, facts: LineFacts) -> None:
    """``G65 Hm P Q R`` as ``machine/hcodes.py`` compiles it."""
    alarm = ctx.dialect.alarm_said(FORMAT)
    extra = next((w for w in after if w.letter not in "HPQR"), None)
    if extra is not None:
        _add(facts, extra, "argument-address",
             f"G65 H takes only P, Q and R, not {extra.letter} ({alarm})",
             f"G65 H 只能带 P、Q、R，不能带 {extra.letter}（{alarm.zh}）", ctx)  # fmt: skip
        return
    by_letter = {w.letter: w for w in after}
    h_word = by_letter["H"]
    h_value = _literal(h_word)
    if h_value is None:
        _add(facts, h_word, "argument-address",
             f"G65 H needs a literal operation number such as H01 ({alarm})",
             f"G65 H 需要写明运算号，例如 H01（{alarm.zh}）", ctx)  # fmt: skip
        return
    h = int(h_value)
    if h not in H_OPERATIONS:
        _add(facts, h_word, "argument-address",
             f"G65 H{h:02d} is not an operation of {ctx.dialect.title} ({alarm})",
             f"G65 H{h:02d} 不是 {ctx.dialect.title} 的运算指令（{alarm.zh}）", ctx)  # fmt: skip
        return
    for letter in "QR":
        w = by_letter.get(letter)
        if w is not None and w.value is not None:
            scan_value(w.value, ctx, facts.findings)
    p_word = by_letter.get("P")
    if p_word is None or p_word.value is None:
        _add(facts, h_word, "argument-address",
             f"G65 H{h:02d} needs P ({alarm})", f"G65 H{h:02d} 需要 P（{alarm.zh}）", ctx)  # fmt: skip
        return
    if h in BRANCHES or h == 99:
        scan_value(p_word.value, ctx, facts.findings)
        if h in BRANCHES:
            literal_jump(p_word.value, f"G65 H{h:02d} P", ctx, facts)
        return
    destination = p_word.value
    if not isinstance(destination, (Var, IndirectVar)):
        _add(facts, p_word, "argument-address",
             f"G65 H{h:02d}: P names the result variable, e.g. P#100 ({alarm})",
             f"G65 H{h:02d}：P 指定存放结果的变量，例如 P#100（{alarm.zh}）", ctx)  # fmt: skip
        return
    if h == 26:
        scan_value(destination, ctx, facts.findings)
    check_write(destination, ctx, facts.findings)


# ---------------------------------------------------------------- NC blocks: codes, M98, M99


def _nc_block(
    words: tuple[Word, ...], call: BlockCall | None, problems: list[BlockProblem], ctx: LineContext, facts: LineFacts
) -> None:
    simple = True
    for w in words:
        if w.value is not None and w.value.__class__ is not Number:
            simple = False
            if not ctx.values.constant(w.value)[0]:
                scan_value(w.value, ctx, facts.findings)
            else:
                scan_value(w.value, ctx, facts.findings, depth_checked=False)
    ms: list[float | None] = [code_value(w) for w in words if w.letter == "M"]
    if not simple and None in ms:
        return  # an M code known only when the block runs
    if call is not None and call.configured:
        _code_call(words, call, ctx, facts)
        return
    for problem in problems:  # refused G and M codes
        facts.findings.append(block_finding(problem, ctx.locale))
    if call is not None and call.local:
        _local_call(words, call, ctx, facts)
    elif call is not None:
        _subprogram_call(words, call, ctx, facts)
    elif RETURN_CODE in ms:
        p = return_word(words)  # the caller's label (machine/jump_words.py)
        value = _constant(p, ctx)
        if p is not None and value is not None:
            facts.returns.append(ReturnJump(int(round_half_away(value)), p.start, p.end))
    elif ctx.foreign_local and (foreign := [m for m in ms if m in ctx.foreign_local]):
        p = _last(words, "P")
        value = _constant(p, ctx)
        if p is not None and value is not None and value == int(value):
            facts.foreign_calls.append((foreign[0], int(value), p.start, p.end))


def _last(words: tuple[Word, ...], letter: str) -> Word | None:
    found = None
    for w in words:
        if w.letter == letter:
            found = w
    return found


def _code_call(words: tuple[Word, ...], call: BlockCall, ctx: LineContext, facts: LineFacts) -> None:
    """A G, M or T code that the machine settings make a call (``Machine.call_code_for``)."""
    w = call.code
    facts.calls.append(CallSite(call.kind, call.number, None, w, w, call.arguments))
    if call.macro:
        _check_arguments(list(call.arguments), ctx, facts)
        if call.count is not None:
            _check_count(call.count, ctx, facts)


def _local_call(words: tuple[Word, ...], call: BlockCall, ctx: LineContext, facts: LineFacts) -> None:
    """Haas ``M97 P n L k`` as ``Machine.local_subprogram_call`` runs it: P is a label of the
    program itself (a ``CallSite`` on the current program, like ``M98 Q``), L a count."""
    how = call.kind
    p_word = call.target
    l_word = call.count
    if l_word is not None:
        _check_count(l_word, ctx, facts)
    if p_word is None:
        m = call.code
        en, zh = alarm_named(SEQUENCE_NUMBER, ctx.dialect)
        _add(facts, m, "undefined-label", f"{how} needs P: the N line to call ({en})",
             f"{how} 需要用 P 指定调用的 N 程序段（{zh}）", ctx)  # fmt: skip
        return
    before = len(facts.jumps)
    if p_word.value is not None:  # a literal label in range, or label-range (not P[NAME])
        literal_jump(p_word.value, f"{how} P", ctx, facts)
    if len(facts.jumps) > before:
        jump = facts.jumps.pop()
        site = CallSite(how, None, None, p_word, call.code, label=jump.label, label_span=(jump.start, jump.end),
                        label_letter="P")  # fmt: skip
        facts.calls.append(site)


def _subprogram_call(words: tuple[Word, ...], call: BlockCall, ctx: LineContext, facts: LineFacts) -> None:
    """``M98 P<count><program> L Q`` as ``_subprogram_target`` in ``machine/nc_blocks.py``."""
    dialect = ctx.dialect
    how = call.kind
    p_word = _last(words, "P")
    l_word = _last(words, "L")
    q_word = _last(words, "Q")
    q_value = _constant(q_word, ctx)
    q = int(round_half_away(q_value)) if q_value is not None and abs(q_value) < 1e9 else None
    q_span = (q_word.start, q_word.end) if q_word is not None else (0, 0)
    named = next((w for w in words if w.letter == "P" and w.name is not None), None)
    if named is not None:
        if not _named_target(named, call, ctx, facts):
            return
        facts.calls[-1] = CallSite(how, None, named.name, named, call.code, label=q, label_span=q_span)
        if l_word is not None:
            _check_count(l_word, ctx, facts)
        return
    if p_word is None:
        m = next(w for w in words if w.letter == "M" and code_value(w) in SUBPROGRAM_CALLS)
        if q_word is None:
            not_found = ctx.dialect.alarm_said(PROGRAM_NOT_FOUND)
            _add(facts, m, "program-not-found",
                 f"{how} needs P (the program), or Q to call the current program ({not_found})",
                 f"{how} 需要 P 指定子程序，或用 Q 调用当前程序（{not_found.zh}）", ctx)  # fmt: skip
            return
        if q is not None:
            facts.calls.append(CallSite(how, None, None, m, m, label=q, label_span=q_span))
        if l_word is not None:
            _check_count(l_word, ctx, facts)
        return
    if isinstance(p_word.value, Bracket) and isinstance(p_word.value.inner, Var):
        return  # P[#100]: known only when the block runs
    p_value = _constant(p_word, ctx)
    if p_value is None:
        return
    p_text = p_word.value.text if isinstance(p_word.value, Number) else None
    try:
        program, _ = program_and_count(p_text, p_value, None, dialect, [])
    except MacroAlarm as alarm:
        _add_alarm(facts, p_word, "program-number", alarm, ctx)
        return
    facts.calls.append(CallSite(how, program, None, p_word, call.code, label=q, label_span=q_span))
    if l_word is None:
        return
    l_value = _constant(l_word, ctx)
    if l_value is None:
        return
    twice: list[str] = []
    try:
        count_in_p_and_l(p_text, p_value, l_value, dialect, twice)  # the L's own range: _check_count
    except MacroAlarm as alarm:
        _add_alarm(facts, l_word, "repeat-count-range", alarm, ctx)
        return
    if twice:
        _add(facts, l_word, "repeat-count-range",
             f"{how}: {twice[0]}", f"{how}：{in_language(twice[0], True)}", ctx, milder=True)  # fmt: skip
    _check_count(l_word, ctx, facts)
