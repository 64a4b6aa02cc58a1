"""Haas reads a dwell's P by its decimal point: with one it counts seconds, without one
milliseconds (Haas mill operator's manual 96-8000, G04: "G04 P10. is a dwell of 10 seconds;
G04 P10 is 10 milliseconds"; docs/semantics.md §9 "Dwell")."""

from __future__ import annotations

import pytest

from running import lines, run


@pytest.mark.parametrize("profile", ["haas", "haas-lathe"])
def test_haas_g04_p_with_a_point_is_seconds_and_without_one_milliseconds(profile: str) -> None:
    # #3001 counts milliseconds: P1.5 is 1.5 s, P500 is 0.5 s, P2. is 2 s, P#1 (#1 = 0.25) is
    # taken as seconds, 0.25 s: 1500, 2000, 4000, 4250 ms on the clock
    text = lines(
        "O1002",
        "#1=0.25",
        "#3001=0",
        "G04 P1.5",
        "#100=#3001",
        "G04 P500",
        "#101=#3001",
        "G04 P2.",
        "#102=#3001",
        "G04 P#1",
        "#103=#3001",
        "M30",
    )
    v = run(text, profile).variables()
    assert [v[100], v[101], v[102], v[103]] == pytest.approx([1500.0, 2000.0, 4000.0, 4250.0], abs=1.0)


def test_haas_g82_p_with_a_point_dwells_seconds_and_without_one_milliseconds() -> None:
    # Haas rapids X, Y, Z at 25,400 mm/min; G21, tool at X0 Y0 Z10 (G00 from the start: 10 mm,
    # 10 / 25400 min = 0.0236 s). G82 G98 Z-2. R1. F60.: rapid 10 -> 1 (9 mm), feed 1 -> -2
    # (3 mm at 60 mm/min: 3 s), dwell, rapid -2 -> 10 (12 mm); the rapids 21 mm are 0.0496 s.
    # P0.5 dwells 0.5 s (it was rounded to P1, 1 s), P250 0.25 s (it was 250 s).
    def hole(p: str) -> float:
        text = lines("O1", "G21 G90 G00 X0 Y0 Z10.", "#3001=0", f"G82 G98 Z-2. R1. {p} F60.", "#100=#3001", "M30")
        return run(text, "haas").variables()[100]

    rapids = 21 / 25400 * 60 * 1000  # ms
    assert hole("P0.5") == pytest.approx(3000 + 500 + rapids, abs=2.0)
    assert hole("P250") == pytest.approx(3000 + 250 + rapids, abs=2.0)
