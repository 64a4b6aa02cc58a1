"""What the static checks learn from one line on its own: findings, jumps and calls.

``LineFacts`` is the result of looking at one block with nothing but the dialect and the machine
settings: the problems it has by itself (``Finding``, columns only, no line or file, so that a
result can be cached per block and reused wherever the block appears) and the facts that need
the rest of the file to judge: literal jump targets (``Jump``), calls with a literal target
(``call_sites.CallSite``) and ``M99 Pn`` returns (``ReturnJump``). ``LineContext`` holds what every line's
check needs, made once per dialect, settings and locale. ``block_finding`` turns a
``BlockProblem`` of ``machine/block_rules.py`` into the finding of its code (``RULE_CODES``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ...bilingual import in_language, is_chinese, pick
from ...dialects import BY_NAME, Dialect
from ...library.machine_file import MachineSettings
from ...library.profiles import machine_profile, profile_settings
from ...machine import block_rules as rules
from ...machine.alarms import MacroAlarm
from ...machine.block_rules import BlockProblem
from ...machine.expressions import ExpressionCompiler, VariableKinds
from ..codes import default_severity
from ..indexes.call_sites import CallSite
from .lathe_signs import LatheSign

RULE_CODES = {
    rules.ABBREVIATION: "dialect-feature",
    rules.MISSING_THEN: "dialect-feature",
    rules.CONDITIONAL_M99: "dialect-feature",
    rules.IF_BLOCK: "dialect-feature",
    rules.BLOCK_IF: "dialect-feature",
    rules.NC_AND_STATEMENT: "nc-and-macro",
    rules.BEFORE_CALL: "g65-nc-words",
    rules.O_WITH_CALL: "g65-nc-words",
    rules.CALL_WORD_ORDER: "g65-word-order",
    rules.G_AFTER_CALL: "argument-address",
    rules.CALL_WITHOUT_P: "program-not-found",
    rules.UNKNOWN_G_CODE: "unknown-g-code",
    rules.M_DECIMAL_POINT: "decimal-point",
    rules.OWN_BLOCK: "own-block",
}  # the diagnostic code of each block rule


@dataclass(frozen=True, slots=True)
class Finding:
    """A problem on one block: 0-based columns in the line, a severity, a code and a message."""

    start: int
    end: int
    severity: str
    code: str
    message: str


def finding(start: int, end: int, code: str, message: str, *, milder: bool = False) -> Finding:
    """A ``Finding`` of ``code`` with the code's default severity, or its milder one where the
    check says the control is lenient (``codes.default_severity``)."""
    return Finding(start, end, default_severity(code, milder), code, message)


def alarm_named(number: int, dialect: Dialect) -> tuple[str, str]:
    """Alarm ``number`` as a check's message names it, English and Chinese: "alarm 128", or
    "alarm" alone where ``dialect`` documents no number for it."""
    said = dialect.alarm_said(number)
    return str(said), said.zh


def alarm_message(alarm: MacroAlarm, locale: str, dialect: Dialect) -> str:
    """The alarm the interpreter would raise, as a check's message: its text and the number
    the control shows (none where ``dialect`` documents none)."""
    en, zh = alarm_named(alarm.number, dialect)
    return pick(locale, f"{alarm.message} ({en})", f"{in_language(alarm.message, True)}（{zh}）")


def block_finding(problem: BlockProblem, locale: str) -> Finding:
    """A block rule's problem as a finding: the code's default severity where the control stops,
    else its milder one (``codes.default_severity``)."""
    message = in_language(problem.finding, is_chinese(locale))
    return finding(problem.start, problem.end, RULE_CODES[problem.rule], message, milder=not problem.stops)


@dataclass(frozen=True, slots=True)
class Jump:
    """A jump to a literal label in the same O program: ``GOTO``, ``IF..GOTO``, ``G65 H80–H86``.
    ``start``/``end`` is the span of the target as written."""

    label: int
    start: int
    end: int
    how: str  # what is written before the label: "GOTO " or "G65 H81 P"


@dataclass(frozen=True, slots=True)
class ReturnJump:
    """``M99 Pn`` with a literal n: a return to label n of the caller."""

    label: int
    start: int
    end: int


@dataclass(slots=True)
class LineFacts:
    """Everything one block says by itself (see the module docstring)."""

    findings: list[Finding] = field(default_factory=list)
    jumps: list[Jump] = field(default_factory=list)
    calls: list[CallSite] = field(default_factory=list)
    returns: list[ReturnJump] = field(default_factory=list)
    # another profile's local subprogram call (Haas M97 P n read under a profile without one):
    # (its M code, the label P names, the span of that label), for profile_suggestion.py
    foreign_calls: list[tuple[float, int, int, int]] = field(default_factory=list)
    # signs of a lathe program read under a mill profile (lathe_signs.py), for profile_suggestion.py
    lathe_signs: list[LatheSign] = field(default_factory=list)

    def __bool__(self) -> bool:
        return bool(self.findings or self.jumps or self.calls or self.returns or self.foreign_calls or self.lathe_signs)


def foreign_local_codes(dialect: Dialect) -> tuple[float, ...]:
    """The local subprogram call codes of the other profiles (``Dialect.local_subprogram_code``)
    that ``dialect`` reads as plain M codes; empty for a dialect that has one of its own."""
    if dialect.local_subprogram_code is not None:
        return ()
    return tuple(sorted({c for d in BY_NAME.values() if (c := d.local_subprogram_code) is not None}))


class LineContext:
    """The dialect, settings and locale of a check, with what they imply made once."""

    def __init__(self, dialect: Dialect, settings: MachineSettings, locale: str = "en") -> None:
        dialect = machine_profile(dialect, settings)
        settings = profile_settings(settings, dialect)  # without the [calls] it does not call, as the run
        self.dialect = dialect
        self.settings = settings
        self.locale = locale
        self.foreign_local = foreign_local_codes(dialect)
        self.kinds = VariableKinds(dialect)
        self.values = ExpressionCompiler(self.kinds)
        # the other dialects, to tell a feature this one lacks from a plain mistake
        self.other_kinds = [VariableKinds(d) for d in BY_NAME.values() if d.name != dialect.name]
        self.calls = settings.calls
        # whether a plain line (``Block.plain``) holds a word the checks look at: made from the
        # words they say they look at (``static_checks.line_context``); until then, every line
        self.plain_hint: Callable[[str], bool] = _every_line

    def key(self) -> tuple[str, int, str]:
        return (self.dialect.name, id(self.settings), self.locale)


def _every_line(line: str) -> bool:
    return True
