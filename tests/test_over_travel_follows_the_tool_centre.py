"""docs/semantics.md §11 "Travel" and §12: under cutter radius compensation (G41/G42) and a
lathe's tool nose radius compensation the stored stroke check holds the machine position, which
follows the tool centre (on a lathe the imaginary tool nose the T offset carries, beside the nose
centre), not the programmed point (planner/cutter_stage.py, ``_pending_travel``,
``centre_travel``). The alarm stands on the block whose centre path crosses the limit, though the
run learns its path only when it reads the next block; the control stops that block at the limit,
and nothing after it is drawn or timed.

The mill (fanuc): travel X -500…0, Y -400…0, Z -450…0 in machine coordinates; G54 X-300 Y-200
Z-100, so in program coordinates X ≤ 300, -200 ≤ Y ≤ 200. D1 is a radius of 10 (#13001).
Every point and time is worked out by hand in the comments."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from cli_capture import cli
from cncmacro.library.limits_settings import MachineLimits
from running import lines, machine, run

TRAVEL = {"X": (-500.0, 0.0), "Y": (-400.0, 0.0), "Z": (-450.0, 0.0)}
LIMITS = MachineLimits(TRAVEL)
PRESETS = {5221: -300.0, 5222: -200.0, 5223: -100.0, 13001: 10.0}  # G54 X, Y, Z; D1's radius
# the lines after the first move run by the run of plain lines (machine/straight_runs.py) and, each
# with a comment, by the general path
PATHS = pytest.mark.parametrize("tail", ["", " (general path)"], ids=["plain-lines", "general-path"])


def centre(mv) -> list[tuple[float, float]]:  # type: ignore[no-untyped-def]
    path = mv.tool_path
    return [(path.start[0], path.start[1])] + [(pc.end[0], pc.end[1]) for pc in path.pieces]


def near(got: list[tuple[float, float]], want: list[tuple[float, float]]) -> bool:
    return len(got) == len(want) and all(math.dist(a, b) < 1e-6 for a, b in zip(got, want, strict=True))


# G41 along X295 (machine X-5): the cut is on the + side, the tool centre at X305 (machine X+5)
STARTUP = ["O1016", "G90 G54 G00 X250. Y0 Z0", "G41 D1 G01 X295. Y0 F1000", "Y-50.", "X250.", "G40 G00 X240. Y-60.",
           "M30"]  # fmt: skip


@PATHS
def test_g41_start_up_whose_tool_centre_passes_the_limit_is_over_travel_on_its_block(tail: str) -> None:
    # line 3 starts up along +X (type A): its centre ends on the perpendicular of line 4 (-Y) at its
    # start, to the left of -Y: (295 + 10, 0) = X305, machine X5, 5 mm past the + limit. The centre
    # path (250,0) -> (305,0) crosses program X300 after 50 mm: the control stops there with OT0500 on
    # line 3; line 4 is read, never made
    text = lines(*(b + tail if k > 2 and not b.startswith("M") else b for k, b in enumerate(STARTUP)))
    m = run(text, limits=LIMITS, presets=PRESETS)
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (500, 3)
    assert "machine X5.000, 5.000 mm past" in m.alarm.message
    moves = m.planner.moves
    assert [mv.line + 1 for mv in moves] == [2, 3]
    assert near(centre(moves[-1]), [(250.0, 0.0), (300.0, 0.0)])
    # 50 mm at F1000 = 3 s; the clock is the moves' own (line 4's provisional 3.6 s is not in it)
    assert moves[-1].seconds == pytest.approx(3.0)
    assert m.planner.clock == pytest.approx(sum(mv.seconds for mv in moves))
    # the cut is the 50 mm made
    assert m.planner.cut_length == pytest.approx(50.0)


def test_check_and_run_put_the_alarm_on_the_block_whose_centre_crosses(tmp_path: Path) -> None:
    (tmp_path / ".cncmacro.toml").write_text(
        '[variables]\n5221 = -300.0\n5222 = -200.0\n5223 = -100.0\n13001 = 10.0\n\n'
        "[limits]\ntravel = { X = [-500, 0], Y = [-400, 0], Z = [-450, 0] }\n",
        encoding="utf-8",
    )  # fmt: skip
    path = tmp_path / "O1016.nc"
    path.write_text(lines(*STARTUP), encoding="utf-8")
    code, out, _ = cli("run", "--json", "--no-save", str(path))
    r = json.loads(out)
    assert code == 1 and (r["alarm"]["number"], r["alarm"]["line"]) == (500, 3)
    assert [mv["line"] for mv in r["moves"]] == [2, 3]
    assert r["moves"][-1]["tool_path"]["pieces"][-1]["to"]["X"] == pytest.approx(300.0)
    code, out, _ = cli("check", str(path))
    assert "O1016.nc:3:" in out and "over-travel" in out, out


@PATHS
def test_g42_acute_outside_corner_leaves_the_travel_though_the_block_ends_inside(tail: str) -> None:
    # Line 3 starts up along +Y to (250,0) (type A) and turns right into line 4 (+X), inside for G42:
    # its centre ends where its offset x = 260 meets line 4's, y = -10: (260,-10). Line 4 cuts +X to
    # X295, 5 mm inside the limit X300; line 5 turns back 135° to the left, (-40,40): for G42 (right
    # side) the corner is outside and acute, so the centre goes through the two extension points, with
    # d = -10 and r = 10: (295 + 10, 0 - 10) = (305,-10) and (295 + 7.071 + 7.071, 0) = (309.142, 0).
    # Line 4's centre path (260,-10) -> (305,-10) -> (309.142,0) crosses X300 at (300,-10), 40 mm
    # along: alarm 500 on line 4, found reading line 5
    text = lines("O0001", "G90 G54 G00 X250. Y-30. Z0", "G42 D1 G01 Y0 F1000", f"X295.{tail}", f"X255. Y40.{tail}",
                 "G40 G00 X240. Y50.", "M30")  # fmt: skip
    m = run(text, limits=LIMITS, presets=PRESETS)
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (500, 4)
    assert "machine X5.000, 5.000 mm past" in m.alarm.message
    moves = m.planner.moves
    assert [mv.line + 1 for mv in moves] == [2, 3, 4]
    assert near(centre(moves[1]), [(250.0, -30.0), (260.0, -10.0)])
    assert near(centre(moves[2]), [(260.0, -10.0), (300.0, -10.0)])
    # line 3: sqrt(10² + 20²) = 22.360680 mm, line 4: 40 mm, at F1000: 1.341641 s + 2.4 s
    assert (moves[1].seconds, moves[2].seconds) == (pytest.approx(math.sqrt(500.0) * 0.06), pytest.approx(2.4))
    assert m.planner.clock == pytest.approx(sum(mv.seconds for mv in moves))
    assert m.planner.cut_length == pytest.approx(math.sqrt(500.0) + 40.0)


@PATHS
def test_a_programmed_path_past_the_limit_whose_tool_centre_stays_inside_runs(tail: str) -> None:
    # G41 with the tool inside: line 3 starts up +X to (305,-40) (5 mm past X300 as programmed) and
    # turns left into line 4 (+Y), inside for G41: its centre ends where its offset y = -30 meets line
    # 4's, x = 295: (295,-30). Line 4 runs +Y along X305, its centre on X295; line 5 turns left to -X
    # (inside): the centre corner is (295,-10); line 5's centre runs to the cancel's corner, type A:
    # its end's perpendicular (270,-10). The centre stays within X295: no alarm (the programmed X305
    # alarmed before). Cut: sqrt(25² + 10²) + 20 + 25 = 26.925824 + 45 mm
    text = lines("O0001", "G90 G54 G00 X270. Y-40. Z0", "G41 D1 G01 X305. F1000", f"Y0{tail}", f"X270.{tail}",
                 "G40 G00 X260. Y10.", "M30")  # fmt: skip
    m = run(text, limits=LIMITS, presets=PRESETS)
    assert m.status == "completed", m.alarm
    moves = m.planner.moves
    assert near(centre(moves[1]), [(270.0, -40.0), (295.0, -30.0)])
    assert near(centre(moves[2]), [(295.0, -30.0), (295.0, -10.0)])
    assert near(centre(moves[3]), [(295.0, -10.0), (270.0, -10.0)])
    assert m.planner.cut_length == pytest.approx(math.sqrt(725.0) + 45.0)


def test_the_g40_cancel_move_stops_where_its_centre_path_crosses_the_limit() -> None:
    # Line 3 starts up +Y to (250,-20), its centre to the left of line 4 (+X) at (250,-10); line 4
    # cuts to X280 (centre on Y-10); line 5 cancels (type A) along (40,-40), a right turn: line 4's
    # centre ends on its end's perpendicular (280,-10) and the cancel runs from there to the
    # programmed end (320,-60), past X300. It crosses X300 halfway, at (300,-35) (the programmed
    # line crosses at (300,-40): the stop is the centre's). 20 mm down X and 25 down Y:
    # sqrt(400 + 625) = 32.0156 mm at F1000 = 1.920937 s; machine X20, 20 mm past
    text = lines("O0001", "G90 G54 G00 X250. Y-40. Z0", "G41 D1 G01 Y-20. F1000", "X280.", "G40 X320. Y-60.", "M30")
    m = run(text, limits=LIMITS, presets=PRESETS)
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (500, 5)
    assert "machine X20.000, 20.000 mm past" in m.alarm.message
    moves = m.planner.moves
    assert [mv.line + 1 for mv in moves] == [2, 3, 4, 5]
    assert near(centre(moves[-1]), [(280.0, -10.0), (300.0, -35.0)])
    assert moves[-1].seconds == pytest.approx(math.sqrt(1025.0) / 1000.0 * 60.0)
    assert m.planner.clock == pytest.approx(sum(mv.seconds for mv in moves))


def test_a_z_move_in_offset_mode_is_held_to_the_travel() -> None:
    # a Z move between two cuts is made at the corner: its own axis is checked as it is made. G54
    # Z-100 puts the + limit at program Z100; Z120. is machine Z20: alarm 500 on line 5, Z stopped
    # at program Z100
    text = lines("O0001", "G90 G54 G00 X250. Y-40. Z0", "G41 D1 G01 Y-20. F1000", "X280.", "G00 Z120.", "X250.",
                 "M30")  # fmt: skip
    m = run(text, limits=LIMITS, presets=PRESETS)
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (500, 5)
    assert m.planner.moves[-1].tool_path.pieces[-1].end[2] == pytest.approx(100.0)


def test_a_g28_after_the_start_up_holds_its_path_to_the_travel() -> None:
    # G42 starts up +Y along X295; a G28 (drawn as programmed) follows, so line 3's centre ends on its
    # end's perpendicular, right of +Y: (305,0), 5 mm past X300. It crosses X300 halfway from
    # (295,-30): at (300,-15), after sqrt(5² + 15²) = 15.811388 mm at F1000 = 0.948683 s; alarm 500 on
    # line 3, the G28 not made
    text = lines("O0001", "G90 G54 G00 X295. Y-30. Z0", "G42 D1 G01 Y0 F1000", "G91 G28 Z0.", "M30")
    m = run(text, limits=LIMITS, presets=PRESETS)
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (500, 3)
    moves = m.planner.moves
    assert [mv.line + 1 for mv in moves] == [2, 3]
    assert near(centre(moves[-1]), [(295.0, -30.0), (300.0, -15.0)])
    assert moves[-1].seconds == pytest.approx(math.sqrt(250.0) * 0.06)


def test_going_back_before_the_alarm_gives_the_block_its_move_again() -> None:
    # a snapshot after line 3 ran, restored after the alarm cut line 3 short (the debugger's step
    # back): line 3 has its provisional path again, to its end's perpendicular (295,10), as the run
    # made it before it read line 4
    m = machine(lines(*STARTUP), limits=LIMITS, presets=PRESETS)
    while not (m.planner.moves and m.planner.moves[-1].line + 1 == 3):
        m.step()
    snap = m.snapshot()
    m.run()
    assert m.status == "alarm"
    assert near(centre(m.planner.moves[-1]), [(250.0, 0.0), (300.0, 0.0)])
    m.restore(snap)
    assert [mv.line + 1 for mv in m.planner.moves] == [2, 3]
    assert near(centre(m.planner.moves[-1]), [(250.0, 0.0), (295.0, 10.0)])
    m.run()
    assert m.status == "alarm" and m.alarm is not None and m.alarm.line + 1 == 3


# A lathe (fanuc-0i-lathe): offset 01 with no X, Z geometry, nose radius 0.8; after G28 the G50
# makes machine 0 program X200 (a diameter) Z100. The X travel -300…0 puts the + limit at program
# X200. G42 along -Z at X199 (radius 99.5), the cancel along -X
LATHE = MachineLimits({"X": (-300.0, 0.0), "Z": (-300.0, 0.0)})


@pytest.mark.parametrize(("tip", "stops"), [(0, True), (3, False)], ids=["tip-0", "tip-3"])
def test_a_lathe_checks_the_tool_nose_the_offset_carries(tip: int, stops: bool) -> None:
    # Tip 0: the nose centre is the tool's reference. The start-up (line 7) runs the centre from the
    # programmed start (X199, Z5) to line 8's perpendicular at Z-30, a radius 99.5 + 0.8 = 100.3
    # (X200.6, machine X0.6: past the + limit). It crosses X200 (radius 100) at 0.5 / 0.8 = 0.625 of
    # the way: Z5 - 0.625 x 35 = Z-16.875, after sqrt(21.875² + 0.5²) = 21.880713 mm (radial) at
    # F100 (G98): 13.128428 s; alarm 500 on line 7.
    # Tip 3: the imaginary tool nose is (-R, -R) from the centre (radial, Z): the centre runs on
    # X200.6 but the nose the offset carries to the machine stays on X199: no alarm
    text = lines("O0001", f"G10 P10001 X0 Z0 R0.8 Q{tip}", "T0101", "G28 U0 W0", "G50 X200. Z100.",
                 "G98 G00 X199. Z5.", "G42 G01 Z-30. F100", "G40 G00 U-10.", "M30")  # fmt: skip
    m = run(text, "fanuc-0i-lathe", limits=LATHE)
    xi, zi = m.planner.axis_index["X"], m.planner.axis_index["Z"]
    if not stops:
        assert m.status == "completed", m.alarm
        return
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (500, 7)
    assert "machine X0.600, 0.600 mm past" in m.alarm.message
    last = m.planner.moves[-1]
    assert last.line + 1 == 7
    end = last.tool_path.pieces[-1].end
    assert (end[xi], end[zi]) == (pytest.approx(200.0), pytest.approx(-16.875))
    assert last.seconds == pytest.approx(math.hypot(21.875, 0.5) / 100.0 * 60.0)
