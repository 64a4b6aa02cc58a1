"""Which dialect a file is read in: DESIGN.md's chain, first match wins.

A comment in the first lines of the file ``(cncmacro: dialect=gsk980tdi)``; then the workspace
setting (``.cncmacro.toml``), then the editor or command-line setting, then ``fanuc``.
"""

from __future__ import annotations

import re

from ..dialects import DEFAULT_DIALECT, normalise_dialect

_MARKER = re.compile(r"\(\s*cncmacro\s*:\s*dialect\s*=\s*([A-Za-z0-9_-]+)\s*\)", re.I)
HEADER_LINES = 5


def dialect_from_text(lines: list[str]) -> str | None:
    """The dialect named by a ``(cncmacro: dialect=...)`` comment in the first lines."""
    for line in lines[:HEADER_LINES]:
        m = _MARKER.search(line)
        if m:
            return normalise_dialect(m.group(1))
    return None


def choose_dialect(lines: list[str], workspace: str | None = None, setting: str | None = None) -> str:
    """The file's dialect by the chain: file comment, workspace, setting, default."""
    return dialect_from_text(lines) or normalise_dialect(workspace) or normalise_dialect(setting) or DEFAULT_DIALECT
