"""The Mitsubishi corpus (tests/corpus/mitsubishi-m70): shop programs of a vertical machining
centre with an M80 control. Each main program runs to completion with the folder's machine file
(``base = "mitsubishi-m70"``) and does what its programmer meant, and ``cncmacro check`` finds
nothing to report in the folder. They choose with the block IF (``IF [..] THEN`` / ``ELSE`` /
``ENDIF``, nested, in loops and in the macros they call) and read the M8's tool compensation
tables (``#[2000+n]`` lengths, ``#2201``… wear, ``#2401``/``#2601`` radius), the skip positions
``#5061``–``#5063``, the modal information ``#4001``/``#4003``/``#4008``/``#4107``/``#4120``, the
clock ``#3011``/``#3012`` and the part counter ``#3901``; under ``fanuc-0i`` the same folder has
``dialect-feature`` errors and a ``profile-suggestion`` naming ``mitsubishi-m70``. Expected
numbers are worked out by hand in the comments."""

from __future__ import annotations

import io
import json
import math
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from cncmacro.cli.check import check_paths
from test_corpus import CORPUS, moves, run, run_json, var

M70 = CORPUS / "mitsubishi-m70"


def xy(m: dict[str, Any]) -> tuple[float, float]:
    return (round(m["to"]["X"], 3), round(m["to"]["Y"], 3))


def check_probe_top_face(r: dict[str, Any]) -> None:
    # the face is found at Z-0.28 (the machine file's skip plane): error -0.28 - 0, G54 Z 0 - 0.28
    assert var(r, 141) == pytest.approx(-0.28) and var(r, 5223) == pytest.approx(-0.28)
    # 0.28 is over the 0.2 the face mill takes: the IF adds the warning line
    assert r["output"] == ["TOP FACE ERROR -0.2800 G54 Z -0.2800", "MORE STOCK THAN THE FACE MILL TAKES - ADD A PASS"]


def check_probe_bore_center(r: dict[str, Any]) -> None:
    # the ball centre (radius 2) touches a circle D36.01 at X100.04 Y59.97: the bore is 36.01 + 2 x 2
    # = D40.01, 0.01 over (inside the 0.02 of the report's IF: the ELSE branch prints OK); G55
    # (vacant, 0) moves by the centre's errors 100.04 - 100 and 59.97 - 60
    assert (var(r, 137), var(r, 140)) == (pytest.approx(40.01), pytest.approx(0.01))
    assert (var(r, 5241), var(r, 5242)) == (pytest.approx(0.04), pytest.approx(-0.03))
    assert r["output"] == ["BORE D40.0100 OK", "CENTRE X0.0400 Y-0.0300"]


def check_tool_life_sister(r: dict[str, Any]) -> None:
    # 287 of 300 parts: not worn out (ELSE), but 287 >= 300 x 0.95 = 285: the warning; T4 cuts
    assert var(r, 120) == 4 and var(r, 530) == 288
    assert r["messages"] == ["T4 AT 95 PERCENT OF ITS LIFE - HAVE A NEW ONE READY"]


def circle(pcd: float, holes: int, start: float) -> list[tuple[float, float]]:
    angles = [math.radians(start + k * 360 / holes) for k in range(holes)]
    return [(round(pcd / 2 * math.cos(a), 3), round(pcd / 2 * math.sin(a), 3)) for a in angles]


def check_part_family_flange(r: dict[str, Any]) -> None:
    # size 2 (the nested IF's middle branch): 8 holes on PCD 160, the first at 180 / 8 = 22.5 deg
    assert [xy(m) for m in moves(r, "G83")] == circle(160.0, 8, 22.5)
    assert circle(160.0, 8, 22.5)[0] == (73.91, 30.615)
    assert {m["to"]["Z"] for m in moves(r, "G83")} == {-24.0}


def check_part_family_bracket(r: dict[str, Any]) -> None:
    # variant 2 (ELSE): two pockets 30 x 24 at X25 and X65. Tool radius #2404 + #2604 = 4.99; half
    # length 15 - 4.99 - 0.2 = 9.81, half width 12 - 4.99 - 0.2 = 6.81; passes FUP[8 / 4] = 2; the
    # finishing lap (Q0.2 > 0: its IF) 0.2 further out, at full depth
    plunges = [m["to"]["Z"] for m in moves(r, "G01", "O9140.nc") if m["line"] in (33, 56)]
    assert plunges == [-4.0, -8.0, -8.0] * 2
    # the stripes go right (even, line 38) and left (odd, line 40) across Y 23.19, 30.0, 36.81
    rough = sorted({xy(m) for m in moves(r, "G01", "O9140.nc") if m["line"] in (38, 40)})
    assert rough[:3] == [(15.19, 30.0), (34.81, 23.19), (34.81, 36.81)]
    lap = [xy(m) for m in moves(r, "G01", "O9140.nc") if 57 <= m["line"] <= 60]
    assert lap[:4] == [(35.01, 22.99), (35.01, 37.01), (14.99, 37.01), (14.99, 22.99)]


def check_tool_length_report(r: dict[str, Any]) -> None:
    assert r["output"] == ["SETUP CHECK 20261122", "T1 L112.500 W0.000", "T2 L98.300 W0.000", "T3 L131.040 W0.000",
                           "T4 L105.600 W-0.020", "T5 L121.900 W0.000", "T6 NO LENGTH", "T20 L150.000 W0.000",
                           "6 TOOLS SET"]  # fmt: skip


def check_wear_comp(r: dict[str, Any]) -> None:
    # part 120: 120 MOD 10 = 0, so the radius wear goes from -0.01 to -0.015
    assert var(r, 2604) == pytest.approx(-0.015)
    assert len(moves(r, "G01")) == 6


def check_warmup(r: dict[str, Any]) -> None:
    # 08:00:00 is before 09:00: four steps from 2000 rpm, a minute each
    assert (var(r, 1), var(r, 2), var(r, 3)) == (2000, 4, 4)
    assert r["messages"] == ["WARM-UP DONE"]


def check_safe_retract(r: dict[str, Any]) -> None:
    # loading side 1 (#160): X-400 Y0. G43 H2 is in force (#4008 = 43): G53 Z0 (O9020 line 14),
    # not the G28 of the ELSE (line 16); machine Z0 is work Z -98.3 with the 98.3 length, G54 at 0
    retract = moves(r, "G00", "O9020.nc")
    assert [m["line"] for m in retract] == [14, 18]
    assert retract[0]["to"]["Z"] == pytest.approx(-98.3) and xy(retract[1]) == (-400.0, 0.0)


def check_face_mill_passes(r: dict[str, Any]) -> None:
    # 2.3 to remove by 1.0: passes of 1.0, 1.0 and the 0.3 left (the ELSE), the face from Z2.3 down
    plunges = [m["to"]["Z"] for m in moves(r, "G01") if m["line"] == 22]
    assert plunges == [pytest.approx(1.3), pytest.approx(0.3), pytest.approx(0.0)]


def check_hole_pattern_select(r: dict[str, Any]) -> None:
    # pattern 1: a 3 x 2 grid at 25
    assert [xy(m) for m in moves(r, "G81")] == [(0.0, 0.0), (25.0, 0.0), (50.0, 0.0), (0.0, 25.0), (25.0, 25.0),
                                                (50.0, 25.0)]  # fmt: skip


MAINS: dict[str, Callable[[dict[str, Any]], None]] = {
    "probe_top_face.nc": check_probe_top_face,
    "probe_bore_center.nc": check_probe_bore_center,
    "tool_life_sister.nc": check_tool_life_sister,
    "part_family_flange.nc": check_part_family_flange,
    "part_family_bracket.nc": check_part_family_bracket,
    "tool_length_report.nc": check_tool_length_report,
    "wear_comp.nc": check_wear_comp,
    "warmup.nc": check_warmup,
    "safe_retract.nc": check_safe_retract,
    "face_mill_passes.nc": check_face_mill_passes,
    "hole_pattern_select.nc": check_hole_pattern_select,
}


@pytest.mark.parametrize("name", list(MAINS))
def test_mitsubishi_corpus_main_runs_to_completion(name: str) -> None:
    MAINS[name](run(M70 / name))


def test_mitsubishi_corpus_has_sixteen_programs_with_block_ifs() -> None:
    files = sorted(p for p in M70.iterdir() if p.suffix == ".nc")
    assert len(files) >= 15
    for p in files:
        lines = p.read_text(encoding="utf-8").splitlines()
        assert lines[0] == "%" and lines[-1] == "%", p.name
    with_blocks = [
        p.name for p in files if any(x.strip() == "ENDIF" for x in p.read_text(encoding="utf-8").splitlines())
    ]
    assert len(with_blocks) == len(files)
    assert {p.name for p in files if not p.name.startswith("O")} == set(MAINS)


def test_check_finds_nothing_in_the_mitsubishi_corpus() -> None:
    out, err = io.StringIO(), io.StringIO()
    status = check_paths([str(M70)], out, err, "json")
    found = json.loads(out.getvalue())
    assert [d for d in found if d["severity"] in ("error", "warning")] == [] and status == 0


def test_a_worn_out_tool_hands_the_part_to_its_sister() -> None:
    r = run(M70 / "tool_life_sister.nc", "530=300")
    assert var(r, 120) == 14 and var(r, 530) == 300  # T14 cut it: T4's count stays
    assert r["messages"] == ["T4 WORN OUT - THIS PART RUNS WITH T14. REPLACE T4 AND SET #530=0"]


@pytest.mark.parametrize(("size", "pcd", "holes"), [(1, 125.0, 4), (3, 180.0, 8)])
def test_the_flange_size_picks_its_bolt_circle(size: int, pcd: float, holes: int) -> None:
    r = run(M70 / "part_family_flange.nc", f"100={size}")
    assert [xy(m) for m in moves(r, "G83")] == circle(pcd, holes, 180 / holes)


def test_an_unknown_flange_size_stops_before_any_hole() -> None:
    status, r = run_json(M70 / "part_family_flange.nc", "100=5")
    assert status == 1 and r["alarm"]["message"] == "FLANGE SIZE #100 MUST BE 1, 2 OR 3"
    assert r["alarm"]["number"] is None and moves(r, "G83") == []  # no number shown (docs/profiles.md)


def test_the_single_pocket_variant_cuts_one_pocket() -> None:
    r = run(M70 / "part_family_bracket.nc", "110=1")
    # 40 x 30 at X40 Y30: half length 20 - 4.99 - 0.2 = 14.81; passes FUP[6 / 3] = 2
    plunges = [m["to"]["Z"] for m in moves(r, "G01", "O9140.nc") if m["line"] in (33, 56)]
    assert plunges == [-3.0, -6.0, -6.0]
    assert min(m["to"]["X"] for m in moves(r, "G01", "O9140.nc") if m["line"] == 40) == pytest.approx(25.19)


def test_the_front_loading_side_retracts_to_the_front() -> None:
    r = run(M70 / "safe_retract.nc", "160=2")
    assert [xy(m) for m in moves(r, "G00", "O9020.nc")][-1] == (0.0, -250.0)


def test_the_second_fixture_pattern_spots_a_circle() -> None:
    r = run(M70 / "hole_pattern_select.nc", "150=2")
    assert [xy(m) for m in moves(r, "G81")] == circle(60.0, 6, 0.0)


def test_a_part_that_ends_the_order_or_wears_the_tool_out_stops_the_cycle() -> None:
    status, r = run_json(M70 / "wear_comp.nc", "2604=-0.048")
    assert status == 1 and r["alarm"]["message"] == "T4 RADIUS WEAR BEYOND -0.05 - CHANGE THE TOOL"
    status, r = run_json(M70 / "wear_comp.nc", "3901=401")
    assert status == 1 and r["alarm"]["message"] == "ORDER COMPLETE"


def test_fanuc_0i_finds_the_block_ifs_and_suggests_mitsubishi() -> None:
    text = (M70 / ".cncmacro.toml").read_text(encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    with tempfile.TemporaryDirectory() as tmp:
        machine = Path(tmp) / "machine.toml"
        machine.write_text("\n".join(x for x in text.splitlines() if not x.startswith(("base", "part_system"))),
                           encoding="utf-8")  # fmt: skip
        status = check_paths([str(M70)], out, err, "json", dialect="fanuc-0i", machine=str(machine))
    found = json.loads(out.getvalue())
    assert status == 1
    features = {Path(d["file"]).name for d in found if d["code"] == "dialect-feature"}
    assert features == {p.name for p in M70.iterdir() if p.suffix == ".nc"}
    suggestions = [d for d in found if d["code"] == "profile-suggestion"]
    assert {Path(d["file"]).name for d in suggestions} == features  # once per file
    assert all("dialect=mitsubishi-m70" in d["message"] and "mazak-eia" in d["message"] for d in suggestions)
