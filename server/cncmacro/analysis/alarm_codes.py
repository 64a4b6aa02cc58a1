"""Which diagnostic code an alarm found by running becomes (docs/design.md "Diagnostic codes").

Each alarm number maps to one code. Where the interpreter names the subject of an alarm
whose number covers several things (``L`` out of range is alarm 119 on fanuc and 291 on
gsk980tdi; a GOTO into a loop is 126), the subject decides, being more precise. Alarm
numbers from the macro-alarm base of the dialect up (``#3000=n`` → 3000+n on fanuc,
5900+n on gsk980tdi, ``G65 H99``) are the program's own alarms: ``macro-alarm``.
"""

from __future__ import annotations

from ..dialects.alarms import (
    ARGUMENT_RANGE,
    BRACKET_NESTING,
    COUNT_TWICE,
    DECIMAL_POINT,
    DIVISION_BY_ZERO,
    FORMAT,
    G_ARGUMENT,
    IMPROPER_G_CODE,
    LOOP_NUMBER,
    MACRO_NESTING,
    MISSING_END,
    NAME_SUBSCRIPT,
    NC_AND_MACRO,
    NO_VARIABLE_NAME,
    OVERFLOW,
    P_VALUE_RANGE,
    PROGRAM_NOT_FOUND,
    SEQUENCE_NUMBER,
    STATEMENT_FORMAT,
    SUBPROGRAM_NESTING,
    VARIABLE_NUMBER,
    WRITE_PROTECTED,
)

MACRO_ALARM = "macro-alarm"

ALARM_CODES: dict[int, str] = {
    DECIMAL_POINT: "decimal-point",
    IMPROPER_G_CODE: "unknown-g-code",
    PROGRAM_NOT_FOUND: "program-not-found",
    SUBPROGRAM_NESTING: "nesting-depth",
    OVERFLOW: "argument-range",
    DIVISION_BY_ZERO: "division-by-zero",
    FORMAT: "syntax",
    VARIABLE_NUMBER: "variable-number",
    WRITE_PROTECTED: "write-protected",
    BRACKET_NESTING: "bracket-depth",
    ARGUMENT_RANGE: "argument-range",
    MACRO_NESTING: "nesting-depth",
    MISSING_END: "loop-mismatch",
    STATEMENT_FORMAT: "syntax",
    LOOP_NUMBER: "loop-number",
    NC_AND_MACRO: "nc-and-macro",
    SEQUENCE_NUMBER: "undefined-label",
    G_ARGUMENT: "argument-address",
    P_VALUE_RANGE: "program-number",
    COUNT_TWICE: "repeat-count-range",
    NO_VARIABLE_NAME: "variable-number",
    NAME_SUBSCRIPT: "variable-number",
}

SUBJECT_CODES: dict[str, str] = {
    "repeat-count": "repeat-count-range",
    "label-range": "label-range",
    "jump-into-loop": "jump-into-loop",
}


def alarm_code(number: int, subject: str | None, macro_alarm_base: int) -> str:
    """The diagnostic code of alarm ``number`` (with the interpreter's ``subject``, if any)."""
    if subject is not None and subject in SUBJECT_CODES:
        return SUBJECT_CODES[subject]
    code = ALARM_CODES.get(number)
    if code is not None:
        return code
    if number >= macro_alarm_base:
        return MACRO_ALARM
    return "syntax"
