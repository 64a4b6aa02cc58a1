"""A lathe program read under a mill profile (docs/profiles.md "How a lathe program is
recognised"): its signs are counted, one strong sign or two ordinary ones of different kinds make
one ``profile-suggestion`` naming a lathe profile, and a mill's own G76, G73, G99, G92, G50 and
tool words make none."""

from __future__ import annotations

from pathlib import Path

from analysis_helpers import analyse_files
from cncmacro.analysis.diagnostics import Diagnostic
from cncmacro.dialects import DIALECTS
from cncmacro.dialects.registry import lathe_forms
from static_helpers import lines

SHAFT = lines(
    "O0100 (SHAFT)",
    "G00 X52. Z2.",
    "G71 U2. R0.5",
    "G71 P10 Q20 U0.5 W0.1 F0.25",
    "N10 G00 X20.",
    "G01 Z-20.",
    "N20 X52.",
    "G70 P10 Q20",
    "M30",
)
THREAD = lines("O0101 (THREAD)", "G00 X34. Z4.", "G76 P010060 Q100 R0.05", "G76 X28.05 Z-25. P975 Q500 F1.5", "M30")
MILL = lines(
    "O2000 (BORE AND PECK)",
    "T1 M06",
    "G90 G54 G00 X0 Y0",
    "G43 Z50. H01",
    "S800 M03",
    "G99 G76 X10. Y10. Z-20. R2. Q0.5 P1000 F80.",  # fine boring: one block with its hole
    "X20.",
    "G98 G73 X30. Y10. Z-30. R2. Q2. P500 F100.",  # peck drilling: P and Q beside its hole
    "G80",
    "G92 X0 Y0 Z0",  # a mill's coordinate setting: no F
    "G50",  # scaling cancelled: no S
    "T12 M06",
    "G99 G81 X1. Y1. Z-0.5 R0.1 F0.5",  # the R level of a drilling cycle, an inch feed
    "G80 G28 G91 Z0",
    "M30",
)


def suggestions(tmp_path: Path, text: str, dialect: str = "fanuc-0i", locale: str = "en") -> list[Diagnostic]:
    found = analyse_files(tmp_path, {"MAIN.nc": text}, dialect=dialect, locale=locale)
    return [d for d in found if d.code == "profile-suggestion"]


def test_a_roughing_cycle_whose_p_and_q_name_labels_of_the_program_alone_marks_a_lathe_program(tmp_path):
    [hint] = suggestions(tmp_path, SHAFT)
    # on line 4 (G71 P10 Q20 ..., the first strong sign), from G71 (column 0) to the end of Q20 (column 11)
    assert (hint.line + 1, hint.column, hint.end_column, hint.severity) == (4, 0, 11, "information")
    assert "lathe program (G71 P10 Q20 on line 4)" in hint.message  # G70 P10 Q20 is the same kind
    assert "mill profile fanuc-0i" in hint.message and "(cncmacro: dialect=fanuc-0i-lathe)" in hint.message
    assert 'base = "fanuc-0i-lathe"' in hint.message


def test_a_g76_thread_in_two_blocks_alone_marks_a_lathe_program(tmp_path):
    [hint] = suggestions(tmp_path, THREAD)
    assert (hint.line + 1, hint.column) == (3, 0)
    assert "G76 P010060 + G76 on line 3" in hint.message


def test_one_ordinary_sign_or_two_of_one_kind_are_not_enough_two_kinds_are(tmp_path):
    assert suggestions(tmp_path, lines("O1", "T0101", "G00 X40. Z2.", "M30")) == []
    assert suggestions(tmp_path, lines("O1", "T0101", "G00 X40. Z2.", "T0202", "M30")) == []
    [hint] = suggestions(tmp_path, lines("O1", "T0101", "G96 S180 M03", "G00 X40. Z2.", "M30"))
    assert (hint.line + 1, hint.column, hint.end_column) == (2, 0, 5)  # on T0101, the first sign
    assert "T0101 on line 2, G96 on line 3" in hint.message


def test_each_ordinary_sign_counts_with_another(tmp_path):
    signs = {
        "G50 S2500": "G50 S2500",  # the spindle clamp
        "G01 U-2. F0.2": "U-2.",  # an incremental move
        "G99 F0.2": "G99 F0.2",  # feed per revolution
        "G92 X29.2 Z-30. F1.5": "G92 X29.2 Z-30. F1.5",  # a thread
        "G71 P10 Q20 U0.5 W0.1": "G71 P10 Q20",  # a roughing cycle whose shape the file lacks
    }
    for block, shown in signs.items():
        assert suggestions(tmp_path, lines("O1", block, "M30")) == [], block
        [hint] = suggestions(tmp_path, lines("O1", block, "T0303", "M30"))
        assert f"{shown} on line 2, T0303 on line 3" in hint.message, block


def test_a_mill_s_g76_fine_boring_g73_peck_drilling_g99_g92_g50_and_tool_words_are_no_signs(tmp_path):
    for mill in ("fanuc-0i", "fanuc-30i", "haas"):
        assert suggestions(tmp_path, MILL, mill) == [], mill


def test_a_macro_call_s_u_and_w_arguments_are_no_moves(tmp_path):
    text = lines("O1", "G65 P9100 U2. W3.", "T0101", "M30", "O9100", "M99")
    assert suggestions(tmp_path, text) == []


def test_under_a_lathe_profile_nothing_is_suggested(tmp_path):
    for lathe in ("fanuc-0i-lathe", "gsk980tdi"):
        assert suggestions(tmp_path, SHAFT, lathe) == [], lathe


def test_a_mill_profile_offers_its_own_control_s_lathe_else_fanuc_0i_lathe(tmp_path):
    assert lathe_forms("fanuc-0i")[0].name == "fanuc-0i-lathe" and "fanuc-haas-lathe" not in DIALECTS
    assert lathe_forms("a-mill-without-a-lathe")[0].name == "fanuc-0i-lathe"
    # haas has a lathe of its own, haas-lathe (docs/profiles.md "haas-lathe")
    [hint] = suggestions(tmp_path, SHAFT, "haas")
    assert "mill profile haas" in hint.message and "Choose the lathe profile haas-lathe " in hint.message
    # fanuc-30i has a lathe form of its own, which the machine file's lathe = true chooses
    [hint] = suggestions(tmp_path, SHAFT, "fanuc-30i")
    assert "mill profile fanuc-30i" in hint.message and "Choose its lathe form, FANUC 30i-B lathe" in hint.message
    assert 'Set lathe = true in .cncmacro.toml (with base = "fanuc-30i")' in hint.message


def test_a_lathe_program_with_gsk_macro_a_arithmetic_is_offered_gsk980tdi(tmp_path):
    # fanuc-0i-lathe has no G65 H01 either: the first lathe that reads the file cleanly is offered
    text = SHAFT.replace("G00 X52. Z2.\n", "G00 X52. Z2.\nG65 H01 P#101 Q5\n", 1)
    [hint] = suggestions(tmp_path, text)
    assert "lathe program" in hint.message and "Choose the lathe profile gsk980tdi " in hint.message


def test_the_suggestion_is_written_in_chinese_too(tmp_path):
    [hint] = suggestions(tmp_path, SHAFT, locale="zh-CN")
    assert "这看起来是车床程序（第 4 行 G71 P10 Q20）" in hint.message
    assert "铣床系统 fanuc-0i" in hint.message and "(cncmacro: dialect=fanuc-0i-lathe)" in hint.message
