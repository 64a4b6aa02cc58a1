"""SARIF 2.1.0 output of diagnostics (``cli.sarif.to_sarif``).

No pinned PyPI package ships the SARIF 2.1.0 JSON schema (sarif-om, sarif-tools, pysarif and
sarif-pydantic were looked at), so these tests hold the log to the schema's required
properties and value sets directly."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from cncmacro.analysis import syntax_diagnostics
from cncmacro.analysis.diagnostics import Diagnostic, Related
from cncmacro.cli.sarif import to_sarif
from cncmacro.syntax.document import ParsedDocument

LEVELS = {"none", "note", "warning", "error"}


def _assert_region(region: dict) -> None:
    assert set(region) >= {"startLine", "startColumn", "endLine", "endColumn"}
    assert region["startLine"] >= 1 and region["startColumn"] >= 1
    assert (region["endLine"], region["endColumn"]) > (region["startLine"], region["startColumn"])


def _assert_location(loc: dict) -> None:
    physical = loc["physicalLocation"]
    assert isinstance(physical["artifactLocation"]["uri"], str) and physical["artifactLocation"]["uri"]
    _assert_region(physical["region"])


def assert_sarif_structure(log: dict) -> None:
    """The properties SARIF 2.1.0 requires, with their value sets."""
    assert log["version"] == "2.1.0"
    assert log["$schema"].endswith("sarif-2.1.0.json")
    assert isinstance(log["runs"], list) and len(log["runs"]) == 1
    run = log["runs"][0]
    driver = run["tool"]["driver"]
    assert driver["name"] == "cncmacro"
    rule_ids = [r["id"] for r in driver["rules"]]
    assert len(rule_ids) == len(set(rule_ids))
    for rule in driver["rules"]:
        assert rule["shortDescription"]["text"]
        assert rule["defaultConfiguration"]["level"] in LEVELS
    for result in run["results"]:
        assert result["message"]["text"]
        assert result["level"] in LEVELS
        assert result["ruleId"] in rule_ids
        assert driver["rules"][result["ruleIndex"]]["id"] == result["ruleId"]
        for loc in result["locations"] + result.get("relatedLocations", []):
            _assert_location(loc)
    json.dumps(log)  # the whole log is plain JSON


def test_syntax_errors_of_a_file_become_sarif_results(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "progs").mkdir()
    text = "O0001\n#1=[2+3\nG01 X10. F100.\nM30\n"
    diagnostics = syntax_diagnostics(ParsedDocument(text).program, "progs/O0001.nc")
    assert diagnostics
    log = to_sarif(diagnostics, "0.1.0")
    assert_sarif_structure(log)
    run = log["runs"][0]
    assert run["tool"]["driver"]["version"] == "0.1.0"
    assert [r["id"] for r in run["tool"]["driver"]["rules"]] == ["syntax"]
    assert run["tool"]["driver"]["rules"][0]["defaultConfiguration"]["level"] == "error"
    first = run["results"][0]
    assert first["ruleId"] == "syntax" and first["level"] == "error"
    assert first["message"]["text"] == diagnostics[0].message
    loc = first["locations"][0]["physicalLocation"]
    assert loc["artifactLocation"]["uri"] == "progs/O0001.nc"
    d = diagnostics[0]
    assert loc["region"] == {
        "startLine": 2,
        "startColumn": d.column + 1,
        "endLine": 2,
        "endColumn": d.end_column + 1,
    }


def test_levels_rules_and_related_locations(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    caller = Related(str(tmp_path / "O1000.nc"), 11, 0, 24, "called from O1000 with G65 P9100")
    diagnostics = [
        Diagnostic("O9100.nc", 6, 0, 6, 30, "warning", "macro-alarm", "ALARM 3001: HOLE COUNT MISSING", (caller,)),
        Diagnostic("O9100.nc", 9, 3, 9, 6, "information", "vacant-argument", "#2 (B) is never passed"),
        Diagnostic("O9100.nc", 20, 0, 22, 4, "hint", "not-executed", "never reached", tags=("unnecessary",)),
        Diagnostic("O9100.nc", 3, 0, 3, 5, "error", "macro-alarm", "one every run reaches"),
    ]
    log = to_sarif(diagnostics, "0.1.0")
    assert_sarif_structure(log)
    run = log["runs"][0]
    rules = {r["id"]: r["defaultConfiguration"]["level"] for r in run["tool"]["driver"]["rules"]}
    assert rules == {"macro-alarm": "error", "not-executed": "note", "vacant-argument": "note"}  # its default
    assert [r["level"] for r in run["results"]] == ["warning", "note", "note", "error"]
    related = run["results"][0]["relatedLocations"]
    assert related[0]["message"]["text"] == "called from O1000 with G65 P9100"
    assert related[0]["physicalLocation"]["artifactLocation"]["uri"] == "O1000.nc"
    assert related[0]["physicalLocation"]["region"]["startLine"] == 12
    assert run["results"][2]["locations"][0]["physicalLocation"]["region"]["endLine"] == 23
    assert "relatedLocations" not in run["results"][1]


def test_a_file_outside_the_current_folder_gets_an_absolute_uri(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "here").mkdir()
    monkeypatch.chdir(tmp_path / "here")
    elsewhere = tmp_path / "other" / "螺纹 切削.nc"
    log = to_sarif([Diagnostic(str(elsewhere), 0, 0, 0, 1, "error", "syntax", "x")], "0.1.0")
    uri = log["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
    assert uri.startswith("file:///")
    assert uri.endswith("/other/%E8%9E%BA%E7%BA%B9%20%E5%88%87%E5%89%8A.nc")


def test_no_diagnostics_is_an_empty_run() -> None:
    log = to_sarif([], "0.1.0")
    assert_sarif_structure(log)
    assert log["runs"][0]["results"] == [] and log["runs"][0]["tool"]["driver"]["rules"] == []
