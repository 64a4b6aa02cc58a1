"""docs/semantics.md §12, "Chamfer or corner R at a start-up, a cancel or a change of side": FANUC's
alarm PS0039 "CHF/CNR NOT ALLOWED IN G41,G42" ("Chamfering or corner R was specified with a
start-up, a cancel, or switching between G41 and G42 ... (cutter compensation or tool nose radius
compensation)", its alarm list) on the FANUC mills and lathes (``Dialect.corner_compensation_alarm``,
planner/cutter_stage.py ``_rounded_corner``); nothing on the profiles whose sources say nothing
of it. A ,R in offset mode is no finding (the corner itself is not simulated, §8)."""

from __future__ import annotations

import pytest

from cncmacro.dialects.alarms import CUTTER_CORNER
from running import lines, run

FANUC_MILLS = ["fanuc", "fanuc-30i"]


def contour(startup: str = "", side: str = "", middle: str = "", cancel: str = "") -> str:
    """A 30 x 30 corner cut with G41 D1 (radius 5): the start-up on line 4, the cancel on line 8,
    with the given corner words on the start-up, the block of line 6 (``side``: G42 there
    switches the side) and line 5 and the cancel."""
    return lines(
        "O0001",
        "G10 L12 P1 R5.",
        "G90 G17 G00 X-20. Y0",
        f"G41 D1 G01 X0 Y0 {startup} F400",
        f"Y30. {middle}",
        f"{side} X30. Y30.",
        "Y0",
        f"G40 X-20. Y0 {cancel}",
        "M30",
    )


@pytest.mark.parametrize("dialect", FANUC_MILLS)
def test_a_corner_r_on_the_start_up_block_is_alarm_39(dialect: str) -> None:
    m = run(contour(startup=",R3."), dialect)
    assert m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1, m.alarm.subject) == (CUTTER_CORNER, 4, "cutter-corner")


@pytest.mark.parametrize("dialect", FANUC_MILLS)
def test_a_corner_r_on_the_cancel_block_is_alarm_39(dialect: str) -> None:
    m = run(contour(cancel=",R2."), dialect)
    assert m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (CUTTER_CORNER, 8)


def test_a_chamfer_on_a_change_from_g41_to_g42_is_alarm_39() -> None:
    m = run(contour(side="G42 ,C2."), "fanuc")
    assert m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (CUTTER_CORNER, 6)


@pytest.mark.parametrize("dialect", FANUC_MILLS)
def test_a_corner_r_in_offset_mode_is_no_finding(dialect: str) -> None:
    m = run(contour(middle=",R5."), dialect)
    assert m.status == "completed", m.alarm


def test_a_chamfer_on_a_lathes_start_up_block_is_alarm_39() -> None:
    # offset 01 nose radius 0.8, tip 3: G42 G01 Z0 ,C1. is the start-up (line 5)
    text = lines("O0001", "G10 P10001 R0.8 Q3", "T0101", "G98 G00 X40. Z5.", "G42 G01 Z0 ,C1. F100",
                 "X60.", "G40 G00 X80.", "M30")  # fmt: skip
    m = run(text, "fanuc-0i-lathe")
    assert m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (CUTTER_CORNER, 5)


@pytest.mark.parametrize("dialect", ["haas", "mitsubishi-m70", "mazak-eia"])
def test_a_corner_r_on_the_start_up_is_no_finding_where_no_source_gives_the_alarm(dialect: str) -> None:
    m = run(contour(startup=",R3.", cancel=",R2."), dialect)
    assert m.status == "completed", m.alarm
