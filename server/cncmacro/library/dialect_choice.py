"""Which dialect a file is read in: docs/design.md's chain, first match wins.

A comment in the first lines of the file ``(cncmacro: dialect=gsk980tdi)``; then the workspace
setting (``.cncmacro.toml``), then the editor or command-line setting, then ``fanuc``. On the
command line ``--dialect`` goes before the machine file: the front end takes the machine file's
profile out first (``profiles.typed_profile_wins``).
"""

from __future__ import annotations

import re

from ..dialects import DEFAULT_DIALECT, normalise_dialect

_MARKER = re.compile(r"\(\s*cncmacro\s*:\s*dialect\s*=\s*([A-Za-z0-9_-]+)\s*\)", re.I)
HEADER_LINES = 5


def dialect_comment(lines: list[str]) -> tuple[int, int, int, str] | None:
    """Where the first ``(cncmacro: dialect=...)`` comment of the first lines is: its 0-based
    line, start and end columns, and the name as written (known or not)."""
    for k, line in enumerate(lines[:HEADER_LINES]):
        m = _MARKER.search(line)
        if m:
            return k, m.start(), m.end(), m.group(1)
    return None


def dialect_from_text(lines: list[str]) -> str | None:
    """The dialect named by a ``(cncmacro: dialect=...)`` comment in the first lines."""
    found = dialect_comment(lines)
    return normalise_dialect(found[3]) if found is not None else None


def choose_dialect(lines: list[str], workspace: str | None = None, setting: str | None = None) -> str:
    """The file's dialect by the chain: file comment, workspace, setting, default."""
    return dialect_and_source(lines, workspace, setting)[0]


def dialect_and_source(lines: list[str], workspace: str | None = None, setting: str | None = None) -> tuple[str, str]:
    """``choose_dialect`` and which link of the chain decided: ``file`` (its comment),
    ``workspace`` (``.cncmacro.toml``), ``setting`` or ``default``."""
    for source, name in (("file", dialect_from_text(lines)), ("workspace", normalise_dialect(workspace)),
                         ("setting", normalise_dialect(setting))):  # fmt: skip
        if name:
            return name, source
    return DEFAULT_DIALECT, "default"
