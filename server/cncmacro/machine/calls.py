"""What the call words mean (docs/semantics.md §5): G65/G66 arguments, P and L, M98 counts.

``map_arguments`` applies argument specifications I and II word by word, left to right, a
later word winning on a shared variable; ``program_and_count`` splits ``M98 P30040`` into
program 40 and count 3; ``repeat_count`` checks L. They take evaluated words and return plain
values, raising ``MacroAlarm`` for what the control refuses; the machine does the calling.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

from ..bilingual import detail
from ..dialects.alarms import ARGUMENT_RANGE, COUNT_TWICE, G_ARGUMENT, P_VALUE_RANGE
from ..dialects.dialect import ARGUMENTS_I, Dialect
from .alarms import MacroAlarm
from .numbers import to_int

NOT_ARGUMENTS = frozenset("GLNOP")
MAX_REPEAT = 9999
_G_GROUPS: dict[str, dict[float, str]] = {}


def g_code_groups(dialect: Dialect) -> dict[float, str]:
    """G code -> the name of its modal group in the dialect's code table (one-shot codes are
    absent): what a G word in a block sets."""
    groups = _G_GROUPS.get(dialect.data_module)
    if groups is None:
        groups = {}
        for doc in dialect.g_codes():
            try:
                code = float(doc.code[1:])
            except ValueError:
                continue
            if doc.group:
                groups[code] = doc.group
        _G_GROUPS[dialect.data_module] = groups
    return groups


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
    count_in_p = 0
    program = n
    if len(digits) > k:
        program = int(digits[-k:])
        count_in_p = int(digits[:-k])
    if count_in_p and l_value is not None:
        if dialect.count_in_p_and_l_alarm:
            raise MacroAlarm(
                COUNT_TWICE,
                detail(
                    f"P{digits} L{to_int(l_value)}: the count is given in both P and L",
                    f"P{digits} L{to_int(l_value)}：P 和 L 同时指定了调用次数",
                ),
            )
        notes.append(detail("the count is given in both P and L; L is used", "P 和 L 同时指定了调用次数，按 L 执行"))
    if l_value is not None:
        return program, repeat_count(l_value, dialect, notes)
    return program, max(1, count_in_p) if len(digits) > k else 1


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
