"""Cycle words without a server: which block of a two-block cycle a line is (the run's rule for a
written block: G71–G73 with P and Q, G74–G76 with an end point; while typing, a letter only the
first block has, else the block above), what a letter means there, and the letter under the
cursor among the block's letters."""

from __future__ import annotations

from cncmacro.dialects import get_dialect
from cncmacro.dialects.cycle_words import FIRST_BLOCK, ONLY_BLOCK, SECOND_BLOCK
from cncmacro.ide.cycle_words import cycle_signature, cycle_word_at
from cncmacro.syntax.block_parser import parse_block

from .documents import document

LATHE = get_dialect("fanuc-0i-lathe")


def _at(text: str, column: int, profile: str = "fanuc-0i-lathe") -> tuple[tuple[str, str], str, str] | None:
    found = cycle_word_at(get_dialect(profile), parse_block(text), column)
    return None if found is None else (found.form.name, found.word.piece, found.word.en)


def test_g71_with_p_and_q_is_the_second_block_and_without_them_the_first() -> None:
    assert _at("G71 U2. R1.", 4) == (FIRST_BLOCK, "U(Δd)", "depth of each cut (a radius, no sign), kept until changed")
    assert _at("G71 P10 Q20 U0.5 W0.1", 12) == (SECOND_BLOCK, "U(Δu)", "finishing allowance in X (a diameter, signed)")
    assert _at("G71 P10 U0.5", 8) is not None and _at("G71 P10 U0.5", 8)[0] == FIRST_BLOCK  # type: ignore[index]


def test_g74_to_g76_with_an_end_point_are_the_second_block() -> None:
    assert _at("G74 R0.5", 4)[:2] == (FIRST_BLOCK, "R(e)")  # type: ignore[index]
    assert _at("G74 W-20. P3000 Q5000 R0.2", 26)[:2] == (SECOND_BLOCK, "R(Δd)")  # type: ignore[index]
    assert _at("G76 P021060 Q50 R0.05", 12)[:2] == (FIRST_BLOCK, "Q(Δdmin)")  # type: ignore[index]
    assert _at("G76 U-2.6 W-30. P1300 Q400 F2.", 22)[:2] == (SECOND_BLOCK, "Q(Δd)")  # type: ignore[index]


def test_words_written_without_spaces_are_read_one_by_one() -> None:
    assert _at("G71U2.R1.", 6)[:2] == (FIRST_BLOCK, "R(e)")  # type: ignore[index]  # R starts where U2. ends
    assert _at("G71P10Q20U0.5W0.1", 9)[:2] == (SECOND_BLOCK, "U(Δu)")  # type: ignore[index]


def test_a_letter_the_block_does_not_take_and_the_g_word_itself_say_nothing() -> None:
    assert _at("G71 U2. R1. X5.", 12) is None  # X is no word of G71's first block
    assert _at("G71 U2. R1.", 1) is None  # the code has its own hover
    assert _at("G01 X5. F0.2", 8) is None  # no cycle


def test_on_a_mill_g73_is_peck_drilling_in_one_block() -> None:
    assert _at("G73 X10. Y5. Z-20. R2. Q3. F100.", 23, "fanuc-0i") == (ONLY_BLOCK, "Q", "depth of each peck")
    assert _at("G73 X10. Y5. Z-20. R2. Q3. F100.", 23, "haas") is None  # Haas's letters are not described


def test_a_block_being_typed_is_the_second_after_a_first_block_and_the_first_otherwise() -> None:
    doc = document("O0001", "G71 U2. R1.", "G71 ", "G72 ", "G71 R", "M30", profile="fanuc-0i-lathe")
    after_first = cycle_signature(doc, 2, 4)
    assert after_first is not None and after_first.form.name == SECOND_BLOCK and after_first.active is None
    fresh = cycle_signature(doc, 3, 4)  # no G72 above
    assert fresh is not None and fresh.form.name == FIRST_BLOCK
    retract = cycle_signature(doc, 4, 5)  # R: only the first block has it, whatever is above
    assert retract is not None and retract.form.name == FIRST_BLOCK and retract.active == 1
    assert cycle_signature(doc, 2, 2) is None  # the cursor is on the code itself


def test_the_letter_under_the_cursor_is_active_and_the_letters_written_are_given() -> None:
    doc = document("O0001", "G76 X27.4 Z-30. P1300 Q400 F2.", "M30", profile="gsk980tdi")
    found = cycle_signature(doc, 1, 24)  # on Q400
    assert found is not None and found.form.name == SECOND_BLOCK
    assert [w.letter for w in found.form.words][found.active or 0] == "Q" and found.active == 6
    assert found.given == frozenset("XZPQF")


def test_gsk_g76_and_g92_read_the_run_out_j_k_the_starts_l_and_threads_per_inch_i() -> None:
    # GSK980TDi §3.24.12: "G76 P(m)(r)(a) Q(△dmin) R(d) J_ K_；… F(I)" (J, K the run-out); §3.24.9:
    # "G92 X(U)_ Z(W)_ F_ J_ K_ L" (L: "多头螺纹的头数"); I: "螺纹每英寸牙数"
    gsk = "gsk980tdi"
    first = "G76 P020060 Q100 R0.05 J1 K2"
    assert _at(first, 23, gsk)[:2] == (FIRST_BLOCK, "J")  # type: ignore[index]
    assert _at(first, 26, gsk)[1:] == ("K", "run-out: its length along the long axis (no sign); left out: as J")  # type: ignore[index]
    assert _at("G76 X27.4 Z-30 P1300 Q400 I12", 26, gsk)[:2] == (SECOND_BLOCK, "I")  # type: ignore[index]
    g92 = "G92 X29 Z-30 F2 J1 K2 L2"
    assert _at(g92, 16, gsk)[1] == "J" and _at(g92, 19, gsk)[1] == "K"  # type: ignore[index]
    assert _at(g92, 22, gsk)[1:] == ("L", "starts of the thread, 1-99 (left out: one), kept")  # type: ignore[index]
    assert _at(g92, 13, gsk)[1] == "F"  # type: ignore[index]  # the lead, not F(L): L is a word of its own
    assert _at(g92, 13)[1] == "F(L)"  # type: ignore[index]  # FANUC's manual writes the lead F(L)
    assert _at(g92, 16) is None  # FANUC's G92 has no J
