"""The control profiles (dialects): data (variable ranges, tables, alarm numbers, switches), never
code paths.

The built-in profiles are the modules of ``dialects/profiles/`` (``fanuc-0i``, the default, once
named ``fanuc``; ``fanuc-30i``; ``gsk980tdi``); ``registry`` lists them. docs/profiles.md says
what each covers and how to add one.
"""

from __future__ import annotations

from .dialect import Dialect as Dialect
from .registry import DEFAULT_PROFILE, all_profiles, names_and_aliases

DEFAULT_DIALECT = DEFAULT_PROFILE
DIALECTS: tuple[str, ...] = tuple(d.name for d in all_profiles())
BY_NAME: dict[str, Dialect] = {d.name: d for d in all_profiles()}


def normalise_dialect(name: str | None) -> str | None:
    """The profile's canonical name, or None for None or an unknown name."""
    if not name:
        return None
    return names_and_aliases().get(name.strip().lower().replace(" ", "").replace("_", "-"))


def nearest_dialect(name: str) -> str | None:
    """The profile (its canonical name) whose name or alias is nearest to the unknown ``name``
    (``hass`` -> ``haas``), or None when none is near."""
    import difflib

    known = names_and_aliases()
    close = difflib.get_close_matches(name.strip().lower().replace("_", "-"), list(known), n=1, cutoff=0.6)
    return known[close[0]] if close else None


def get_dialect(name: str | None = None) -> Dialect:
    """The ``Dialect`` for a name or alias (the default for None); ``ValueError`` if unknown."""
    canonical = normalise_dialect(name) if name else DEFAULT_DIALECT
    if canonical is None:
        raise ValueError(f"unknown profile {name!r}; choose one of {', '.join(DIALECTS)}")
    return BY_NAME[canonical]


def choices_text(zh: bool = False) -> str:
    """The profiles as a user reads them in a message: ``fanuc-0i, fanuc-30i or gsk980tdi``
    (``fanuc-0i、fanuc-30i 或 gsk980tdi`` in Chinese)."""
    names = list(DIALECTS)
    if len(names) == 1:
        return names[0]
    return ("、".join(names[:-1]) + " 或 " if zh else ", ".join(names[:-1]) + " or ") + names[-1]
