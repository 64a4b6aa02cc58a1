"""The user's changes to the severities of diagnostic codes.

The codes and their default severities are ``analysis/codes.py``'s ``CODES``.
``apply_severities`` applies a ``[severity]`` table from ``.cncmacro.toml`` (or an editor
setting) to a list of diagnostics: each listed code gets the severity given, and ``off`` drops
its diagnostics. An unknown code or severity is a ``ValueError`` that names it, so a typing
mistake in settings is never silently ignored.
"""

from __future__ import annotations

import difflib
from dataclasses import replace

from .codes import CODES, SEVERITIES
from .diagnostics import Diagnostic

OFF = "off"
SETTINGS_VALUES = (*SEVERITIES, OFF)


def check_overrides(overrides: dict[str, str], source: str = "severity") -> dict[str, str]:
    """The overrides with their values lower-cased; ``ValueError`` naming the first unknown
    code or value (``source`` says where they came from, e.g. the settings table's name)."""
    checked: dict[str, str] = {}
    for code, value in overrides.items():
        if code not in CODES:
            near = difflib.get_close_matches(str(code), list(CODES), n=1, cutoff=0.6)
            meant = f"did you mean '{near[0]}'? " if near else ""
            raise ValueError(f"{source}: '{code}' is not a diagnostic code: {meant}(known: {', '.join(sorted(CODES))})")
        level = value.strip().lower() if isinstance(value, str) else value
        if level not in SETTINGS_VALUES:
            raise ValueError(f"{source}: '{code}' must be one of {', '.join(SETTINGS_VALUES)}, not {value!r}")
        checked[code] = level
    return checked


def apply_severities(diagnostics: list[Diagnostic], overrides: dict[str, str]) -> list[Diagnostic]:
    """``diagnostics`` with each overridden code's severity changed; codes set to ``off`` are
    dropped. The order is kept. ``ValueError`` for an unknown code or severity."""
    levels = check_overrides(overrides)
    if not levels:
        return list(diagnostics)
    out: list[Diagnostic] = []
    for d in diagnostics:
        level = levels.get(d.code)
        if level is None or level == d.severity:
            out.append(d)
        elif level != OFF:
            out.append(replace(d, severity=level))
    return out
