"""Words and forms a control refuses: a G code it lacks, a decimal point in an M code (docs/semantics.md
§8), an abbreviated macro word (§1), IF without THEN and the conditional M99 (§4) where the
dialect has none of them.

A G code is known when the dialect's table lists it (``G_CODES`` of its data module, codes of
both the milling and the turning series, the 30i's and the grinding cycles), when the machine
settings make it a call (``[calls]``, e.g. ``G100 = 9010``) or when a switch of the dialect
names it (``extra_offset_code``, ``extra_offset_aliases``: Haas G154, G110–G129). On a dialect with
``word_format_alarms`` (FANUC) any other G code is alarm 010 "improper G code", and an M code
written with a decimal point (``M30.``) is alarm 007 "illegal use of decimal point". Elsewhere
(GSK980TDi, whose manuals at hand give neither a complete code list nor those alarms) both are
only warnings and a run goes on as if the word were a one-shot code.

``WH`` for WHILE is read by FANUC (``Dialect.keyword_abbreviations``), ``IF[..] #1=2`` without
THEN by the FANUC profiles and Haas (``Dialect.if_without_then``), Haas's conditional jump
``[cond] M99 P n`` and an IF that governs the NC words after it, ``IF [..] G01 X1.``, by Haas
(``Dialect.conditional_m99``, ``Dialect.if_governs_block``); a dialect without the switch stops
with alarm 114 at such a block. The interpreter (``blocks.py``, ``nc_blocks.py``) and the static checks
(``analysis/checks/call_checks.py``, ``analysis/checks/statement_checks.py``) take their messages from here.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache
from typing import TYPE_CHECKING

from ..bilingual import Detail, detail
from ..dialects import get_dialect
from ..dialects.alarms import DECIMAL_POINT, FORMAT, IMPROPER_G_CODE
from ..dialects.dialect import ANY_BLOCK
from ..planner.modal_groups import extra_offset_codes
from ..planner.numbers import round_half_away
from ..syntax.nodes import LOGICAL_SYMBOLS, Number, Word
from .word_sets import WordSet

if TYPE_CHECKING:
    from ..dialects import Dialect


@cache
def known_g_codes(dialect: str) -> frozenset[float]:
    """The G codes that the dialect's table lists, as the interpreter rounds them (5.1, 54.0)."""
    out = set()
    for doc in get_dialect(dialect).g_codes():
        try:
            out.add(float(doc.code[1:]))
        except ValueError:
            continue
    return frozenset(out)


def machine_g_codes(dialect: Dialect) -> frozenset[float]:
    """The G codes a machine file declares as plain codes (``Dialect.extra_codes``)."""
    return frozenset(float(c.code[1:]) for c in dialect.extra_codes if c.code[0] == "G")


def g_code_known(value: float, dialect: Dialect, calls: Mapping[str, object]) -> bool:
    """Whether ``G<value>`` (rounded as an address value) exists for the dialect or the machine."""
    return (
        value in known_g_codes(dialect.name)
        or f"G{value:g}" in calls
        or value in machine_g_codes(dialect)
        or value == dialect.extra_offset_code
        or value in dialect.extra_offset_aliases
    )


def unknown_g_code(shown: str, dialect: Dialect) -> Detail:
    """What to say of ``G<shown>`` that the dialect's table and the machine's call codes lack."""
    if dialect.word_format_alarms:
        alarm = dialect.alarm_titled(IMPROPER_G_CODE, 3)
        return detail(
            f"G{shown}: {dialect.title} has no such G code ({alarm}); a code that the "
            "machine maps to a macro belongs in the machine file's [calls], one the machine builder added "
            "in its [codes]",
            f"G{shown}：{dialect.title} 没有这个G代码（{alarm.zh}）；若机床把它设为宏程序调用，"
            "请写入机床文件的 '[calls]' 表；若是机床厂家增加的代码，请写入 '[codes]' 表",
        )
    return detail(
        f"G{shown} is not in the {dialect.title} G-code table: the control alarms on a G code it does not have; "
        "a code that the machine maps to a macro belongs in the machine file's [calls], one the machine builder added "
        "in its [codes]",
        f"G{shown} 不在 {dialect.title} 的G代码表中：系统没有的G代码会报警；若机床把它设为宏程序调用，"
        "请写入机床文件的 '[calls]' 表；若是机床厂家增加的代码，请写入 '[codes]' 表",
    )


def m_decimal_point(word: Word, dialect: Dialect) -> Detail | None:
    """What to say of an M code written with a decimal point (``M30.``), or None."""
    value = word.value
    if word.letter != "M" or value.__class__ is not Number or not value.has_point:
        return None
    text = value.text
    whole = text.split(".")[0] or "0"
    alarm = dialect.alarm_titled(DECIMAL_POINT, 3)
    return detail(
        f"M{text}: an M code takes no decimal point ({alarm}); write M{whole}",
        f"M{text}：M代码只能写整数（{alarm.zh}）；请写作 M{whole}",
    )


_SEQUENCE_CYCLES = (70.0, 71.0, 72.0, 73.0)  # their P and Q name the shape's first and last N
_END_POINT = frozenset("XZUW")  # a G74-G76 block with one of these is the second (lathe_cycles.py)


def point_refused(word: Word, gs: tuple[float, ...], letters: frozenset[str], dialect: Dialect) -> Detail | None:
    """What to say of a literal written with a decimal point in an address the control takes
    without one (``Dialect.no_point_words``; ``gs`` the block's G codes, ``letters`` its letters),
    or None: how the run reads it, since the manuals give no alarm for these (docs/semantics.md §8)."""
    value = word.value
    if value.__class__ is not Number or not value.has_point:
        return None
    letter, text, v = word.letter, value.text, value.value
    table = dialect.no_point_words
    code = next((g for g in gs if letter in table.get(g, "")), None)
    if code is None and letter not in table.get(ANY_BLOCK, ""):
        return None
    whole = text.split(".")[0] or "0"
    if code is None:  # T, S: whole numbers, rounded half away from zero as a value from a variable is
        shown = f"{letter}{int(round_half_away(v))}"
        reading = detail(f"{shown}", f"{shown}")
        written = f"{letter}{whole}" if v == int(v) else shown  # T0101. -> T0101, S1000.5 -> S1001
        fix = detail(f"{written}", f"{written}")
    elif code == 4.0:
        reading = detail(f"{v:g} ms ({v / 1000:g} s)", f"{v:g} 毫秒（{v / 1000:g} 秒）")
        fix = detail(f"P{v * 1000:g} or X{v:g} for {v:g} s", f"P{v * 1000:g} 或 X{v:g}（{v:g} 秒）")
    elif code in _SEQUENCE_CYCLES or (code == 76.0 and letter == "P" and not letters & _END_POINT):
        # a sequence number N, or G76's digits m r a
        shown = f"{'N' if code in _SEQUENCE_CYCLES else letter}{round(v)}"
        reading = detail(f"{shown}", f"{shown}")
        fix = detail(f"{letter}{whole}", f"{letter}{whole}")
    else:
        mm = f"{v * 0.001:.7f}".rstrip("0").rstrip(".")  # 0.00005, not 5e-05
        reading = detail(f"{v:g} least input increments, {mm} mm", f"{v:g} 个最小输入增量，即 {mm} 毫米")
        fix = detail(f"{letter}{v * 1000:g} for {v:g} mm", f"{letter}{v * 1000:g}（即 {v:g} 毫米）")
    g = f"G{int(code):02d}" if code is not None else ""
    where = detail(f"{letter}", f"{letter}") if code is None else detail(f"{g}'s {letter}", f"{g} 的 {letter}")
    return detail(
        f"{letter}{text}: {dialect.title} takes {where} without a decimal point; the run reads it as {reading}: "
        f"write {fix}",
        f"{letter}{text}：{dialect.title} 的 {where.zh} 不带小数点；运行时读作 {reading.zh}：请写作 {fix.zh}",
    )


def abbreviation_refused(text: str, word: str, dialect: Dialect) -> Detail:
    """What to say of a macro word written shortened (``text`` for ``word``) on a dialect that
    does not read abbreviations."""
    alarm = dialect.alarm_said(FORMAT)
    return detail(
        f"'{text}' for {word}: abbreviated macro words are a FANUC feature that {dialect.title} does not "
        f"have; the control stops here with {alarm}; write {word}",
        f"'{text}' 表示 {word}：宏语句关键字的缩写是 FANUC 的功能，{dialect.title} 不支持；"
        f"系统执行到此处{alarm.zh}；请写作 {word}",
    )


def missing_then(dialect: Dialect) -> Detail:
    """What to say of ``IF [cond] <statement>`` without THEN on a dialect that needs THEN."""
    alarm = dialect.alarm_said(FORMAT)
    return detail(
        f"THEN is missing: {dialect.title} runs only IF[...] GOTO n and IF[...] THEN <statement>, and "
        f"stops at this block with {alarm}; write THEN before the statement (FANUC and Haas controls run it without)",
        f"缺少 THEN：{dialect.title} 只接受 IF[...] GOTO n 和 IF[...] THEN <语句>，执行到此程序段时{alarm.zh}；"
        "请在语句前写 THEN（FANUC 与哈斯系统可以省略）",
    )


def if_block_refused(dialect: Dialect, words: bool) -> Detail:
    """What to say of ``IF [cond]`` followed by NC words (``words``) or by nothing, on a dialect
    whose IF governs no block (``Dialect.if_governs_block`` off)."""
    alarm = dialect.alarm_said(FORMAT)
    if words:
        return detail(
            f"IF [...] followed by NC words: {dialect.title} runs only IF[...] GOTO n and IF[...] THEN <macro "
            f"statement>, and stops at this block with {alarm} (a Haas control runs the words when the condition "
            "holds); jump over the block instead: IF [reverse condition] GOTO n",
            f"IF [...] 之后是 NC 代码：{dialect.title} 只接受 IF[...] GOTO n 和 IF[...] THEN <宏语句>，"
            f"执行到此程序段时{alarm.zh}（哈斯系统在条件成立时执行这些代码）；"
            "请改为用 IF [相反条件] GOTO n 跳过该程序段",
        )
    return detail(
        f"IF [...] with nothing after it: {dialect.title} needs GOTO n or THEN <macro statement> after the "
        f"condition and stops at this block with {alarm}",
        f"IF [...] 之后没有内容：{dialect.title} 要求条件之后写 GOTO n 或 THEN <宏语句>，执行到此程序段时{alarm.zh}",
    )


# the controls that read the block form of IF, named where another control refuses it
BLOCK_IF_CONTROLS = detail("Mitsubishi M70/M80 and Mazak controls", "三菱 M70/M80 与马扎克系统")


def block_if_refused(dialect: Dialect, word: str) -> Detail:
    """What to say of the block form of IF (``word``: ``IF [...] THEN`` alone, ``ELSE`` or ``ENDIF``)
    on a dialect without it (``Dialect.block_if`` off)."""
    alarm = dialect.alarm_said(FORMAT)
    controls = BLOCK_IF_CONTROLS
    return detail(
        f"{word}: the block form IF [...] THEN / ELSE / ENDIF is not a macro statement of {dialect.title}, which "
        f"stops at this block with {alarm} ({controls} run it); here write IF [reverse condition] GOTO n "
        "around the blocks",
        f"{word}：块形式 IF [...] THEN / ELSE / ENDIF 不是 {dialect.title} 的宏语句，执行到此程序段时{alarm.zh}"
        f"（{controls.zh}可以执行）；在此系统上请用 IF [相反条件] GOTO n 跳过这些程序段",
    )


# the controls that read AND and OR spelled ``&&`` and ``||``, named where another control refuses them
LOGICAL_SYMBOL_CONTROLS = detail("Mazak controls in EIA/ISO", "马扎克系统的 EIA/ISO 程序")


def logical_symbol_refused(dialect: Dialect, symbol: str) -> Detail:
    """What to say of ``&&`` or ``||`` on a dialect that does not read them
    (``Dialect.logical_symbols`` off): the word to write instead."""
    alarm = dialect.alarm_said(FORMAT)
    word = LOGICAL_SYMBOLS[symbol]
    controls = LOGICAL_SYMBOL_CONTROLS
    return detail(
        f"'{symbol}' is not an operator of {dialect.title}, which stops at this block with {alarm} "
        f"({controls} read it as {word}); write {word}",
        f"“{symbol}”不是 {dialect.title} 的运算符，执行到此程序段时{alarm.zh}（{controls.zh}读作 {word}）；"
        f"请写作 {word}",
    )


def conditional_m99_refused(dialect: Dialect) -> Detail:
    """What to say of Haas's conditional jump ``[cond] M99 P n`` on a dialect that does not read it."""
    alarm = dialect.alarm_said(FORMAT)
    return detail(
        f"[cond] M99 P n is Haas's conditional jump (the same as IF [cond] GOTO n); {dialect.title} does not "
        f"read a condition before M99 and stops at this block with {alarm}; write IF [cond] GOTO n",
        f"[条件] M99 P n 是哈斯系统的条件跳转（等同于 IF [条件] GOTO n）；{dialect.title} 不接受 M99 之前的条件，"
        f"执行到此程序段时{alarm.zh}；请写作 IF [条件] GOTO n",
    )


def refused_words(dialect: Dialect, calls: Mapping[str, object]) -> tuple[WordSet, ...]:
    """The words the refusals look at (``word_sets.py``): a G code outside those
    ``g_code_known`` knows, an M code written with a decimal point, and the letters of
    ``Dialect.no_point_words`` written with one, and the codes the manual wants in a block of their
    own (``Dialect.own_block_codes``)."""
    known = set(known_g_codes(dialect.name)) | extra_offset_codes(dialect) | machine_g_codes(dialect)
    for code in calls:
        if code[:1] == "G" and code[1:]:
            try:
                known.add(float(code[1:]))
            except ValueError:
                continue
    # the letters some block takes without a decimal point (``point_refused``)
    no_point = sorted(set("".join(dialect.no_point_words.values())))
    own = (WordSet("G", frozenset(dialect.own_block_codes)),) if dialect.own_block_codes else ()  # block_rules.py
    return (
        WordSet("G", outside=frozenset(known)),
        WordSet("M", point=True),
        *(WordSet(x, point=True) for x in no_point),
        *own,
    )
