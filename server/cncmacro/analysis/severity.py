"""Diagnostic codes, their default severities, and the user's changes to them.

``CODES`` is docs/design.md's table of stable diagnostic codes: each code's default severity and a
one-line description (the SARIF output's rules use both). ``apply_severities`` applies a
``[severity]`` table from ``.cncmacro.toml`` (or an editor setting) to a list of diagnostics:
each listed code gets the severity given, and ``off`` drops its diagnostics. An unknown code or
severity is a ``ValueError`` that names it, so a typing mistake in settings is never silently
ignored.
"""

from __future__ import annotations

from dataclasses import replace
from typing import NamedTuple

from .diagnostics import SEVERITIES, Diagnostic

OFF = "off"
SETTINGS_VALUES = (*SEVERITIES, OFF)


class CodeInfo(NamedTuple):
    """A diagnostic code's default severity and what it reports."""

    severity: str
    description: str


CODES: dict[str, CodeInfo] = {
    "syntax": CodeInfo("error", "The block does not parse."),
    "bracket-depth": CodeInfo("error", "More than 5 nested brackets (alarm 118)."),
    "undefined-label": CodeInfo("error", "A GOTO, M99 P, M98 Q, M97 P or H80-H86 target has no N label."),
    "duplicate-label": CodeInfo("warning", "An N number is used twice where it is a jump target."),
    "duplicate-program": CodeInfo("warning", "An O number used twice in a file: the control keeps the first program."),
    "label-range": CodeInfo("error", "A GOTO target is outside 1-99999."),
    "loop-mismatch": CodeInfo("error", "DO without END, END without DO, or crossing loops (alarms 124/126)."),
    "loop-number": CodeInfo("error", "A DO/END number outside 1-3, or loops nested deeper than 3 (alarm 126)."),
    "jump-into-loop": CodeInfo("error", "A jump into a DO range from outside it."),
    "g65-nc-words": CodeInfo(
        "error",
        "G65/G66 shares its block with another G or M code, an O word or a prior word (a modal G code "
        "before it is a warning where the control sets it and calls).",
    ),
    "argument-address": CodeInfo("error", "G, L, N, O or P used as a macro argument (alarm 129)."),
    "argument-order": CodeInfo("warning", "I, J, K arguments out of their I, J, K order within a set (fanuc)."),
    "repeat-count-range": CodeInfo("error", "A repeat count (L, or the count in P) is outside 1-9999."),
    "program-not-found": CodeInfo("error", "A call names a program that is not in the workspace."),
    "program-number": CodeInfo("error", "A program number has too many digits, or a program name is not allowed."),
    "variable-number": CodeInfo("error", "A variable number that does not exist in the dialect (alarm 115)."),
    "write-protected": CodeInfo("error", "An assignment to #0 or to a read-only system variable (alarm 116)."),
    "write-only": CodeInfo("error", "A write-only system variable is read."),
    "nc-and-macro": CodeInfo("error", "NC words and a macro statement in one block (alarm 127)."),
    "dialect-feature": CodeInfo("error", "Syntax that the selected dialect lacks."),
    "corner-word": CodeInfo(
        "warning", "A ,C/,R/,A corner word without a G01/G02/G03 move, or on a profile whose manual lacks it."
    ),
    "profile-suggestion": CodeInfo("information", "The file reads cleanly as another profile: likely written for it."),
    "nesting-depth": CodeInfo("error", "Macro or subprogram nesting is exceeded when the program runs."),
    "division-by-zero": CodeInfo("error", "A division by zero found by running the program (alarm 112)."),
    "argument-range": CodeInfo("error", "A SQRT, ASIN, ACOS or LN argument out of range, found by running (119)."),
    "macro-alarm": CodeInfo("warning", "A run of the program reaches #3000= or G65 H99 (a macro alarm)."),
    "vacant-argument": CodeInfo("information", "A macro reads an argument that a caller never passes."),
    "run-limit": CodeInfo("information", "The analysis run stopped at its block budget (a possible endless loop)."),
    "not-executed": CodeInfo("hint", "Blocks that the analysis runs never reached."),
    "decimal-point": CodeInfo("error", "An M code written with a decimal point (alarm 007)."),
    "unknown-g-code": CodeInfo("error", "A G code the control lacks and the machine does not map to a call (010)."),
    "keyword-abbreviation": CodeInfo("hint", "A macro word written shortened (WH for WHILE), read as the whole word."),
    "after-tape-end": CodeInfo("hint", "Text after the closing % (the end of the tape), which is not read."),
    "internal-error": CodeInfo("error", "The checker itself failed on this line, program or file (a bug to report)."),
    "machine-file": CodeInfo("error", "The machine file (.cncmacro.toml) cannot be used: the defaults stand in."),
}


def check_overrides(overrides: dict[str, str], source: str = "severity") -> dict[str, str]:
    """The overrides with their values lower-cased; ``ValueError`` naming the first unknown
    code or value (``source`` says where they came from, e.g. the settings table's name)."""
    checked: dict[str, str] = {}
    for code, value in overrides.items():
        if code not in CODES:
            raise ValueError(f"{source}: '{code}' is not a diagnostic code (known: {', '.join(sorted(CODES))})")
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
