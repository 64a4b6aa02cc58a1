"""The registry of diagnostic codes (``analysis/codes.py``) against docs/design.md "Diagnostic
codes" and against the checks: every code a check names is registered, no check writes a
severity of its own, and a run's alarm becomes the code the registry gives its number."""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

from cncmacro.analysis.checks.line_facts import RULE_CODES
from cncmacro.analysis.codes import CODES, FOUND, MACRO_ALARM, RUN, SEVERITIES, STATIC, alarm_code, default_severity
from cncmacro.dialects.alarms import ALARMS

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "server" / "cncmacro"

# the calls that make a finding, and where each takes the code (argument index; or ``code=``)
CODE_ARGUMENT = {
    "finding": 2,  # analysis/checks/line_facts.py
    "diagnostic": 5,  # analysis/diagnostics.py
    "Finding": 3,
    "Diagnostic": 6,  # also lsprotocol's types.Diagnostic, which takes code=
    "_add": 2,  # analysis/checks/call_checks.py
    "_diagnostic": 2,  # analysis/runs/run_checks.py
    "default_severity": 0,
}
SEVERITY_ARGUMENT = {"Finding": 2, "Diagnostic": 5}


def design_table() -> dict[str, tuple[str, str]]:
    """docs/design.md's table of codes: code -> (severity as written, found)."""
    text = (ROOT / "docs" / "design.md").read_text(encoding="utf-8").split("### Diagnostic codes")[1]
    text = text.split("\n### ")[0]
    rows = re.findall(r"^\| `([a-z0-9-]+)` \| ([a-z /]+) \| ([a-z]+) \|", text, re.M)
    return {code: (severity, found) for code, severity, found in rows}


def test_the_registry_is_the_design_table() -> None:
    table = design_table()
    assert list(table) == list(CODES)  # the same codes, in the same order
    for code, (severity, found) in table.items():
        c = CODES[code]
        assert severity == (f"{c.severity} / {c.milder}" if c.milder else c.severity), code
        assert found == c.found, code


def test_each_record_is_complete() -> None:
    for name, c in CODES.items():
        assert c.name == name
        assert c.severity in SEVERITIES and c.milder in (*SEVERITIES, None) and c.milder != c.severity, name
        assert c.found in FOUND, name
        assert c.description.strip() and c.description.zh.strip() and c.description.zh != str(c.description), name
        # what stands for a run's alarm is found by running
        assert not (c.alarms or c.subjects) or c.found != STATIC, name


def test_each_alarm_number_is_a_known_alarm_of_one_code() -> None:
    numbers = [n for c in CODES.values() for n in c.alarms]
    assert len(numbers) == len(set(numbers))
    assert set(numbers) <= set(ALARMS)
    subjects = [s for c in CODES.values() for s in c.subjects]
    assert len(subjects) == len(set(subjects))


@pytest.mark.parametrize(
    ("number", "subject", "code"),
    [
        (112, None, "division-by-zero"),
        (115, None, "variable-number"),
        (1099, None, "variable-number"),
        (128, None, "undefined-label"),
        (128, "label-range", "label-range"),  # the subject is more precise than the number
        (126, "jump-into-loop", "jump-into-loop"),
        (119, "repeat-count", "repeat-count-range"),
        (119, None, "argument-range"),
        (3001, None, MACRO_ALARM),  # from the macro-alarm base up: the program's own
        (999, None, "syntax"),  # a number no code claims
    ],
)
def test_an_alarm_of_a_run_becomes_its_code(number: int, subject: str | None, code: str) -> None:
    assert alarm_code(number, subject, 3000) == code


def test_a_milder_severity_only_where_the_registry_has_one() -> None:
    assert default_severity("repeat-count-range", milder=True) == "warning"
    assert default_severity("repeat-count-range") == "error"
    with pytest.raises(ValueError, match="'undefined-label' has no milder severity"):
        default_severity("undefined-label", milder=True)
    with pytest.raises(KeyError):
        default_severity("undefined-lable")


def _modules() -> Iterator[tuple[Path, ast.Module]]:
    for path in sorted(PACKAGE.rglob("*.py")):
        yield path, ast.parse(path.read_text(encoding="utf-8"))


def _string_constants() -> dict[str, str]:
    """Every module-level ``NAME = "text"`` of the package, by name (a name given two values is
    left out)."""
    seen: dict[str, set[str]] = {}
    for _, tree in _modules():
        for node in tree.body:
            if isinstance(node, ast.Assign) and isinstance(node.value, ast.Constant):
                for target in node.targets:
                    if isinstance(target, ast.Name) and isinstance(node.value.value, str):
                        seen.setdefault(target.id, set()).add(node.value.value)
    return {name: next(iter(values)) for name, values in seen.items() if len(values) == 1}


def _called(call: ast.Call) -> str | None:
    f = call.func
    return f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else None


def _argument(call: ast.Call, index: int, keyword: str) -> ast.expr | None:
    starred = [i for i, a in enumerate(call.args) if isinstance(a, ast.Starred)]
    if starred:  # diagnostic(file, *span, code, message): the code comes after the positions
        after = starred[-1] + 1
        return call.args[after] if keyword == "code" and after < len(call.args) else None
    if index < len(call.args):
        return call.args[index]
    return next((k.value for k in call.keywords if k.arg == keyword), None)


def _named_codes() -> list[tuple[str, int, str, ast.Call]]:
    """(file, line, code, call) for every call that makes a finding with a code it names: a
    string, or a module-level constant of the package."""
    constants = _string_constants()
    out = []
    for path, tree in _modules():
        for call in ast.walk(tree):
            if not isinstance(call, ast.Call) or (name := _called(call)) not in CODE_ARGUMENT:
                continue
            arg = _argument(call, CODE_ARGUMENT[name], "code")
            code = None
            if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
                code = arg.value
            elif isinstance(arg, ast.Name) and arg.id in constants:
                code = constants[arg.id]
            if code is not None:
                out.append((str(path.relative_to(PACKAGE)), call.lineno, code, call))
    return out


def test_every_code_a_check_names_is_registered() -> None:
    named = _named_codes()
    unknown = [f"{file}:{line}: {code}" for file, line, code, _ in named if code not in CODES]
    assert not unknown, f"codes not in analysis/codes.py: {unknown}"
    # a block rule of machine/block_rules.py names its code in RULE_CODES
    ruled = set(RULE_CODES.values())
    assert ruled <= set(CODES), f"block rules' codes not in analysis/codes.py: {ruled - set(CODES)}"
    # and the walk sees the checks: each code is named by a check or a block rule, or stands for a run's alarm
    seen = {code for _, _, code, _ in named} | ruled
    assert {c.name for c in CODES.values() if not (c.alarms or c.subjects or c.found == RUN)} <= seen
    assert {"undefined-label", "corner-word", "vacant-argument", "not-executed", "machine-file"} <= seen


def test_milder_is_asked_only_of_a_code_that_has_it() -> None:
    wrong = []
    for file, line, code, call in _named_codes():
        milder = next((k.value for k in call.keywords if k.arg == "milder"), None)
        if milder is not None and not (isinstance(milder, ast.Constant) and milder.value is False):
            if CODES[code].milder is None:
                wrong.append(f"{file}:{line}: {code}")
    assert not wrong, f"milder severity asked of a code without one: {wrong}"


def test_no_check_writes_a_severity_of_its_own() -> None:
    """A finding's severity is its code's (``finding``, ``diagnostic``): a ``Finding`` or
    ``Diagnostic`` made with a literal severity in the analysis is a second copy of the registry."""
    written = []
    for path, tree in _modules():
        if path.parent.name != "analysis":
            continue
        for call in ast.walk(tree):
            if isinstance(call, ast.Call) and (name := _called(call)) in SEVERITY_ARGUMENT:
                arg = _argument(call, SEVERITY_ARGUMENT[name], "severity")
                if isinstance(arg, ast.Constant):
                    written.append(f"{path.name}:{call.lineno}: {ast.unparse(arg)}")
    assert not written, f"severities written by hand: {written}"
