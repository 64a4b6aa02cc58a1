"""SARIF 2.1.0 output: diagnostics as a static-analysis log that code-review tools read.

``to_sarif`` builds one run of the ``cncmacro`` tool: a rule for each diagnostic code used
(with its default severity and description from ``analysis.codes.CODES``) and a result for
each diagnostic. Levels are SARIF's: ``error``, ``warning``, and ``note`` for information and
hint. File names become URIs relative to the current folder when the file lies below it, else
absolute ``file://`` URIs, the bytes of the name percent-encoded (a name that is not UTF-8 keeps
its bytes; the messages show it as ``files.shown_text`` does); regions are 1-based, with the end
column just after the last character, as SARIF counts them.
"""

from __future__ import annotations

import os
from pathlib import Path, PurePosixPath
from typing import Any
from urllib.parse import quote

from ..analysis.codes import CODES
from ..analysis.diagnostics import Diagnostic, Related
from ..library.files import shown_text

SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
SARIF_VERSION = "2.1.0"
TOOL_NAME = "cncmacro"
LEVELS = {"error": "error", "warning": "warning", "information": "note", "hint": "note"}


def to_sarif(diagnostics: list[Diagnostic], tool_version: str) -> dict[str, Any]:
    """A SARIF 2.1.0 log (a JSON-ready dict) holding ``diagnostics``."""
    rule_ids = sorted({d.code for d in diagnostics})
    index = {code: i for i, code in enumerate(rule_ids)}
    results = [_result(d, index[d.code]) for d in diagnostics]
    return {
        "$schema": SARIF_SCHEMA,
        "version": SARIF_VERSION,
        "runs": [
            {
                "tool": {
                    "driver": {
                        "name": TOOL_NAME,
                        "version": tool_version,
                        "rules": [_rule(code) for code in rule_ids],
                    }
                },
                "columnKind": "unicodeCodePoints",
                "results": results,
            }
        ],
    }


def _rule(code: str) -> dict[str, Any]:
    info = CODES.get(code)
    severity = info.severity if info else "warning"
    description = str(info.description) if info else f"cncmacro diagnostic '{code}'."
    return {
        "id": code,
        "name": code,
        "shortDescription": {"text": description},
        "defaultConfiguration": {"level": LEVELS[severity]},
        "properties": {"severity": severity},
    }


def _result(d: Diagnostic, rule_index: int) -> dict[str, Any]:
    result: dict[str, Any] = {
        "ruleId": d.code,
        "ruleIndex": rule_index,
        "level": LEVELS.get(d.severity, "warning"),
        "message": {"text": shown_text(d.message)},
        "locations": [_location(d.file, d.line, d.column, d.end_line, d.end_column)],
    }
    if d.related:
        result["relatedLocations"] = [_related(r, i) for i, r in enumerate(d.related)]
    if d.tags:
        result["properties"] = {"tags": list(d.tags)}
    return result


def _related(r: Related, i: int) -> dict[str, Any]:
    loc = _location(r.file, r.line, r.column, r.line, r.end_column)
    loc["id"] = i
    loc["message"] = {"text": shown_text(r.message)}
    return loc


def _location(file: str, line: int, column: int, end_line: int, end_column: int) -> dict[str, Any]:
    """A SARIF location; the diagnostic's 0-based lines and columns become 1-based."""
    end_column = max(end_column, column + 1) if end_line == line else end_column
    return {
        "physicalLocation": {
            "artifactLocation": {"uri": artifact_uri(file)},
            "region": {
                "startLine": line + 1,
                "startColumn": column + 1,
                "endLine": max(end_line, line) + 1,
                "endColumn": end_column + 1,
            },
        }
    }


def artifact_uri(file: str) -> str:
    """``file`` as a URI: relative (with ``/``) when it lies in or below the current folder,
    else an absolute ``file://`` URI. Characters a URI cannot hold (spaces, Chinese names) are
    percent-encoded as UTF-8, and the bytes of a name that is not UTF-8 as they are."""
    path = Path(file)
    absolute = path if path.is_absolute() else Path.cwd() / path
    try:
        relative = Path(os.path.normpath(absolute)).relative_to(Path.cwd())
    except ValueError:
        return Path(os.path.normpath(absolute)).as_uri()
    return quote(os.fsencode(PurePosixPath(*relative.parts)), safe="/")
