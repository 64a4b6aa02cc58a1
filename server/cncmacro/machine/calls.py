"""What the call words mean (docs/semantics.md §5): which call a block makes, G65/G66 arguments,
P and L, M98 counts.

``recognise_call`` is the one place that says what a block calls: ``G65``/``G66`` (a macro, or on
gsk980tdi ``G65 Hm`` macro arithmetic), a G, M or T code that the machine file's ``[calls]``
makes a call, ``M98``/``M198`` (a subprogram), or the dialect's local subprogram call (Haas ``M97
P n``, ``Dialect.local_subprogram_code``); ``call_word_pattern`` finds the lines that may hold one,
``call_words`` the words it looks at in a line of plain words.
``map_arguments`` applies argument specifications I and II word by word, left to right, a
later word winning on a shared variable; ``program_and_count`` splits ``M98 P30040`` into
program 40 and count 3; ``repeat_count`` checks L. They take evaluated words and return plain
values, raising ``MacroAlarm`` for what the control refuses; the machine does the calling.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

from ..bilingual import detail
from ..dialects.alarms import ARGUMENT_RANGE, COUNT_TWICE, G_ARGUMENT, P_VALUE_RANGE
from ..dialects.dialect import ARGUMENTS_I, Dialect
from ..library.machine_file import CallCode
from ..planner.modal_groups import g_code_groups
from ..planner.numbers import round_half_away, to_increment, to_int
from ..syntax.nodes import Number, Word
from .alarms import MacroAlarm
from .word_sets import WordSet

NOT_ARGUMENTS = frozenset("GLNOP")
MACRO_CALLS = (65.0, 66.0)  # G65, G66
SUBPROGRAM_CALLS = (98.0, 198.0)  # M98, M198
MAX_REPEAT = 9999


def codes_before_call(words: list[tuple[str, float | None]], dialect: Dialect) -> list[float] | None:
    """The words written before ``G65``/``G66`` in its block (N apart), as (letter, literal
    value or None): the G codes the control carries out before it calls, or None when the block
    is alarm 127. Only N may precede the call (seed 001 注3, seed 000 §3.28.3); a dialect whose
    ``modal_g_before_call`` is ``"execute"`` (FANUC) sets modal G codes there and then calls, as
    programs that run in production show. Any other word, a one-shot G code or G66/G67 is 127."""
    if dialect.modal_g_before_call != "execute":
        return None
    groups = g_code_groups(dialect)
    codes: list[float] = []
    for letter, value in words:
        if letter != "G" or value is None:
            return None
        group = groups.get(value)
        if group is None or group == "macro":
            return None
        codes.append(value)
    return codes


@dataclass(slots=True)
class Arguments:
    """Locals filled by a call: number -> value, with the letter that filled each, and any
    remark the mapping made (I/J/K out of order on fanuc)."""

    values: dict[int, float | None] = field(default_factory=dict)
    letters: dict[int, str] = field(default_factory=dict)
    remarks: list[str] = field(default_factory=list)
    # local number -> the factor its value was divided by: an argument written without a decimal
    # point, read in least input increments (``decimal_point = "increment"``), for ``ADP``
    increments: dict[int, float] = field(default_factory=dict)


def map_arguments(words: Sequence[tuple[str, float | None]], dialect: Dialect) -> Arguments:
    """Locals for the argument words of a G65/G66 block (P, L and the G code removed)."""
    out = Arguments()
    counts = {"I": 0, "J": 0, "K": 0}
    last = (-1, -1)  # (set, I=0 J=1 K=2) of the previous I/J/K word
    out_of_order = False
    for letter, value in words:
        if letter in NOT_ARGUMENTS:
            raise MacroAlarm(
                G_ARGUMENT,
                detail(
                    f"address {letter} cannot be an argument of a macro call",
                    f"地址 {letter} 不能作为宏程序调用的自变量",
                ),
            )
        if letter in counts:
            k = counts[letter]
            if k >= 10:
                raise MacroAlarm(G_ARGUMENT, detail(f"more than 10 {letter} arguments", f"自变量 {letter} 超过 10 个"))
            counts[letter] = k + 1
            number = {"I": 4, "J": 5, "K": 6}[letter] + 3 * k
            here = (k, "IJK".index(letter))
            out_of_order = out_of_order or here < last
            last = here
        else:
            number = ARGUMENTS_I.get(letter, 0)
            if not number:
                raise MacroAlarm(
                    G_ARGUMENT,
                    detail(
                        f"address {letter} cannot be an argument of a macro call",
                        f"地址 {letter} 不能作为宏程序调用的自变量",
                    ),
                )
        if value is None and not dialect.vacant_address_is_zero:
            continue  # a vacant argument is not passed (fanuc)
        out.values[number] = 0.0 if value is None else value
        out.letters[number] = letter if letter not in counts else f"{letter}{counts[letter]}"
    if out_of_order and dialect.ijk_order_matters:
        out.remarks.append(
            detail(
                "I, J and K arguments should come in the order I, J, K within each set",
                "每组自变量应按 I、J、K 的顺序指定",
            ),
        )
    return out


def repeat_count(value: float | None, dialect: Dialect, notes: list[str]) -> int:
    """The L of a call: 1 when absent; below 1 is an alarm; above 9999 is clamped (with a
    note) where the dialect clamps, else an alarm."""
    if value is None:
        return 1
    n = to_int(value)
    if n < 1:
        raise MacroAlarm(
            P_VALUE_RANGE if dialect.count_in_p_and_l_alarm else ARGUMENT_RANGE,
            detail(f"L{n}: the repeat count must be 1 to 9999", f"L{n}：重复次数必须在 1～9999 之间"),
            "repeat-count",
        )
    if n > MAX_REPEAT:
        if dialect.clamp_repeat_count:
            notes.append(
                detail(f"L{n} is above 9999; the control runs it 9999 times", f"L{n} 超过 9999，系统按 9999 次执行"),
            )
            return MAX_REPEAT
        raise MacroAlarm(
            ARGUMENT_RANGE,
            detail(f"L{n}: the repeat count must be 1 to 9999", f"L{n}：重复次数必须在 1～9999 之间"),
            "repeat-count",
        )
    return n


def program_and_count(
    p_text: str | None, p_value: float | None, l_value: float | None, dialect: Dialect, notes: list[str]
) -> tuple[int, int]:
    """``M98 P<count><program> L<count>``: (program number, repeat count). A P with more
    digits than a program number has (``Dialect.m98_program_digits``: 4, or up to 8 on a
    machine with longer program numbers) carries the count in the digits before them."""
    digits, program, count_in_p = _split_p(p_text, p_value, dialect)
    if l_value is not None:
        _count_twice(digits, count_in_p, l_value, dialect, notes)
        return program, repeat_count(l_value, dialect, notes)
    return program, max(1, count_in_p) if len(digits) > dialect.m98_program_digits else 1


def count_in_p_and_l(
    p_text: str | None, p_value: float | None, l_value: float, dialect: Dialect, notes: list[str]
) -> None:
    """The rule of ``M98 P<count><program> L<count>`` alone, as ``program_and_count`` applies it
    when the block runs: the alarm (or the note) for a count given in both P and L, with the L
    written; the L's own range is ``repeat_count``'s."""
    digits, _, count_in_p = _split_p(p_text, p_value, dialect)
    _count_twice(digits, count_in_p, l_value, dialect, notes)


def _split_p(p_text: str | None, p_value: float | None, dialect: Dialect) -> tuple[str, int, int]:
    """An M98's P as (its digits, the program, the count in its leading digits or 0)."""
    if p_value is None:
        raise MacroAlarm(P_VALUE_RANGE, detail("M98 needs P: the program to call", "M98 需要用 P 指定被调用的程序"))
    n = to_int(p_value)
    if n < 0:
        raise MacroAlarm(P_VALUE_RANGE, detail(f"P{n}: a program number cannot be negative", f"P{n}：程序号不能为负数"))
    digits = p_text.lstrip("+") if p_text and p_text.lstrip("+").isdigit() else str(n)
    k = dialect.m98_program_digits
    if len(digits) > 8:
        count_digits = 8 - k
        raise MacroAlarm(
            P_VALUE_RANGE,
            detail(
                f"P{digits}: at most 8 digits ({count_digits} for the count, {k} for the program)",
                f"P{digits}：最多 8 位（前 {count_digits} 位为调用次数，后 {k} 位为程序号）",
            )
            if count_digits
            else detail(
                f"P{digits}: a program number has at most 8 digits (the count goes in L)",
                f"P{digits}：程序号最多 8 位（调用次数用 L 指定）",
            ),
        )
    if len(digits) > k:
        return digits, int(digits[-k:]), int(digits[:-k])
    return digits, n, 0


def _count_twice(digits: str, count_in_p: int, l_value: float, dialect: Dialect, notes: list[str]) -> None:
    """A count in P's leading digits and an L: the alarm where the control refuses it (its text
    names the P and the L as written), else a note that L is used."""
    if not count_in_p:
        return
    if dialect.count_in_p_and_l_alarm:
        raise MacroAlarm(
            COUNT_TWICE,
            detail(
                f"P{digits} L{to_int(l_value)}: the count is given in both P and L",
                f"P{digits} L{to_int(l_value)}：P 和 L 同时指定了调用次数",
            ),
        )
    notes.append(detail("the count is given in both P and L; L is used", "P 和 L 同时指定了调用次数，按 L 执行"))


def macro_program_number(value: float | None, dialect: Dialect) -> int:
    """The program a G65/G66 P (or a gsk980tdi ``M98 P[#100]``) names: at most 4 digits on
    gsk980tdi (alarm 291), 8 on fanuc."""
    if value is None:
        raise MacroAlarm(
            P_VALUE_RANGE,
            detail("the call needs P: the program to call", "调用需要用 P 指定被调用的程序"),
        )
    n = to_int(value)
    if n < 0 or n >= 10**dialect.program_digits:
        raise MacroAlarm(
            P_VALUE_RANGE,
            detail(
                f"P{n}: a program number has at most {dialect.program_digits} digits",
                f"P{n}：程序号最多 {dialect.program_digits} 位",
            ),
        )
    return n


def bad_name_detail(name: str) -> str:
    """The text of the alarm for a bracketed program name the control refuses
    (``library.programs.is_program_name``)."""
    return detail(
        f"P[{name}]: a program name may hold only letters, digits and + - _ . and may not start with '.'",
        f"P[{name}]：程序名只能由字母（含中文）、数字及 + - _ . 组成，且不能以 . 开头",
    )


def argument_targets(letters: list[str]) -> list[int | None]:
    """The local each argument word of a G65/G66 block fills, word by word (specification I,
    and II for repeated I, J, K: the k-th I fills #(4+3(k-1))); None for a letter that is not
    an argument or an eleventh I, J or K. Used by editors to label arguments."""
    counts = {"I": 0, "J": 0, "K": 0}
    out: list[int | None] = []
    for letter in letters:
        letter = letter.upper()
        if letter in counts:
            k = counts[letter]
            counts[letter] = k + 1
            out.append({"I": 4, "J": 5, "K": 6}[letter] + 3 * k if k < 10 else None)
        elif letter in NOT_ARGUMENTS:
            out.append(None)
        else:
            out.append(ARGUMENTS_I.get(letter))
    return out


def letters_for_local(number: int) -> tuple[str | None, str | None]:
    """Which argument fills local ``#number``: (the letter under specification I, the word
    under specification II such as ``I2`` for the second I), each None when none does."""
    spec1 = next((letter for letter, n in ARGUMENTS_I.items() if n == number), None)
    spec2: str | None = None
    if number in (1, 2, 3):
        spec2 = "ABC"[number - 1]
    elif 4 <= number <= 33:
        k, r = divmod(number - 4, 3)
        spec2 = f"{'IJK'[r]}{k + 1}"
    return spec1, spec2


# ---------------------------------------------------------------- which call a block makes


@dataclass(frozen=True, slots=True)
class BlockCall:
    """The call a block makes. ``kind`` is ``G65``, ``G66``, ``M98``, ``M198``, the dialect's local
    call (``M97``, ``local``) or a code of the machine file (``G100``, ``M50``, ``T``,
    ``configured``); ``code`` is the word that makes it, ``at`` its index among the block's words.
    ``target`` is the word that names what is called (P: the last P of an M code call; a
    configured code's own word), None when there is none; the block alone gives the program's
    ``number`` (a literal P read by ``macro_program_number``/``program_and_count``, or the machine
    file's program), its bracketed ``name`` (``P[CUT]``), or the ``label`` (M97 P, M98 Q).
    ``count`` is the L word, ``repeats`` the count the block alone gives (L, or the digits of M98
    P before the program's), ``arguments`` the words that fill locals (a macro call's).
    ``arithmetic`` is gsk980tdi's ``G65 Hm P Q R``: macro arithmetic and branches, not a call."""

    kind: str
    code: Word
    at: int
    target: Word | None
    number: int | None = None
    name: str | None = None
    label: int | None = None
    count: Word | None = None
    repeats: int | None = None
    arguments: tuple[Word, ...] = ()
    macro: bool = False
    local: bool = False
    configured: bool = False
    arithmetic: bool = False


def code_value(w: Word) -> float | None:
    """A literal word's value as the interpreter rounds a code (G to 0.1, M and the other
    integer addresses to a whole number), or None when it is not a literal."""
    v = w.value
    if v.__class__ is not Number:
        return None
    x: float = v.value
    if w.letter == "G":
        return to_increment(x, 1) if x != int(x) else x
    if w.letter in ("M", "T", "P", "L", "Q", "H"):
        return round_half_away(x)
    return x


def g_code_name(code: float | None) -> str:
    """``G01``, ``G5.1``: a G code as people write it."""
    if code is None:
        return "G"
    return f"G{int(code):02d}" if code == int(code) else f"G{code:g}"


def recognise_call(
    words: Sequence[Word],
    dialect: Dialect,
    calls: Mapping[str, CallCode] | Mapping[str, object] | None = None,
    value: Callable[[Word], float | None] = code_value,
) -> BlockCall | None:
    """The call that a block of these ``words`` makes, or None (see ``BlockCall``). ``calls`` are the
    machine file's call codes; ``value`` gives a word's value when it is known without running
    (the literal by default; the interpreter also folds constant expressions). G65/G66 come
    first, wherever they stand; then a configured code, M98/M198, and the local call."""
    m_at: list[int] = []
    for i, w in enumerate(words):
        letter = w.letter
        if letter == "G":
            v = w.value
            if v.__class__ is Number and v.value in MACRO_CALLS:
                return _macro_call(words, i, v.value, dialect)
        elif letter == "M":
            m_at.append(i)
    if calls:
        for i, w in enumerate(words):
            if w.letter in ("G", "M"):
                x = value(w)
                if x is None:
                    continue
                code = f"{w.letter}{x:g}"
            elif w.letter == "T" and "T" in calls:
                code = "T"
            else:
                continue
            configured = calls.get(code)
            if isinstance(configured, CallCode):
                macro = configured.call == "macro"
                count = next((a for a in words if a.letter == "L"), None)
                args = tuple(a for a in words if a is not w and a.letter != "L" and not _same_code(a, code, value))
                return BlockCall(code, w, i, w, configured.program, count=count, repeats=_literal_count(count),
                                 arguments=args if macro else (), macro=macro, configured=True)  # fmt: skip
    if not m_at:
        return None
    ms = [(i, words[i], value(words[i])) for i in m_at]
    local = dialect.local_subprogram_code
    for wanted in (98.0, 198.0, local):
        if wanted is None:
            continue
        hit = next(((i, w) for i, w, x in ms if x == wanted), None)
        if hit is None:
            continue
        if wanted == 198.0 and any(x == 98.0 for _, _, x in ms):
            continue
        i, w = hit
        p = last_word(words, "P")
        count = last_word(words, "L")
        if wanted == local:
            label = _label(p)
            return BlockCall(
                f"M{local:g}", w, i, p, label=label, count=count, repeats=_literal_count(count), local=True
            )
        q = last_word(words, "Q")
        number, repeats = _subprogram_number(p, count, dialect)
        name = p.name if p is not None else None
        return BlockCall("M98" if wanted == 98.0 else "M198", w, i, p, number, name, _label(q), count, repeats)
    return None


def _macro_call(words: Sequence[Word], at: int, g: float, dialect: Dialect) -> BlockCall:
    """The G65 or G66 call (``g``) of ``words[at]``."""
    code = words[at]
    kind = "G65" if g == 65.0 else "G66"
    after = words[at + 1 :]
    p = next((w for w in after if w.letter == "P"), None)
    count = next((w for w in after if w.letter == "L"), None)
    if kind == "G65" and h_code_form(after, dialect):
        return BlockCall(kind, code, at, p, arithmetic=True)
    number = None
    if p is not None and p.value.__class__ is Number:
        try:
            number = macro_program_number(p.value.value, dialect)
        except MacroAlarm:
            number = None
    args = tuple(w for w in after if w.letter not in ("P", "L"))
    name = p.name if p is not None else None
    return BlockCall(kind, code, at, p, number, name, count=count, repeats=_literal_count(count), arguments=args,
                     macro=True)  # fmt: skip


def h_code_form(after: Sequence[Word], dialect: Dialect) -> bool:
    """Whether ``G65`` followed by the words ``after`` is macro A's ``G65 Hm P Q R`` (arithmetic
    and branches, ``machine/hcodes.py``) rather than a macro call: on a dialect with ``h_codes``,
    the first of P and H after G65 decides. The GSK980TDi's manual has G65 followed at once by P or
    H (§3.28.3 note 3) and H an argument of a call, #11 (§3.28.3.1, specification I), so
    ``G65 P9013 H5`` calls O9013 with #11 = 5 and ``G65 H01 P#100 Q5`` assigns (docs/semantics.md §7)."""
    if not dialect.h_codes:
        return False
    for w in after:
        if w.letter == "P":
            return False
        if w.letter == "H":
            return True
    return False


def _subprogram_number(p: Word | None, count: Word | None, dialect: Dialect) -> tuple[int | None, int | None]:
    """(program, count) of ``M98 P`` with a literal P (and L), as ``program_and_count`` reads them."""
    if p is None or p.value.__class__ is not Number:
        return None, _literal_count(count)
    l_value = count.value.value if count is not None and count.value.__class__ is Number else None
    try:
        return program_and_count(p.value.text, p.value.value, l_value, dialect, [])
    except MacroAlarm:
        try:
            return program_and_count(p.value.text, p.value.value, None, dialect, [])[0], None
        except MacroAlarm:
            return None, None


def _literal_count(count: Word | None) -> int | None:
    if count is None:
        return 1
    v = count.value
    if v.__class__ is not Number:
        return None
    n = to_int(v.value)
    return n if 1 <= n <= MAX_REPEAT else None


def _label(w: Word | None) -> int | None:
    if w is None or w.value.__class__ is not Number:
        return None
    x = w.value.value
    return int(round_half_away(x)) if abs(x) < 1e9 else None


def last_word(words: Sequence[Word], letter: str) -> Word | None:
    """The last word of ``letter`` in ``words`` (the one a control takes when a letter is written twice)."""
    found = None
    for w in words:
        if w.letter == letter:
            found = w
    return found


def _same_code(w: Word, code: str, value: Callable[[Word], float | None]) -> bool:
    if w.letter not in ("G", "M"):
        return False
    x = value(w)
    return x is not None and f"{w.letter}{x:g}" == code


def call_words(dialect: Dialect, calls: Mapping[str, object] | None = None) -> tuple[WordSet, ...]:
    """The words ``recognise_call`` looks at (``word_sets.py``): G65 and G66, M98, M198 and the
    dialect's local call code, and the G and M codes the machine file's ``[calls]`` makes calls
    (``T`` alone: every T word)."""
    local = dialect.local_subprogram_code
    ms = {*SUBPROGRAM_CALLS, *((local,) if local is not None else ())}
    out = [WordSet("G", frozenset(MACRO_CALLS)), WordSet("M", frozenset(ms))]
    for code in calls or ():
        letter, digits = code[:1], code[1:]
        if code == "T":
            out.append(WordSet("T"))
        elif letter in ("G", "M") and digits:
            try:
                out.append(WordSet(letter, frozenset((float(digits),))))
            except ValueError:
                continue
    return tuple(out)


def call_word_pattern(calls: Mapping[str, object], local: float | None = None) -> str:
    """A pattern for the words in a line of text that may make a call (``recognise_call``): G65,
    G66, M98, M198, the dialect's local call code and the machine file's call codes. A line
    without one calls nothing."""
    codes = "65|66|98|198" + (f"|{local:g}" if local is not None else "")
    parts = [rf"[GgMm][ \t]*\+?0*(?:{codes})(?![0-9])"]
    for code in calls:
        letter, digits = code[:1], code[1:]
        whole = digits.split(".")[0].lstrip("0") or "0"
        if not digits or not whole.isdigit():
            parts.append(f"[{letter.upper()}{letter.lower()}]")
        else:
            parts.append(rf"[{letter.upper()}{letter.lower()}][ \t]*\+?0*{re.escape(whole)}(?![0-9])")
    return "|".join(parts)
