"""The interface signals read or written as one number are the single-bit signals
(docs/semantics.md §8, "Interface signals"): on `fanuc` #1032 is UI000–UI015, the sum of
#[1000+i] × 2^i, and #1132 is UO000–UO015, bit i the signal #[1100+i] (the 0i table's rows,
seed 003 §4.1, parameter MIF = 0); on `fanuc-30i` #1032 and #1132 are the 32 signals
#1000–#1031 and #1100–#1131 (MIF = 1), signed; on `gsk980tdi` #1032 and #1132 are the bytes
G54/G55 and F54/F55, which #1000–#1015 and #1100–#1115 read bit by bit. They were stored apart.
"""

from __future__ import annotations

import pytest

from running import final, lines


@pytest.mark.parametrize("dialect", ["fanuc", "fanuc-30i"])
def test_writing_output_bits_changes_the_output_word(dialect: str) -> None:
    # #1100 = 1 (2^0) and #1103 = 1 (2^3): #1132 = 1 + 8 = 9
    got = final(lines("#1132=0", "#1100=1", "#1103=1", "#101=#1132", "M30"), dialect)
    assert got[101] == 9.0


@pytest.mark.parametrize("dialect", ["fanuc", "fanuc-30i"])
def test_writing_the_output_word_sets_its_bits(dialect: str) -> None:
    # 6 = 0b110: #1100 = 0, #1101 = 1, #1102 = 1, #1103 = 0
    got = final(lines("#1100=1", "#1103=1", "#1132=6", "#101=#1100", "#102=#1101", "#103=#1102", "#104=#1103",
                      "M30"), dialect)  # fmt: skip
    assert (got[101], got[102], got[103], got[104]) == (0.0, 1.0, 1.0, 0.0)


@pytest.mark.parametrize("dialect", ["fanuc", "fanuc-30i", "gsk980tdi"])
def test_the_input_word_reads_the_input_bits(dialect: str) -> None:
    # #1000 = 1, #1002 = 1, #1015 = 1: #1032 = 1 + 4 + 32768 = 32773
    got = final(lines("#101=#1032", "M30"), dialect, presets={1000: 1.0, 1002: 1.0, 1015: 1.0})
    assert got[101] == 32773.0


def test_a_preset_input_word_gives_its_bits() -> None:
    # --set 1032=5 (0b101): #1000 = 1, #1001 = 0, #1002 = 1
    got = final(lines("#101=#1000", "#102=#1001", "#103=#1002", "M30"), presets={1032: 5.0})
    assert (got[101], got[102], got[103]) == (1.0, 0.0, 1.0)


def test_gsk_output_word_reads_the_output_bits() -> None:
    # F54.1 and F55.0 (#1101, #1108): #1132 = 2 + 256 = 258
    got = final(lines("#101=#1132", "M30"), "gsk980tdi", presets={1101: 1.0, 1108: 1.0})
    assert got[101] == 258.0


def test_30i_output_word_is_signed_in_bit_31() -> None:
    # -1 sets all 32 bits: #1131 = 1, and reads back -1 (bit 31 the sign)
    got = final(lines("#1132=-1", "#101=#1131", "#102=#1132", "#103=#1100", "M30"), "fanuc-30i")
    assert (got[101], got[102], got[103]) == (1.0, -1.0, 1.0)


def test_0i_word_of_32_outputs_has_no_bits_and_keeps_its_value() -> None:
    # #1133 (UO100-UO131) has no single-bit variables on the 0i: stored as written
    got = final(lines("#1133=12345", "#101=#1133", "#102=#1132", "M30"))
    assert got[101] == 12345.0 and got[102] == 0.0
