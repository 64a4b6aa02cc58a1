"""docs/semantics.md §9: on FANUC a tap's P dwells at the bottom of the hole and again at the R point
on its way out (``DrillCycle.dwell_at_r``; FANUC's tapping format: "P_ : Dwell time at the bottom of
the hole and at point R when a return is made"), and the hover of the P of a G84/G74 (a lathe's
G84/G88) says so, in English and Chinese, from the same data the run times the hole by. The table
of words is shared with Mitsubishi and Mazak, whose taps dwell at the bottom only: their hover
keeps "dwell at the bottom". Before, every profile's hover said "dwell at the bottom (ms)"."""

from __future__ import annotations

import pytest

from cncmacro.dialects import get_dialect
from cncmacro.ide.cycle_words import cycle_signature, cycle_word_at
from cncmacro.syntax.block_parser import parse_block

from .documents import document

AT_R = (
    "dwell at the bottom of the hole and again at the R point on the way out (ms)",
    "孔底及返回到R点时的暂停时间（毫秒）",
)
BOTTOM = ("dwell at the bottom (ms)", "孔底暂停时间（毫秒）")
MILL_TAP = "G99 G84 X10. Y0 Z-10. R2. P1000 F600"  # P at column 26


def _p_meaning(text: str, column: int, profile: object) -> tuple[str, str]:
    dialect = profile if not isinstance(profile, str) else get_dialect(profile)
    found = cycle_word_at(dialect, parse_block(text), column)  # type: ignore[arg-type]
    assert found is not None and found.word.letter == "P"
    return found.word.en, found.word.zh


@pytest.mark.parametrize("profile", ["fanuc-0i", "fanuc-30i"])
@pytest.mark.parametrize("code", ["G84", "G74"])
def test_a_fanuc_taps_p_is_the_dwell_at_the_bottom_and_at_r(profile: str, code: str) -> None:
    assert _p_meaning(MILL_TAP.replace("G84", code), 26, profile) == AT_R


@pytest.mark.parametrize("profile", ["mitsubishi-m70", "mazak-eia"])
def test_mitsubishi_and_mazak_taps_dwell_at_the_bottom_only(profile: str) -> None:
    assert _p_meaning(MILL_TAP, 26, profile) == BOTTOM


def test_other_fanuc_cycles_keep_the_dwell_at_the_bottom() -> None:
    assert _p_meaning("G82 X10. Y0 Z-10. R2. P1000 F600", 22, "fanuc-0i") == BOTTOM


@pytest.mark.parametrize("code", ["G84", "G88"])
def test_a_fanuc_lathes_tap_says_the_same(code: str) -> None:
    text = f"{code} X0 C0 Z-10. R-5. P500 F1."  # P at column 21
    assert _p_meaning(text, 22, "fanuc-0i-lathe") == AT_R
    assert _p_meaning(text, 22, get_dialect("fanuc-30i").lathe_variant) == AT_R
    assert _p_meaning("G85 X0 C0 Z-10. R-5. P500 F1.", 22, "fanuc-0i-lathe") == BOTTOM


def test_signature_help_lists_the_same_meaning() -> None:
    doc = document("O0001", MILL_TAP, "M30", profile="fanuc-0i")
    found = cycle_signature(doc, 1, 27)
    assert found is not None and found.active is not None
    word = found.form.words[found.active]
    assert (word.letter, word.en, word.zh) == ("P", *AT_R)
