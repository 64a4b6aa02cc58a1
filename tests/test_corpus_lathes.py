"""The lathe corpora (tests/corpus/gsk980tdi and tests/corpus/fanuc-0i-lathe): shop programs of a
GSK980TDi and a FANUC 0i-TF lathe. ``cncmacro check`` finds nothing in them (no error, no
warning, and no information either: ``ALLOWED_INFOS`` is empty; their branches on a part counter or a
wear value kept on the machine stop the analysis with an ``unknown-value`` hint), every main program runs to
completion in a time a lathe could take for it (10 s to 30 min, some cutting), and each does what
its programmer meant: the passes of a cycle where the control makes them, a thread's last pass
at the root diameter, an offset written. O2016's and g92_thread_m24's times are worked out by hand.

Programs that use a feature the simulated lathe does not run as the control does yet are listed
in ``WAITING`` with what they wait for; their tests are expected to fail (strictly: a test that
starts passing must be moved out of the list)."""

from __future__ import annotations

import io
import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from cncmacro.cli.check import check_paths
from test_corpus import CORPUS, GSK, moves, run, run_json, var

FANUC_T = CORPUS / "fanuc-0i-lathe"

# (file name, diagnostic code) of the information findings the lathe programs may have: none
ALLOWED_INFOS: frozenset[tuple[str, str]] = frozenset()


def cuts(r: dict[str, Any], line: int) -> list[dict[str, Any]]:
    """The moves a block made at the feed (a cycle's passes included)."""
    return [m for m in r["moves"] if m["line"] == line and m["kind"] != "rapid" and m["mode"] != "G00"]


def ends(r: dict[str, Any], line: int, axis: str) -> list[float]:
    return [round(m["to"][axis], 3) for m in cuts(r, line)]


def cycle_ends(r: dict[str, Any], code: str) -> list[tuple[float, float]]:
    """Where each move of a single cycle ``code`` (G90/G92/G94) ended its cut: the leg that is
    not a rapid, else the move's end point."""
    out = []
    for m in r["moves"]:
        if m["mode"] != code:
            continue
        legs = [leg for leg in m.get("legs") or [] if not leg["rapid"]]
        to = legs[0]["to"] if legs else m["to"]
        out.append((round(to["X"], 3), round(to["Z"], 3)))
    return out


# ---------------------------------------------------------------- gsk980tdi


def check_g71_stepped_shaft(r: dict[str, Any]) -> None:
    rough = [m for m in r["moves"] if m.get("pass_of") == "G71"]
    assert rough and min(m["to"]["X"] for m in rough) == pytest.approx(14.5)  # shape's X14 + U0.5
    finish = [m for m in r["moves"] if m["line"] in range(13, 22) and m["mode"] in ("G02", "G03")]
    assert [m["mode"] for m in finish] == ["G02", "G03"]  # G70 runs the arcs as written
    assert r["messages"] == ["M00 program stop"]


def check_g71_id_bushing(r: dict[str, Any]) -> None:
    bore = [m for m in r["moves"] if m.get("pass_of") == "G71"]
    # an ID cycle: every pass above the shape's end X19 - 0.4, in the D20 hole, and none outside
    assert min(m["to"]["X"] for m in bore) == pytest.approx(18.6)
    assert max(m["to"]["X"] for m in bore) == pytest.approx(42.0 - 0.4)  # U-0.4 leaves stock in the bore
    assert cycle_ends(r, "G90") == [(50.5, -42.0), (50.0, -42.0)]  # X50 repeats the G90 to Z-42


def check_g72_flange_face(r: dict[str, Any]) -> None:
    levels = sorted({round(m["to"]["Z"], 3) for m in r["moves"] if m.get("pass_of") == "G72" and m["mode"] == "G01"})
    assert levels[0] == pytest.approx(-12.0 + 0.2)  # the deepest level stops at the face + W0.2
    assert len([m for m in r["moves"] if m["line"] == 14 and m["mode"] == "G03"]) == 1  # G70: the R3 fillet


def check_g73_forging(r: dict[str, Any]) -> None:
    # the rapids from each pass's offset start An straight in along X to Bn (N10 is G00 X0: GSK
    # §3.23.3, "ns 程序段是 G00 时按快速移动速度"); A→A1 and Cn→An+1 move Z too
    starts = [m for m in r["moves"] if m.get("pass_of") == "G73" and m["mode"] == "G00"
              and m["to"]["Z"] == m["from"]["Z"]]  # fmt: skip
    # 4 passes, relief 4 (radius) = 8 on X shrinking by thirds; each starts at the shape's X0 + U0.4
    assert [round(m["to"]["X"], 3) for m in starts] == pytest.approx([8.4, 5.733, 3.067, 0.4], abs=1e-3)


def check_g90_g94_taper(r: dict[str, Any]) -> None:
    assert cycle_ends(r, "G90") == [(37.0, -45.0), (34.5, -45.0), (34.5, -30.0), (34.5, -30.0), (34.5, -30.0),
                                    (34.0, -30.0), (34.0, -45.0)]  # fmt: skip
    assert cycle_ends(r, "G94")[:2] == [(-1.0, 1.0), (-1.0, 0.0)]  # Z0 repeats the G94 to X-1


def check_g92_thread_m24(r: dict[str, Any]) -> None:
    assert cycle_ends(r, "G92") == [(x, -32.0) for x in (23.2, 22.6, 22.1, 21.7, 21.5, 21.4, 21.4)]


def check_g76_thread_pair(r: dict[str, Any]) -> None:
    external = [m for m in r["moves"] if m["line"] == 12 and m["mode"] != "G00"]
    # Δd√n from 0.4 to k - d = 0.975 - 0.05: n = 1..6, then 2 finishing passes at the root
    assert len(external) >= 8 and external[-1]["to"]["X"] == pytest.approx(28.05)


def check_g32_thread_taper(r: dict[str, Any]) -> None:
    passes = moves(r, "G32")
    assert [m["from"]["X"] for m in passes] == [19.4, 18.9, 18.5, 18.2, 18.05, 18.05]
    assert all(m["from"]["Z"] == 4.0 and m["to"]["Z"] == -22.0 for m in passes)


def check_g75_grooves(r: dict[str, Any]) -> None:
    plunges = [round(m["to"]["Z"], 3) for m in r["moves"] if m.get("pass_of") == "G75"
               and m["to"]["X"] == pytest.approx(30.2)]  # fmt: skip
    assert sorted(set(plunges), reverse=True) == [-24.0, -27.5, -31.0, -32.0]  # Q3.5 steps, the last to Z-32


def check_g74_face_drill(r: dict[str, Any]) -> None:
    pecks = sorted({round(m["to"]["Z"], 3) for m in r["moves"] if m.get("pass_of") == "G74" and m["line"] == 18
                    and m["mode"] != "G00"}, reverse=True)  # fmt: skip
    assert pecks == [3.0 - 6.0 * k for k in range(1, 8)] + [-40.0]  # Q6 pecks from the start Z3, the last to Z-40


def check_ellipse_while(r: dict[str, Any]) -> None:
    finish = [m["to"] for m in r["moves"] if m["line"] == 36]
    assert len(finish) == 60
    for p in finish:  # every point on the ellipse a=30, b=14 centred on Z-30 (on the 0.001 grid)
        assert (p["X"] / 28.0) ** 2 + ((p["Z"] + 30.0) / 30.0) ** 2 == pytest.approx(1.0, abs=1e-4)
    assert (finish[-1]["X"], finish[-1]["Z"]) == pytest.approx((28.0, -30.0))


def check_thread_depth_loop(r: dict[str, Any]) -> None:
    g92 = cycle_ends(r, "G92")
    # total depth 3.9 on the diameter, 1.2·√n to 3.85: n = 1..11 (1.2·√11 = 3.98 is held at 3.85)
    assert var(r, 150) == 12 and len(g92) == 13
    assert g92[0] == (34.8, -40.0) and g92[-1] == (32.1, -40.0)


def check_wear_offset_update(r: dict[str, Any]) -> None:
    assert var(r, 2001) == pytest.approx(0.02) and var(r, 2101) == pytest.approx(-0.01)  # nothing measured


def check_g65_h_face_passes(r: dict[str, Any]) -> None:
    faces = [m for m in moves(r, "G01") if m["to"]["X"] == -1.0]
    assert [m["to"]["Z"] for m in faces] == [3.0, 1.5, 0.0] and var(r, 104) == 3


def check_pname_partoff(r: dict[str, Any]) -> None:
    partoff = moves(r, "G01", "QIEDUAN.CNC")
    assert (partoff[-1]["to"]["X"], partoff[-1]["to"]["Z"]) == (-0.5, -29.0)  # 25 long + the 4 wide blade


# ---------------------------------------------------------------- fanuc-0i-lathe


def check_o2001(r: dict[str, Any]) -> None:
    assert any(m.get("pass_of") == "G71" for m in r["moves"])
    assert [m["mode"] for m in r["moves"] if m["mode"] in ("G02", "G03") and not m.get("pass_of")] == [
        "G02", "G03", "G02"]  # fmt: skip


def check_o2002(r: dict[str, Any]) -> None:
    """The face at G96 S160 under the G50 S2000 clamp, from D64 to X-1.6 at F0.18 per revolution,
    by hand: n = 160000/(πD) until D = 160000/(2000π) = 25.465 (r0 = 12.732), then 2000 rev/min.
    The time is ∫ dr/(F·n): π(32² − r0²)/(0.18·160000) = 0.094017 min, then (r0 + 0.8)/(0.18·2000)
    = 0.037590 min; 0.131607 min = 7.896 s."""
    face = cuts(r, 10)
    assert len(face) == 1 and face[0]["time"] == pytest.approx(7.896, rel=0.01)


def check_o2003(r: dict[str, Any]) -> None:
    levels = sorted({round(m["to"]["Z"], 3) for m in r["moves"] if m.get("pass_of") == "G72" and m["mode"] == "G01"})
    assert levels[0] == pytest.approx(-15.0 + 0.2)  # the deepest level stops at the flange face + W0.2
    assert len([m for m in r["moves"] if m["line"] == 14 and m["mode"] == "G03"]) == 1  # G70: the R4 fillet


def check_o2004(r: dict[str, Any]) -> None:
    starts = [m for m in r["moves"] if m.get("pass_of") == "G73" and m["mode"] == "G00"
              and m["to"]["X"] != 46.0]  # fmt: skip
    # 4 passes, relief 3.5 (radius) = 7 on X shrinking by thirds; each starts at the shape's X0 + U0.4
    assert [round(m["to"]["X"], 3) for m in starts] == pytest.approx([7.4, 5.067, 2.733, 0.4], abs=1e-3)


def check_o2005(r: dict[str, Any]) -> None:
    assert cycle_ends(r, "G90") == [(42.0, -44.0), (38.5, -44.0), (38.5, -40.0), (38.5, -40.0), (38.5, -40.0),
                                    (38.0, -40.0), (38.0, -44.0)]  # fmt: skip
    assert cycle_ends(r, "G94") == [(-1.0, 1.0), (-1.0, 0.0), (38.5, -44.0)]  # Z0 repeats the facing


def check_o2006(r: dict[str, Any]) -> None:
    assert cycle_ends(r, "G92") == [(x, -37.0) for x in (29.1, 28.5, 28.0, 27.7, 27.5, 27.4, 27.4)]


def check_o2007(r: dict[str, Any]) -> None:
    internal = [m for m in r["moves"] if m["line"] == 18 and m["mode"] != "G00"]
    # Δd√n from 0.35 to k − d = 1.3 − 0.05 : n = 1..13, then 2 finishing
    assert len(internal) >= 15 and internal[-1]["to"]["X"] == pytest.approx(48.0)


def check_o2008(r: dict[str, Any]) -> None:
    passes = moves(r, "G32")
    assert [(m["from"]["X"], m["to"]["X"]) for m in passes] == [
        (24.14, 25.64), (23.54, 25.04), (23.14, 24.64), (22.84, 24.34), (22.62, 24.12), (22.62, 24.12)]  # fmt: skip


def check_o2009(r: dict[str, Any]) -> None:
    bottoms = {round(m["to"]["Z"], 3) for m in r["moves"] if m.get("pass_of") == "G75"
               and m["to"]["X"] == pytest.approx(50.2)}  # fmt: skip
    assert bottoms == {-13.0, -15.5, -18.0, -28.0, -30.5, -33.0, -43.0, -45.5, -48.0}


def check_o2010(r: dict[str, Any]) -> None:
    pecks = sorted({round(m["to"]["Z"], 3) for m in r["moves"] if m.get("pass_of") == "G74" and m["line"] == 17
                    and m["mode"] != "G00"}, reverse=True)  # fmt: skip
    assert pecks == [3.0 - 5.0 * k for k in range(1, 13)] + [-60.0]  # Q5 pecks from the start Z3, the last to Z-60


def check_o2011(r: dict[str, Any]) -> None:
    finish = [m["to"] for m in r["moves"] if m["line"] == 35]
    assert len(finish) == math.ceil(25 / 0.4)  # 0.4 steps from Z0 to the centre, the last one held at 0
    for p in finish:  # on the ellipse a=25, b=18 centred on Z-25 (on the 0.001 grid)
        assert (p["X"] / 36.0) ** 2 + ((p["Z"] + 25.0) / 25.0) ** 2 == pytest.approx(1.0, abs=1e-4)


def check_o2012(r: dict[str, Any]) -> None:
    g92 = cycle_ends(r, "G92")
    # 3.9 deep on the diameter, 1.1·√n held at 3.85: n = 1..13 (1.1·√13 = 3.97), then two at the root
    assert var(r, 150) == 14 and len(g92) == 15 and g92[-1] == (44.1, -45.0)


def check_o2013(r: dict[str, Any]) -> None:
    assert var(r, 510) == 1  # first part on this insert: no offset step


def check_o2014(r: dict[str, Any]) -> None:
    passes = [(m["to"]["X"], m["to"]["Z"]) for m in moves(r, "G01", "O9014.nc") if m["from"]["Z"] != m["to"]["Z"]]
    assert passes == [(42.0, -60.0), (40.4, -60.0), (37.4, -40.0), (34.4, -40.0), (32.4, -40.0),
                      (29.4, -18.0), (26.4, -18.0), (24.4, -18.0)]  # fmt: skip


def check_o2015(r: dict[str, Any]) -> None:
    grooves = [m["to"]["Z"] for m in moves(r, "G01", "O3015.nc")]
    assert grooves == [-15.0, -25.0, -35.0, -45.0]
    assert cycle_ends(r, "G90") == [(34.5, -60.0), (34.0, -60.0)]


def check_o2016(r: dict[str, Any]) -> None:
    assert len([m for m in r["moves"] if m.get("pass_of") == "G71" and m["mode"] == "G01"]) == 5 + 4  # levels + shape


def check_g83_g84_end_holes(r: dict[str, Any]) -> None:
    # G83 from Z3 to Z-25 at F80 (G98): 6 pecks of 5 mm, a 1 mm retract after the first five: 33 mm of
    # feed (24.75 s), 5 + 28 mm of rapids at 8000 (0.2475 s); the taps at 1.5 x 300 = 450 mm/min, 25 mm
    # in and out: 6.667 s each, and both end where they started, at Z5
    holes = [(m["mode"], m["time"], m["from"]["Z"]) for m in r["moves"] if m["mode"] in ("G83", "G84", "G33")]
    assert [(mode, z) for mode, _, z in holes] == [("G83", 3.0), ("G84", 5.0), ("G33", 5.0)]
    assert [t for _, t, _ in holes] == pytest.approx([24.75 + 0.2475, 50 / 450 * 60, 50 / 450 * 60])
    after = next(m for m in r["moves"] if m["line"] == 19)  # N170, after the G33
    assert after["from"]["Z"] == 5.0


def check_o2017(r: dict[str, Any]) -> None:
    # face holes at F120 (G98): from Z5 rapid to R (Z2) 0.012 s, 20 mm in Q4 pecks without a retract
    # 10 s, P300 0.3 s, back 23 mm 0.092 s; the next three turn C 90 deg first (0.5 s at 10,800/min)
    face = [(m["to"]["C"], m["time"]) for m in r["moves"] if m["mode"] == "G83"]
    assert [c for c, _ in face] == [0.0, 90.0, 180.0, 270.0]
    assert [t for _, t in face] == pytest.approx([10.404, 10.904, 10.904, 10.904])
    # cross holes from X90: R-5 (a radius) to X80 0.025 s, 20 mm of radius at F100 12 s, P200 0.2 s,
    # back 25 mm 0.125 s; the second turns C 180 deg first (1 s)
    side = [(m["to"]["X"], m["to"]["C"], m["time"]) for m in r["moves"] if m["mode"] == "G87"]
    assert [(x, c) for x, c, _ in side] == [(40.0, 0.0), (40.0, 180.0)]
    assert [t for _, _, t in side] == pytest.approx([12.35, 13.35])


MAINS: dict[Path, Callable[[dict[str, Any]], None]] = {
    GSK / "g71_stepped_shaft.cnc": check_g71_stepped_shaft,
    GSK / "g71_id_bushing.cnc": check_g71_id_bushing,
    GSK / "g72_flange_face.cnc": check_g72_flange_face,
    GSK / "g73_forging.cnc": check_g73_forging,
    GSK / "g90_g94_taper.cnc": check_g90_g94_taper,
    GSK / "g92_thread_m24.cnc": check_g92_thread_m24,
    GSK / "g76_thread_pair.cnc": check_g76_thread_pair,
    GSK / "g32_thread_taper.cnc": check_g32_thread_taper,
    GSK / "g75_grooves.cnc": check_g75_grooves,
    GSK / "g74_face_drill.cnc": check_g74_face_drill,
    GSK / "ellipse_while.cnc": check_ellipse_while,
    GSK / "thread_depth_loop.cnc": check_thread_depth_loop,
    GSK / "wear_offset_update.cnc": check_wear_offset_update,
    GSK / "g65_h_face_passes.cnc": check_g65_h_face_passes,
    GSK / "pname_partoff.cnc": check_pname_partoff,
    GSK / "g83_g84_end_holes.cnc": check_g83_g84_end_holes,
    FANUC_T / "O2001.nc": check_o2001,
    FANUC_T / "O2002.nc": check_o2002,
    FANUC_T / "O2003.nc": check_o2003,
    FANUC_T / "O2004.nc": check_o2004,
    FANUC_T / "O2005.nc": check_o2005,
    FANUC_T / "O2006.nc": check_o2006,
    FANUC_T / "O2007.nc": check_o2007,
    FANUC_T / "O2008.nc": check_o2008,
    FANUC_T / "O2009.nc": check_o2009,
    FANUC_T / "O2010.nc": check_o2010,
    FANUC_T / "O2011.nc": check_o2011,
    FANUC_T / "O2012.nc": check_o2012,
    FANUC_T / "O2013.nc": check_o2013,
    FANUC_T / "O2014.nc": check_o2014,
    FANUC_T / "O2015.nc": check_o2015,
    FANUC_T / "O2016.nc": check_o2016,
    FANUC_T / "O2017.nc": check_o2017,
}

# Programs waiting for a feature of the simulated lathe, with what each waits for (their tests are
# strict expected failures); none since the threads, grooves and CSS of the lathe cycles
WAITING: dict[Path, str] = {}


def _id(p: Path) -> str:
    return f"{p.parent.name}/{p.name}"


def _params() -> list[Any]:
    return [pytest.param(p, id=_id(p), marks=[pytest.mark.xfail(strict=True, reason=WAITING[p])] if p in WAITING
                         else []) for p in MAINS]  # fmt: skip


@pytest.mark.parametrize("path", _params())
def test_lathe_program_runs_in_a_plausible_time_and_does_what_it_means(path: Path) -> None:
    r = run(path)
    assert r["lathe"] is True
    assert 10.0 <= r["cycle"]["seconds"] <= 30 * 60 and r["cycle"]["cut"] > 0
    MAINS[path](r)


def test_lathe_corpora_check_clean() -> None:
    out, err = io.StringIO(), io.StringIO()
    status = check_paths([str(GSK), str(FANUC_T)], out, err, "json")
    names = {p.name for p in MAINS} | {"QIEDUAN.CNC", "O9013.nc", "O9014.nc", "O3015.nc"}
    found = [d for d in json.loads(out.getvalue()) if Path(d["file"]).name in names]
    bad = [d for d in found if (Path(d["file"]).name, d["code"]) not in ALLOWED_INFOS]
    assert bad == [] and status == 0 and err.getvalue() == ""


def test_lathe_corpora_hold_fifteen_programs_each() -> None:
    assert len([p for p in MAINS if p.parent == GSK]) >= 15 and len([p for p in MAINS if p.parent == FANUC_T]) >= 15


def test_wear_offset_update_writes_the_measured_error_into_the_wear() -> None:
    # measured D30.02 and Z-50.03 against D30 and Z-50: X wear 0.02 − 0.02, Z wear −0.01 + 0.03
    r = run(GSK / "wear_offset_update.cnc", "520=30.02", "521=-50.03")
    assert var(r, 2001) == pytest.approx(0.0) and var(r, 2101) == pytest.approx(0.02)
    assert var(r, 520) is None and var(r, 521) is None


def test_wear_offset_update_stops_on_an_error_over_the_limit() -> None:
    status, r = run_json(GSK / "wear_offset_update.cnc", "520=30.15")
    assert status == 1 and r["alarm"]["number"] == 5941  # #3000=41 on a GSK: 5900 + 41


def test_o2013_steps_the_wear_by_g10_and_alarms_over_the_limit() -> None:
    # the 20th part calls O9013: G10 P1 U-0.01 adds to the X wear -0.195, #2001 reads -0.205, over the limit C0.2
    status, r = run_json(FANUC_T / "O2013.nc", "510=19", "2001=-0.195")
    assert status == 1 and r["alarm"]["number"] == 3013


def test_g92_thread_m24_takes_the_time_worked_out_by_hand() -> None:
    """g92_thread_m24.cnc timed by hand with the gsk980tdi profile's rapids (X 6,000 mm/min on
    the radius, Z 8,000), a 1 s turret index, from X0 Z0.

    - G00 X100 Z100: 100 mm of Z = 0.75 s; T0101 1 s; G00 X32 Z2: 98 mm of Z = 0.735 s.
    - G90 at F0.25 × S900 = 225 mm/min: in at rapid, 42 mm along Z, out at the feed, back 42 mm at
      rapid: X27 2.5 mm in = 0.025 + 11.2 + 0.6667 + 0.315 = 12.2067 s; X24.5 (the Z-40 kept)
      3.75 mm = 0.0375 + 11.2 + 1.0 + 0.315 = 12.5525 s.
    - G00 X18 Z1: 7 mm of X = 0.07 s; at F0.12 × 900 = 108 mm/min the chamfer 2.9·√2 = 4.1012 mm
      = 2.2785 s, Z-40 38.1 mm = 21.1667 s, X30 3.1 mm = 1.7222 s; G00 X100 Z100: 140 of Z = 1.05 s.
    - T0202 1 s; G00 X32 Z-36: 136 of Z = 1.02 s; G01 X20 at 0.06 × 500 = 30 mm/min: 6 mm = 12 s;
      G04 X0.3; G00 X32 0.06 s; G00 X100 Z100 1.02 s.
    - T0303 1 s; G00 X26 Z5: 95 of Z = 0.7125 s. Seven G92 passes at the lead 2 × S500 = 1000 mm/min,
      each 37 mm = 2.22 s and back 37 mm of Z = 0.2775 s, in and out at rapid 2 × (26 − X)/2 mm:
      2 × 14.05 mm / 6,000 = 0.281 s for the seven; G00 X100 Z100 0.7125 s.
    Total 89.120 s; cut 42 + 2.5 + 42 + 3.75 + 4.1012 + 38.1 + 3.1 + 6 + 7 × 37 = 400.55 mm."""
    r = run(GSK / "g92_thread_m24.cnc")
    assert r["cycle"]["seconds"] == pytest.approx(89.120, rel=0.01)
    assert r["cycle"]["cut"] == pytest.approx(400.55, rel=0.01)


def test_o2016_takes_the_time_worked_out_by_hand() -> None:
    """O2016 timed by hand with the profile's rapids (X 12,000 mm/min on the radius, Z 15,000) and
    G97 S1000: rough feed F0.25 = 250 mm/min, finish F0.1 = 100 mm/min.

    - T0101: 1 s; G00 X42 Z2 from X0 Z0: 21 mm radial / 12,000 = 0.105 s.
    - G71 U2 R1, U0.5 W0: levels X38, X34, X30, X26, X22 (the next, X18, passes the shape's first
      point X20.5). X38 and X34 cut Z2 → Z-50 (52 mm), X30, X26 and X22 meet the step at Z-30
      (32 mm): 200 mm = 48 s. The pass along the shape + U0.5: 32 + 5 + 20 + 6 = 63 mm = 15.12 s.
      Rapids: steps in 2, 3, 3, 3, 3 mm radial (0.010 + 4 × 0.015 s), five 45° pull-backs of 1 mm
      (0.005 s each), back along Z 51, 51, 31, 31, 31 mm (0.204 × 2 + 0.124 × 3 s), to X20.5
      (1.75 mm, 0.00875 s), from Z-50 to Z2 (0.208 s) and X42.5 to X42 (0.00125 s): 1.093 s.
    - G70: G00 X20 (11 mm, 0.055 s), 63 mm at 100 mm/min = 37.8 s, back to Z2 (0.208 s): 38.063 s.
    - G00 X150 Z150: 148 mm of Z / 15,000 = 0.592 s.
    Total 1 + 0.105 + 63.12 + 1.093 + 38.063 + 0.592 = 103.973 s; cut 263 + 63 = 326 mm."""
    r = run(FANUC_T / "O2016.nc")
    assert r["cycle"]["seconds"] == pytest.approx(103.973, rel=0.01)
    assert r["cycle"]["cut"] == pytest.approx(326.0, rel=0.01)
