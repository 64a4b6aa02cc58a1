"""Values the machine has and the folder does not: unknown, not vacant (docs/semantics.md §2,
"Unknown, not vacant").

A program reads values the control keeps from one day to the next: the commons kept at power-off
(#500–#999, the extended ranges), the tool and work offset tables, the tool loaded in the
spindle before the program commands a T; where a probe's G31 touched the part (#5061…, or the
commons a G31 writes on the GSK980TDi, #995…, unless the machine file's ``[skip]`` table models
it: ``touch_unknown``); the positions that add such an offset (#5021…, #5041…, #5081…:
``position_unknown``); and what the machine sends the program as it runs,
the interface input signals (FANUC #1000–#1015 and #1032, Haas #1000–#1063…: a probe switched
on, a pallet in place), which a program may read but never write. Offline, nothing says what they hold; taking them as
vacant or 0 makes a production program's ``#641=#640/#706`` a "division by zero" the control
never raises. So an analysis run (``check`` and the editor: ``Machine(kept_unknown=True)``)
reads each of them that neither the machine file's ``[variables]`` nor the persistent file
gives as **unknown**: NaN, which every arithmetic operation and function carries on (an unknown
divisor divides to unknown, no alarm). A macro checked without its caller gets unknown
arguments and unknown commons cleared at power-off (#100–#199), which its caller sets
(``Machine.unknown_from_caller``). Vacant stays vacant where the program itself could have set
the value: a main program's locals, arguments a caller did not pass, a main program's commons
cleared at power-on (#100–#199), but on a profile whose operator sets them before a run
(``Dialect.volatile_commons_set_before``, GSK980TDi).

Where the run must decide something with an unknown (a branch, an address word sent to the
NC, a variable, label or program number made from it) the control would use its value; the
run stops that path there with ``UnknownValue`` (planner/alarms.py), a note that names the
variable and how to give it, and the text after it is still checked, not faded as unreached;
where one side of a branch is nothing but the program's own macro alarm, the run follows the
other side instead, as the machine does in production (``guards.py``).
The motion takes an offset written from an unknown as 0 (``Machine.stored``). ``cncmacro run``
and the debugger, which simulate one machine, keep reading these values as vacant (0 for the
offsets).
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING

from ..dialects.tables import SKIP_POSITIONS
from ..planner.whereabouts import position_known

if TYPE_CHECKING:
    from collections.abc import Iterable

    from ..dialects import Dialect
    from ..dialects.tables import CommonRange
    from ..library.skip_model import SkipModel
    from ..planner.planner import Planner
    from .expressions import VariableKinds

UNKNOWN = math.nan
# the groups of stored system variables the machine keeps (dialects/tables.py): its offsets and its
# parts counters (#3901, #3902: the operator sets the count required on the setting screen)
KEPT_GROUPS = frozenset({"tool", "work", "counters"})
_NUMBER = re.compile(r"#\s*(\d+)")
_ASSIGNMENT = re.compile(r"\s*(?:N\d+\s*)?#\s*(\d+)\s*=(.*)", re.IGNORECASE)


def seed_unknowns(kinds: VariableKinds, commons: list[float | None]) -> None:
    """Make every kept common below #1000 that has no value unknown (``commons`` is
    ``Machine.C``, after the presets and the persistent file); the ones cleared at power-off
    too where the profile says the operator or an earlier run sets them
    (``Dialect.volatile_commons_set_before``)."""
    _unknown_where_vacant(kinds.ranges if kinds.dialect.volatile_commons_set_before else kinds.persistent, commons)


def seed_caller_commons(kinds: VariableKinds, commons: list[float | None]) -> None:
    """A macro or subprogram checked without its caller: make the commons cleared at power-off
    (#100–#199) that have no value unknown, as its arguments are. Its caller may set them before
    the call (``#101=6. M98 P1007``), as it passes arguments, and that caller is not here."""
    _unknown_where_vacant(kinds.volatile, commons)


def _unknown_where_vacant(ranges: Iterable[CommonRange], commons: list[float | None]) -> None:
    for r in ranges:
        first, end = r.first, min(r.last, 999) + 1
        if first < end:
            commons[first:end] = [UNKNOWN if v is None else v for v in commons[first:end]]


def kept_extended(kinds: VariableKinds, n: int) -> bool:
    """Whether extended common ``#n`` (#1000 up) is kept at power-off."""
    return any(r.first <= n <= r.last for r in kinds.persistent)


def kept_variables(text: str, kinds: VariableKinds, dialect: Dialect) -> list[int]:
    """The variables of a block's ``text`` whose value the machine keeps (the commons kept at
    power-off and the offsets), in order, each once."""
    return [n for n in variables_in(text) if is_kept(n, kinds, dialect)]


def variables_in(text: str) -> list[int]:
    """The ``#n`` of ``text`` with a literal number, in order, each once."""
    return list(dict.fromkeys(int(match.group(1)) for match in _NUMBER.finditer(text)))


def is_kept(n: int, kinds: VariableKinds, dialect: Dialect) -> bool:
    """Whether the machine keeps ``#n`` from one day to the next (module docstring)."""
    kind = kinds.kind(n)
    if kind == "persistent" or (kind == "extended" and kept_extended(kinds, n)):
        return True
    if kind == "common":  # cleared at power-off, set by the operator or an earlier run before this one
        return dialect.volatile_commons_set_before
    if kind == "system":
        row = dialect.system_variable(n)
        return row is not None and (row.group in KEPT_GROUPS or is_tool(n, dialect))
    return False


def is_input(n: int, dialect: Dialect) -> bool:
    """Whether system variable ``#n`` is an input signal the machine sends: a row of the
    ``signals`` group that a program cannot write (module docstring)."""
    row = dialect.system_variable(n)
    return row is not None and is_input_row(row.group, row.access)


def is_input_row(group: str, access: str) -> bool:
    """Whether a system-variable row of ``group`` and ``access`` is an input signal."""
    return group == "signals" and "w" not in access


def touch_unknown(kept_unknown: bool, skip: SkipModel) -> bool:
    """Whether where a G31 touched is unknown to a run: an analysis run (``kept_unknown``) whose
    machine file has no ``[skip]`` table to say where the probe touches. The skip position then
    reads unknown (#5061…), and a G31 leaves the commons it writes unknown (GSK #995…)."""
    return kept_unknown and not skip


def position_unknown(kept_unknown: bool, p: Planner, which: str, axis: int) -> bool:
    """Whether axis ``axis``'s position of a kind (a ``position`` row's ``which``: machine, current,
    tool offset…) is unknown to a run: an analysis run (``kept_unknown``) where the position adds
    an offset the folder does not give, or lies after a coordinate setting or a G30 at a place
    the folder does not know (planner/whereabouts.py, the rule the travel check follows too).
    ``cncmacro run`` reads them with the offsets it lacks as 0."""
    return kept_unknown and not position_known(p, which, axis)


def is_skip_position(n: int, dialect: Dialect) -> bool:
    """Whether ``#n`` holds where a G31 stopped: the skip position (FANUC #5061…), or a common
    in which the control stores it (``Dialect.skip_commons``: GSK #995…). The place the probe
    touched, which only the machine finds (the machine file's ``[skip]`` table models it)."""
    if any(number == n for _, number in dialect.skip_commons):
        return True
    row = dialect.system_variable(n)
    return row is not None and row.source == "position" and row.param in SKIP_POSITIONS


def is_tool(n: int, dialect: Dialect) -> bool:
    """Whether system variable ``#n`` reads the tool number (FANUC #4120, Haas #3026)."""
    row = dialect.system_variable(n)
    return row is not None and row.source == "code" and row.param == "T"


def assigned(text: str) -> tuple[int, str] | None:
    """``(n, the expression)`` of a block ``#n=expression`` with a literal ``n``, else None."""
    match = _ASSIGNMENT.match(text)
    return (int(match.group(1)), match.group(2)) if match else None
