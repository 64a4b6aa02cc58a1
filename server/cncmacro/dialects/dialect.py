"""A dialect as one object: its switches (docs/semantics.md's per-dialect rules) and its tables.

The interpreter never asks "is this gsk?"; it reads a switch or a table from here. Adding a
dialect means adding a data module and one ``Dialect`` value, not a code path.
"""

from __future__ import annotations

import importlib
from bisect import bisect_right
from dataclasses import dataclass, field
from functools import cache

from .tables import CodeDoc, FunctionDoc, SystemVariable

# G65 argument specification I (docs/semantics.md §5): letter -> local variable number.
ARGUMENTS_I = {
    "A": 1, "B": 2, "C": 3, "I": 4, "J": 5, "K": 6, "D": 7, "E": 8, "F": 9, "H": 11, "M": 13,
    "Q": 17, "R": 18, "S": 19, "T": 20, "U": 21, "V": 22, "W": 23, "X": 24, "Y": 25, "Z": 26,
}  # fmt: skip


@dataclass(frozen=True)
class Dialect:
    """Everything that differs between controls. Field names say what each switch decides."""

    name: str
    title: str
    data_module: str
    # §2 vacant: fanuc tells vacant from 0 in EQ/NE; gsk980tdi treats vacant as 0 everywhere
    vacant_differs_in_eq: bool
    # §2 addresses: a vacant address value drops the word (fanuc) or is 0 (gsk980tdi)
    vacant_address_is_zero: bool
    # §2 #9 followed by a common variable number is indirection (gsk980tdi)
    nine_indirection: bool
    # §3 C-style relations == != < > <= >=
    c_relations: bool
    # §6 #3000=n raises alarm base+n
    macro_alarm_base: int
    # §7 G65 Hm P Q R arithmetic and branches
    h_codes: bool
    # §5 bracketed program names P[CUT]
    bracket_names: bool
    # §5 digits allowed in P for a program number
    program_digits: int
    # §5 nesting
    macro_levels: int
    subprogram_levels: int
    # §5 L above 9999 is clamped (True) or an error (False)
    clamp_repeat_count: bool
    # §5 a count in P together with L is alarm 293
    count_in_p_and_l_alarm: bool
    # §8 a lathe: X is a diameter and U, V, W, H are incremental X, Y, Z, C
    lathe: bool
    # the axes in system-variable order (#5001 is the first)
    axes: tuple[str, ...]
    # motion codes after which a G66 modal call is made
    modal_call_codes: frozenset[float]
    # the modal state at power-on (MODAL_GROUPS names -> G code)
    modal_defaults: dict[str, float] = field(default_factory=dict)
    # which G code sets the coordinate system (G92 on a mill, G50 on this lathe)
    coordinate_setting_code: float = 92.0
    # which G codes are canned cycles that leave the tool where it started
    cycle_codes: frozenset[float] = frozenset()
    # §5 fanuc wants I, J, K in that order within each set (a warning otherwise)
    ijk_order_matters: bool = False
    # §8 the G-code table lists every code of the control and its alarms for a refused word are
    # known: a G code outside the table and the machine's call codes is alarm 010, a decimal point
    # in an M code alarm 007; without this switch both are warnings and a run goes on
    word_format_alarms: bool = False
    # §1 the first two or more letters of a macro word stand for the word (WH for WHILE)
    keyword_abbreviations: bool = False
    # §4 IF [cond] <statement> without THEN runs the statement (Haas); elsewhere alarm 114
    if_without_then: bool = False

    @property
    def incremental_letters(self) -> dict[str, str]:
        """On a lathe, U V W H move X Y Z C incrementally."""
        if not self.lathe:
            return {}
        return {"U": "X", "V": "Y", "W": "Z", "H": "C"}

    def system_variables(self) -> tuple[SystemVariable, ...]:
        return _tables(self.data_module)[0]

    def system_variable(self, number: int) -> SystemVariable | None:
        """The table row that describes ``#number``, or None when it does not exist."""
        rows, firsts = _tables(self.data_module)[:2]
        k = bisect_right(firsts, number) - 1
        if k >= 0 and number <= rows[k].last:
            return rows[k]
        return None

    def g_codes(self) -> tuple[CodeDoc, ...]:
        return _tables(self.data_module)[2]

    def m_codes(self) -> tuple[CodeDoc, ...]:
        return _tables(self.data_module)[3]

    def functions(self) -> tuple[FunctionDoc, ...]:
        return _functions()


@cache
def _tables(module: str) -> tuple[tuple[SystemVariable, ...], list[int], tuple[CodeDoc, ...], tuple[CodeDoc, ...]]:
    mod = importlib.import_module(f"{__package__}.{module}")
    rows = tuple(sorted(mod.SYSTEM_VARIABLES, key=lambda r: r.first))
    return rows, [r.first for r in rows], tuple(mod.G_CODES), tuple(mod.M_CODES)


@cache
def _functions() -> tuple[FunctionDoc, ...]:
    mod = importlib.import_module(f"{__package__}.functions_data")
    return tuple(mod.FUNCTIONS)


FANUC = Dialect(
    name="fanuc",
    title="FANUC 0i Custom Macro B",
    data_module="fanuc_data",
    vacant_differs_in_eq=True,
    vacant_address_is_zero=False,
    nine_indirection=False,
    c_relations=False,
    macro_alarm_base=3000,
    h_codes=False,
    bracket_names=False,
    program_digits=8,
    macro_levels=4,
    subprogram_levels=10,
    clamp_repeat_count=False,
    count_in_p_and_l_alarm=False,
    lathe=False,
    axes=("X", "Y", "Z", "A"),
    modal_call_codes=frozenset({0.0, 1.0, 2.0, 3.0}),
    modal_defaults={"plane": 17.0, "feed": 94.0},
    coordinate_setting_code=92.0,
    cycle_codes=frozenset({73.0, 74.0, 76.0, 81.0, 82.0, 83.0, 84.0, 85.0, 86.0, 87.0, 88.0, 89.0}),
    ijk_order_matters=True,
    word_format_alarms=True,
    keyword_abbreviations=True,
)

GSK980TDI = Dialect(
    name="gsk980tdi",
    title="GSK980TDi",
    data_module="gsk980tdi_data",
    vacant_differs_in_eq=False,
    vacant_address_is_zero=True,
    nine_indirection=True,
    c_relations=True,
    macro_alarm_base=5900,
    h_codes=True,
    bracket_names=True,
    program_digits=4,
    macro_levels=4,
    subprogram_levels=12,
    clamp_repeat_count=True,
    count_in_p_and_l_alarm=True,
    lathe=True,
    axes=("X", "Y", "Z", "C", "B"),
    modal_call_codes=frozenset({0.0, 1.0, 2.0, 3.0, 5.0}),
    modal_defaults={"plane": 18.0, "feed": 98.0},
    coordinate_setting_code=50.0,
    cycle_codes=frozenset({70.0, 71.0, 72.0, 73.0, 74.0, 75.0, 76.0, 90.0, 92.0, 94.0, 83.0, 84.0, 87.0, 88.0}),
)

BY_NAME = {d.name: d for d in (FANUC, GSK980TDI)}
