"""The server's settings: the editor's ``cncMacro`` section, and the severities in force.

The editor's settings come from ``initializationOptions`` at start and from
``workspace/configuration`` (section ``cncMacro``) after ``initialized`` and on every
``workspace/didChangeConfiguration``: ``dialect``, ``severity`` (diagnostic code ->
``error|warning|information|hint|off``), ``runBudget`` (blocks per analysis run) and
``inlayHints.values`` (show the value each assignment left in the analysis run; off). The
machine file a program is read with (``library/machine_files.py``) gives the dialect that the chain of
docs/design.md puts before the editor's, and severities that the editor's override
(``merged_severities``).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from typing import Any

from ..analysis.severity import check_overrides
from ..dialects import DIALECTS, nearest_dialect, normalise_dialect
from ..library.machine_file import MachineSettings

SECTION = "cncMacro"
log = logging.getLogger(__name__)


@dataclass
class Settings:
    """What the editor set; None or empty where it set nothing."""

    dialect: str | None = None
    severity: dict[str, str] = field(default_factory=dict)
    run_budget: int | None = None
    inlay_values: bool = False
    # what was set wrong, for the editor to show: a key of texts.py and its values
    problems: list[tuple[str, dict[str, str]]] = field(default_factory=list)

    @classmethod
    def from_mapping(cls, data: Any) -> Settings:
        """Settings from the ``cncMacro`` object (or an object holding it); bad values are
        logged and skipped, never fatal."""
        if not isinstance(data, dict):
            return cls()
        if isinstance(data.get(SECTION), dict):
            data = data[SECTION]
        out = cls()
        dialect = data.get("dialect")
        if isinstance(dialect, str) and dialect:
            out.dialect = normalise_dialect(dialect)
            if out.dialect is None:
                log.warning("cncMacro.dialect: unknown dialect %r", dialect)
                out.problems.append(_unknown_dialect(dialect))
        sev = data.get("severity")
        if isinstance(sev, dict):
            out.severity = {str(k): str(v).lower() for k, v in sev.items()}
            for code, level in out.severity.items():
                try:
                    check_overrides({code: level}, "cncMacro.severity")
                except ValueError as e:
                    out.problems.append(("setting_refused", {"text": str(e)}))
        budget = data.get("runBudget")
        if isinstance(budget, int) and not isinstance(budget, bool) and budget > 0:
            out.run_budget = budget
        hints = data.get("inlayHints")
        values = hints.get("values") if isinstance(hints, dict) else data.get("inlayHints.values")
        out.inlay_values = values is True
        return out


def _unknown_dialect(name: str) -> tuple[str, dict[str, str]]:
    """The message (a key of texts.py and its values) for a ``cncMacro.dialect`` that names no
    profile, with the nearest name."""
    near = nearest_dialect(name)
    values = {"name": name, "near": near or "", "names": ", ".join(DIALECTS)}
    return ("unknown_dialect_near" if near else "unknown_dialect"), values


def merged_severities(machine: MachineSettings | None, editor: Settings) -> dict[str, str]:
    """The severity overrides in force: the machine file's, then the editor's on top."""
    out: dict[str, str] = dict(getattr(machine, "severity", {}) or {}) if machine else {}
    out.update(editor.severity)
    return out


def valid_severities(overrides: dict[str, str]) -> dict[str, str]:
    """``overrides`` without the entries that name no code or no severity (each one logged)."""
    out = {}
    for code, level in overrides.items():
        try:
            out.update(check_overrides({code: level}, "cncMacro.severity"))
        except ValueError as e:
            log.warning("%s", e)
    return out
