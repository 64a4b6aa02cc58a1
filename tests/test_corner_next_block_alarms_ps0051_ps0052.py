"""docs/semantics.md §8, "Chamfer and corner words": the block after a chamfer or corner R (,C,
,R) must go on with a G01, G02 or G03 move in its plane. FANUC's public alarm list: PS0051
"MISSING MOVE AFTER CHF/CNR", "Improper movement or the move distance was specified in the block
next to the chamfering or corner R block", and PS0052 "CODE IS NOT G01 AFTER CHF/CNR", "The block
next to the chamfering or corner R block is not G01". On the FANUC profiles the run stops there
(`corner-next`, ``Dialect.corner_next_alarm``); Haas, Mitsubishi and Mazak, whose sources at hand
say nothing of it, leave the corner sharp (or cut it at the next move) as before. Before, the
FANUC run left the corner sharp and went on."""

from __future__ import annotations

from math import sqrt

import pytest

from cncmacro.dialects import get_dialect
from running import lines, run

FANUC_MILLS = ("fanuc-0i", "fanuc-30i")
CORNER_NO_MOVE, CORNER_NOT_CUT = 51, 52  # PS0051, PS0052
START = "G90 G17 G21 G94 G00 X0 Y0"


def _alarm(text: str, profile: object) -> tuple[int, int, str]:
    m = run(text, profile)  # type: ignore[arg-type]
    assert m.status == "alarm" and m.alarm is not None, m.status
    return m.alarm.number, m.alarm.line + 1, m.alarm.subject


def _ends(m):
    return [(mv.line + 1, mv.mode, tuple(round(v, 6) for v in mv.end[:2])) for mv in m.planner.moves]


@pytest.mark.parametrize("profile", FANUC_MILLS)
def test_a_g00_after_a_chamfer_is_alarm_ps0052(profile: str) -> None:
    # line 4 is a G00, not G01: "The block next to the chamfering or corner R block is not G01"
    text = lines("O1000", START, "G01 X50. ,C3. F600.", "G00 Y50.", "M30")
    assert _alarm(text, profile) == (CORNER_NOT_CUT, 4, "corner-next")


def test_a_drilling_cycle_after_a_corner_r_is_alarm_ps0052() -> None:
    text = lines("O1000", START, "G01 X50. ,R5. F600.", "G99 G81 X60. Y10. Z-5. R2.", "G80", "M30")
    assert _alarm(text, "fanuc-0i") == (CORNER_NOT_CUT, 4, "corner-next")


@pytest.mark.parametrize("profile", FANUC_MILLS)
def test_a_block_without_a_move_after_a_chamfer_is_alarm_ps0051(profile: str) -> None:
    # M08 on line 4 moves nothing: "MISSING MOVE AFTER CHF/CNR"
    text = lines("O1000", START, "G01 X50. ,C3. F600.", "M08", "G01 Y50.", "M30")
    assert _alarm(text, profile) == (CORNER_NO_MOVE, 4, "corner-next")


def test_the_program_end_right_after_a_chamfer_is_alarm_ps0051() -> None:
    text = lines("O1000", START, "G01 X50. ,C3. F600.", "M30")
    assert _alarm(text, "fanuc-0i") == (CORNER_NO_MOVE, 4, "corner-next")


def test_a_move_off_the_plane_after_a_chamfer_is_alarm_ps0051() -> None:
    # G17 (X, Y): a Z move is an improper movement for the corner
    text = lines("O1000", START, "G01 X50. ,C3. F600.", "G01 Z-5.", "M30")
    assert _alarm(text, "fanuc-0i") == (CORNER_NO_MOVE, 4, "corner-next")


def test_a_lathe_g00_after_a_chamfer_is_alarm_ps0052() -> None:
    lathe = get_dialect("fanuc-30i").lathe_variant
    for profile in ("fanuc-0i-lathe", lathe):
        text = lines("O1000", "G00 X20. Z2.", "G99 S500 M03", "G01 Z0 F0.1", "X40. ,C2.", "G00 X60.", "M30")
        assert _alarm(text, profile) == (CORNER_NOT_CUT, 6, "corner-next")


def test_a_dwell_between_the_two_moves_is_no_alarm_and_the_chamfer_is_cut() -> None:
    m = run(lines("O1000", START, "G01 X50. ,C3. F600.", "G04 P500", "G01 Y50.", "M30"), "fanuc-0i")
    assert m.status == "completed", m.alarm
    # ,C3 between +X and +Y: X47 Y0, the chamfer to X50 Y3, then Y50; at 10 mm/s 4.7 s, 0.3·√2 s,
    # 4.7 s, and the dwell P500 (ms) 0.5 s
    assert _ends(m)[1:] == [(3, 1.0, (47.0, 0.0)), (3, 1.0, (50.0, 3.0)), (5, 1.0, (50.0, 50.0))]
    assert m.planner.clock == pytest.approx(9.4 + 0.3 * sqrt(2.0) + 0.5)


@pytest.mark.parametrize("profile", ("haas", "mitsubishi-m70", "mazak-eia"))
def test_other_makers_leave_the_corner_sharp_before_a_g00(profile: str) -> None:
    m = run(lines("O1000", START, "G01 X50. ,C3. F600.", "G00 Y50.", "M30"), profile)
    assert m.status == "completed", m.alarm
    assert _ends(m) == [(2, 0.0, (0.0, 0.0)), (3, 1.0, (50.0, 0.0)), (4, 0.0, (50.0, 50.0))]


def test_haas_cuts_the_chamfer_across_a_block_without_a_move() -> None:
    m = run(lines("O1000", START, "G01 X50. ,C3. F600.", "M08", "G01 Y50.", "M30"), "haas")
    assert m.status == "completed", m.alarm
    assert _ends(m)[1:] == [(3, 1.0, (47.0, 0.0)), (3, 1.0, (50.0, 3.0)), (5, 1.0, (50.0, 50.0))]
