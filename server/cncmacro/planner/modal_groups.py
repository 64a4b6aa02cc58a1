"""Which modal group each G code sets, from the profile's code table (docs/semantics.md §8).

``g_code_groups`` reads the group of every G code of the profile's table once (one-shot codes
are absent); ``extra_offset_codes`` names the codes that select an extra work offset by the
profile's switches (Haas ``G154``, ``G110``–``G129``), which set the work offset group whatever
the table says. The planner keeps the modal state by these; the macro machine asks them which G
codes a call's block may set first.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..dialects import Dialect

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


def extra_offset_codes(dialect: Dialect) -> frozenset[float]:
    """The G codes that select an extra work offset by the dialect's switches (Haas ``G154``
    and ``G110``–``G129``): codes of the control whether or not its table lists them."""
    code = dialect.extra_offset_code
    return frozenset(dialect.extra_offset_aliases if code is None else (code, *dialect.extra_offset_aliases))
