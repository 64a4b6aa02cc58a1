"""The profile as one machine has it: a built-in profile with a machine file applied.

``.cncmacro.toml`` may name the machine's common ranges, the digits of an M98 program number,
the programs kept on the control, extra system variables and the profile's lathe form
(``lathe = true``). Every layer above asks
``machine_profile`` for the ``Dialect`` to work with, so those settings reach the interpreter,
the checks, hover and the debugger alike.

``file_profile`` is the one answer to "which profile is this file read in": docs/design.md's
chain (``dialect_choice.py``: the file's comment, the machine file's ``base``, the setting,
the default) with the machine file applied. ``cncmacro check`` and the language server's
analysis, the language server's open documents, the call index and ``cncmacro run`` and the
debugger (``machine/setup.py``) all ask it, so a file gets one profile whichever of them reads
it; ``profile_source`` says which link of the chain decided. On the command line the profile a
person types (``--dialect``) wins over the machine file's: ``typed_profile_wins`` gives the
settings to read with and the note that says so.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from dataclasses import replace
from typing import TypeVar

from ..bilingual import Detail, detail
from ..dialects import Dialect, get_dialect
from ..dialects.tables import CommonRange
from ..syntax.document import head_lines
from .dialect_choice import HEADER_LINES, choose_dialect, dialect_and_source
from .machine_file import MachineSettings, standard_calls

_T = TypeVar("_T")
_made: dict[tuple[str, int], tuple[MachineSettings, Dialect]] = {}
_kept: dict[tuple[str, int], tuple[MachineSettings, MachineSettings]] = {}


def file_profile(source: str | Sequence[str], settings: MachineSettings | None, setting: str | None = None) -> Dialect:
    """The profile of a file whose text (or lines) is ``source``, read with the machine file
    ``settings`` (None: none) and ``setting`` (the editor's ``cncMacro.dialect``, ``--dialect``
    or a launch's ``dialect``). A text's first lines are counted as an editor counts them
    (``split_lines``), so a form feed in a comment moves no line."""
    return machine_profile(choose_dialect(_head(source), _named(settings), setting), settings)


def profile_source(source: str | Sequence[str], settings: MachineSettings | None, setting: str | None = None) -> str:
    """Which link of ``file_profile``'s chain decided: ``file`` (its comment), ``workspace``
    (the machine file), ``setting`` or ``default``."""
    return dialect_and_source(_head(source), _named(settings), setting)[1]


def typed_profile_wins(
    settings: MachineSettings, typed: str | None, machine_file: str
) -> tuple[MachineSettings, Detail | None]:
    """``settings`` with the profile a person typed on the command line (``--dialect``) in place
    of the machine file's, and a note naming both when they differ (None when nothing was
    overridden). A file's own ``(cncmacro: dialect=..)`` comment still wins over both."""
    named = settings.dialect
    if typed is None or named is None:
        return settings, None
    settings = replace(settings, dialect=None)
    if typed == named:
        return settings, None
    return settings, detail(
        f"--dialect {typed} is used: it overrides {named}, the profile that {machine_file} names",
        f"使用 --dialect {typed}：它取代了 {machine_file} 指定的系统类型 {named}",
    )


def _head(source: str | Sequence[str]) -> list[str]:
    """The first lines of a file, where its dialect comment may be."""
    return head_lines(source, HEADER_LINES) if isinstance(source, str) else list(source[:HEADER_LINES])


def _named(settings: MachineSettings | None) -> str | None:
    """The profile the machine file names (its ``base``), if any."""
    return settings.dialect if settings is not None else None


def machine_profile(name: str | Dialect | None, settings: MachineSettings | None) -> Dialect:
    """The profile ``name`` (or the machine file's, or the default) with ``settings`` applied."""
    base = name if isinstance(name, Dialect) else get_dialect(name or (settings.dialect if settings else None))
    if settings is None:
        return base
    if settings.lathe and not base.lathe and base.lathe_variant is not None:
        base = base.lathe_variant  # ``lathe = true``: the control's lathe form (fanuc-30i)
    changes: dict[str, object] = {}
    if settings.common is not None:
        ranges = (r for first, last in settings.common for r in _common_ranges(base, first, last))
        changes["common_ranges"] = tuple(ranges)
    if settings.part_system_commons:
        changes["part_system_commons"] = settings.part_system_commons
    if settings.program_digits is not None:
        changes["m98_program_digits"] = settings.program_digits
    if settings.programs_on_control:
        changes["programs_on_control"] = settings.programs_on_control
    if settings.system_variables:
        changes["extra_rows"] = settings.system_variables
    if settings.codes:
        changes["extra_codes"] = settings.codes
    if settings.timing:
        changes["timing"] = base.timing.changed(settings.timing)
    if not changes:
        return base
    return _once(_made, base.name, settings, lambda: base.configured(**changes))


def profile_settings(settings: MachineSettings, dialect: Dialect) -> MachineSettings:
    """``settings`` as the profile ``dialect`` reads them: without the ``[calls]`` entries it
    does not call (``standard_calls``: a standard G code on GSK980TDi), so that the run and the
    checks, which both take their settings here, run the standard code; ``settings`` itself when
    it keeps every entry."""
    dropped = standard_calls(settings, dialect)
    if not dropped:
        return settings
    calls = {k: c for k, c in settings.calls.items() if k not in dropped}
    return _once(_kept, dialect.name, settings, lambda: replace(settings, calls=calls))


def _once(made: dict[tuple[str, int], tuple[MachineSettings, _T]], name: str, settings: MachineSettings,
          make: Callable[[], _T]) -> _T:  # fmt: skip
    """``make()`` for the machine file's ``settings`` under the profile ``name``, made once while
    those settings are the ones in use (``made`` keeps at most 64)."""
    key = (name, id(settings))
    hit = made.get(key)
    if hit is not None and hit[0] is settings:
        return hit[1]
    value = make()
    if len(made) > 64:
        made.clear()
    made[key] = (settings, value)
    return value


def _common_ranges(base: Dialect, first: int, last: int) -> list[CommonRange]:
    """A machine's common range, cut where the profile's ranges begin and end: each piece inside
    one of them is kept at power-off as it is; a piece outside them is kept from #500 up."""
    ends = (n for r in base.common_ranges for n in (r.first, r.last + 1))
    cuts = sorted({first, last + 1, *(n for n in ends if first < n <= last)})
    out = []
    for a, b in itertools.pairwise(cuts):
        around = base.allows_common(a, b - 1)
        out.append(CommonRange(a, b - 1, around.persistent if around is not None else a >= 500))
    return out
