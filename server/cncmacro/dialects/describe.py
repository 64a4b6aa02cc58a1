"""What a dialect's tables say about one thing, ready to show a person.

The tables (``fanuc_data``, ``gsk980tdi_data``, ``functions_data``) hold rows that may cover a
range of numbers with ``{axis}`` and ``{index}`` in their text; the functions here pick the row
for one variable number, G/M code or function name and fill those in, in English or Chinese.
The class of a variable (local, common, persistent, system) follows docs/semantics.md §2 with the
common range a machine setting. Nothing here runs a program.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..bilingual import pick
from .dialect import Dialect
from .tables import CodeDoc, FunctionDoc

LOCAL = "local"
COMMON = "common"
PERSISTENT = "persistent"
SYSTEM = "system"
NULL = "null"
UNDEFINED = "undefined"

# The axis letters that turn (ISO 841: A, B, C about X, Y, Z): a position or offset of such an axis
# is in degrees, whatever unit the program's lengths are in.
ROTARY_AXES = frozenset("ABC")
LENGTH = "mm"  # a row's unit for a length: the program's input unit, mm under G21, inch under G20
DEGREES = "deg"


def variable_class(number: int, dialect: Dialect) -> str:
    """``local`` (#1–#33), ``common`` (a volatile common range of the profile as the machine has
    it), ``persistent`` (a kept one, #500–#999), ``system`` (#1000 and above), ``null`` (#0) or
    ``undefined`` (any other number)."""
    if number == 0:
        return NULL
    if 1 <= number <= 33:
        return LOCAL
    common = dialect.common_range_of(number)
    if common is not None:
        return PERSISTENT if common.persistent else COMMON
    if number >= 1000:
        return SYSTEM
    return UNDEFINED


def axis_name(dialect: Dialect, k: int) -> str:
    """The k-th axis (0-based) of the dialect, as the tables' ``{axis}`` means it."""
    if k < len(dialect.axes):
        return dialect.axes[k]
    return f"{k + 1}th"


@dataclass(frozen=True, slots=True)
class VariableDoc:
    """A system variable described for one number: ``text`` in the chosen language, its
    ``unit`` (``deg`` for a length row read on a rotary axis; ``unit_text`` shows it),
    ``access`` (``r``, ``w``, ``rw``), ``axis`` (None when the row has none) and the row's
    ``group``."""

    number: int
    text: str
    unit: str
    access: str
    axis: str | None
    group: str
    first: int
    last: int


def describe_system_variable(dialect: Dialect, number: int, locale: str | None = None) -> VariableDoc | None:
    """The description of system variable ``#number``, or None when the dialect has none."""
    row = dialect.system_variable(number)
    if row is None:
        return None
    k = number - row.first
    template = pick(locale, row.en, row.zh)
    axis = axis_name(dialect, k) if "{axis}" in row.en else None
    text = template.replace("{axis}", axis or "").replace("{index}", str(k + 1))
    if "{diameter}" in text:  # a lathe's X value is a diameter: said on the X axis's row only
        text = text.replace("{diameter}", pick(locale, " (on the diameter)", "（直径值）") if axis == "X" else "")
    unit = DEGREES if row.unit == LENGTH and axis in ROTARY_AXES else row.unit
    return VariableDoc(number, text, unit, row.access, axis, row.group, row.first, row.last)


def unit_text(unit: str, inch: bool | None, locale: str | None = None) -> str:
    """A variable's ``unit`` as a person reads it: a length in the unit in force (``inch`` True
    under G20, False under G21, None when it is not known: then both), an angle in degrees."""
    if unit == DEGREES:
        return pick(locale, "degrees", "度")
    if unit != LENGTH:
        return unit
    if inch is None:
        return pick(locale, "mm (inch under G20)", "mm（G20 下为英寸）")
    return pick(locale, "inch", "英寸") if inch else LENGTH


def code_key(letter: str, value: float) -> str:
    """How the tables spell a code: ``G01``, ``G54.1``, ``M98``."""
    if value == int(value):
        return f"{letter}{int(value):02d}"
    return f"{letter}{int(value):02d}.{round((value - int(value)) * 10)}"


def code_doc(dialect: Dialect, letter: str, value: float) -> CodeDoc | None:
    """The table row of the G or M code ``letter``+``value``, if the dialect has it."""
    letter = letter.upper()
    if letter not in ("G", "M"):
        return None
    key = code_key(letter, value)
    for doc in dialect.g_codes() if letter == "G" else dialect.m_codes():
        if doc.code == key:
            return doc
    return None


def function_docs(dialect: Dialect, name: str) -> list[FunctionDoc]:
    """Every documented form of a function, operator or statement keyword (``ATAN`` has two)."""
    name = name.upper()
    return [f for f in dialect.functions() if f.name == name]
