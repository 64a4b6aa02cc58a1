"""The checks of a local subprogram call (Haas ``M97 P n L k``, docs/semantics.md §5 "M97 local
subprogram call") where the dialect has the switch: its P is a label of the program itself
(``undefined-label`` when there is none, alarm 128 when run), its L a count, and the blocks it
calls are run by the analysis, so they are not ``not-executed``. Without the switch M97 is a
plain M code and none of this applies.
"""

from __future__ import annotations

from pathlib import Path

from cncmacro.analysis.checks.static_checks import static_diagnostics
from cncmacro.analysis.diagnostics import Diagnostic
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.dialects import Dialect, get_dialect
from cncmacro.library.machine_file import MachineSettings
from cncmacro.syntax.document import ParsedDocument
from running import haas_switched
from static_helpers import at, coded, lines

HAAS = haas_switched()


def check(text: str, dialect: Dialect = HAAS, locale: str = "en") -> list[Diagnostic]:
    doc = ParsedDocument(text)
    return static_diagnostics(doc.program, "MAIN.nc", dialect, MachineSettings(), None, locale)


def test_5_m97_p_to_a_missing_n_is_undefined_label() -> None:
    text = lines("O0011", "M97 P99", "N10 M97 P1000 L2", "M30", "N1000 #100=1", "M99")
    [d] = coded(check(text), "undefined-label")
    assert at(d) == (2, 5, 7, "error")
    assert d.message == "M97 P99: there is no N99 in O0011 (alarm 128)"
    [zh] = coded(check(text, locale="zh-cn"), "undefined-label")
    assert zh.message == "M97 P99：O0011 中没有 N99（报警 128）"
    assert coded(check(text, get_dialect("fanuc")), "undefined-label") == []  # M97 is a plain M code there


def test_5_m97_p_looks_in_its_own_program_only() -> None:
    text = lines("O0011", "M97 P5", "M30", "O0012", "N5 M99")
    [d] = coded(check(text), "undefined-label")
    assert at(d)[:2] == (2, 5)


def test_5_m97_without_p_and_with_a_bad_l() -> None:
    found = check(lines("M97", "M97 P5 L0", "M97 P0", "M30", "N5 M99"))
    assert [at(d)[0] for d in coded(found, "undefined-label")] == [1]
    assert [at(d)[:2] for d in coded(found, "repeat-count-range")] == [(2, 7)]
    assert [at(d)[:2] for d in coded(found, "label-range")] == [(3, 5)]
    assert check(lines("M97", "M97 P5 L0", "M97 P0", "M30", "N5 M99"), get_dialect("fanuc")) == []


def _analyse(tmp_path: Path, text: str, dialect: Dialect) -> list[Diagnostic]:
    ws = WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000))
    ws.dialect_of = lambda lines: dialect  # type: ignore[method-assign]
    path = tmp_path / "O0011.nc"
    path.write_text(text, encoding="utf-8")
    ws.open(str(path), text, 1)
    result = ws.analyze(str(path))
    assert result is not None
    return [d for diags in result.diagnostics.values() for d in diags]


def test_5_the_blocks_an_m97_calls_are_executed(tmp_path: Path) -> None:
    text = lines("O0011", "M97 P1000", "M30", "N1000 #100=1", "G01 X1. F100", "M99")
    assert coded(_analyse(tmp_path, text, HAAS), "not-executed") == []
    [d] = coded(_analyse(tmp_path, text, get_dialect("fanuc")), "not-executed")
    assert (d.line + 1, d.end_line + 1) == (4, 6)  # without the switch the run ends at M30
