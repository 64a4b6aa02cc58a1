"""``cncmacro check`` over a folder where one file trips the checker: every other file's findings
still print (docs/design.md "Diagnostic codes": ``internal-error``)."""

from __future__ import annotations

import io
import json
from pathlib import Path

import pytest

from cncmacro.analysis.checks import static_checks
from cncmacro.analysis.runs.run_checks import EntryRun
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.cli.check import check_paths


def check_json(*paths: Path) -> tuple[int, list[dict[str, object]]]:
    out, err = io.StringIO(), io.StringIO()
    status = check_paths([str(p) for p in paths], out, err, "json")
    return status, json.loads(out.getvalue())


def folder(tmp_path: Path, hard: str) -> Path:
    (tmp_path / "O0001.nc").write_text(f"O0001\n{hard}\nM30\n", encoding="utf-8")
    (tmp_path / "O0002.nc").write_text("O0002\n#1=#50+1\nM30\n", encoding="utf-8")
    return tmp_path


def mistakes(found: list[dict[str, object]]) -> list[tuple[str, int, str]]:
    return [(Path(str(d["file"])).name, int(d["line"]), str(d["code"])) for d in found]  # type: ignore[call-overload]


@pytest.mark.parametrize("hard", ["#1=1" + "+1" * 500, "#1=" + "-" * 1000 + "1"])
def test_a_file_with_a_very_long_expression_does_not_silence_the_others(tmp_path: Path, hard: str) -> None:
    status, found = check_json(folder(tmp_path, hard))
    assert status == 1
    assert mistakes(found) == [("O0002.nc", 2, "variable-number")]


def test_a_checker_fault_on_one_line_is_an_internal_error_there(tmp_path: Path, monkeypatch) -> None:
    real = static_checks.check_statements

    def faulty(block, ctx, facts):  # type: ignore[no-untyped-def]
        if any(getattr(getattr(s, "target", None), "number", 0) == 7 for s in block.statements):
            raise RuntimeError("a bug")
        return real(block, ctx, facts)

    monkeypatch.setattr(static_checks, "check_statements", faulty)
    (tmp_path / "O0001.nc").write_text("O0001\n#7=1\n#2=#50\nM30\n", encoding="utf-8")
    status, found = check_json(tmp_path / "O0001.nc")
    assert status == 1
    assert mistakes(found) == [("O0001.nc", 2, "internal-error"), ("O0001.nc", 3, "variable-number")]
    assert "fault of the checker, not of the program" in str(found[0]["message"])


def test_a_checker_fault_in_one_run_costs_only_that_run(tmp_path: Path, monkeypatch) -> None:
    real = EntryRun.advance

    def faulty(self, should_cancel=None):  # type: ignore[no-untyped-def]
        if self.entry.file.path.endswith("O0001.nc"):
            raise RecursionError("deep")
        return real(self, should_cancel)

    monkeypatch.setattr(EntryRun, "advance", faulty)
    (tmp_path / "O0001.nc").write_text("O0001\n#1=1\nM30\n", encoding="utf-8")
    (tmp_path / "O0002.nc").write_text("O0002\n#1=0\n#2=1/#1\nM30\n", encoding="utf-8")
    status, found = check_json(tmp_path)
    assert mistakes(found) == [("O0001.nc", 1, "internal-error"), ("O0002.nc", 3, "division-by-zero")]
    assert status == 1


def test_when_the_whole_analysis_fails_each_file_is_checked_on_its_own(tmp_path: Path, monkeypatch) -> None:
    real = WorkspaceAnalysis._result

    def faulty(self, version):  # type: ignore[no-untyped-def]
        if any(Path(p).name == "O0001.nc" for p in self.docs):
            raise MemoryError
        return real(self, version)

    monkeypatch.setattr(WorkspaceAnalysis, "_result", faulty)
    status, found = check_json(folder(tmp_path, "#1=1"))
    assert mistakes(found) == [("O0001.nc", 1, "internal-error"), ("O0002.nc", 2, "variable-number")]
    assert status == 1
