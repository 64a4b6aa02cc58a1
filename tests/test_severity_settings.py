"""Severity settings: the ``[severity]`` table of ``.cncmacro.toml`` and ``apply_severities``
(docs/design.md "Every code's severity can be changed or switched off in settings")."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from cncmacro.analysis import syntax_diagnostics
from cncmacro.analysis.codes import CODES
from cncmacro.analysis.diagnostics import Diagnostic
from cncmacro.analysis.severity import apply_severities
from cncmacro.library.machine_file import MachineFileError, load_machine_file
from cncmacro.syntax.document import ParsedDocument

ROOT = Path(__file__).resolve().parent.parent
BROKEN = "O0001\n#1=[2+3\nG01 X10. F100.\nIF[#1 GT] GOTO5\nM30\n"


def _diagnostics() -> list[Diagnostic]:
    found = syntax_diagnostics(ParsedDocument(BROKEN).program, "O0001.nc")
    found.append(Diagnostic("O0001.nc", 2, 0, 2, 3, "warning", "macro-alarm", "ALARM 3001 reached"))
    found.append(Diagnostic("O0001.nc", 4, 0, 4, 3, "hint", "not-executed", "never reached"))
    return found


def test_every_design_code_has_a_default_severity() -> None:
    assert CODES["syntax"].severity == "error"
    assert CODES["duplicate-label"].severity == "warning"
    assert CODES["vacant-argument"].severity == "information"
    assert CODES["not-executed"].severity == "hint"
    assert all(info.severity in ("error", "warning", "information", "hint") for info in CODES.values())
    documented = design_codes()
    assert set(documented) == set(CODES)
    assert all(CODES[code].severity in levels.split(" / ") for code, levels in documented.items())


def design_codes() -> dict[str, str]:
    """docs/design.md's table of diagnostic codes: code -> its default severity as written."""
    table = (ROOT / "docs" / "design.md").read_text(encoding="utf-8").split("### Diagnostic codes")[1]
    return {m.group(1): m.group(2) for m in re.finditer(r"^\| `([a-z0-9-]+)` \| ([a-z /]+) \|", table, re.M)}


def test_the_design_table_and_the_code_table_agree_on_severities() -> None:
    for code, severity in design_codes().items():
        assert CODES[code].severity == severity.split(" /")[0], code


def test_a_code_can_be_given_another_severity() -> None:
    before = _diagnostics()
    assert [d.code for d in before].count("syntax") == 2
    after = apply_severities(before, {"syntax": "warning", "not-executed": "information"})
    assert [d.severity for d in after if d.code == "syntax"] == ["warning", "warning"]
    assert [d.severity for d in after if d.code == "not-executed"] == ["information"]
    assert [d.severity for d in after if d.code == "macro-alarm"] == ["warning"]  # untouched
    assert [(d.line, d.code, d.message) for d in after] == [(d.line, d.code, d.message) for d in before]


def test_off_drops_the_code_and_keeps_the_rest_in_order() -> None:
    before = _diagnostics()
    after = apply_severities(before, {"macro-alarm": "off"})
    assert [d.code for d in after] == [d.code for d in before if d.code != "macro-alarm"]


def test_values_are_read_in_any_case() -> None:
    after = apply_severities(_diagnostics(), {"macro-alarm": "Error"})
    assert [d.severity for d in after if d.code == "macro-alarm"] == ["error"]


def test_no_overrides_changes_nothing() -> None:
    before = _diagnostics()
    assert apply_severities(before, {}) == before


def test_an_unknown_code_is_a_clear_error() -> None:
    with pytest.raises(ValueError, match="'macro-alram' is not a diagnostic code"):
        apply_severities(_diagnostics(), {"macro-alram": "off"})


def test_an_unknown_severity_is_a_clear_error() -> None:
    with pytest.raises(ValueError, match="'syntax' must be one of error, warning, information, hint, off"):
        apply_severities(_diagnostics(), {"syntax": "fatal"})


def _machine_file(tmp_path: Path, text: str) -> Path:
    path = tmp_path / ".cncmacro.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_machine_file_severity_table_is_read(tmp_path: Path) -> None:
    settings = load_machine_file(
        _machine_file(tmp_path, 'dialect = "fanuc"\n[severity]\nmacro-alarm = "error"\nnot-executed = "OFF"\n')
    )
    assert settings.severity == {"macro-alarm": "error", "not-executed": "off"}
    after = apply_severities(_diagnostics(), settings.severity)
    assert "not-executed" not in {d.code for d in after}
    assert [d.severity for d in after if d.code == "macro-alarm"] == ["error"]


def test_machine_file_without_severity_table_changes_nothing(tmp_path: Path) -> None:
    assert load_machine_file(_machine_file(tmp_path, 'dialect = "fanuc"\n')).severity == {}


def test_machine_file_bad_severity_names_the_key(tmp_path: Path) -> None:
    with pytest.raises(MachineFileError, match=r"'severity\.syntax' must be one of error, warning"):
        load_machine_file(_machine_file(tmp_path, '[severity]\nsyntax = "loud"\n'))
    with pytest.raises(MachineFileError, match=r"'severity\.syntax' must be one of"):
        load_machine_file(_machine_file(tmp_path, "[severity]\nsyntax = 3\n"))


def test_machine_file_severity_must_be_a_table(tmp_path: Path) -> None:
    with pytest.raises(MachineFileError, match="'severity' must be a table"):
        load_machine_file(_machine_file(tmp_path, 'severity = "off"\n'))
