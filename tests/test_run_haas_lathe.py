"""What sets ``haas-lathe`` apart (docs/profiles.md "haas-lathe: sources and decisions",
docs/semantics.md §10): each program runs under ``haas-lathe`` and, the same text, under
``fanuc-0i`` (the mill default), which does otherwise. Every number is worked by hand.

haas-lathe's rapids: 24,000 mm/min on X (of the radius) and Z; G99 at power-on."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest

from cli_capture import cli
from cncmacro.dialects import get_dialect
from running import lines


def run_as(folder: Path, profile: str, *body: str) -> dict[str, Any]:
    """``cncmacro run --json`` of ``body`` as a program of ``profile`` (whatever the run's end)."""
    path = folder / f"{profile}.nc"
    path.write_text(lines(f"O01000 (cncmacro: dialect={profile})", *body), encoding="utf-8")
    _, out, err = cli("run", "--json", "--no-save", str(path))
    assert out, err
    result: dict[str, Any] = json.loads(out)
    return result


def passes(result: dict[str, Any], code: str) -> list[dict[str, Any]]:
    return [mv for mv in result["moves"] if mv.get("pass_of") == code]


def test_haas_lathe_answers_to_haas_st_and_haas_sl() -> None:
    assert get_dialect("haas-st").name == "haas-lathe"
    assert get_dialect("haas-sl").name == "haas-lathe"
    assert get_dialect("haas-lathe").lathe and not get_dialect("haas").lathe


def test_offsets_2001_and_2101_are_the_geometry_t0101_adds_and_5023_reads_z(tmp_path: Path) -> None:
    # X geometry 0.4 (a diameter), Z geometry -0.2 of offset 1; T0101; G00 X50. Z2.
    # haas-lathe: machine X = 50 + 0.4 = 50.4 (#5021), machine Z = 2 - 0.2 = 1.8 (#5023, the third axis)
    # fanuc-0i: T0101 is a tool number, #2001/#2101 are its H wear offsets: X 50, Z 2 as programmed
    body = ("#2001 = 0.4", "#2101 = -0.2", "T0101", "G00 X50. Z2.", "#100 = #5021", "#101 = #5023", "M30")
    lathe = run_as(tmp_path, "haas-lathe", *body)["variables"]
    mill = run_as(tmp_path, "fanuc-0i", *body)["variables"]
    assert (lathe["100"], lathe["101"]) == pytest.approx((50.4, 1.8))
    assert (mill["100"], mill["101"]) == pytest.approx((50.0, 2.0))


def test_g10_p_writes_the_wear_at_2701_where_a_fanuc_lathe_keeps_its_geometry(tmp_path: Path) -> None:
    # G10 P1 X0.1 Z-0.05 writes the wear of offset 1: on haas-lathe #2701 (X wear), #2801 (Z wear);
    # fanuc-0i-lathe keeps its wear at #2001/#2101, so its #2701 (X geometry) stays 0;
    # fanuc-0i (a mill): #2701 is an H offset no G10 P1 X writes
    body = ("G10 P1 X0.1 Z-0.05", "#100 = #2701", "#101 = #2801", "#102 = #2001", "M30")
    haas = run_as(tmp_path, "haas-lathe", *body)["variables"]
    fanuc_lathe = run_as(tmp_path, "fanuc-0i-lathe", *body)["variables"]
    mill = run_as(tmp_path, "fanuc-0i", *body)["variables"]
    assert (haas["100"], haas["101"], haas["102"]) == pytest.approx((0.1, -0.05, 0.0))
    assert (fanuc_lathe["100"], fanuc_lathe["102"]) == pytest.approx((0.0, 0.1))
    assert mill.get("100") != pytest.approx(0.1)


def test_g99_feed_per_revolution_is_in_force_at_power_on(tmp_path: Path) -> None:
    # G97 S500: G01 Z-18. F0.2 from Z2 is 20 mm at 0.2 x 500 = 100 mm/min: 12 s (haas-lathe, G99);
    # fanuc-0i powers on in G94: 0.2 mm/min, 20 mm take 100 minutes = 6000 s. #4010 (group 10) reads 99
    body = ("G97 S500 M03", "G00 X40. Z2.", "G01 Z-18. F0.2", "#100 = #4010", "M30")
    lathe = run_as(tmp_path, "haas-lathe", *body)
    mill = run_as(tmp_path, "fanuc-0i", *body)
    assert lathe["moves"][-1]["time"] == pytest.approx(12.0)
    assert lathe["variables"]["100"] == 99.0
    assert mill["moves"][-1]["time"] == pytest.approx(6000.0)


# a shaft: from X40 Z5, the shape X30 to Z-20, then up to X40; allowances U0.5 (diameter) W0.1
SHAFT = ("G97 S500 M03", "G00 X40. Z5.", "G71 P10 Q20 U0.5 W0.1 D2. F0.25", "N10 G00 X30.", "G01 Z-20.",
         "N20 X40.", "G70 P10 Q20", "M30")  # fmt: skip


def test_g71_in_one_block_roughs_in_cuts_of_d_and_g70_finishes_the_shape(tmp_path: Path) -> None:
    # D2. is the depth of each cut, a radius: levels X36, X32 (X28 would pass the offset shape's X30.5).
    # each level cuts from Z5 to the offset shoulder Z-20 + 0.1 = -19.9: 24.9 mm at 0.25 x 500 = 125 mm/min
    #   = 11.952 s; then the offset shape: X30.5 Z5.1 to Z-19.9 (25 mm, 12 s), up to X40.5 (5 mm radius, 2.4 s).
    # G70: Z5 to Z-20 (25 mm, 12 s), X30 to X40 (5 mm, 2.4 s).
    # fanuc-0i: G71 is no code of a mill; nothing roughs
    lathe = run_as(tmp_path, "haas-lathe", *SHAFT)
    cuts = [mv for mv in passes(lathe, "G71") if mv["mode"] == "G01"]
    assert [mv["to"]["X"] for mv in cuts] == pytest.approx([36.0, 32.0, 30.5, 40.5])
    assert [mv["to"]["Z"] for mv in cuts] == pytest.approx([-19.9] * 4)
    assert [mv["time"] for mv in cuts] == pytest.approx([11.952, 11.952, 12.0, 2.4])
    finish = [mv for mv in lathe["moves"] if mv["mode"] == "G01" and mv.get("pass_of") is None]
    assert [mv["time"] for mv in finish] == pytest.approx([12.0, 2.4])
    mill = run_as(tmp_path, "fanuc-0i", *SHAFT)
    assert not passes(mill, "G71")


def test_g76_in_one_block_threads_at_d_times_the_root_of_the_pass_down_to_k(tmp_path: Path) -> None:
    # G76 X20. Z-20. K1. D0.5 F2. from X24 Z5, G97 S500: depths 0.5 sqrt(n) while below K = 1:
    #   0.5, 0.7071, 0.8660, then 1.0 (the pass at K is the last): X = 20 + 2 (1 - depth)
    #   = 21.0, 20.5858, 20.2679, 20.0; each thread 25 mm at 2 x 500 = 1000 mm/min: 1.5 s
    # fanuc-0i: G76 is a mill's fine boring; no thread is cut
    body = ("G97 S500 M03", "G00 X24. Z5.", "G76 X20. Z-20. K1. D0.5 F2.", "M30")
    lathe = run_as(tmp_path, "haas-lathe", *body)
    threads = [mv for mv in passes(lathe, "G76") if mv["mode"] == "G32"]
    depths = [0.5, 0.5 * math.sqrt(2), 0.5 * math.sqrt(3), 1.0]
    assert [mv["to"]["X"] for mv in threads] == pytest.approx([20 + 2 * (1 - d) for d in depths])
    assert [mv["time"] for mv in threads] == pytest.approx([1.5] * 4)
    mill = run_as(tmp_path, "fanuc-0i", *body)
    assert not [mv for mv in mill["moves"] if mv["mode"] == "G32"]


def test_g75_steps_i_along_x_and_k_along_z(tmp_path: Path) -> None:
    # G75 X20. Z-30. I1. K3. F0.1 from X24 Z5, G97 S500: pecks of I1 (a radius, 2 on the diameter):
    # X22, X20; columns every K3 from Z5: 5, 2, ..., -28, then the end -30: 13 columns of 2 pecks;
    # each peck 1 mm at 0.1 x 500 = 50 mm/min: 1.2 s. fanuc-0i: G75 is no code of a mill
    body = ("G97 S500 M03", "G00 X24. Z5.", "G75 X20. Z-30. I1. K3. F0.1", "M30")
    lathe = run_as(tmp_path, "haas-lathe", *body)
    pecks = [mv for mv in passes(lathe, "G75") if mv["mode"] == "G01"]
    assert len(pecks) == 13 * 2
    assert sorted({mv["to"]["Z"] for mv in pecks}) == pytest.approx(sorted({-30.0, *(5.0 - 3 * k for k in range(12))}))
    assert all(mv["time"] == pytest.approx(1.2) for mv in pecks)
    mill = run_as(tmp_path, "fanuc-0i", *body)
    assert not passes(mill, "G75")


def test_g90_tapers_by_i(tmp_path: Path) -> None:
    # G90 X30. Z-10. I-1. F0.2 from X40 Z2: the cut starts at X30 + 2 x (-1) = 28 (I a radius, as FANUC's R)
    # fanuc-0i: G90 is absolute positioning, the block a move to X30 Z-10
    body = ("G97 S500 M03", "G00 X40. Z2.", "G90 X30. Z-10. I-1. F0.2", "M30")
    lathe = run_as(tmp_path, "haas-lathe", *body)
    legs = lathe["moves"][-1]["legs"]
    assert (legs[0]["to"]["X"], legs[0]["to"]["Z"]) == (28.0, 2.0)
    mill = run_as(tmp_path, "fanuc-0i", *body)
    assert "legs" not in mill["moves"][-1]


def test_g73_in_one_block_repeats_the_shape_d_times_from_i_k_relief_to_none(tmp_path: Path) -> None:
    # G73 P10 Q20 I3. K1. U0.5 W0.1 D3 F0.25 from X50 Z5 (shape X30 to Z-20, up to X50), G97 S500:
    # three passes with the relief shrinking evenly: (3, 1), (1.5, 0.5), (0, 0) on top of the allowances:
    #   X 30 + 0.5 + 2 x 3 = 36.5, 33.5, 30.5; the cut ends at Z -20 + 0.1 + 1 = -18.9, -19.4, -19.9;
    #   each 25 mm along Z at 0.25 x 500 = 125 mm/min: 12 s, then 20 mm of diameter (10 of radius): 4.8 s
    # fanuc-0i: G73 is a mill's peck drilling; nothing roughs
    body = ("G97 S500 M03", "G00 X50. Z5.", "G73 P10 Q20 I3. K1. U0.5 W0.1 D3 F0.25", "N10 G00 X30.", "G01 Z-20.",
            "N20 X50.", "M30")  # fmt: skip
    lathe = run_as(tmp_path, "haas-lathe", *body)
    cuts = [mv for mv in passes(lathe, "G73") if mv["mode"] == "G01"]
    assert [mv["to"]["X"] for mv in cuts[::2]] == pytest.approx([36.5, 33.5, 30.5])
    assert [mv["to"]["Z"] for mv in cuts[::2]] == pytest.approx([-18.9, -19.4, -19.9])
    assert [mv["time"] for mv in cuts] == pytest.approx([12.0, 4.8] * 3)
    mill = run_as(tmp_path, "fanuc-0i", *body)
    assert not passes(mill, "G73")
