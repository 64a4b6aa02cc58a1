"""The FANUC 30i corpus (tests/corpus/fanuc-30i): shop programs of a horizontal machining centre
with a 31i-B control. Each main program runs to completion with the folder's machine file and
does what its programmer meant (an offset written, a hole count, a printed report line), and
``cncmacro check`` finds no error or warning in the folder. They use what the 30i has and the 0i
lacks: 8-digit program numbers (``M98 P00012346 L3`` is O00012346 three times, not O2346 once),
``[#_NAME]`` system variables, commons #100-#499, π and e in #3101/#3102, ``POW``, ``ADP`` and
``ATAN[a,b]``."""

from __future__ import annotations

import io
import json
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from cncmacro.cli.check import check_paths
from test_corpus import CORPUS, moves, run, run_json, var

F30I = CORPUS / "fanuc-30i"


def check_probe_datum_corner(r: dict[str, Any]) -> None:
    touches = [m["to"] for m in moves(r, "G31", "O00009811.nc")]
    assert [round(t["Z"], 3) for t in touches][:1] == [-0.35]
    assert round(touches[1]["X"], 3) == -2.612 and round(touches[2]["Y"], 3) == -2.422  # ball centres
    # G54.1 P1 (#7001...) moved by the errors: edges found at X-0.12 (ball radius 2.492), Y0.07, Z-0.35
    assert (var(r, 7001), var(r, 7002), var(r, 7003)) == pytest.approx((-402.435, -310.45, -655.75))
    assert (var(r, 331), var(r, 332), var(r, 333)) == pytest.approx((-0.12, 0.07, -0.35))
    assert var(r, 5221) == pytest.approx(-388.2)  # G54 untouched
    date, errors, offsets = r["output"]
    assert re.fullmatch(r"DATUM CORNER 20261122 80\d{3}", date)  # [#_DATE], [#_TIME] of the fixed clock
    assert errors == "ERROR X-0.1200 Y0.0700 Z-0.3500"
    assert offsets == "OFFSET 101 X-402.4350 Y-310.4500 Z-655.7500"


def check_probe_face_pallet2(r: dict[str, Any]) -> None:
    assert var(r, 501) == 2 and var(r, 502) == 1  # M60 A2 brought pallet 2 in
    touches = [(m["to"]["X"], m["to"]["Y"], round(m["to"]["Z"], 3)) for m in moves(r, "G31")]
    assert touches == [(15.0, 15.0, -0.35), (145.0, 15.0, -0.35), (80.0, 105.0, -0.35)]
    assert var(r, 5243) == pytest.approx(-640.65)  # G55 Z moved by the mean error
    assert var(r, 5223) == pytest.approx(-640.15)  # G54 Z untouched
    assert var(r, 530) == pytest.approx(-0.35) and var(r, 540) == 1  # the history ring
    assert r["output"] == ["FACE HEIGHT PALLET 2", "POINTS -0.350 -0.350 -0.350", "MEAN -0.350 FLATNESS 0.000",
                           "HISTORY SLOT 1"]  # fmt: skip


def check_set_tool_lengths(r: dict[str, Any]) -> None:
    lengths = {t: var(r, 11000 + t) for t in (3, 7, 12, 25)}
    assert lengths == pytest.approx({3: 184.95, 7: 142.25, 12: 118.1, 25: 125.35})  # rough lengths - 0.35
    assert var(r, 10003) == 0  # the wear of a measured tool starts again at 0
    assert var(r, 11009) == pytest.approx(151.2)  # a tool not in the list keeps its length
    assert var(r, 410) == 4 and var(r, 511) == 4 and var(r, 500) == 25
    assert len(moves(r, "G31", "O00009850.nc")) == 8  # a fast and a slow touch per tool
    assert r["output"][1:] == ["T3 H184.9500 CHANGE-0.350", "T7 H142.2500 CHANGE-0.350", "T12 H118.1000 CHANGE-0.350",
                               "T25 H125.3500 CHANGE-0.350", "MEASURED 4 TOOLS"]  # fmt: skip
    assert re.fullmatch(r"TOOL LENGTHS JOB 1203 20261122 \d+", r["output"][0])


def check_bolt_circles(r: dict[str, Any]) -> None:
    tapped = moves(r, "G83")
    assert len(tapped) == 8
    assert (tapped[0]["to"]["X"], tapped[0]["to"]["Y"]) == pytest.approx((73.91, 30.615))  # PCD 160 at 22.5 deg
    cooling = moves(r, "G81")
    assert len(cooling) == 31  # FIX[2 * PI * 150 / 30] = FIX[31.4]
    assert (cooling[0]["to"]["X"], cooling[0]["to"]["Y"], cooling[0]["to"]["Z"]) == (150.0, 0.0, -15.0)
    assert var(r, 120) == 39


def check_peck_g66_faces(r: dict[str, Any]) -> None:
    pecks = moves(r, "G01", "O00008110.nc")
    assert var(r, 121) == 24 and var(r, 122) == 7  # 4 faces x 6 holes, 7 pecks in each
    assert len(pecks) == 24 * 7
    # peck n = 2 + 6 * e^(-(n-1)/3): 8, 6.299, 5.081, 4.207, 3.582, 3.133, then the rest to Z-30
    assert [m["to"]["Z"] for m in pecks[:7]] == pytest.approx([-6.0, -12.299, -17.38, -21.587, -25.169, -28.302, -30.0])
    holes = {(m["to"]["X"], m["to"]["Y"]) for m in pecks}
    assert holes == {(x, y) for x in (-40.0, 0.0, 40.0) for y in (-25.0, 25.0)}


def check_spec2_port_pattern(r: dict[str, Any]) -> None:
    spots = [(m["to"]["X"], m["to"]["Y"], m["to"]["Z"]) for m in moves(r, "G82")]
    assert spots == [(20.0, 15.0, -2.0), (55.0, 15.0, -3.5), (90.0, 15.0, -2.0), (20.0, 60.0, -5.0), (90.0, 60.0, -5.0)]
    assert var(r, 131) == 5


def check_face_mill_levels(r: dict[str, Any]) -> None:
    passes = moves(r, "G01", "O00012345.nc")
    assert len(passes) == 12  # M98 P00012346 L3 x M98 P00012345 L4
    assert [m["to"]["Z"] for m in passes] == [1.0] * 4 + [0.5] * 4 + [0.0] * 4
    assert [m["to"]["Y"] for m in passes] == [15.0, 55.0, 95.0, 135.0] * 3
    assert all(m["from"]["X"] == -50.0 and m["to"]["X"] == 290.0 for m in passes)


def check_pallet_cycle(r: dict[str, Any]) -> None:
    assert var(r, 501) == 1 and var(r, 502) == 2  # pallet 1 was in: two changes
    assert var(r, 503) == 1 and var(r, 504) == 1  # one cycle on each pallet
    assert var(r, 3901) == 214  # [#_PRTSA] counted both covers
    faced = moves(r, "G01", "O00012345.nc")
    assert len(faced) == 8 and {m["to"]["Z"] for m in faced} == {0.0}


def check_helical_bore(r: dict[str, Any]) -> None:
    helix = moves(r, "G03", "O00008130.nc")
    first = [m for m in helix if m["centre"]["X"] == 60.0]
    second = [m for m in helix if m["centre"]["X"] == 160.0]
    assert len(first) == 22 + 1 and len(second) == 20 + 1  # FUP[32/1.5] and FUP[24/1.25] turns, a flat one
    assert first[0]["to"]["X"] == 67.5 and second[0]["to"]["X"] == 171.0  # (D - T) / 2 off the centre
    assert first[-1]["to"]["Z"] == -30.0 and second[-1]["to"]["Z"] == -22.0
    assert var(r, 123) == 2 and var(r, 124) == 20


def check_op20_slots(r: dict[str, Any]) -> None:
    assert var(r, 616) == 88 and var(r, 614) == 121  # a cycle more on each tool
    assert var(r, 3901) == 213
    assert re.fullmatch(r"20261122 \d+ O12030020 PART 213 CYCLE \d+ S", r["output"][0])
    slots = [m for m in moves(r, "G01") if m["to"]["Z"] == -6.0 and m["from"]["Z"] == -6.0]
    assert [(m["to"]["X"], m["to"]["Y"]) for m in slots] == [(110.0, 30.0), (110.0, 70.0)]


MAINS: dict[str, Callable[[dict[str, Any]], None]] = {
    "probe_datum_corner.nc": check_probe_datum_corner,
    "probe_face_pallet2.nc": check_probe_face_pallet2,
    "set_tool_lengths.nc": check_set_tool_lengths,
    "bolt_circles.nc": check_bolt_circles,
    "peck_g66_faces.nc": check_peck_g66_faces,
    "spec2_port_pattern.nc": check_spec2_port_pattern,
    "face_mill_levels.nc": check_face_mill_levels,
    "pallet_cycle.nc": check_pallet_cycle,
    "helical_bore.nc": check_helical_bore,
    "op20_slots.nc": check_op20_slots,
}


@pytest.mark.parametrize("name", list(MAINS))
def test_fanuc_30i_corpus_main_runs_to_completion(name: str) -> None:
    MAINS[name](run(F30I / name))


def test_fanuc_30i_corpus_has_eighteen_programs_with_8_digit_numbers() -> None:
    files = sorted(p for p in F30I.iterdir() if p.suffix == ".nc")
    assert len(files) >= 18
    headers = [m for p in files for m in re.findall(r"(?m)^O(\d+)", p.read_text(encoding="utf-8"))]
    assert len(headers) >= 18 and all(len(h) == 8 for h in headers)


def test_pallet_change_from_pallet_two_counts_three_changes() -> None:
    r = run(F30I / "pallet_cycle.nc", "501=2")
    assert var(r, 501) == 1 and var(r, 502) == 3


def test_pallet_change_alarms_when_the_pallet_is_not_seated() -> None:
    status, r = run_json(F30I / "pallet_cycle.nc", "1000=0")  # [#_UI[1]] off
    assert status == 1 and r["alarm"]["number"] == 3031
    assert Path(r["alarm"]["file"]).name == "O00009020.nc"


def test_pallet_cycle_alarms_when_the_batch_is_complete() -> None:
    status, r = run_json(F30I / "pallet_cycle.nc", "3901=400")  # [#_PRTSA] reached [#_PRTSN]
    assert status == 1 and r["alarm"]["number"] == 3060 and r["alarm"]["line"] == 5


def test_tool_at_the_end_of_its_life_stops_with_a_message_and_counts_again() -> None:
    r = run(F30I / "op20_slots.nc", "616=299")
    assert r["messages"] == ["TOOL AT THE END OF ITS LIFE - REPLACE IT, THEN CYCLE START"]
    assert var(r, 616) == 0 and var(r, 614) == 121


def test_check_finds_no_error_or_warning_in_the_fanuc_30i_corpus() -> None:
    out, err = io.StringIO(), io.StringIO()
    status = check_paths([str(F30I)], out, err, "json")
    found = json.loads(out.getvalue())
    bad = [d for d in found if d["severity"] in ("error", "warning")]
    assert bad == [] and status == 0 and err.getvalue() == ""
