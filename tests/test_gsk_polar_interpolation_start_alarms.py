"""GSK980TDi: polar coordinate interpolation may not start under feed per revolution or in tool
nose radius compensation (its manual, §3.9 G12.1, 注意事项 3: "在C刀补中间或G99状态下不能启动极坐标插补，
否则报警", polar interpolation cannot be started in C compensation or in the G99 state, else an
alarm). The run stops at the G12.1 block with the control's alarm, shown without a number (the
manual gives none), `polar-start` in check; FANUC's lathe profile starts it as written (docs/semantics.md §10.1)."""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from running import final, lines, run

HEAD = ("O0001", "T0101", "M03 S500", "G0 X80 C0 Z0")


def polar_alarm(text: str) -> int:
    """The 1-based line of the polar-start alarm the gsk980tdi run stops with."""
    m = run(text, "gsk980tdi")
    assert m.status == "alarm" and m.alarm is not None and m.alarm.subject == "polar-start", m.status
    return m.alarm.line + 1


def test_g12_1_under_g99_is_the_alarm() -> None:
    # G99 on line 5, G12.1 on line 6: the alarm at line 6
    assert polar_alarm(lines(*HEAD, "G99", "G12.1", "G01 X40 C10 F0.1", "G13.1", "M30")) == 6


def test_g12_1_in_tool_nose_radius_compensation_is_the_alarm() -> None:
    text = lines(*HEAD, "G98", "G41 G01 X70 F100", "G12.1", "G01 X40 C10", "G13.1", "G40 G0 X90", "M30")
    assert polar_alarm(text) == 7


def test_g12_1_under_g98_after_g40_starts() -> None:
    # G41 cancelled by G40 before G12.1, feed per minute: the run goes on to M30 (#1 set after G13.1)
    text = lines(*HEAD, "G98", "G41 G01 X70 F100", "G40 G01 X80", "G12.1", "G01 X40 C10", "G13.1", "#1=1", "M30")
    assert final(text, "gsk980tdi")[1] == 1


def test_fanuc_lathe_starts_it_under_g99() -> None:
    assert final(lines(*HEAD, "G99", "G12.1", "G01 X40 C10 F0.1", "G13.1", "#1=1", "M30"), "fanuc-0i-lathe")[1] == 1


@pytest.mark.parametrize("locale", ["en", "zh-CN"])
def test_check_shows_it_as_polar_start_error(tmp_path: Path, locale: str) -> None:
    text = lines(*HEAD, "G99", "G12.1", "G01 X40 C10 F0.1", "G13.1", "M30")
    found = [d for d in analyse_files(tmp_path, {"O0001.nc": text}, "gsk980tdi", locale=locale)
             if d.code == "polar-start"]  # fmt: skip
    assert [(d.line + 1, d.severity) for d in found] == [(6, "error")]
    assert ("G99" in found[0].message) and (("feed per revolution" in found[0].message) == (locale == "en"))
