"""What a single block may contain (docs/semantics.md §1, §4, §5, §8): the rules decided from the
block alone, before anything runs, written once for the interpreter and the static checks.

``validate_block`` lists each ``BlockProblem`` of a block in the interpreter's order: a refused
macro-word abbreviation, IF without THEN, Haas's conditional ``[cond] M99 P n`` and an IF before
NC words or nothing (alarm 114; on Haas such an IF governs the rest of its block,
``Dialect.if_governs_block``), NC words beside a macro statement (alarm 127), the words a
``G65``/``G66`` may not share its block with (a word before it, alarm 127, or a modal G code the control sets first,
``Dialect.modal_g_before_call``; an O word, 127; a word other than P or H right after it where the
manual wants one, ``Dialect.call_first_letters``, a warning; a G code among its arguments, 129), a
call without P (076), and, in a block of NC words that no code of the machine file makes a call, a G
code that neither the dialect nor the machine has (010) and an M code written with a decimal
point (007) (``machine/words.py``).

A problem whose ``stops`` is True is an alarm: the interpreter raises the first one as the block's
alarm when the block runs (``message``, the alarm's text), and the static checks report each as
an error (``finding``, the same problem said with its alarm number, as a check that does not run
says it). A problem that does not stop (a modal G code before G65 on FANUC, an unknown G code on
a dialect without ``word_format_alarms``) runs on, and the static checks warn. What depends on a
value (the program a P names, a count, argument letters) is the shared helpers' of
``machine/calls.py``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import EllipsisType

from ..bilingual import Detail, detail
from ..dialects.alarms import (
    DECIMAL_POINT,
    FORMAT,
    G_ARGUMENT,
    IMPROPER_G_CODE,
    NC_AND_MACRO,
    NOT_ALONE,
    PROGRAM_NOT_FOUND,
)
from ..dialects.dialect import Dialect
from ..syntax.nodes import Block, Else, EndIf, If, Number, Statement, Word
from .calls import BlockCall, code_value, codes_before_call, g_code_name, recognise_call
from .words import (
    abbreviation_refused,
    block_if_refused,
    conditional_m99_refused,
    g_code_known,
    if_block_refused,
    m_decimal_point,
    missing_then,
    point_refused,
    unknown_g_code,
)

# the rules, as ``BlockProblem.rule`` names them
ABBREVIATION = "abbreviation"  # WH for WHILE where the dialect does not read it
MISSING_THEN = "missing-then"  # IF [..] <statement> where the dialect needs THEN
CONDITIONAL_M99 = "conditional-m99"  # [cond] M99 P n where the dialect does not read it
IF_BLOCK = "if-block"  # IF [cond] before NC words or nothing, where the IF governs no block
BLOCK_IF = "block-if"  # IF [cond] THEN alone, ELSE or ENDIF, where the dialect has no block IF
# the forms of a macro statement a dialect may lack: raised after the block's other format alarms
DIALECT_FORMS = (MISSING_THEN, CONDITIONAL_M99, IF_BLOCK, BLOCK_IF)
NC_AND_STATEMENT = "nc-and-macro"  # NC words and a macro statement in one block
BEFORE_CALL = "before-call"  # words before G65/G66
O_WITH_CALL = "o-with-call"  # an O word in a G65/G66 block
CALL_WORD_ORDER = "call-word-order"  # a word other than P (or H) right after G65/G66 where the manual wants one
G_AFTER_CALL = "g-argument"  # a G code among the arguments of G65/G66
CALL_WITHOUT_P = "call-without-p"  # G65/G66 without P
UNKNOWN_G_CODE = "unknown-g-code"  # a G code neither the dialect nor the machine has
M_DECIMAL_POINT = "decimal-point"  # an M code written with a decimal point
OWN_BLOCK = "own-block"  # a word beside a code the manual wants in a block of its own


@dataclass(frozen=True, slots=True)
class BlockProblem:
    """One thing the block may not contain: the alarm a control gives for it, what the run's
    alarm says (``message``) and what a check without running says (``finding``), the columns
    of the words concerned, and whether the control stops there (see the module docstring).
    ``words`` are the words a G65/G66 may not share its block with (``BEFORE_CALL``: every word
    before the call; ``O_WITH_CALL``: the O word), which the editor's split moves."""

    rule: str
    alarm: int
    message: Detail
    finding: Detail
    start: int
    end: int
    stops: bool = True
    words: tuple[Word, ...] = ()


def validate_block(
    block: Block,
    dialect: Dialect,
    calls: Mapping[str, object] | None = None,
    value: Callable[[Word], float | None] = code_value,
    call: BlockCall | EllipsisType | None = ...,
) -> list[BlockProblem]:
    """The problems of ``block`` that the block alone decides, in the interpreter's order.
    ``calls`` are the machine file's call codes; ``value`` gives a word's value when it is known
    without running (the literal, by default; the interpreter also folds constant expressions);
    ``call`` is ``recognise_call``'s answer for the block when the caller has it already (``...``:
    not given, recognised here)."""
    out: list[BlockProblem] = []
    if block.abbreviations and not dialect.keyword_abbreviations:
        for a in block.abbreviations:
            text = abbreviation_refused(a.text, a.word, dialect)
            out.append(BlockProblem(ABBREVIATION, FORMAT, text, text, a.start, a.end))
    words = block.words
    if block.statements:
        first = block.statements[0]
        # an IF without GOTO, alone in the block: on Haas it governs the rest of the block
        governing = (
            first
            if isinstance(first, If) and first.goto is None and not first.opens_block and len(block.statements) == 1
            else None
        )
        if words or block.corners:
            if governing is None or (governing.then is not None and not dialect.if_governs_block):
                out.append(_nc_and_statement(block, dialect))
                return out
            if not dialect.if_governs_block:
                text = if_block_refused(dialect, True)
                out.append(BlockProblem(IF_BLOCK, FORMAT, text, text, governing.start, governing.end))
                return out
        elif governing is not None and governing.then is None and not dialect.if_governs_block:
            text = if_block_refused(dialect, False)
            out.append(BlockProblem(IF_BLOCK, FORMAT, text, text, governing.start, governing.end))
            return out
        if not dialect.block_if:
            for s in block.statements:
                word = _block_if_word(s)
                if word is not None:
                    text = block_if_refused(dialect, word)
                    out.append(BlockProblem(BLOCK_IF, FORMAT, text, text, s.start, s.end))
        if not dialect.if_without_then or not dialect.conditional_m99:
            for s in block.statements:
                if s.__class__ is If and (s.implicit_then or s.m99 is not None):
                    _statement(s, dialect, out)
        return out
    if not words:
        return out
    if calls is None:
        calls = {}
    if call is ...:
        call = recognise_call(words, dialect, calls, value)
    if call is None:
        _refused_words(words, dialect, calls, value, out)
    elif call.kind == "G65" or call.kind == "G66":
        _macro_call(words, call.at, call.kind, call.arithmetic, dialect, out)
    elif not call.configured:  # a configured code's other words are its arguments
        _refused_words(words, dialect, calls, value, out)
    return out


def _block_if_word(s: Statement) -> str | None:
    """How a refusal names a statement of the block form of IF, or None for another statement."""
    if isinstance(s, If):
        return "IF [...] THEN" if s.opens_block else None
    if isinstance(s, Else):
        return "ELSE"
    if isinstance(s, EndIf):
        return "ENDIF"
    return None


def _nc_and_statement(block: Block, dialect: Dialect) -> BlockProblem:
    w = block.words[0] if block.words else block.corners[0]
    letter = w.letter if block.words else f",{w.letter}"
    alarm = dialect.alarm_said(NC_AND_MACRO)
    return BlockProblem(
        NC_AND_STATEMENT,
        NC_AND_MACRO,
        detail(f"{letter} word and a macro statement in one block", f"{letter} 代码与宏语句在同一程序段"),
        detail(
            f"the NC word {letter} and a macro statement in one block ({alarm}); only N may precede a macro statement",
            f"NC代码 {letter} 与宏语句在同一程序段（{alarm.zh}）；宏语句之前只允许 N",
        ),
        w.start,
        w.end,
    )


def _statement(s: Statement, dialect: Dialect, out: list[BlockProblem]) -> None:
    if s.__class__ is not If:
        return
    then = s.then
    if s.implicit_then and then is not None and not dialect.if_without_then:
        text = missing_then(dialect)
        out.append(BlockProblem(MISSING_THEN, FORMAT, text, text, then.start, then.end))
    if s.m99 is not None and not dialect.conditional_m99:
        text = conditional_m99_refused(dialect)
        out.append(BlockProblem(CONDITIONAL_M99, FORMAT, text, text, s.start, s.end))
    if then is not None:
        _statement(then, dialect, out)


def _macro_call(
    words: tuple[Word, ...], at: int, name: str, arithmetic: bool, dialect: Dialect, out: list[BlockProblem]
) -> None:
    """G65/G66 and the words beside it, as ``machine/nc_blocks.py`` compiles them."""
    if at > 0:
        before = words[:at]
        codes = codes_before_call([(w.letter, _raw_g(w)) for w in before], dialect)
        w = before[0]
        title = dialect.title
        alarm = dialect.alarm_said(NC_AND_MACRO)
        if codes is None:
            g = _raw_g(w)
            word = g_code_name(g) if w.letter == "G" and g is not None else w.letter
            out.append(BlockProblem(
                BEFORE_CALL, NC_AND_MACRO,
                detail(f"{w.letter} before {name}: only N may precede {name} in its block",
                       f"{name} 之前有 {w.letter}：程序段中 {name} 之前只允许出现 N"),
                detail(f"{word} before {name}: only N may precede {name} in its block; {title} stops with {alarm}",
                       f"{name} 之前只允许出现 N，不能有 {word}：{title} {alarm.zh}（停止运行）"),
                w.start, w.end, words=before,
            ))  # fmt: skip
            return
        shown = " ".join(g_code_name(c) for c in codes)
        text = detail(
            f"{shown} before {name}: {title} sets {shown} (it stays in force) and then {name} calls the macro; "
            f"controls that allow only N before {name} (GSK) stop with {alarm}, so {shown} is better on a block "
            "of its own",
            f"{name} 之前的 {shown}：{title} 先执行 {shown}（模态保持有效），再由 {name} 调用宏程序；"
            f"{name} 之前只允许 N 的系统（GSK）会{alarm.zh}，建议把 {shown} 单独写一段",
        )
        out.append(BlockProblem(BEFORE_CALL, NC_AND_MACRO, text, text, w.start, before[-1].end, False, before))
    after = words[at + 1 :]
    for w in after:
        if w.letter == "O":  # M after G65 is the argument #13; G is alarm 129 below
            out.append(BlockProblem(
                O_WITH_CALL, NC_AND_MACRO,
                detail(f"{name} may not share its block with an O word", f"{name} 不能与 O 代码在同一程序段"),
                detail(f"{name} may not share its block with an O word ({dialect.alarm_said(NC_AND_MACRO)})",
                       f"{name} 不能与 O 代码在同一程序段（{dialect.alarm_said(NC_AND_MACRO).zh}）"),
                w.start, w.end, words=(w,),
            ))  # fmt: skip
            return
    first = dialect.call_first_letters
    if first and after and after[0].letter not in first:
        out.append(_word_order(after[0], name, first, arithmetic, dialect))
    if arithmetic:
        return  # G65 Hm P Q R: its words are machine/hcodes.py's
    for w in after:
        if w.letter == "G":
            out.append(BlockProblem(
                G_AFTER_CALL, G_ARGUMENT,
                detail(f"G after {name}: a G code cannot be an argument", f"{name} 之后有 G：G 代码不能作为自变量"),
                detail(f"G after {name}: a G code cannot be an argument ({dialect.alarm_said(G_ARGUMENT)})",
                       f"{name} 之后的 G 代码不能作为自变量（{dialect.alarm_said(G_ARGUMENT).zh}）"),
                w.start, w.end,
            ))  # fmt: skip
            break
    if not any(w.letter == "P" for w in after):
        call = words[at]
        out.append(BlockProblem(
            CALL_WITHOUT_P, PROGRAM_NOT_FOUND,
            detail(f"{name} needs P: the program to call", f"{name} 需要用 P 指定被调用的程序"),
            detail(f"{name} needs P: the program to call ({dialect.alarm_said(PROGRAM_NOT_FOUND)})",
                   f"{name} 需要 P 指定被调用的程序（{dialect.alarm_said(PROGRAM_NOT_FOUND).zh}）"),
            call.start, call.end,
        ))  # fmt: skip


def _word_order(w: Word, name: str, first: str, arithmetic: bool, dialect: Dialect) -> BlockProblem:
    """A word right after G65/G66 that is none of ``Dialect.call_first_letters`` (GSK980TDi
    §3.28.3 note 3, "紧跟其后要出现P或H代码字"). The manual gives no alarm for it, so the block runs
    on, read by its first P or H (``calls.h_code_form``), and the check warns."""
    letters = Detail(" or ".join(first), "或".join(first))  # "P or H", "P或H": the letters as each language lists them
    if arithmetic:
        reading, fix = detail("G65 H (macro arithmetic)", "G65 H（宏运算）"), "H"
    else:
        reading, fix = detail("a macro call", "宏程序调用"), "P"
    fix = fix if fix in first else first[0]
    title = dialect.title
    return BlockProblem(
        CALL_WORD_ORDER, FORMAT,
        detail(f"{w.letter} right after {name}: {letters} must follow {name} at once",
               f"{name} 之后紧跟的是 {w.letter}：{name} 之后必须紧跟 {letters.zh}"),
        detail(f"{w.letter} right after {name}: {title}'s manual has {letters} follow {name} at once and gives no "
               f"alarm for another word; the block is read as {reading}: write {fix} right after {name}",
               f"{name} 之后紧跟的是 {w.letter}：{title} 手册规定 {name} 之后紧跟 {letters.zh}，未给出其他代码的报警；"
               f"本程序段按{reading.zh}读取：请把 {fix} 紧接在 {name} 之后"),
        w.start, w.end, False,
    )  # fmt: skip


def _raw_g(w: Word) -> float | None:
    """A G word's literal value as written (what the interpreter compares before a call)."""
    v = w.value
    return v.value if w.letter == "G" and v.__class__ is Number else None


def _refused_words(
    words: tuple[Word, ...],
    dialect: Dialect,
    calls: Mapping[str, object],
    value: Callable[[Word], float | None],
    out: list[BlockProblem],
) -> None:
    """A G code the control lacks, an M code with a decimal point: alarms where the dialect has
    ``word_format_alarms``, otherwise remarks the run goes past."""
    stops = dialect.word_format_alarms
    for w in words:
        if w.letter == "G":
            v = value(w)
            if v is not None and not g_code_known(v, dialect, calls):
                shown = w.value.text if isinstance(w.value, Number) else f"{v:g}"
                text = unknown_g_code(shown, dialect)
                out.append(BlockProblem(UNKNOWN_G_CODE, IMPROPER_G_CODE, text, text, w.start, w.end, stops))
        elif w.letter == "M":
            point = m_decimal_point(w, dialect)
            if point is not None:
                out.append(BlockProblem(M_DECIMAL_POINT, DECIMAL_POINT, point, point, w.start, w.end, stops))
    if dialect.own_block_codes:
        _own_block(words, dialect, out)
    if dialect.no_point_words:  # T0101., G04 P1.5, G74 Q5.: read as written, said as a warning
        gs = tuple(v for w in words if w.letter == "G" and (v := _raw_g(w)) is not None)
        letters = frozenset(w.letter for w in words)
        for w in words:
            point = point_refused(w, gs, letters, dialect)
            if point is not None:
                out.append(BlockProblem(M_DECIMAL_POINT, DECIMAL_POINT, point, point, w.start, w.end, False))


def _own_block(words: tuple[Word, ...], dialect: Dialect, out: list[BlockProblem]) -> None:
    """A word beside a G code the manual wants in a block of its own (``Dialect.own_block_codes``):
    an alarm where the manual gives one for its letter (GSK980TDi's G22/G23 beside a G, M, S or T
    code), else a warning; the first such word of each code."""
    for w in words:
        code = _raw_g(w)
        rule = dialect.own_block_codes.get(code) if code is not None else None
        if rule is None:
            continue
        alarmed, allowed = rule
        beside = [o for o in words if o is not w and o.letter != "N"]
        stop = next((o for o in beside if o.letter in alarmed), None)
        other = stop or next((o for o in beside if allowed != "*" and o.letter not in allowed), None)
        if other is None:
            continue
        v = other.value
        g, word = f"G{code:g}", other.letter + (v.text if isinstance(v, Number) else "")
        if stop is not None:
            text = detail(f"{g} shares its block with {word}: write {g} in a block of its own",
                          f"{g} 与 {word} 同段：请将 {g} 单独编为一段")  # fmt: skip
        else:
            text = detail(f"{g} shares its block with {word}: the control's manual wants {g} in a block of its own",
                          f"{g} 与 {word} 同段：系统手册要求 {g} 单独编为一段")  # fmt: skip
        finding = text
        if stop is not None:  # a check that does not run names the alarm, as the run's report does
            said = dialect.alarm_said(NOT_ALONE)
            finding = detail(f"{text} ({said})", f"{text.zh}（{said.zh}）")
        out.append(BlockProblem(OWN_BLOCK, NOT_ALONE, text, finding, other.start, other.end, stop is not None))


def first_alarm(problems: list[BlockProblem]) -> BlockProblem | None:
    """The problem the control stops at: the first that stops."""
    for p in problems:
        if p.stops:
            return p
    return None
