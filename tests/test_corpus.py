"""The corpus of realistic programs (tests/corpus): every main program runs to completion with
``cncmacro run --no-save`` and does what its programmer meant (a hole count, an end point, a
counter, a printed line), and ``cncmacro check`` finds no error or warning in the corpus or
the examples."""

from __future__ import annotations

import contextlib
import io
import json
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from cncmacro.cli.check import check_paths
from cncmacro.cli.main import main

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "tests" / "corpus"
FANUC = CORPUS / "fanuc-0i"
GSK = CORPUS / "gsk980tdi"


def run_json(path: Path, *presets: str) -> tuple[int, dict[str, Any]]:
    """The exit status and JSON result of ``cncmacro run --no-save --json`` on a corpus file,
    with the folder's machine settings but persistent variables that start vacant (a
    ``.cncmacro-vars.json`` left by a run by hand must not change what the tests see)."""
    out = io.StringIO()
    with tempfile.TemporaryDirectory() as tmp:
        machine = Path(tmp) / ".cncmacro.toml"
        settings = (path.parent / ".cncmacro.toml").read_text(encoding="utf-8")
        machine.write_text('persistent_file = "vars.json"\n' + settings, encoding="utf-8")
        argv = ["run", "--no-save", "--json", "--machine", str(machine), str(path)]
        for p in presets:
            argv += ["--set", p]
        with contextlib.redirect_stdout(out):
            status = main(argv)
    return status, json.loads(out.getvalue())


def run(path: Path, *presets: str) -> dict[str, Any]:
    """The result of a run that must complete."""
    status, result = run_json(path, *presets)
    assert status == 0 and result["status"] == "completed", result["alarm"]
    return result


def var(result: dict[str, Any], n: int) -> float | None:
    return result["variables"].get(str(n))


def moves(result: dict[str, Any], mode: str, file: str | None = None) -> list[dict[str, Any]]:
    return [m for m in result["moves"] if m["mode"] == mode and (file is None or Path(m["file"]).name == file)]


# ---------------------------------------------------------------- fanuc


def check_probe_vice(r: dict[str, Any]) -> None:
    probes = moves(r, "G31")
    assert [round(m["to"]["Z"], 3) for m in probes][:1] == [-0.35]
    assert round(probes[1]["to"]["X"], 3) == 60.08
    assert var(r, 5223) == pytest.approx(-0.35) and var(r, 5221) == pytest.approx(0.08)
    assert r["output"] == ["PROBE REPORT O1001", "Z ERROR -0.350", "X ERROR 0.080", "G54 Z -0.350"]


def check_thread_mill(r: dict[str, Any]) -> None:
    internal = moves(r, "G03", "O9130.nc")  # right-hand: G03 climbing
    external = moves(r, "G02", "O9130.nc")  # left-hand: G02 climbing
    assert len(internal) == 3 * 8 and len(external) == 2 * 7  # passes x pitches climbed
    assert internal[-1]["to"]["X"] == pytest.approx(6.0)  # last pass: D24 - D12 cutter, on the radius
    assert internal[-1]["to"]["Z"] == pytest.approx(-2.0)
    assert external[-1]["to"]["X"] == pytest.approx(80.0 + 24.0)  # D36 + D12 cutter, on the radius


def check_rect_pocket(r: dict[str, Any]) -> None:
    plunges = [m["to"]["Z"] for m in moves(r, "G01", "O9140.nc") if m["from"]["Z"] != m["to"]["Z"]]
    assert plunges == pytest.approx([-6.5 / 3, -13 / 3, -6.5, -2.0, -4.0], abs=1e-3)  # Z on the 0.001 grid
    xs = [m["to"]["X"] for m in moves(r, "G01", "O9140.nc")]
    assert min(xs) == pytest.approx(14.0) and max(xs) == pytest.approx(88.0)  # walls minus the tool radius


def check_circular_pocket(r: dict[str, Any]) -> None:
    helixes = moves(r, "G03")
    assert min(m["to"]["Z"] for m in helixes) == pytest.approx(-12.0)
    assert max(m["to"]["X"] for m in helixes) == pytest.approx(18.0)  # D52 pocket, D16 tool
    assert var(r, 111) == 4


def check_g66_drill_plate(r: dict[str, Any]) -> None:
    bottoms = [(m["to"]["X"], m["to"]["Y"]) for m in moves(r, "G01", "O9150.nc") if m["to"]["Z"] == -22.0]
    assert len(bottoms) == 8 and var(r, 510) == 8
    assert bottoms[:3] == [(20.0, 15.0), (50.0, 15.0), (80.0, 15.0)] and bottoms[-1] == (5.0, 60.0)


def check_spec2_stepped_holes(r: dict[str, Any]) -> None:
    holes = [(m["to"]["X"], m["to"]["Y"], m["to"]["Z"]) for m in moves(r, "G01", "O9160.nc")]
    assert holes == [(10.0, 10.0, -5.0), (40.0, 10.0, -13.0), (70.0, 10.0, -21.0), (70.0, 40.0, -5.0)]


def check_coolant_rows(r: dict[str, Any]) -> None:
    holes = [(m["to"]["X"], m["to"]["Y"], m["to"]["Z"]) for m in moves(r, "G01", "O9170.nc")]
    rows = [[(10.0 + 12.0 * k, y, -15.0) for k in range(4)] for y in (10.0, 30.0)]
    assert holes == rows[0] + rows[1] + [(20.0 + 20.0 * k, 50.0, -22.0) for k in range(3)]
    assert var(r, 140) == 8  # M8. on the last call; the M of a G65 block is its argument #13


def check_m98_tapping_grid(r: dict[str, Any]) -> None:
    taps = moves(r, "G84")
    assert len(taps) == 20
    grid = {(x, y) for x in (10, 30, 50, 70, 90) for y in (10, 25, 40, 55)}
    assert {(m["to"]["X"], m["to"]["Y"]) for m in taps} == grid


def check_pallet_change(r: dict[str, Any]) -> None:
    assert var(r, 521) == 1 and var(r, 522) == 2
    faced = [m for m in moves(r, "G01", "O0044.nc") if m["to"]["X"] == 130.0]
    assert len(faced) == 2


def check_part_counter(r: dict[str, Any]) -> None:
    assert var(r, 3901) == 42 and var(r, 530) == 1
    assert var(r, 10003) == pytest.approx(-0.02)  # no wear step at the first part


def check_ellipse_boss(r: dict[str, Any]) -> None:
    assert r["messages"] == ["LOAD THE TOOL BY HAND, THEN CYCLE START"]
    assert var(r, 520) == 25
    last = moves(r, "G01")[-1]
    assert (last["to"]["X"], last["to"]["Y"]) == pytest.approx((46.0, 0.0), abs=1e-3)
    assert min(m["to"]["Z"] for m in moves(r, "G01")) == pytest.approx(-8.0)


def check_probe_bore(r: dict[str, Any]) -> None:
    """The bore of the machine file (D50.02 at X120.03 Y79.985, a D45.02 circle for the ball
    centre) touched four times by O9814: each G31 stops on its wall with the skip signal on, and
    the macro's copies of #5061/#5062 after each touch are those contact points."""
    touches = moves(r, "G31", "O9814.nc")
    assert all(m["skip"] for m in touches)
    points = [(m["to"]["X"], m["to"]["Y"]) for m in touches]
    half_chord = (22.51**2 - 0.015**2) ** 0.5  # the X touches run along Y80, 0.015 off the centre
    model = [(120.03 + half_chord, 80), (120.03 - half_chord, 80), (120.03, 102.495), (120.03, 57.475)]
    assert points == [pytest.approx(p) for p in model]
    skip_positions = [var(r, 550), var(r, 551), var(r, 552), var(r, 553)]  # #5061, #5061, #5062, #5062
    assert skip_positions == pytest.approx([model[0][0], model[1][0], model[2][1], model[3][1]])
    assert (var(r, 135), var(r, 136), var(r, 137)) == pytest.approx((120.03, 79.985, 50.02))
    assert (var(r, 5221), var(r, 5222)) == pytest.approx((0.03, -0.015))  # G54 moved to the centre
    assert r["output"] == ["BORE REPORT O1013", "CENTRE X120.030 Y79.985", "DIAMETER 50.020 ERROR 0.020",
                           "G54 X0.030 Y-0.015"]  # fmt: skip


# ---------------------------------------------------------------- gsk980tdi


def check_ellipse_handle(r: dict[str, Any]) -> None:
    contour = moves(r, "G01", "椭圆.CNC")
    assert len(contour) == 45
    assert (contour[-1]["to"]["X"], contour[-1]["to"]["Z"]) == pytest.approx((30.0, -24.0))


def check_parabola(r: dict[str, Any]) -> None:
    finish = [m for m in moves(r, "G01") if m["line"] == 35]
    assert len(finish) == 61  # 0.2 added 60 times stays just below 12 in doubles: one more, clamped step
    assert (finish[-1]["to"]["X"], finish[-1]["to"]["Z"]) == pytest.approx((24.0, -9.0))


def check_thread_g32(r: dict[str, Any]) -> None:
    passes = moves(r, "G32")
    assert var(r, 150) == 7 and var(r, 151) == pytest.approx(21.4)
    assert len(passes) == 8 and all(m["from"]["Z"] == 5.0 and m["to"]["Z"] == -31.0 for m in passes)


def check_thread_g92_g76(r: dict[str, Any]) -> None:
    g92 = moves(r, "G92")
    assert [m["to"]["X"] for m in g92] == pytest.approx([29.7, 29.4, 29.1, 28.8, 28.5, 28.2, 28.15])
    threads = [m for m in moves(r, "G32") if m.get("pass_of") == "G76"]  # G76's passes, each a thread
    assert threads[-1]["to"]["X"] == pytest.approx(28.05)


def check_wear_comp(r: dict[str, Any]) -> None:
    assert var(r, 3901) == 119 and var(r, 500) == 1 and var(r, 501) == 1
    assert var(r, 2001) == pytest.approx(0.02)  # no compensation at the first part


def check_grooves_h_codes(r: dict[str, Any]) -> None:
    bottoms = [m["to"]["Z"] for m in moves(r, "G01", "CUT.CNC") if m["to"]["X"] == 35.0]
    assert bottoms == [-10.0, -18.0, -26.0, -34.0, -42.0]
    assert var(r, 154) == 5


def check_m98_roughing(r: dict[str, Any]) -> None:
    cuts = [m["to"]["X"] for m in moves(r, "G01", "O0012.nc")]
    assert cuts == [47.0, 44.0, 41.0, 38.0, 35.0, 32.0]


def check_g66_cross_holes(r: dict[str, Any]) -> None:
    holes = [m["to"]["Z"] for m in moves(r, "G01", "O9030.nc") if m["to"]["X"] == 20.0]
    assert holes == [-12.0, -24.0, -36.0, -48.0] and var(r, 160) == 4


MAINS: dict[Path, Callable[[dict[str, Any]], None]] = {
    FANUC / "probe_vice.nc": check_probe_vice,
    FANUC / "thread_mill.nc": check_thread_mill,
    FANUC / "rect_pocket.nc": check_rect_pocket,
    FANUC / "circular_pocket.nc": check_circular_pocket,
    FANUC / "g66_drill_plate.nc": check_g66_drill_plate,
    FANUC / "spec2_stepped_holes.nc": check_spec2_stepped_holes,
    FANUC / "coolant_rows.nc": check_coolant_rows,
    FANUC / "m98_tapping_grid.nc": check_m98_tapping_grid,
    FANUC / "pallet_change.nc": check_pallet_change,
    FANUC / "part_counter.nc": check_part_counter,
    FANUC / "ellipse_boss.nc": check_ellipse_boss,
    FANUC / "probe_bore.nc": check_probe_bore,
    GSK / "ellipse_handle.cnc": check_ellipse_handle,
    GSK / "parabola.cnc": check_parabola,
    GSK / "thread_g32.cnc": check_thread_g32,
    GSK / "thread_g92_g76.cnc": check_thread_g92_g76,
    GSK / "wear_comp.cnc": check_wear_comp,
    GSK / "grooves_h_codes.cnc": check_grooves_h_codes,
    GSK / "m98_roughing.cnc": check_m98_roughing,
    GSK / "g66_cross_holes.cnc": check_g66_cross_holes,
}


@pytest.mark.parametrize("path", list(MAINS), ids=lambda p: f"{p.parent.name}/{p.name}")
def test_corpus_main_runs_to_completion(path: Path) -> None:
    MAINS[path](run(path))


def test_corpus_has_two_dozen_programs_some_in_gb18030() -> None:
    files = [p for p in CORPUS.rglob("*") if p.is_file() and p.suffix.lower() in (".nc", ".cnc")]
    assert len(files) >= 24
    gb18030 = []
    for p in files:
        data = p.read_bytes()
        try:
            data.decode("utf-8")
        except UnicodeDecodeError:
            assert "椭圆" in data.decode("gb18030") or "螺纹" in data.decode("gb18030")
            gb18030.append(p.name)
    assert len(gb18030) >= 2


def test_part_counter_steps_the_h03_wear_every_25_parts() -> None:
    r = run(FANUC / "part_counter.nc", "530=24")
    assert var(r, 530) == 25 and var(r, 10003) == pytest.approx(-0.03)


def test_part_counter_stops_for_a_worn_insert() -> None:
    r = run(FANUC / "part_counter.nc", "530=200")
    assert r["messages"] == ["INSERT OF T03 WORN OUT - CHANGE IT AND SET #530=0"]
    assert var(r, 530) == 1 and var(r, 10003) == 0


def test_part_counter_alarms_when_the_order_is_complete() -> None:
    status, result = run_json(FANUC / "part_counter.nc", "3901=500")
    assert status == 1 and result["alarm"]["number"] == 3050 and result["alarm"]["line"] == 6


def test_wear_comp_applies_the_wear_every_tenth_part_through_9xxx_indirection() -> None:
    r = run(GSK / "wear_comp.cnc", "501=9")
    assert var(r, 2001) == pytest.approx(0.01) and var(r, 2101) == pytest.approx(-0.015)


def test_part_catcher_stops_at_the_end_of_the_batch() -> None:
    r = run(GSK / "wear_comp.cnc", "3901=119")
    assert var(r, 3901) == 120
    assert len(r["messages"]) == 1 and "M00" in r["messages"][0]  # O9020 stops for the next bar


def test_pallet_change_from_pallet_two() -> None:
    r = run(FANUC / "pallet_change.nc", "521=2")
    assert var(r, 521) == 1 and var(r, 522) == 3


def test_check_finds_no_error_or_warning_in_the_corpus_and_examples() -> None:
    out, err = io.StringIO(), io.StringIO()
    status = check_paths([str(CORPUS), str(ROOT / "examples")], out, err, "json")
    found = json.loads(out.getvalue())
    intended = ("O08100.nc", 5, "macro-alarm")  # haas/bad_hole_count.nc leaves out H on purpose
    bad = [d for d in found if d["severity"] in ("error", "warning") and (Path(d["file"]).name, d["line"], d["code"])
           != intended]  # fmt: skip
    assert bad == [] and status == 0 and err.getvalue() == ""
