"""GSK980TDi's ellipse (G6.2/G6.3, manual §3.6) and parabola (G7.2/G7.3, §3.7) are cut along the
curve, not along its chord (docs/semantics.md §8, "Conic moves"): the manual's own examples, the way
round as G02/G03 pick it, the curve in a G70 shape, and the control's alarms.

Expectations are worked from the manual's numbers: X is a diameter, the curve lies in the ZX plane
with X as a radius; G98 (per minute) at power-on. A curve is cut as pieces turning at most 2°
each: the vertices lie on the curve, and its time is its length (the integral below, by
Simpson's rule) over the feed, to the pieces' 0.01 %."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from cli_capture import cli, run_json
from running import lines


def run_gsk(folder: Path, *body: str) -> dict[str, Any]:
    return run_json(folder, lines("O0001 (cncmacro: dialect=gsk980tdi)", *body, "M30"), "O0001.nc")


def pieces(result: dict[str, Any], line: int) -> list[dict[str, Any]]:
    return [mv for mv in result["moves"] if mv["line"] == line]


def simpson(f: Callable[[float], float], a: float, b: float, n: int = 2000) -> float:
    h = (b - a) / n
    return h / 3 * (f(a) + f(b) + sum((4 if k % 2 else 2) * f(a + k * h) for k in range(1, n)))


def test_g6_3_cuts_the_manuals_egg_about_the_axis(tmp_path: Path) -> None:
    # §3.6's program (figure 3-24): from X24.24 Z0, G6.3 X32.92 W-60 A44 B20. The ellipse centred on
    # the axis at Z-35 passes through both: (35/44)^2 + (12.12/20)^2 = 1.0000 and (25/44)^2 +
    # (16.46/20)^2 = 1.0002. Going round as G03 it passes over its top: X40 at Z-35. Its length
    # from the angle t1 = acos(35/44) = 37.29 deg to t2 = 180 - acos(25/44) = 124.62 deg of
    # (44 cos t, 20 sin t), at F100 per minute
    result = run_gsk(tmp_path, "G0 X60 Z5", "M03 S200", "G01 X24.24 Z0 F100", "G6.3 X32.92 W-60 A44 B20", "G01 X60")
    cut = pieces(result, 5)
    assert len(cut) > 40  # 87 deg round, 2 deg a piece
    assert (cut[0]["from"]["X"], cut[0]["from"]["Z"]) == (24.24, 0.0)
    assert (cut[-1]["to"]["X"], cut[-1]["to"]["Z"]) == pytest.approx((32.92, -60.0))
    for mv in cut:
        z, r = mv["to"]["Z"], mv["to"]["X"] / 2
        assert ((z + 35) / 44) ** 2 + (r / 20) ** 2 == pytest.approx(1.0, abs=0.002)  # the manual's rounding
    top = max(cut, key=lambda mv: mv["to"]["X"])["to"]
    assert top["X"] == pytest.approx(40.0, abs=0.01) and top["Z"] == pytest.approx(-35.0, abs=1.0)
    t1, t2 = math.acos(35 / 44), math.pi - math.acos(25 / 44)
    length = simpson(lambda t: math.hypot(44 * math.sin(t), 20 * math.cos(t)), t1, t2)
    assert sum(mv["time"] for mv in cut) == pytest.approx(length / 100 * 60, rel=1e-3)
    assert all(mv["mode"] == "G6.3" and mv["kind"] == "feed" for mv in cut)


def test_g6_2_goes_round_as_g02_on_the_other_ellipse(tmp_path: Path) -> None:
    # the same ends with G6.2: of the two ellipses through them, the one going round as G02. Its
    # centre is the egg's reflected through the chord's middle (Z-30, radius 14.29): Z-25, radius
    # 28.58; it dips to X = 2 (28.58 - 20) = 17.16 at Z-25, below both ends
    result = run_gsk(tmp_path, "G98 G01 X24.24 Z0 F100", "G6.2 X32.92 W-60 A44 B20")
    cut = pieces(result, 3)
    low = min(cut, key=lambda mv: mv["to"]["X"])["to"]
    assert low["X"] == pytest.approx(17.16, abs=0.02) and low["Z"] == pytest.approx(-25.0, abs=1.0)
    for mv in cut:
        z, r = mv["to"]["Z"], mv["to"]["X"] / 2
        assert ((z + 25) / 44) ** 2 + ((r - 28.58) / 20) ** 2 == pytest.approx(1.0, abs=0.002)


def test_g7_3_cuts_the_manuals_parabola(tmp_path: Path) -> None:
    # §3.7's program (figure 3-32): from X30 Z0, G7.3 X60 Z-40 P10 mm Q180000 (its axis along Z;
    # P in least input increments: P10000 at 0.001 mm, the manual's P100000 at 0.0001 mm). The
    # parabola r' = (r + d)^2 / 20 opening towards -Z through (Z0, r15) and (Z-40, r30):
    # 40 = ((30 + d)^2 - (15 + d)^2) / 20 gives d = 25/6 = 4.1667, and its vertex is at
    # Z = (15 + d)^2 / 20 = 18.368: Z = 18.368 - (r + 4.1667)^2 / 20. G7.3 goes round as G03: the
    # diameter grows fast first (the other parabola, G7.2's, opens towards +Z). At F120 per minute
    result = run_gsk(
        tmp_path, "G00 X120 Z100 T0101 M03 S800", "G00 X0 Z10", "G01 Z0 F120 M08", "X30",
        "G7.3 X60 Z-40 P10000 Q180000", "G01 X90 Z-60",
    )  # fmt: skip
    cut = pieces(result, 6)
    d = 25 / 6
    vertex = (15 + d) ** 2 / 20
    for mv in cut:
        assert mv["to"]["Z"] == pytest.approx(vertex - (mv["to"]["X"] / 2 + d) ** 2 / 20, abs=1e-6)
    assert (cut[-1]["to"]["X"], cut[-1]["to"]["Z"]) == pytest.approx((60.0, -40.0))
    length = simpson(lambda r: math.hypot(1.0, (r + d) / 10), 15.0, 30.0)
    assert sum(mv["time"] for mv in cut) == pytest.approx(length / 120 * 60, rel=1e-3)
    # X45 is reached at Z = 18.368 - 26.667^2 / 20 = -17.188, where the chord is at X42.9
    halfway = min(cut, key=lambda mv: abs(mv["to"]["X"] - 45))["to"]
    assert (halfway["X"], halfway["Z"]) == pytest.approx((45.0, -17.188), abs=1e-3)


def test_an_ellipse_in_a_g70_shape_is_finished_along_the_curve(tmp_path: Path) -> None:
    # §3.6 note 8: G6.2/G6.3 may be used in G70-G73. The egg as a G71/G70 shape: the finishing
    # pass passes over its top, X40 at Z-35
    result = run_gsk(
        tmp_path, "G98 T0101 M03 S800", "G00 X70 Z5", "G71 U2 R1 F150", "G71 P10 Q20 U0.5 W0.2",
        "N10 G00 X24.24", "G01 Z0", "G6.3 X32.92 W-60 A44 B20", "N20 G01 X70", "G70 P10 Q20",
    )  # fmt: skip
    finish = [mv for mv in pieces(result, 8) if mv.get("pass_of") is None]
    assert len(finish) > 40
    assert max(mv["to"]["X"] for mv in finish) == pytest.approx(40.0, abs=0.01)


@pytest.mark.parametrize(
    ("block", "said"),
    [
        ("G6.2 X30 Z-20 A30 F100", "A and B must not be 0 or left out"),  # §3.6 note 1: B left out is 0
        ("G6.2 X200 Z-200 A10 B5 F100", "farther from the start than the ellipse's long axis"),  # note 5
        ("G7.2 X40 Z-20 F100", "P: it must not be 0 or left out"),  # §3.7 note 1
        ("G7.2 W-10 P1000 F100", "parallel to the parabola's axis"),  # note 4: Z only, the axis along Z
        ("G05 X40 Z-20 F100", "I and K must not both be left out"),  # §3.5 note 3
        ("G05 X20 Z-20 I0 K-10 F100", "on one line"),  # note 2: all three at X20
    ],
)
def test_the_control_alarms_where_the_manual_says_and_the_run_cuts_straight(
    tmp_path: Path, block: str, said: str
) -> None:
    program = tmp_path / "O0001.nc"
    program.write_text(lines("O0001 (cncmacro: dialect=gsk980tdi)", "G98 G00 X20 Z0", block, "M30"), encoding="utf-8")
    code, out, _ = cli("check", str(program))
    assert code == 1
    assert out.count("[curve-fault]") == 1 and ":3:1: error:" in out and said in out
    cut = pieces(run_json(tmp_path, program.read_text(encoding="utf-8"), "O0001.nc"), 3)
    assert len(cut) == 1  # straight to the end point
