"""Haas M96 P n Q i jumps to N n when discrete input i (#1000 + i) is 0, and goes on when it is 1
(Haas mill operator's manual 96-8000, M codes: "N90 M96 P10 Q27 (Loop to N10 if spare input [#27]
is 0); N95 M30 (If spare input is 1 then end program)"; rev R, macros: "M96 Pxx Qxx - Conditional
Local Branch when Discrete Input Signal is 0"; docs/semantics.md §4 "M96"). In an analysis the
input is unknown unless the machine file gives it: the branch is undecided."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import cli
from running import lines, run

_TEXT = lines("O1020", "#100=0", "M96 P20 Q22 (JUMP TO N20 IF INPUT 22 IS OFF)", "#100=1", "N20 #101=2", "M30")


@pytest.mark.parametrize(("input_22", "expected"), [(0.0, None), (1.0, 1.0)])
def test_haas_m96_jumps_when_the_input_is_0_and_goes_on_when_it_is_1(input_22: float, expected: float | None) -> None:
    # #1022 = 0: to N20, #100 stays 0; #1022 = 1: on to #100=1; N20 runs either way
    m = run(_TEXT, "haas", presets={1022: input_22})
    assert m.status == "completed", m.alarm
    v = m.variables()
    assert v[100] == (0.0 if expected is None else expected) and v[101] == 2.0


def test_haas_m96_on_an_input_the_folder_does_not_give_is_undecided_in_check(tmp_path: Path) -> None:
    (tmp_path / "O1020.nc").write_text(_TEXT, encoding="utf-8")
    code, out, err = cli("check", "--hints", "--dialect", "haas", str(tmp_path / "O1020.nc"))
    assert code == 0 and err == ""
    found = [line.split(":", 1)[1] for line in out.splitlines()]
    assert len(found) == 1 and found[0].startswith("3:1: hint:") and found[0].endswith("[unknown-value]")
