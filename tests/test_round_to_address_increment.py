"""ROUND inside an NC address rounds to the address's least increment in the unit in force
(docs/semantics.md §3): 0.001 mm, 0.0001 inch under G20, 0.001° for an angle (A, B, C) in
either unit. The source is Haas's own worked example (Haas mill operator's manual 96-8000,
Macros, "Notes on Functions"): "#1= 1.00333 ; G0 X[ ROUND[ #1 ] + ROUND[ #1 ] ] ; (Table moves
to 2.0066)", "G0 A[ #1 + #1 ] ; (Axis moves to 2.007)", "G0 A[ ROUND[ #1 ] + ROUND[ #1 ] ] ;
(Axis moves to 2.006)". An angle's address value without ROUND is rounded the same way.
"""

from __future__ import annotations

import pytest

from running import final, lines

HAAS_EXAMPLE = lines(
    "G20 G17 G90",
    "G00 G54 X0 Y0",
    "#1=1.00333",
    "G00 X[#1+#1]",  # 2.00666 -> 2.0067 (inch: 4 places)
    "#101=#5001",
    "G00 X[ROUND[#1]+ROUND[#1]]",  # ROUND[1.00333] = 1.0033 (4 places); 1.0033 + 1.0033 = 2.0066
    "#102=#5001",
    "G00 A[#1+#1]",  # an angle: 2.00666 -> 2.007 (3 places in either unit)
    "#103=#5004",
    "G00 A[ROUND[#1]+ROUND[#1]]",  # ROUND[1.00333] = 1.003 (3 places); 1.003 + 1.003 = 2.006
    "#104=#5004",
    "M30",
)


@pytest.mark.parametrize("dialect", ["haas", "fanuc", "fanuc-30i"])
def test_round_in_an_inch_address_rounds_to_the_tenth_of_a_thousandth(dialect: str) -> None:
    got = final(HAAS_EXAMPLE, dialect)
    assert got[101] == pytest.approx(2.0067, abs=1e-9)
    assert got[102] == pytest.approx(2.0066, abs=1e-9)  # it was 2.006: ROUND went to 3 places under G20
    assert got[103] == pytest.approx(2.007, abs=1e-9)  # it was 2.0067: an angle took 4 places under G20
    assert got[104] == pytest.approx(2.006, abs=1e-9)


def test_round_in_a_metric_address_stays_at_the_thousandth() -> None:
    # G21: ROUND[1.00333] = 1.003; 1.003 + 1.003 = 2.006; without ROUND 2.00666 -> 2.007
    got = final(lines("G21 G90", "#1=1.00333", "G00 X[ROUND[#1]+ROUND[#1]]", "#102=#5001",
                      "G00 X[#1+#1]", "#101=#5001", "M30"))  # fmt: skip
    assert got[102] == pytest.approx(2.006, abs=1e-9)
    assert got[101] == pytest.approx(2.007, abs=1e-9)


def test_round_in_an_assignment_is_still_a_whole_number_under_g20() -> None:
    assert final(lines("G20", "#1=1.00333", "#2=ROUND[#1]", "M30"))[2] == 1.0
