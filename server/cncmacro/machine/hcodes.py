"""GSK980TDi macro A: ``G65 Hm P#i Q#j R#k`` (docs/semantics.md §7, seed 000 §3.28.2).

P names the destination variable (for H80–H86 and H99 a sequence number or alarm number);
Q and R are variables or constants, and ``Q-#102`` negates. The table of operations is
docs/semantics.md's; vacant counts as 0 in an operation, as everywhere on this control, and
``H01``, the assignment, copies a vacant Q as ``#i=#j`` does. Compiled once per block,
like every other block.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ..bilingual import detail
from ..dialects.alarms import ARGUMENT_RANGE, DIVISION_BY_ZERO, FORMAT
from ..planner.alarms import UnknownValue
from ..planner.numbers import bcd, bin_, round_half_away
from ..syntax.nodes import Block, IndirectVar, Number, Var, Word
from .alarms import MacroAlarm, macro_alarm_number, raiser
from .guards import Passed

if TYPE_CHECKING:
    from .blocks import CompiledFile, Runner
    from .machine import Machine


def _div(j: float, k: float) -> float:
    if k == 0:
        raise MacroAlarm(DIVISION_BY_ZERO, detail("G65 H05: division by zero (R is 0)", "G65 H05：除数为零（R 为 0）"))
    return j / k


def _rem(j: float, k: float) -> float:
    if k == 0:
        raise MacroAlarm(
            DIVISION_BY_ZERO,
            detail("G65 H23: remainder of a division by zero (R is 0)", "G65 H23：求余的除数为零（R 为 0）"),
        )
    return j - math.trunc(j / k) * k


def _sqrt(j: float, k: float) -> float:
    if j < 0:
        raise MacroAlarm(
            ARGUMENT_RANGE,
            detail(f"G65 H21: square root of a negative number ({j:g})", f"G65 H21：负数不能开平方（{j:g}）"),
        )
    return math.sqrt(j)


def _atan(j: float, k: float) -> float:
    if j == 0 and k == 0:
        raise MacroAlarm(ARGUMENT_RANGE, detail("G65 H34: the angle of 0/0", "G65 H34：0/0 无法求出角度"))
    r = math.degrees(math.atan2(j, k))
    return r + 360.0 if r < 0 else r


def _int(x: float) -> int:
    return int(round_half_away(x))


ARITHMETIC: dict[int, Callable[[float, float], float]] = {
    1: lambda j, k: j,
    2: lambda j, k: j + k,
    3: lambda j, k: j - k,
    4: lambda j, k: j * k,
    5: _div,
    11: lambda j, k: float(_int(j) | _int(k)),
    12: lambda j, k: float(_int(j) & _int(k)),
    13: lambda j, k: float(_int(j) ^ _int(k)),
    21: _sqrt,
    22: lambda j, k: abs(j),
    23: _rem,
    24: lambda j, k: bin_(j),
    25: lambda j, k: bcd(j),
    27: lambda j, k: math.hypot(j, k),
    31: lambda j, k: j * math.sin(math.radians(k)),
    32: lambda j, k: j * math.cos(math.radians(k)),
    33: lambda j, k: j * math.tan(math.radians(k)),
    34: _atan,
}

BRANCHES: dict[int, Callable[[float, float], bool]] = {
    80: lambda j, k: True,
    81: lambda j, k: j == k,
    82: lambda j, k: j != k,
    83: lambda j, k: j > k,
    84: lambda j, k: j < k,
    85: lambda j, k: j >= k,
    86: lambda j, k: j <= k,
}


def compile_h_code(cf: CompiledFile, words: list[Word], nxt: int, block: Block | None = None) -> Runner:
    """The closure for ``G65 Hm P.. Q.. R..`` (``words`` are those after G65, ``block`` the
    whole block, whose comment after ``H99 Pn`` is the alarm's text)."""
    by_letter = {w.letter: w for w in words}
    extra = [w.letter for w in words if w.letter not in "HPQR"]
    if extra:
        return raiser(
            FORMAT,
            detail(
                f"G65 H takes only P, Q and R (found {', '.join(extra)})",
                f"G65 H 只能指定 P、Q 和 R（多余的地址：{', '.join(extra)}）",
            ),
        )
    h_word = by_letter["H"]
    if not isinstance(h_word.value, Number):
        return raiser(
            FORMAT,
            detail("G65 H needs a literal operation number such as H01", "G65 H 需要直接写出运算号，例如 H01"),
        )
    h = int(h_word.value.value)
    q = _operand(cf, by_letter.get("Q"))
    r = _operand(cf, by_letter.get("R"))
    p_word = by_letter.get("P")
    if p_word is None or p_word.value is None:
        return raiser(FORMAT, detail(f"G65 H{h:02d} needs P", f"G65 H{h:02d} 需要 P"))
    if h in BRANCHES or h == 99:
        target = cf.values.value(p_word.value)
        if h == 99:
            dialect = cf.machine.dialect
            text = h99_message(block.comment_after(p_word.end)) if block is not None else None

            def alarm(m: Machine, pc: int) -> int:
                n = _int(target(m) or 0.0)
                number = macro_alarm_number(n, dialect, f"G65 H99 P{n}")
                raise MacroAlarm(
                    number,
                    text or detail(f"G65 H99 P{n}: user alarm {number}", f"G65 H99 P{n}：用户报警 {number}"),
                )

            return alarm
        test = BRANCHES[h]
        jump = cf.jump
        passed = Passed() if cf.machine.kept_unknown else None

        def branch(m: Machine, pc: int) -> int:
            j, k = q(m), r(m)
            if j != j or k != k:  # a branch on an unknown (unknown_values.py)
                if passed is None:
                    raise UnknownValue
                # the program's own guard: the side that does not alarm (guards.py)
                taken = cf.guard_jump(m, pc, nxt, target, passed)
            else:
                taken = test(j, k)
            if taken:
                return jump(m.frame, pc, target(m))
            return nxt

        return branch
    destination = p_word.value
    if not isinstance(destination, (Var, IndirectVar)):
        return raiser(
            FORMAT,
            detail(
                f"G65 H{h:02d}: P names the result variable, e.g. P#100",
                f"G65 H{h:02d}：P 指定存放结果的变量，例如 P#100",
            ),
        )
    if isinstance(destination, Var):
        n = float(destination.number)
        where: Callable[[Any], float | None] = lambda m: n  # noqa: E731
    else:
        where = cf.values.value(destination.index)
    if h == 26:
        dest_value = cf.values.value(destination)

        def scale(m: Machine, pc: int) -> int:
            k = r(m)
            if k == 0:
                raise MacroAlarm(
                    DIVISION_BY_ZERO,
                    detail("G65 H26: division by zero (R is 0)", "G65 H26：除数为零（R 为 0）"),
                )
            m.write(where(m), (dest_value(m) or 0.0) * q(m) / k)
            return nxt

        return scale
    if h == 1:
        copied = _copied(cf, by_letter.get("Q"))

        def assign(m: Machine, pc: int) -> int:
            m.write(where(m), copied(m))
            return nxt

        return assign
    op = ARITHMETIC.get(h)
    if op is None:
        return raiser(
            FORMAT,
            detail(f"G65 H{h:02d} is not an operation of this control", f"G65 H{h:02d} 不是本系统的运算命令"),
        )

    def arithmetic(m: Machine, pc: int) -> int:
        j, k = q(m), r(m)
        m.write(where(m), math.nan if j != j or k != k else op(j, k))  # unknown in, unknown out
        return nxt

    return arithmetic


def h99_message(comment: str | None) -> str | None:
    """The alarm text of ``G65 H99 Pn(/text)``: the comment after P without its leading ``/``
    (seed 000 §3.28.2 writes ``P15(/用户自定义报警)``, whose text is 用户自定义报警); None when
    there is none, and then the alarm has no text of its own, as the seed's note 1 says."""
    if comment is None:
        return None
    text = comment.strip()
    if text.startswith("/"):
        text = text[1:].strip()
    return text or None


def _copied(cf: CompiledFile, w: Word | None) -> Callable[[Any], float | None]:
    """The value ``G65 H01 P#i Q#j`` assigns: ``#j`` as it is, vacant included, as ``#i=#j`` copies
    it (seed 000 §3.28.1, "除用<空变量>赋值以外，其余所有情况下的用于运算的<空变量>与“0”相同": only an
    assignment keeps vacant); ``Q-#j`` is an operation (-0), and no Q assigns 0."""
    if w is None or w.value is None:
        return lambda m: 0.0
    return cf.values.value(w.value)


def _operand(cf: CompiledFile, w: Word | None) -> Callable[[Any], float]:
    if w is None or w.value is None:
        return lambda m: 0.0
    get = cf.values.value(w.value)
    return lambda m: get(m) or 0.0
