"""GSK980TDi reads a one-argument function followed by a bare number, as its manual's own example
writes it (§3.29.2, "转移和循环", the THEN format: "IF[#101>=7.22]THEN #101=SIN30；其含义为：…即将
30 度的正弦值赋予变量#101", the sine of 30 degrees is given to #101). Its table (§3.29.1) writes
``SIN[#j]``; only a number is shown bare, so ``SIN#1`` stays a syntax error. The other profiles,
whose manuals bracket every argument, stop with alarm 114 on it (docs/semantics.md §3)."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import cli
from running import alarm, final, lines


def test_the_manuals_example_gives_the_sine_of_30_degrees() -> None:
    # #101 = 8 >= 7.22, so #101 = sin 30° = 0.5 (alarm 125, a syntax error, before)
    v = final(lines("#101=8", "IF[#101>=7.22]THEN #101=SIN30", "M30"), "gsk980tdi")
    assert v[101] == pytest.approx(0.5)


def test_a_bare_argument_binds_before_the_operators() -> None:
    # COS60 + SIN30 * 2 = 0.5 + 0.5 × 2 = 1.5; SQRT16 = 4
    v = final(lines("#1=COS60+SIN30*2", "#2=SQRT16", "M30"), "gsk980tdi")
    assert v[1] == pytest.approx(1.5) and v[2] == 4


def test_check_passes_it_on_gsk980tdi_and_refuses_it_elsewhere(tmp_path: Path) -> None:
    path = tmp_path / "O0131.nc"
    path.write_text(lines("O0131", "#101=SIN30", "#102=SIN#101", "M30"), encoding="utf-8")
    code, out, _ = cli("check", "--dialect", "gsk980tdi", str(path))
    assert code == 1
    assert [row.split(":")[1] for row in out.splitlines() if "[syntax]" in row] == ["3"]  # only SIN#101
    code, out, _ = cli("check", "--dialect", "fanuc-0i-lathe", str(path))
    assert code == 1
    assert ":2:6: error: SIN30: a function's argument is written in brackets, SIN[30] (alarm 114) [syntax]" in out


def test_a_fanuc_control_stops_on_it_with_alarm_114() -> None:
    assert alarm(lines("#1=SIN30", "M30"), "fanuc-0i-lathe") == (114, 1)
