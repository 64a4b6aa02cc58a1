"""Numbers as the control computes them (docs/semantics.md §3): FANUC rounding, never Python's.

``round_half_away`` is ROUND (2.5 -> 3, -2.5 -> -3); ``fix`` truncates toward zero and ``fup``
rounds away from zero. ``to_increment`` rounds an axis value to its least increment (0.001 mm,
0.0001 inch), deciding ties on the decimal value that was written, so that 1.0005 becomes
1.001 as on the control and not 1.000 as binary floating point would have it;
``increment_places`` says how many decimals an address's least input increment has (an angle's
0.001° in either unit) and ``in_least_increments`` reads a number written without a decimal
point as a count of them (the machine file's ``decimal_point = "increment"``). ``bcd`` and
``bin_`` convert between binary and binary-coded decimal. Every function raises
``MacroAlarm`` for a value the control would refuse.
"""

from __future__ import annotations

import math
from decimal import ROUND_HALF_UP, Decimal, InvalidOperation

from ..bilingual import detail, pick
from ..dialects.alarms import ARGUMENT_RANGE, MAX_VALUE, OVERFLOW
from ..dialects.describe import ROTARY_AXES
from .alarms import MacroAlarm, UnknownValue


def round_half_away(x: float) -> float:
    """Round to a whole number, halves away from zero (never banker's rounding). An unknown
    value (NaN) cannot be made whole: ``UnknownValue``."""
    if x != x:
        raise UnknownValue
    if x >= 0:
        f = math.floor(x)
        return float(f + 1 if x - f >= 0.5 else f)
    f = math.floor(-x)
    return -float(f + 1 if -x - f >= 0.5 else f)


def to_int(x: float) -> int:
    """The integer an integer address (M, S, T, H, D, P, L, N) receives."""
    if abs(x) > MAX_VALUE:  # an unknown (NaN) is not too large: round_half_away says so
        raise MacroAlarm(OVERFLOW, detail(f"value {x} is too large for an address", f"数值 {x} 超出地址的允许范围"))
    return int(round_half_away(x))


def fix(x: float) -> float:
    """FIX: toward zero (FIX[-1.7] = -1)."""
    return float(math.trunc(x))


def fup(x: float) -> float:
    """FUP: away from zero (FUP[-1.2] = -2, FUP[1.2] = 2)."""
    return float(math.ceil(x)) if x >= 0 else float(math.floor(x))


# the addresses whose value is a length or an angle, counted in least input increments when written
# without a decimal point on a control without calculator-type input (docs/semantics.md §3, §5)
INCREMENT_LETTERS = frozenset("XYZUVWABCIJKRQ")
# the angles among them: 0.001° in either unit (Haas 96-8000, "Notes on Functions": "For metric and
# angle dimensions, three-place precision is the default. For inch, four-place precision")
ANGLE_LETTERS = ROTARY_AXES


def increment_places(letter: str, inch: bool) -> int:
    """The decimals of address ``letter``'s least input increment: 0.001 mm and 0.001°, 0.0001
    inch for a length under G20."""
    return 4 if inch and letter not in ANGLE_LETTERS else 3


def in_least_increments(letter: str, value: float, inch: bool) -> float:
    """``value``, written without a decimal point in address ``letter``, read as least input
    increments (X10 is 0.010 mm, 0.0010 inch under G20); a letter that is no length or angle
    (D, E, F, H, M, S, T) keeps its value."""
    if letter not in INCREMENT_LETTERS:
        return value
    return value / _SCALE[increment_places(letter, inch)]


def to_increment(x: float, places: int = 3) -> float:
    """Round ``x`` to ``places`` decimals, halves away from zero, judged on its shortest
    decimal form (what was written or computed, as the control sees it). An unknown value
    (NaN) has no increment: ``UnknownValue``."""
    if x != x:
        raise UnknownValue
    scaled = x * _SCALE[places]
    f = math.floor(scaled)
    frac = scaled - f
    if abs(frac - 0.5) > 1e-6:  # not near a tie: binary arithmetic decides correctly
        return (f + 1 if frac > 0.5 else f) / _SCALE[places]
    try:
        d = Decimal(repr(x)).quantize(_QUANT[places], rounding=ROUND_HALF_UP)
    except InvalidOperation:
        raise MacroAlarm(OVERFLOW, detail(f"value {x} is out of range", f"数值 {x} 超出范围")) from None
    return float(d)


_SCALE = {1: 10.0, 3: 1000.0, 4: 10000.0}
_QUANT = {1: Decimal("0.1"), 3: Decimal("0.001"), 4: Decimal("0.0001")}


def bcd(x: float) -> float:
    """BCD[x]: a binary number to binary-coded decimal (BCD[25] = 37, i.e. 0x25)."""
    n = to_int(x)
    if n < 0:
        raise MacroAlarm(ARGUMENT_RANGE, detail(f"BCD of a negative number ({n})", f"BCD 的自变量为负数（{n}）"))
    return float(int(str(n), 16))


def bin_(x: float) -> float:
    """BIN[x]: binary-coded decimal to binary (BIN[37] = 25); a digit above 9 is alarm 119."""
    n = to_int(x)
    if n < 0:
        raise MacroAlarm(ARGUMENT_RANGE, detail(f"BIN of a negative number ({n})", f"BIN 的自变量为负数（{n}）"))
    digits = f"{n:x}"
    if not digits.isdigit():
        raise MacroAlarm(
            ARGUMENT_RANGE,
            detail(f"BIN[{n}]: {n} is not binary-coded decimal", f"BIN[{n}]：{n} 不是 BCD 码"),
        )
    return float(int(digits))


def format_value(x: float | None, digits: int | None, decimals: int | None, whole_part: bool = False) -> str:
    """How DPRNT prints ``#i[ab]``: ``a`` digits before the point and ``b`` after it,
    rounded; vacant prints as 0, unknown (NaN) as ``?``. Without a format the value prints as
    the control shows it. With ``whole_part`` (``Dialect.dprnt_whole_part``) the whole part is
    printed in full, at least one digit however few ``a`` reserves, and ``[a0]`` prints it
    without the fraction (Haas: 1.5436 as ``[40]`` is 1)."""
    v = 0.0 if x is None else x
    if v != v:
        return "?"
    if digits is None:
        return format_plain(v)
    b = decimals or 0
    text = str(int(abs(v))) if whole_part and not b else f"{abs(v):.{b}f}"
    whole, _, frac = text.partition(".")
    if not whole_part:
        whole = whole[-digits:] if digits > 0 else ""
    sign = "-" if v < 0 and float(text) != 0 else ""
    return f"{sign}{whole or '0'}" + (f".{frac}" if b else "")


def format_plain(v: float | None) -> str:
    """A value for people: vacant, a whole number without point, or up to 6 decimals."""
    if v is None:
        return "<vacant>"
    if v != v:
        return "<unknown>"
    if v == int(v) and abs(v) < 1e15:
        return str(int(v))
    text = f"{v:.6f}".rstrip("0").rstrip(".")
    return text if text not in ("-0", "") else "0"


def shown_value(v: float | None, locale: str | None) -> str:
    """A value as the debugger shows it (the Variables view, watch, hover, console and log
    points): ``format_plain``, vacant as ``<vacant>`` (``<空>`` in a Chinese locale)."""
    return pick(locale, "<vacant>", "<空>") if v is None else format_plain(v)
