"""Arguments written without a decimal point on a machine that reads numbers in least input
increments (the machine file's ``decimal_point = "increment"``, docs/semantics.md §5): a length
or angle address (X Y Z U V W A B C I J K R Q) passes least input increments, the others (D E F
H M S T) their value as written, as an NC word of the same block is read. FANUC Series 16i/18i
operator's manual B-63684EN/01, §16 "Position of the decimal point": "The units used for
argument data passed without a decimal point correspond to the least input increment of each
address." The least input increment is 0.001 mm, 0.0001 inch under G20, 0.001° for A, B, C.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from running import final, lines

MACRO = lines("O9000", *(f"#{100 + n}=#{n}" for n in (1, 4, 5, 7, 9, 17, 18, 20, 24, 25, 26)), "M99")


def _folder(tmp_path: Path) -> Path:
    (tmp_path / "O9000.nc").write_text(MACRO, encoding="utf-8")
    return tmp_path


def test_arguments_without_a_point_pass_least_increments(tmp_path: Path) -> None:
    got = final(lines("O0001", "G21", "G65 P9000 X5 Y5. Z-25 A5 I5 J5. D5 F5 Q5 R5 T5", "M30"),
                folder=_folder(tmp_path), decimal_point="increment")  # fmt: skip
    # X5 -> 5 x 0.001 = 0.005; Y5. has a point: 5; Z-25 -> -0.025; A5 -> 0.005 (0.001°)
    assert (got[124], got[125], got[126], got[101]) == (0.005, 5.0, -0.025, 0.005)
    # I5 -> #4 = 0.005, J5. -> #5 = 5; Q5, R5 -> 0.005 (they were 5 each: passed as written)
    assert (got[104], got[105], got[117], got[118]) == (0.005, 5.0, 0.005, 0.005)
    # D, F, T are no lengths: 5 as written
    assert (got[107], got[109], got[120]) == (5.0, 5.0, 5.0)


def test_inch_arguments_without_a_point_pass_tenths_of_a_thousandth(tmp_path: Path) -> None:
    got = final(lines("O0001", "G20", "G65 P9000 X5 A5", "M30"), folder=_folder(tmp_path), decimal_point="increment")
    # X5 -> 5 x 0.0001 inch = 0.0005; A5 -> 5 x 0.001° = 0.005 (an angle's increment in either unit)
    assert got[124] == pytest.approx(0.0005, abs=1e-12) and got[101] == pytest.approx(0.005, abs=1e-12)


def test_g66_arguments_without_a_point_pass_least_increments(tmp_path: Path) -> None:
    got = final(lines("O0001", "G21 G90", "G66 P9000 X5 R2.", "G00 X1.", "G67", "M30"),
                folder=_folder(tmp_path), decimal_point="increment")  # fmt: skip
    assert got[124] == 0.005 and got[118] == 2.0  # X5 -> 0.005; R2. as written


def test_calculator_input_passes_arguments_as_written(tmp_path: Path) -> None:
    got = final(lines("O0001", "G21", "G65 P9000 X5 Q5", "M30"), folder=_folder(tmp_path))
    assert got[124] == 5.0 and got[117] == 5.0


def test_inch_nc_word_without_a_point_is_tenths_of_a_thousandth() -> None:
    # the same rule for an NC word: G20 X10 -> 10 x 0.0001 inch = 0.001 (it was 0.010: 0.001 per unit)
    got = final(lines("G20", "G90 G00 X10 Y20.", "#1=#5001", "#2=#5002", "M30"), decimal_point="increment")
    assert got[1] == pytest.approx(0.001, abs=1e-12) and got[2] == 20.0


def test_adp_gives_back_the_value_written(tmp_path: Path) -> None:
    (tmp_path / "O9001.nc").write_text(lines("O9001", "#101=#24", "#102=ADP[#24]", "#103=ADP[#25]",
                                             "#24=7", "#104=ADP[#24]", "M99"), encoding="utf-8")  # fmt: skip
    got = final(lines("O0001", "G21", "G65 P9001 X10 Y10.", "M30"), "fanuc-30i", folder=tmp_path,
                decimal_point="increment")  # fmt: skip
    # X10 passes 0.010 and ADP makes it 10 again; Y10. was passed with its point: ADP keeps 10;
    # #24 written again by the macro (7) is no argument any more: ADP keeps 7
    assert (got[101], got[102], got[103], got[104]) == (0.01, 10.0, 10.0, 7.0)
