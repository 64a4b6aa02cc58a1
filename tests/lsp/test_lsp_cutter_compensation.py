"""Cutter radius compensation in the editor (docs/semantics.md §12): the run's findings land on
the line the control stops on."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, diagnostics_for, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


def found(got: types.PublishDiagnosticsParams) -> list[tuple[int, str, types.DiagnosticSeverity | None]]:
    return [(d.range.start.line, str(d.code), d.severity) for d in got.diagnostics if d.code != "not-executed"]


async def test_a_start_up_on_an_arc_is_alarm_34_on_its_line(fanuc_en: LanguageClient) -> None:
    # line 3 (0-based) starts G41 on a G02: PS0034, where the run stops
    text = "O0110\nG10 L12 P1 R5.\nG90 G17 G00 X0 Y0\nG41 D1 G02 X20. Y0 R10. F100\nM30\n"
    uri = open_file(fanuc_en, FANUC / "cutter_arc_start.nc", text)
    got = await diagnostics_for(fanuc_en, uri, 1)
    assert found(got) == [(3, "cutter-arc", types.DiagnosticSeverity.Error)]
    (alarm,) = got.diagnostics[:1]
    assert "alarm 34" in alarm.message


async def test_a_groove_narrower_than_the_cutter_is_interference_on_the_block_that_finds_it(
    fanuc_en: LanguageClient,
) -> None:
    # radius 5 in a groove 3 wide: the bottom (line 6, 0-based) would be cut backwards; the control
    # finds it reading the right wall (line 7) and stops there: PS0041, naming line 7 (1-based) of the bottom
    text = ("O0111\nG10 L12 P1 R5.\nG90 G17 G00 X0 Y10.\nG41 D1 G01 Y0 F100\nX20.\nY-10.\nX23.\nY0\nX40.\n"
            "G40 Y10.\nM30\n")  # fmt: skip
    uri = open_file(fanuc_en, FANUC / "cutter_groove.nc", text)
    got = await diagnostics_for(fanuc_en, uri, 1)
    assert found(got) == [(7, "cutter-interference", types.DiagnosticSeverity.Error)]
    assert "alarm 41" in got.diagnostics[0].message and "line 7" in got.diagnostics[0].message
