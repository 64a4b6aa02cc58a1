"""The machine file's ``[limits]`` in the editor (docs/semantics.md §11): the language server puts
the over-travel alarm, the unknown tool and the spindle speed above the top on their lines, each
with its code and severity, and the over-travel in Chinese for a Chinese editor."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import HERE, diagnostics_for, open_file, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="session")

LIMITS = HERE / "workspace_limits"  # G54 X -300, X travel [-500, 0], spindle 8000, tools 1-24
limits_en = session_fixture(LIMITS, "en")
limits_zh = session_fixture(LIMITS, "zh-CN")
# machine X = program X - 300: X320. is machine X20, 20 mm past the + limit 0
PROGRAM = "O0001\nG90 G54 G00 X0\nS9000 M03\nT30 M06\nG01 X320. F1000\nM30\n"


def _found(params: types.PublishDiagnosticsParams) -> list[tuple[int, object, types.DiagnosticSeverity | None]]:
    return sorted((d.range.start.line, d.code, d.severity) for d in params.diagnostics)


async def test_each_limit_finding_is_on_its_line(limits_en: LanguageClient) -> None:
    uri = open_file(limits_en, LIMITS / "O0001.nc", PROGRAM)
    params = await diagnostics_for(limits_en, uri, 1)
    assert _found(params) == [
        (2, "spindle-limit", types.DiagnosticSeverity.Warning),
        (3, "unknown-tool", types.DiagnosticSeverity.Error),
        (4, "over-travel", types.DiagnosticSeverity.Error),
        (5, "not-executed", types.DiagnosticSeverity.Hint),  # the alarm stops the run before M30
    ]
    [travel] = [d for d in params.diagnostics if d.code == "over-travel"]
    assert "X+ over travel" in travel.message and "20.000 mm past" in travel.message


async def test_the_over_travel_reads_in_chinese(limits_zh: LanguageClient) -> None:
    uri = open_file(limits_zh, LIMITS / "O0002.nc", PROGRAM.replace("O0001", "O0002"))
    params = await diagnostics_for(limits_zh, uri, 1)
    [travel] = [d for d in params.diagnostics if d.code == "over-travel"]
    assert "X 轴+向超程" in travel.message and "20.000 mm" in travel.message
