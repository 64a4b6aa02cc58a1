"""docs/semantics.md §12, "G31 in offset mode": a skip commanded while G41/G42 is in force is
FANUC's alarm PS0035 "CAN NOT COMMANDED G31" (mills and lathes) and Mitsubishi's program error
P608 (M700V/M70V programming manual §15.2 (6), and G31.1-G31.3 "work the same", §15.3 (3)); the
GSK980TDi (§3.16 note 1) and Haas ask for the compensation to be cancelled first and name no
alarm: a `cutter-skip` warning there, the skip made as programmed (planner/cutter_stage.py
``skip_in_offset``)."""

from __future__ import annotations

import pytest

from cncmacro.dialects import get_dialect
from cncmacro.dialects.alarms import CUTTER_SKIP
from running import lines, run

# offset D1 radius 5 (G10 L12 on FANUC, Mitsubishi and Haas alike: each writes its own memory);
# the probe move G31 on line 6 comes with G41 still in force
MILL = [
    "O0001",
    "G10 L12 P1 R5.",
    "G90 G17 G00 X-20. Y-20.",
    "G41 D1 G01 X0 Y0 F100",
    "Y30.",
    "G31 X60. F100",
    "G40 G00 X80. Y40.",
    "M30",
]

# a lathe: offset 01 nose radius 0.8, tip 3; G42 turning the diameter, then a G31 on line 6
LATHE = [
    "O0001",
    "G10 P10001 R0.8 Q3",
    "T0101",
    "G98 G00 X40. Z5.",
    "G42 G01 Z0 F100",
    "G31 Z-30. F50",
    "G40 G00 X80.",
    "M30",
]


@pytest.mark.parametrize("dialect", ["fanuc", "fanuc-30i", "mitsubishi-m70"])
def test_g31_in_g41_is_the_controls_alarm_on_a_mill(dialect: str) -> None:
    m = run(lines(*MILL), dialect)
    assert m.status == "alarm"
    assert m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1, m.alarm.subject) == (CUTTER_SKIP, 6, "cutter-skip")


def test_a_multi_step_skip_in_g41_is_program_error_p608_on_mitsubishi() -> None:
    text = lines(*MILL).replace("G31 X60.", "G31.2 X60.")
    m = run(text, "mitsubishi-m70")
    assert m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (CUTTER_SKIP, 6)


@pytest.mark.parametrize(
    "dialect", ["fanuc-0i-lathe", get_dialect("fanuc-30i").lathe_variant], ids=["fanuc-0i-lathe", "fanuc-30i-lathe"]
)
def test_g31_in_g42_is_alarm_35_on_a_fanuc_lathe(dialect: object) -> None:
    m = run(lines(*LATHE), dialect)  # type: ignore[arg-type]
    assert m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (CUTTER_SKIP, 6)


def test_g31_in_g42_on_the_gsk980tdi_is_a_warning_and_the_skip_is_made_as_programmed() -> None:
    m = run(lines(*LATHE), "gsk980tdi")
    assert m.status == "completed", m.alarm
    assert [(n.line + 1, n.subject) for n in m.notes if n.kind == "cutter"] == [(6, "cutter-skip")]
    skip = next(mv for mv in m.planner.moves if mv.line + 1 == 6)
    # the G31 runs from the programmed X40 Z0 to Z-30 as programmed (no nose-centre path)
    assert skip.tool_path is None
    x, z = m.planner.axis_index["X"], m.planner.axis_index["Z"]
    assert (skip.start[x], skip.start[z], skip.end[x], skip.end[z]) == (40.0, 0.0, 40.0, -30.0)


@pytest.mark.parametrize("dialect", ["haas", "mazak-eia"])
def test_g31_in_g41_is_a_warning_where_no_alarm_is_named(dialect: str) -> None:
    m = run(lines(*MILL), dialect)
    assert m.status == "completed", m.alarm
    assert [(n.line + 1, n.subject) for n in m.notes if n.kind == "cutter"] == [(6, "cutter-skip")]


def test_g31_after_g40_is_no_finding() -> None:
    # G40 on line 6 before the skip: the compensation is cancelled, the probe move is allowed
    text = lines(*MILL[:5], "G40 G01 X-10. Y40.", "G31 X60. F100", "M30")
    m = run(text, "fanuc")
    assert m.status == "completed", m.alarm


def test_g31_after_g41_without_a_move_is_alarm_35_too() -> None:
    # G41 D1 alone (no start-up move yet): G41 is in force, the group 07 code not cancelled
    text = lines("O0001", "G10 L12 P1 R5.", "G90 G17 G00 X-20. Y-20.", "G41 D1", "G31 X60. F100", "M30")
    m = run(text, "fanuc")
    assert m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (CUTTER_SKIP, 5)
