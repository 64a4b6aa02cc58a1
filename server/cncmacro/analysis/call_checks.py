"""Checks of a block of NC words (docs/semantics.md §5, §7): calls, returns and their words.

The block is read in the interpreter's order (``machine/nc_blocks.py``): a ``G65``/``G66``
makes the block a macro call (only ``N`` before it and no O word: ``g65-nc-words``, alarm 127; a
modal G code before it is a warning where the dialect's control sets it and calls, FANUC);
on gsk980tdi ``G65 H..`` without L is the macro A form; otherwise a code that the machine
settings configure as a call, then ``M98``/``M198``, the dialect's local subprogram call (Haas
``M97 P n``: its P is a label of the same program, judged like ``M98 Q``) and ``M99``. What is decided is decided by
the interpreter's own helpers in ``machine/calls.py`` (``map_arguments`` for argument letters,
``repeat_count`` and ``program_and_count`` for counts, ``macro_program_number`` for P), run on
the literal values: an alarm they raise becomes an error here, a note a warning. Calls with a
literal target become ``CallSite`` facts for ``program-not-found``; literal ``H80–H86 P``
targets ``Jump`` facts; ``M99 Pn`` a ``ReturnJump``.
"""

from __future__ import annotations

from ..bilingual import in_language, pick
from ..dialects.alarms import P_VALUE_RANGE
from ..library.programs import is_program_name
from ..machine.alarms import MacroAlarm
from ..machine.calls import (
    argument_targets,
    bad_name_detail,
    codes_before_call,
    macro_program_number,
    map_arguments,
    program_and_count,
    repeat_count,
)
from ..machine.hcodes import ARITHMETIC, BRANCHES
from ..machine.numbers import round_half_away, to_increment
from ..machine.words import g_code_known, m_decimal_point, unknown_g_code
from ..syntax.nodes import Block, Bracket, IndirectVar, Number, Var, Word
from .line_facts import CallSite, LineContext, LineFacts, ReturnJump, finding
from .statement_checks import literal_jump
from .variable_checks import check_write, scan_value

H_OPERATIONS = frozenset((*ARITHMETIC, *BRANCHES, 26, 99))
SUBPROGRAM_CALLS = (98.0, 198.0)


def check_words(block: Block, ctx: LineContext, facts: LineFacts) -> None:
    """Findings and facts of a block of NC words (no macro statement)."""
    words = block.words
    for i, w in enumerate(words):
        g = _literal(w) if w.letter == "G" else None
        if g == 65.0 or g == 66.0:
            _macro_call(words, i, g, ctx, facts)
            return
    _nc_block(words, ctx, facts)


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


# ---------------------------------------------------------------- G65 / G66


def _macro_call(words: tuple[Word, ...], at: int, g: float, ctx: LineContext, facts: LineFacts) -> None:
    name = "G65" if g == 65.0 else "G66"
    if at > 0 and not _words_before_call(words[:at], name, ctx, facts):
        return
    after = words[at + 1 :]
    for w in after:
        if w.letter == "O":
            _add(facts, w, "g65-nc-words",
                 f"{name} may not share its block with an O word (alarm 127)",
                 f"{name} 不能与 O 代码在同一程序段（报警 127）", ctx)  # fmt: skip
            return
    dialect = ctx.dialect
    has_h = any(w.letter == "H" for w in after)
    has_l = any(w.letter == "L" for w in after)
    if g == 65.0 and has_h and not has_l:
        if dialect.h_codes:
            _h_code(words[at], after, ctx, facts)
            return
        if _looks_like_h_code(after):
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
    args = [w for w in after if w.letter not in ("P", "L")]
    for w in args:
        if w.letter == "G":
            _add(facts, w, "argument-address",
                 f"G after {name}: a G code cannot be an argument (alarm 129)",
                 f"{name} 之后的 G 代码不能作为自变量（报警 129）", ctx)  # fmt: skip
            break
    else:
        _check_arguments(args, ctx, facts)
    p_word = next((w for w in after if w.letter == "P"), None)
    l_word = next((w for w in after if w.letter == "L"), None)
    _macro_target(words[at], p_word, name, ctx, facts)
    if l_word is not None:
        _check_count(l_word, ctx, facts)


def _words_before_call(before: tuple[Word, ...], name: str, ctx: LineContext, facts: LineFacts) -> bool:
    """Words before G65/G66 through the interpreter's ``codes_before_call``: what the control does
    with them decides the severity (``Dialect.modal_g_before_call``). An alarm is an error and ends
    the checks of the block (False); modal G codes that the control sets before it calls are a
    warning that says so (True: the call is checked on)."""
    codes = codes_before_call([(w.letter, _code_value(w) if w.letter == "G" else None) for w in before], ctx.dialect)
    title = ctx.dialect.title
    if codes is None:
        w = before[0]
        word = _g_name(_code_value(w)) if w.letter == "G" and _code_value(w) is not None else w.letter
        _add(facts, w, "g65-nc-words",
             f"{word} before {name}: only N may precede {name} in its block; {title} stops with alarm 127",
             f"{name} 之前只允许出现 N，不能有 {word}：{title} 报警 127（停止运行）", ctx)  # fmt: skip
        return False
    shown = " ".join(_g_name(c) for c in codes)
    w = before[0]
    # milder: the control carries them out and then calls
    facts.findings.append(finding(w.start, before[-1].end, "g65-nc-words", pick(ctx.locale,
        f"{shown} before {name}: {title} sets {shown} (it stays in force) and then {name} calls the macro; "
        f"controls that allow only N before {name} (GSK) stop with alarm 127, so {shown} is better on a block "
        "of its own",
        f"{name} 之前的 {shown}：{title} 先执行 {shown}（模态保持有效），再由 {name} 调用宏程序；"
        f"{name} 之前只允许 N 的系统（GSK）会报警 127，建议把 {shown} 单独写一段"),
        milder=True))  # fmt: skip
    return True


def _g_name(code: float | None) -> str:
    if code is None:
        return "G"
    return f"G{int(code):02d}" if code == int(code) else f"G{code:g}"


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
        _add(facts, bad, "argument-address",
             f"{alarm.message} (alarm {alarm.number})",
             f"{in_language(alarm.message, True)}（报警 {alarm.number}）", ctx)  # fmt: skip
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


def _macro_target(call: Word, p_word: Word | None, name: str, ctx: LineContext, facts: LineFacts) -> None:
    dialect = ctx.dialect
    if p_word is None:
        _add(facts, call, "program-not-found",
             f"{name} needs P: the program to call (alarm 76)",
             f"{name} 需要 P 指定被调用的程序（报警 076）", ctx)  # fmt: skip
        return
    if p_word.name is not None:
        _named_target(p_word, name, ctx, facts)
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
             f"{alarm.message} on {dialect.title} (alarm {alarm.number})",
             f"{in_language(alarm.message, True)}（{dialect.title}，报警 {alarm.number}）", ctx)  # fmt: skip
        return
    facts.calls.append(CallSite(name, program, None, p_word.start, p_word.end))


def _named_target(p_word: Word, how: str, ctx: LineContext, facts: LineFacts) -> bool:
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
             f"{in_language(text, False)} (alarm {P_VALUE_RANGE})",
             f"{in_language(text, True)}（报警 {P_VALUE_RANGE}）", ctx)  # fmt: skip
        return False
    facts.calls.append(CallSite(how, None, name, p_word.start, p_word.end))
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
        _add(facts, l_word, "repeat-count-range",
             f"{alarm.message} (alarm {alarm.number})",
             f"{in_language(alarm.message, True)}（报警 {alarm.number}）", ctx)  # fmt: skip
        return
    if notes:
        _add(facts, l_word, "repeat-count-range", in_language(notes[0], False), in_language(notes[0], True), ctx,
             milder=True)  # fmt: skip


# ---------------------------------------------------------------- G65 H (macro A, gsk980tdi)


def _h_code(g65: Word, after: tuple[Word, ...], ctx: LineContext, facts: LineFacts) -> None:
    """``G65 Hm P Q R`` as ``machine/hcodes.py`` compiles it."""
    extra = next((w for w in after if w.letter not in "HPQR"), None)
    if extra is not None:
        _add(facts, extra, "argument-address",
             f"G65 H takes only P, Q and R, not {extra.letter} (alarm 114)",
             f"G65 H 只能带 P、Q、R，不能带 {extra.letter}（报警 114）", ctx)  # fmt: skip
        return
    by_letter = {w.letter: w for w in after}
    h_word = by_letter["H"]
    h_value = _literal(h_word)
    if h_value is None:
        _add(facts, h_word, "argument-address",
             "G65 H needs a literal operation number such as H01 (alarm 114)",
             "G65 H 需要写明运算号，例如 H01（报警 114）", ctx)  # fmt: skip
        return
    h = int(h_value)
    if h not in H_OPERATIONS:
        _add(facts, h_word, "argument-address",
             f"G65 H{h:02d} is not an operation of {ctx.dialect.title} (alarm 114)",
             f"G65 H{h:02d} 不是 {ctx.dialect.title} 的运算指令（报警 114）", ctx)  # fmt: skip
        return
    for letter in "QR":
        w = by_letter.get(letter)
        if w is not None and w.value is not None:
            scan_value(w.value, ctx, facts.findings)
    p_word = by_letter.get("P")
    if p_word is None or p_word.value is None:
        _add(facts, h_word, "argument-address",
             f"G65 H{h:02d} needs P (alarm 114)", f"G65 H{h:02d} 需要 P（报警 114）", ctx)  # fmt: skip
        return
    if h in BRANCHES or h == 99:
        scan_value(p_word.value, ctx, facts.findings)
        if h in BRANCHES:
            literal_jump(p_word.value, f"G65 H{h:02d} P", ctx, facts)
        return
    destination = p_word.value
    if not isinstance(destination, (Var, IndirectVar)):
        _add(facts, p_word, "argument-address",
             f"G65 H{h:02d}: P names the result variable, e.g. P#100 (alarm 114)",
             f"G65 H{h:02d}：P 指定存放结果的变量，例如 P#100（报警 114）", ctx)  # fmt: skip
        return
    if h == 26:
        scan_value(destination, ctx, facts.findings)
    check_write(destination, ctx, facts.findings)


# ---------------------------------------------------------------- NC blocks: codes, M98, M99


def _code_value(w: Word) -> float | None:
    """A literal G or M code as the interpreter rounds it."""
    v = _literal(w)
    if v is None:
        return None
    if w.letter == "G":
        return to_increment(v, 1) if v != int(v) else v
    return round_half_away(v)


def _nc_block(words: tuple[Word, ...], ctx: LineContext, facts: LineFacts) -> None:
    simple = True
    for w in words:
        if w.value is not None and w.value.__class__ is not Number:
            simple = False
            if not ctx.values.constant(w.value)[0]:
                scan_value(w.value, ctx, facts.findings)
            else:
                scan_value(w.value, ctx, facts.findings, depth_checked=False)
    ms: list[float] = []
    for w in words:
        if w.letter == "M":
            v = _code_value(w)
            if v is None:
                if not simple:
                    return  # an M code known only when the block runs
            else:
                ms.append(v)
    if ctx.calls and _code_call(words, ctx, facts):
        return
    _refused_words(words, ctx, facts)
    local = ctx.dialect.local_subprogram_code
    if 98.0 in ms or 198.0 in ms:
        _subprogram_call(words, "M98" if 98.0 in ms else "M198", ctx, facts)
    elif local is not None and local in ms:
        _local_call(words, local, ctx, facts)
    elif 99.0 in ms:
        p = _last(words, "P")
        value = _constant(p, ctx)
        if p is not None and value is not None:
            facts.returns.append(ReturnJump(int(round_half_away(value)), p.start, p.end))


def _refused_words(words: tuple[Word, ...], ctx: LineContext, facts: LineFacts) -> None:
    """A literal G code that neither the dialect nor the machine has, an M code with a decimal
    point (``machine/words.py``): errors where the dialect's alarms for them are known."""
    dialect = ctx.dialect
    milder = not dialect.word_format_alarms
    for w in words:
        if w.letter == "G":
            v = _code_value(w)
            if v is not None and not g_code_known(v, dialect, ctx.calls):
                message = unknown_g_code(w.value.text, dialect)  # type: ignore[union-attr]
                _add(facts, w, "unknown-g-code", str(message), message.zh, ctx, milder=milder)
        elif w.letter == "M":
            point = m_decimal_point(w)
            if point is not None:
                _add(facts, w, "decimal-point", str(point), point.zh, ctx, milder=milder)


def _last(words: tuple[Word, ...], letter: str) -> Word | None:
    found = None
    for w in words:
        if w.letter == letter:
            found = w
    return found


def _code_call(words: tuple[Word, ...], ctx: LineContext, facts: LineFacts) -> bool:
    """A G, M or T code that the machine settings make a call (``Machine.call_code_for``)."""
    calls = ctx.calls
    for w in words:
        if w.letter in ("G", "M"):
            v = _code_value(w)
            code = f"{w.letter}{v:g}" if v is not None else None
        elif w.letter == "T" and "T" in calls:
            code = "T"
        else:
            continue
        call = calls.get(code) if code else None
        if call is None:
            continue
        facts.calls.append(CallSite(code, call.program, None, w.start, w.end))  # type: ignore[arg-type]
        if call.call == "macro":
            args = [a for a in words if a is not w and a.letter != "L" and not _same_code(a, code)]  # type: ignore[arg-type]
            _check_arguments(args, ctx, facts)
            l_word = next((a for a in words if a.letter == "L"), None)
            if l_word is not None:
                _check_count(l_word, ctx, facts)
        return True
    return False


def _same_code(w: Word, code: str) -> bool:
    if w.letter not in ("G", "M"):
        return False
    v = _code_value(w)
    return v is not None and f"{w.letter}{v:g}" == code


def _local_call(words: tuple[Word, ...], code: float, ctx: LineContext, facts: LineFacts) -> None:
    """Haas ``M97 P n L k`` as ``Machine.local_subprogram_call`` runs it: P is a label of the
    program itself (a ``CallSite`` on the current program, like ``M98 Q``), L a count."""
    how = f"M{code:g}"
    p_word = _last(words, "P")
    l_word = _last(words, "L")
    if l_word is not None:
        _check_count(l_word, ctx, facts)
    if p_word is None:
        m = next(w for w in words if w.letter == "M" and _code_value(w) == code)
        _add(facts, m, "undefined-label", f"{how} needs P: the N line to call (alarm 128)",
             f"{how} 需要用 P 指定调用的 N 程序段（报警 128）", ctx)  # fmt: skip
        return
    before = len(facts.jumps)
    if p_word.value is not None:  # a literal label in range, or label-range (not P[NAME])
        literal_jump(p_word.value, f"{how} P", ctx, facts)
    if len(facts.jumps) > before:
        jump = facts.jumps.pop()
        facts.calls.append(CallSite(how, None, None, p_word.start, p_word.end, jump.label, (jump.start, jump.end), "P"))


def _subprogram_call(words: tuple[Word, ...], how: str, ctx: LineContext, facts: LineFacts) -> None:
    """``M98 P<count><program> L Q`` as ``_subprogram_target`` in ``machine/nc_blocks.py``."""
    dialect = ctx.dialect
    p_word = _last(words, "P")
    l_word = _last(words, "L")
    q_word = _last(words, "Q")
    q_value = _constant(q_word, ctx)
    q = int(round_half_away(q_value)) if q_value is not None and abs(q_value) < 1e9 else None
    q_span = (q_word.start, q_word.end) if q_word is not None else (0, 0)
    named = next((w for w in words if w.letter == "P" and w.name is not None), None)
    if named is not None:
        if not _named_target(named, how, ctx, facts):
            return
        facts.calls[-1] = CallSite(how, None, named.name, named.start, named.end, q, q_span)
        if l_word is not None:
            _check_count(l_word, ctx, facts)
        return
    if p_word is None:
        m = next(w for w in words if w.letter == "M" and _code_value(w) in SUBPROGRAM_CALLS)
        if q_word is None:
            _add(facts, m, "program-not-found",
                 f"{how} needs P (the program), or Q to call the current program (alarm 76)",
                 f"{how} 需要 P 指定子程序，或用 Q 调用当前程序（报警 076）", ctx)  # fmt: skip
            return
        if q is not None:
            facts.calls.append(CallSite(how, None, None, m.start, m.end, q, q_span))
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
        _add(facts, p_word, "program-number",
             f"{alarm.message} (alarm {alarm.number})",
             f"{in_language(alarm.message, True)}（报警 {alarm.number}）", ctx)  # fmt: skip
        return
    facts.calls.append(CallSite(how, program, None, p_word.start, p_word.end, q, q_span))
    if l_word is None:
        return
    l_value = _constant(l_word, ctx)
    if l_value is None:
        return
    twice: list[str] = []
    try:
        program_and_count(p_text, p_value, 1.0, dialect, twice)  # L=1 is always valid: only P against L is judged
    except MacroAlarm as alarm:
        _add(facts, l_word, "repeat-count-range",
             f"{alarm.message} (alarm {alarm.number})",
             f"{in_language(alarm.message, True)}（报警 {alarm.number}）", ctx)  # fmt: skip
        return
    if twice:
        _add(facts, l_word, "repeat-count-range",
             f"{how}: {twice[0]}", f"{how}：{in_language(twice[0], True)}", ctx, milder=True)  # fmt: skip
    _check_count(l_word, ctx, facts)
