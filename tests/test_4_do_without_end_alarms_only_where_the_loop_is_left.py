"""A WHILE/DO whose END m is not in its program (docs/semantics.md §4): the body runs while the
condition holds, and the control raises alarm 124 only where it has to look for the END, when
the condition is false. So a program that ends (M30) inside the body before any END is needed
runs to its end; the check warns, and it is an error where the run meets the alarm."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import cli
from running import alarm, final, lines

BODY_ENDS_FIRST = lines("O1016", "#1=0", "WHILE[#1 LT 3]DO1", "#1=#1+1", "#2=7", "M30")
FALSE_AT_ONCE = lines("O1017", "#1=5", "WHILE[#1 LT 3]DO1", "#1=#1+1", "M30")


@pytest.mark.parametrize("dialect", ["fanuc", "fanuc-0i-lathe", "gsk980tdi"])
def test_do_without_end_runs_its_body_while_the_condition_holds(dialect: str) -> None:
    # #1=0 < 3: into the body, #1 = 0 + 1 = 1, #2 = 7, M30 ends the program: no END was needed.
    # It stopped at the WHILE with alarm 124 before (#1 stayed 0, #2 vacant).
    got = final(BODY_ENDS_FIRST, dialect)
    assert got[1] == 1 and got[2] == 7


@pytest.mark.parametrize("dialect", ["fanuc", "fanuc-0i-lathe", "gsk980tdi"])
def test_do_without_end_is_alarm_124_where_the_condition_is_false(dialect: str) -> None:
    # #1=5 is not < 3: the control looks for END 1 to go on after it; there is none (line 3).
    assert alarm(FALSE_AT_ONCE, dialect) == (124, 3)


def test_check_warns_of_a_do_without_end_and_errs_where_the_run_meets_the_alarm(tmp_path: Path) -> None:
    runs = tmp_path / "runs"
    runs.mkdir()
    (runs / "O1016.nc").write_text(BODY_ENDS_FIRST, encoding="utf-8")
    code, out, _ = cli("check", "--dialect", "fanuc-0i-lathe", str(runs / "O1016.nc"))
    assert code == 0 and ":3:1: warning: DO 1 has no END 1 (alarm 124): the control raises it where" in out
    stops = tmp_path / "stops"
    stops.mkdir()
    (stops / "O1017.nc").write_text(FALSE_AT_ONCE, encoding="utf-8")
    code, out, _ = cli("check", "--dialect", "fanuc-0i-lathe", str(stops / "O1017.nc"))
    assert code == 1 and ":3:1: error: DO 1 has no END 1 (alarm 124) [loop-mismatch]" in out
    assert "warning" not in out
