"""The dialects: data (variable ranges, tables, alarm numbers, switches), never code paths.

Two dialects exist: ``fanuc`` (FANUC 0i Custom Macro B, the default) and ``gsk980tdi``.
"""

from __future__ import annotations

DEFAULT_DIALECT = "fanuc"
DIALECTS = ("fanuc", "gsk980tdi")
_ALIASES = {"fanuc": "fanuc", "fanuc0i": "fanuc", "gsk": "gsk980tdi", "gsk980tdi": "gsk980tdi", "gsk980": "gsk980tdi"}


def normalise_dialect(name: str | None) -> str | None:
    """The dialect's canonical name, or None for None or an unknown name."""
    if not name:
        return None
    return _ALIASES.get(name.strip().lower().replace(" ", ""))
