"""The dialects: data (variable ranges, tables, alarm numbers, switches), never code paths.

Three dialects exist: ``fanuc`` (FANUC 0i Custom Macro B, the default), ``gsk980tdi`` and
``fanuc-30i`` (FANUC 30i-B Custom Macro).
"""

from __future__ import annotations

from .dialect import BY_NAME, Dialect

DEFAULT_DIALECT = "fanuc"
DIALECTS = ("fanuc", "gsk980tdi", "fanuc-30i")
_ALIASES = {
    "fanuc": "fanuc", "fanuc0i": "fanuc", "gsk": "gsk980tdi", "gsk980tdi": "gsk980tdi", "gsk980": "gsk980tdi",
    "fanuc30i": "fanuc-30i", "30i": "fanuc-30i", "fanuc-30i": "fanuc-30i",
}  # fmt: skip


def normalise_dialect(name: str | None) -> str | None:
    """The dialect's canonical name, or None for None or an unknown name."""
    if not name:
        return None
    return _ALIASES.get(name.strip().lower().replace(" ", ""))


def get_dialect(name: str | None = None) -> Dialect:
    """The ``Dialect`` for a name or alias (the default for None); ``ValueError`` if unknown."""
    canonical = normalise_dialect(name) if name else DEFAULT_DIALECT
    if canonical is None:
        raise ValueError(f"unknown dialect {name!r}; choose one of {', '.join(DIALECTS)}")
    return BY_NAME[canonical]
