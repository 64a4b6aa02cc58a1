"""The profile as one machine has it: a built-in profile with a machine file applied.

``.cncmacro.toml`` may name the machine's common ranges, the digits of an M98 program number,
the programs kept on the control and extra system variables. Every layer above asks
``machine_profile`` for the ``Dialect`` to work with, so those settings reach the interpreter,
the checks, hover and the debugger alike.
"""

from __future__ import annotations

from ..dialects import Dialect, get_dialect
from ..dialects.tables import CommonRange
from .machine_file import MachineSettings

_made: dict[tuple[str, int], tuple[MachineSettings, Dialect]] = {}


def machine_profile(name: str | Dialect | None, settings: MachineSettings | None) -> Dialect:
    """The profile ``name`` (or the machine file's, or the default) with ``settings`` applied."""
    base = name if isinstance(name, Dialect) else get_dialect(name or (settings.dialect if settings else None))
    if settings is None:
        return base
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
