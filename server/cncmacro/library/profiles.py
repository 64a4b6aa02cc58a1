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
it; ``profile_source`` says which link of the chain decided.
"""

from __future__ import annotations

from collections.abc import Sequence

from ..dialects import Dialect, get_dialect
from ..dialects.tables import CommonRange
from ..syntax.document import head_lines
from .dialect_choice import HEADER_LINES, choose_dialect, dialect_and_source
from .machine_file import MachineSettings

_made: dict[tuple[str, int], tuple[MachineSettings, Dialect]] = {}


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
        changes["common_ranges"] = tuple(_common_range(base, first, last) for first, last in settings.common)
    if settings.program_digits is not None:
        changes["m98_program_digits"] = settings.program_digits
    if settings.programs_on_control:
        changes["programs_on_control"] = settings.programs_on_control
    if settings.system_variables:
        changes["extra_rows"] = settings.system_variables
    if settings.timing:
        changes["timing"] = base.timing.changed(settings.timing)
    if not changes:
        return base
    key = (base.name, id(settings))
    made = _made.get(key)
    if made is not None and made[0] is settings:
        return made[1]
    profile = base.configured(**changes)
    if len(_made) > 64:
        _made.clear()
    _made[key] = (settings, profile)
    return profile


def _common_range(base: Dialect, first: int, last: int) -> CommonRange:
    """A machine's common range, kept at power-off where the profile's range around it is."""
    around = base.allows_common(first, last)
    return CommonRange(first, last, around.persistent if around is not None else first >= 500)
