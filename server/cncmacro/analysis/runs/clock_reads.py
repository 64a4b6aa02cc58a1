"""Whether a program file may read the simulated clock.

A run that resumes after an edit takes the rest of the run before the edit over once their
states are equal (``run_convergence.py``); where a file may read the clock (a timer, the date
or the time, or any variable through indirection), the clock has to be equal too. Whether it
may is told from the text alone, generously: ``#[`` (indirection), a clock variable of any
profile by number or by its 30i name, or a GSK ``#9xxx`` (indirection through a common); a
comment that mentions one counts too. An open document counts its places once and keeps the
count across edits (``workspace_documents.py``); a file on disk is looked at once per load
(``DiskClockReads``).
"""

from __future__ import annotations

import re

from ...dialects import DIALECTS, get_dialect
from ...library.programs import LoadedFile

_CLOCK_NUMBERS = sorted({
    str(n) for name in DIALECTS for row in get_dialect(name).system_variables()
    if row.source in ("timer", "date", "time") for n in range(row.first, row.last + 1)
})  # fmt: skip
_CLOCK_NAMES = sorted({
    v.name for name in DIALECTS for v in get_dialect(name).system_variable_names()
    if any(str(n) in _CLOCK_NUMBERS for n in range(v.first, v.last + 1))
})  # fmt: skip
# a read of the clock: ``#[``, a clock variable (by number or 30i name), or a GSK ``#9xxx``
# (indirection through a common)
_CLOCK_READ = re.compile(
    r"#[ \t]*(?:\[|0*(?:" + "|".join(_CLOCK_NUMBERS) + r"|9\d{3})(?!\d)|_(?:" + "|".join(_CLOCK_NAMES) + r")(?!\w))",
    re.I,
)


def clock_reads(lines: list[str]) -> int:
    """How many places of ``lines`` may read the clock."""
    return len(_CLOCK_READ.findall("\n".join(lines)))


class DiskClockReads:
    """Whether each file on disk may read the clock, kept until the file is loaded again."""

    __slots__ = ("_seen",)

    def __init__(self) -> None:
        self._seen: dict[str, tuple[LoadedFile, bool]] = {}

    def reads(self, path: str, loaded: LoadedFile) -> bool:
        """Whether ``loaded``, the file at ``path`` as it was read last, may read the clock."""
        cached = self._seen.get(path)
        if cached is None or cached[0] is not loaded:
            cached = self._seen[path] = (loaded, clock_reads(loaded.lines) > 0)
        return cached[1]
