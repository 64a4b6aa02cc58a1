"""FANUC 30i-B lathe data (G-code system A): the tables of ``fanuc-30i`` when the machine file
says ``lathe = true`` (the profile's ``lathe_variant``; docs/profiles.md, "fanuc-30i lathes").

The 30i's rows where a lathe reads a number the same way (signals, constants, timers, positions
and the many-axis position numbers, work offsets, names), and the lathe's own where it differs,
as ``fanuc_lathe_data`` has them for the 0i-TF: the tool offsets at #10001… (999 of each kind)
with #2001… the short numbers of offsets 1-64, the modal groups of system A (#4001…, and #4201…
for the block being executed), the T code with its offset number, the offset in effect (#5081…).
The 30i mill's other numbers for G54.1 P1-P48 at #14001… are not a lathe's: there #14001… are
Y wear offsets. The G and M codes are the 0i-TF lathe's.
"""

from __future__ import annotations

from dataclasses import replace

from . import fanuc_lathe_data as lathe
from . import shared_data as shared
from .profiles import fanuc_30i as mill
from .tables import CodeDoc, SystemVariable, SystemVariableName

_EXECUTING = mill.EXECUTING


def _executing(row: SystemVariable) -> SystemVariable:
    """A modal row of the previous block as the block being executed reads it (#4201 for #4001)."""
    return replace(row, first=row.first + _EXECUTING, last=row.last + _EXECUTING,
                   en=f"{row.en}; of the block being executed", zh=f"{row.zh}；正在执行的程序段的")  # fmt: skip


_LETTERS = tuple(sorted((*shared.CODE_LETTERS, *lathe.LATHE_CODE_LETTERS)))
_PREVIOUS: tuple[SystemVariable, ...] = (
    *(lathe.modal_row(group) for group in range(1, mill.GROUPS + 1)),
    *shared.code_letter_rows(_LETTERS),
)


def _mill_only(row: SystemVariable) -> bool:
    """A 30i mill row a lathe reads otherwise: the 0i's (``fanuc_lathe_data.mill_only``), the
    executing block's modal rows, and the #14001… numbers of G54.1 (Y wear on a lathe)."""
    return (lathe.mill_only(row) and row.first != 4000) or (4201 <= row.first <= 4399) or 14001 <= row.first <= 19999


SYSTEM_VARIABLES: tuple[SystemVariable, ...] = (
    *(row for row in mill.SYSTEM_VARIABLES if not _mill_only(row)),
    *lathe.tool_offset_rows(999),
    *_PREVIOUS,
    *(_executing(row) for row in _PREVIOUS),
    lathe.TOOL_OFFSET_IN_EFFECT,
)


def _kept(name: SystemVariableName) -> bool:
    """A 30i name a lathe keeps: not the H and D offsets' (their numbers are X, Z, radius and tip
    offsets here), and only where a row of the lathe's has its numbers (no D or H code letter)."""
    if 10001 <= name.first <= 13999:
        return False
    return all(any(row.first <= n <= row.last for row in SYSTEM_VARIABLES) for n in (name.first, name.last))


SYSTEM_VARIABLE_NAMES: tuple[SystemVariableName, ...] = tuple(filter(_kept, mill.SYSTEM_VARIABLE_NAMES))

G_CODES: tuple[CodeDoc, ...] = lathe.G_CODES
M_CODES: tuple[CodeDoc, ...] = mill.M_CODES
