"""Honest geometry in the editor (docs/semantics.md §8, "Arcs" and "Units"): an arc the control
cannot cut as written is found on its own line, and a G20 program's lenses speak inches."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, diagnostics_for, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


def found(got: types.PublishDiagnosticsParams) -> list[tuple[int, str, types.DiagnosticSeverity | None]]:
    return [(d.range.start.line, str(d.code), d.severity) for d in got.diagnostics]


async def test_arc_findings_are_on_the_arcs_lines(fanuc_en: LanguageClient) -> None:
    # line 2: R10. for a chord of 50 (a warning, the run goes on); line 4: R with the end at the
    # start (a warning); line 5: I10.1 from X0 to X20.: 10.1 and 9.9 from the centre, alarm 20,
    # where the run stops (the M30 after it is never reached)
    text = "O0100\nG90 G17 G00 X0 Y0\nG02 X50. Y0 R10. F100\nG00 X0 Y0\nG02 X0 Y0 R10.\nG03 X20. Y0 I10.1 J0\nM30\n"
    uri = open_file(fanuc_en, FANUC / "geometry_arcs.nc", text)
    got = await diagnostics_for(fanuc_en, uri, 1)
    sev = types.DiagnosticSeverity
    warning, error, hint = sev.Warning, sev.Error, sev.Hint
    assert found(got) == [(2, "arc-short-radius", warning), (4, "arc-r-full-circle", warning),
                          (5, "arc-radius", error), (6, "not-executed", hint)]  # fmt: skip
    (alarm,) = [d for d in got.diagnostics if d.code == "arc-radius"]
    assert "alarm 20" in alarm.message and "0.200 off its circle" in alarm.message


async def test_an_inch_programs_lens_is_in_inches(fanuc_en: LanguageClient) -> None:
    # G20: X0 -> X10. at F20. is 10 in, 30 s; the rapid back 254 mm at 24000 mm/min 0.635 s
    text = "O0101\nG20 G90 G00 X0 Y0\nG01 X10. F20.\nG00 X0\nM30\n"
    uri = open_file(fanuc_en, FANUC / "geometry_inch.nc", text)
    await diagnostics_for(fanuc_en, uri, 1)
    got = await fanuc_en.text_document_code_lens_async(types.CodeLensParams(types.TextDocumentIdentifier(uri)))
    titles = [(lens.range.start.line, lens.command.title if lens.command else "") for lens in got or []]
    assert titles == [(0, "≈ 31 s · 10.0 in cut · 10.0 in rapid")]


async def test_a_unit_change_after_a_move_is_a_warning_on_its_line(fanuc_en: LanguageClient) -> None:
    text = "O0102\nG21 G90 G00 X0 Y0\nG01 X10. F100\nG20\nG01 X1.\nM30\n"
    uri = open_file(fanuc_en, FANUC / "geometry_units.nc", text)
    got = await diagnostics_for(fanuc_en, uri, 1)
    assert found(got) == [(3, "unit-change", types.DiagnosticSeverity.Warning)]
