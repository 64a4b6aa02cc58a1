"""Tool nose radius compensation in the editor (docs/semantics.md §12): the GSK980TDi's rule that
a G70-G73 shape is compensated only from a G41/G42 on its first block lands on the line that
breaks it."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import GSK, diagnostics_for, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


async def test_a_g42_after_the_shape_first_block_is_a_warning_on_its_line(gsk_en: LanguageClient) -> None:
    # the workspace's machine file: gsk980tdi. G42 on line 7 (0-based), the shape's second block: the
    # control does not compensate the cycle (GSK980TDi §3.23.1, no alarm): a cycle-shape warning there
    text = ("O0120\nG10 P10001 R0.8 Q3\nT0101\nG98 G00 X70. Z5.\nG71 U1. R0.5\nG71 P10 Q20 U0.4 W0.1 F100\n"
            "N10 G00 X40.\nG42 G01 Z0 F50\nX60. Z-20.\nN20 Z-40.\nG70 P10 Q20\nM30\n")  # fmt: skip
    uri = open_file(gsk_en, GSK / "nose_second_block.CNC", text)
    got = await diagnostics_for(gsk_en, uri, 1)
    found = [(d.range.start.line, str(d.code), d.severity) for d in got.diagnostics if d.code != "not-executed"]
    assert found == [(7, "cycle-shape", types.DiagnosticSeverity.Warning)]
    assert "first block" in got.diagnostics[0].message
