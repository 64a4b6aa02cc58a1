"""The Mazak corpus (tests/corpus/mazak-eia): shop programs of a vertical machining centre with a
Mazatrol Smooth control running EIA/ISO programs. Each main program runs to completion with the
folder's machine file (``base = "mazak-eia"``) and does what its programmer meant, and ``cncmacro
check`` finds nothing to report in the folder. They join conditions with ``&&`` and ``||``, choose
with the block IF (``IF [..] THEN`` / ``ELSE`` / ``ENDIF``, nested), loop with ``WH`` and jump with
``GO``, and read the tool offsets (``#[11000+n]`` lengths, ``#10004`` wear, ``#12004``/``#13004``
radius), the skip positions ``#5061``/``#5063``, the modal information ``#4003``/``#4008``/``#4014``/
``#4120``, the clock ``#3011``/``#3012`` and the part counters ``#3901``/``#3902``; under ``fanuc-0i``
the same folder has ``dialect-feature`` errors and a ``profile-suggestion`` naming ``mazak-eia`` in
every file. Expected numbers are worked out by hand in the comments."""

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

MAZAK = CORPUS / "mazak-eia"


def xy(m: dict[str, Any]) -> tuple[float, float]:
    return (round(m["to"]["X"], 3), round(m["to"]["Y"], 3))


def circle(cx: float, cy: float, pcd: float, holes: int) -> list[tuple[float, float]]:
    angles = [math.radians(k * 360 / holes) for k in range(holes)]
    return [(round(cx + pcd / 2 * math.cos(a), 3), round(cy + pcd / 2 * math.sin(a), 3)) for a in angles]


def check_probe_top_face(r: dict[str, Any]) -> None:
    # the face is found at Z-0.18 (the skip plane): error -0.18 - 0, G54 Z 0 - 0.18; 0.1 < 0.18 <= 0.5:
    # the && holds and the report adds the line of the extra pass
    assert var(r, 141) == pytest.approx(-0.18) and var(r, 5223) == pytest.approx(-0.18)
    assert r["output"] == ["FACE ERROR -0.1800 G54 Z -0.1800", "FACE MILL ADDS A PASS"]


def check_probe_edge_x(r: dict[str, Any]) -> None:
    # the ball centre stops at X58.05 (the target 60 - 2 + 4 = 62 is not reached); the edge is
    # 58.05 + the 2.0 ball radius = 60.05, 0.05 off: G54 X moves by 0.05, and 0.05 > 0.02 stops
    assert [round(m["to"]["X"], 3) for m in moves(r, "G31")] == [58.05]
    assert var(r, 144) == pytest.approx(60.05) and var(r, 5221) == pytest.approx(0.05)
    assert r["messages"] == ["EDGE MOVED MORE THAN 0.02 - CHECK THE VICE STOP"]


def check_tool_life_count(r: dict[str, Any]) -> None:
    # 470 of 500 parts: not worn out (ELSE), but 470 >= 500 x 0.9 = 450: the warning; T4 cuts, 471
    assert var(r, 120) == 4 and var(r, 530) == 471
    assert r["messages"] == ["T4 PAST 90 PERCENT OF ITS LIFE - HAVE A NEW ONE READY"]


def check_part_family_plate(r: dict[str, Any]) -> None:
    # size 2 (the nested IF's middle branch): 4 x 2 holes at 35, row by row
    assert [xy(m) for m in moves(r, "G81")] == [(x * 35.0, y * 35.0) for y in range(2) for x in range(4)]
    assert {m["to"]["Z"] for m in moves(r, "G81")} == {-12.0}


def check_part_family_slot(r: dict[str, Any]) -> None:
    # variant 1: one slot X0 -> X40, plunging 2, 4, 6 (WH while the depth is under 6)
    plunges = [m["to"]["Z"] for m in moves(r, "G01") if m["line"] == 26]
    assert plunges == [-2.0, -4.0, -6.0]
    assert max(m["to"]["X"] for m in moves(r, "G01")) == 40.0


def check_tool_length_check(r: dict[str, Any]) -> None:
    # T1-T5, T14 and T20 have a length (all inside 50-250); T4's wear -0.03
    assert r["output"] == ["SETUP CHECK 20261128", "T1 L120.400 W0.000", "T2 L95.200 W0.000", "T3 L128.750 W0.000",
                           "T4 L102.300 W-0.030", "T5 L117.600 W0.000", "T14 L101.900 W0.000",
                           "T20 L148.000 W0.000", "7 TOOLS SET"]  # fmt: skip


def check_wear_adjust(r: dict[str, Any]) -> None:
    # part 230: 230 MOD 10 = 0 && 230 NE 0, so the radius wear goes from -0.012 to -0.017
    assert var(r, 12004) == pytest.approx(-0.017)
    assert len(moves(r, "G01")) == 6


def check_warmup(r: dict[str, Any]) -> None:
    # 07:15:00 is before 09:00 (the || holds): five steps from 1000 rpm by 1500, the last at 7000
    assert (var(r, 1), var(r, 2), var(r, 3)) == (8500, 5, 5)
    assert var(r, 550) == 1 and r["messages"] == ["WARM-UP DONE"]


def check_bolt_circle(r: dict[str, Any]) -> None:
    # six holes on PCD 80 from 0 deg, spotted to Z-3 and drilled to Z-18
    holes = circle(0.0, 0.0, 80.0, 6)
    assert holes[1] == (20.0, 34.641)
    assert [xy(m) for m in moves(r, "G81")] == holes * 2
    assert [m["to"]["Z"] for m in moves(r, "G81")] == [-3.0] * 6 + [-18.0] * 6


def check_safe_start(r: dict[str, Any]) -> None:
    # G90, G54 and G49 at the start: no alarm, G91 G28 Z0 (not G53); T5's G43 then lets the tap run
    assert [xy(m) for m in moves(r, "G84")] == [(10.0, 10.0)]
    assert [m["line"] for m in moves(r, "G00") if m["file"].endswith("safe_start.nc")][:1] == [9]


def check_face_passes(r: dict[str, Any]) -> None:
    # 2.4 to remove by 1.0: the face at 1.4, 0.4 and 0 (the ELSE takes what is left)
    plunges = [m["to"]["Z"] for m in moves(r, "G01") if m["line"] == 18]
    assert plunges == [pytest.approx(1.4), pytest.approx(0.4), pytest.approx(0.0)]


def check_two_fixtures(r: dict[str, Any]) -> None:
    # both vices (#150 = 3): four holes on PCD 24 round X30 Y20 in G54, then the same in G55
    holes = circle(30.0, 20.0, 24.0, 4)
    assert [xy(m) for m in moves(r, "G81")] == holes * 2


MAINS: dict[str, Callable[[dict[str, Any]], None]] = {
    "probe_top_face.nc": check_probe_top_face,
    "probe_edge_x.nc": check_probe_edge_x,
    "tool_life_count.nc": check_tool_life_count,
    "part_family_plate.nc": check_part_family_plate,
    "part_family_slot.nc": check_part_family_slot,
    "tool_length_check.nc": check_tool_length_check,
    "wear_adjust.nc": check_wear_adjust,
    "warmup.nc": check_warmup,
    "bolt_circle.nc": check_bolt_circle,
    "safe_start.nc": check_safe_start,
    "face_passes.nc": check_face_passes,
    "two_fixtures.nc": check_two_fixtures,
}


@pytest.mark.parametrize("name", list(MAINS))
def test_mazak_corpus_main_runs_to_completion(name: str) -> None:
    MAINS[name](run(MAZAK / name))


def test_mazak_corpus_has_sixteen_programs_that_use_what_sets_mazak_apart() -> None:
    files = sorted(p for p in MAZAK.iterdir() if p.suffix == ".nc")
    assert len(files) >= 15
    for p in files:
        lines = p.read_text(encoding="utf-8").splitlines()
        assert lines[0] == "%" and lines[-1] == "%", p.name
    texts = {p.name: p.read_text(encoding="utf-8") for p in files}
    assert all("&&" in t or "||" in t for t in texts.values())
    assert sum("ENDIF" in t for t in texts.values()) >= 12 and sum("WH [" in t for t in texts.values()) >= 6
    assert {p.name for p in files if not p.name.startswith("O")} == set(MAINS)


def test_check_finds_nothing_in_the_mazak_corpus() -> None:
    out, err = io.StringIO(), io.StringIO()
    status = check_paths([str(MAZAK)], out, err, "json")
    found = json.loads(out.getvalue())
    assert [d for d in found if d["severity"] in ("error", "warning")] == [] and status == 0


def test_a_worn_out_tool_hands_the_part_to_its_sister() -> None:
    r = run(MAZAK / "tool_life_count.nc", "530=500")
    assert var(r, 120) == 14 and var(r, 530) == 500  # T14 cut it: T4's count stays
    assert r["messages"] == ["T4 WORN OUT - THIS PART RUNS WITH T14. REPLACE T4 AND SET #530=0"]


@pytest.mark.parametrize(("size", "across", "rows", "pitch"), [(1, 3, 2, 30.0), (3, 5, 3, 40.0)])
def test_the_plate_size_picks_its_hole_grid(size: int, across: int, rows: int, pitch: float) -> None:
    r = run(MAZAK / "part_family_plate.nc", f"100={size}")
    assert [xy(m) for m in moves(r, "G81")] == [(x * pitch, y * pitch) for y in range(rows) for x in range(across)]


def test_an_unknown_plate_size_stops_before_any_hole() -> None:
    # 0 LT 1: the first side of the || holds
    status, r = run_json(MAZAK / "part_family_plate.nc", "100=0")
    assert status == 1 and r["alarm"]["message"] == "PLATE SIZE #100 MUST BE 1, 2 OR 3"
    assert r["alarm"]["number"] is None and moves(r, "G81") == []  # no number shown (docs/profiles.md)


def test_the_second_slot_variant_cuts_two_shorter_slots() -> None:
    r = run(MAZAK / "part_family_slot.nc", "110=2")
    # slots X0 -> X25 and X50 -> X75, three plunges each
    assert [m["to"]["X"] for m in moves(r, "G01") if m["line"] == 27] == [25.0] * 3 + [75.0] * 3


def test_an_unknown_slot_variant_jumps_to_its_alarm() -> None:
    # 3 NE 1 && 3 NE 2: GO 900, past every move
    status, r = run_json(MAZAK / "part_family_slot.nc", "110=3")
    assert status == 1 and r["alarm"]["message"] == "SLOT VARIANT #110 MUST BE 1 OR 2" and r["moves"] == []


def test_after_nine_the_warm_spindle_needs_two_steps() -> None:
    # 10:30:00 is not before 09:00 and #550 = 1: neither side of the || holds, two steps
    r = run(MAZAK / "warmup.nc", "3012=103000", "550=1")
    assert (var(r, 1), var(r, 3)) == (4000, 2)


def test_only_the_second_vice_is_drilled() -> None:
    r = run(MAZAK / "two_fixtures.nc", "150=2")
    # #1 = 1: [1 EQ 1] && [[2 EQ 1] || [2 EQ 3]] fails; #1 = 2: [2 EQ 2] && [2 GE 2] holds
    assert [xy(m) for m in moves(r, "G81")] == circle(30.0, 20.0, 24.0, 4)


def test_a_part_that_ends_the_order_or_wears_the_tool_out_stops_the_cycle() -> None:
    # part 240: 240 MOD 10 = 0, -0.048 - 0.005 = -0.053 is beyond -0.05
    status, r = run_json(MAZAK / "wear_adjust.nc", "3901=240", "12004=-0.048")
    assert status == 1 and r["alarm"]["message"] == "T4 RADIUS WEAR BEYOND -0.05 - CHANGE THE TOOL"
    status, r = run_json(MAZAK / "wear_adjust.nc", "3901=500")
    assert status == 1 and r["alarm"]["message"] == "ORDER COMPLETE"


def test_fanuc_0i_finds_the_mazak_syntax_and_suggests_mazak() -> None:
    text = (MAZAK / ".cncmacro.toml").read_text(encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    with tempfile.TemporaryDirectory() as tmp:
        machine = Path(tmp) / "machine.toml"
        machine.write_text("\n".join(x for x in text.splitlines() if not x.startswith("base")), encoding="utf-8")
        status = check_paths([str(MAZAK)], out, err, "json", dialect="fanuc-0i", machine=str(machine))
    found = json.loads(out.getvalue())
    assert status == 1
    features = {Path(d["file"]).name for d in found if d["code"] == "dialect-feature"}
    assert features == {p.name for p in MAZAK.iterdir() if p.suffix == ".nc"}
    suggestions = [d for d in found if d["code"] == "profile-suggestion"]
    assert {Path(d["file"]).name for d in suggestions} == features  # once per file
    assert all("dialect=mazak-eia" in d["message"] for d in suggestions)
