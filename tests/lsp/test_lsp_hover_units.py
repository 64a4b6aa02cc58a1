"""The unit a system variable's hover gives: a rotary axis's position or offset in degrees, a
length in the unit the program is in (inch under G20, as the code lens counts it), and both when
the hover cannot know it (a program no analysis run started from)."""

from __future__ import annotations

import pytest
from pytest_lsp import LanguageClient

from cncmacro.dialects import describe

from .lsp_session import FANUC, HAAS, close_file, diagnostics_for, hover_text, open_file

ASYNC = pytest.mark.asyncio(loop_scope="session")


def facts(text: str) -> str:
    """The hover's line of facts (access · unit · axis)."""
    return next(line for line in text.splitlines() if " · " in line and ":" in line)


@ASYNC
async def test_a_rotary_axis_variable_is_in_degrees(fanuc_en: LanguageClient, fanuc_zh: LanguageClient) -> None:
    # fanuc-0i-lathe: axes X, Z, C, Y, so #5003, #5023, #5043, #5223 are the C axis; fanuc-0i: X, Y, Z, A,
    # so #5004 and #5024 are the A axis. #5001/#5002 stay lengths.
    lathe = "O1 (cncmacro: dialect=fanuc-0i-lathe)\n#1=#5003+#5023+#5043+#5223+#5002\nM30\n"
    uri = open_file(fanuc_en, FANUC / "rotary_lathe.nc", lathe)
    for col in (3, 9, 15, 21):
        text = await hover_text(fanuc_en, uri, 1, col)
        assert "unit: degrees" in facts(text) and "axis: C" in facts(text), text
    assert "unit: mm" in facts(await hover_text(fanuc_en, uri, 1, 27))  # #5002, the Z axis
    close_file(fanuc_en, uri)
    mill = "O2 (cncmacro: dialect=fanuc-0i)\n#1=#5004+#5024\nM30\n"
    uri = open_file(fanuc_zh, FANUC / "rotary_mill.nc", mill)
    for col in (3, 9):
        text = await hover_text(fanuc_zh, uri, 1, col)
        assert "单位: 度" in facts(text) and "轴: A" in facts(text), text
    close_file(fanuc_zh, uri)


@ASYNC
async def test_haas_a_axis_is_in_degrees(haas_en: LanguageClient) -> None:
    uri = open_file(haas_en, HAAS / "rotary_haas.nc", "O3 (cncmacro: dialect=haas)\n#1=#5004+#5024\nM30\n")
    for col in (3, 9):
        assert "unit: degrees" in facts(await hover_text(haas_en, uri, 1, col))
    close_file(haas_en, uri)


@ASYNC
async def test_a_length_variable_follows_g20_and_g21(fanuc_en: LanguageClient) -> None:
    # the run starts from O7001 and completes in G20: positions and offsets read in inches
    inch = "O7001 (INCH)\n(cncmacro: dialect=fanuc-0i)\nG20 G90 G54\nG00 X1.\n#1=#5001+#5221+#2001\nM30\n"
    uri = open_file(fanuc_en, FANUC / "O7001.nc", inch)
    await diagnostics_for(fanuc_en, uri, 1)
    for col in (3, 9, 15):
        assert "unit: inch" in facts(await hover_text(fanuc_en, uri, 4, col))
    close_file(fanuc_en, uri)
    metric = inch.replace("G20", "G21").replace("O7001", "O7002")
    uri = open_file(fanuc_en, FANUC / "O7002.nc", metric)
    await diagnostics_for(fanuc_en, uri, 1)
    assert "unit: mm" in facts(await hover_text(fanuc_en, uri, 4, 3))
    assert "inch" not in facts(await hover_text(fanuc_en, uri, 4, 3))
    close_file(fanuc_en, uri)


def test_a_length_whose_unit_is_not_known_names_both() -> None:
    # before an analysis run has timed the program (or in completion, which has no line's unit)
    assert describe.unit_text("mm", None, "en") == "mm (inch under G20)"
    assert describe.unit_text("mm", None, "zh-CN") == "mm（G20 下为英寸）"
    assert describe.unit_text("ms", True, "en") == "ms"  # not a length: as the row says
