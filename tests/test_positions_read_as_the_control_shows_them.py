"""Position variables read back as the control shows them (docs/semantics.md §8): a position the
run sums from the work offset, the tool's and the program's is rounded to 1e-9 of the unit, so
machine 0 after a return to the reference point reads 0, not the last bits of the sums. A shop's
home check `IF [#5023 NE 0] #3000=1 (Z NOT HOME)` reached its alarm on every check: #5023 read
8.9e-16 after `G28 G91 Z0.` with an inch work offset and a tool length offset."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import cli
from running import lines, run

HOME_CHECKS = {
    "haas": (
        "G20 G17 G40 G80 G90 G94", "G10 L2 P1 X-14.2371 Y-8.1093 Z-18.3317", "G10 L10 P1 R6.1234",
        "G10 L11 P1 R-0.0013", "T1 M06", "G00 G54 X1.1 Y0.7", "G43 H01 Z0.1", "G01 Z-0.3 F10.", "G28 G91 Z0.",
        "G90", "#100=#5023", "IF [#5023 NE 0] #3000=1 (Z NOT HOME)",
    ),
    "haas-lathe": (
        "G20 G18 G40 G80 G99", "G10 L2 P1 X0. Z-10.", "#2101=-5.", "#2801=-0.001", "T101", "G00 G54 X2.0 Z0.1",
        "G28 U0. W0.", "#100=#5023", "IF [#5023 NE 0] #3000=1 (TURRET NOT HOME)",
    ),
}  # fmt: skip


@pytest.mark.parametrize("dialect", sorted(HOME_CHECKS))
def test_machine_zero_reads_zero_after_the_reference_return(dialect: str) -> None:
    # Z at machine 0: the work offset and the tool's length (geometry + wear) added back give
    # exactly 0 on the control; the sums here left 8.881784197001252e-16
    m = run(lines(*HOME_CHECKS[dialect], "M30"), dialect)
    assert m.status == "completed", m.alarm
    assert m.C[100] == 0.0


def test_a_home_check_after_g28_reaches_no_alarm_in_check(tmp_path: Path) -> None:
    # the Haas mill's check before a pallet change, as a shop writes it: each axis at machine 0
    program = tmp_path / "O01019.nc"
    program.write_text(lines("%", "O01019 (cncmacro: dialect=haas)", *HOME_CHECKS["haas"][:-3], "G28 G91 Z0.",
                             "G28 G91 X0. Y0.", "G90", "IF [#5023 NE 0] #3000=1 (Z NOT HOME)",
                             "IF [#5021 NE 0] #3000=2 (X NOT HOME)", "IF [#5022 NE 0] #3000=3 (Y NOT HOME)", "M30",
                             "%"),
                       encoding="utf-8")  # fmt: skip
    assert cli("check", str(program))[:2] == (0, "")
