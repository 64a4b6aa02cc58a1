"""Haas's own milling cycles that are not simulated (docs/semantics.md §8, `Dialect.unsimulated_codes`):
the circular pockets G12/G13, the engraving G47, the bolt patterns G70/G71/G72 and the general
pocket G150 move no axis and leave the tool at its start point, and the run says once a block that
the cycle is not simulated. Before, their Z (a depth) was a move in the mode in force: after a G00,
a rapid plunge into the part, drawn and timed as one."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import cli, run_json
from running import lines

START = ("G20 G17 G40 G80 G90 G94", "G00 G54 X1. Y1. Z0.1")


@pytest.mark.parametrize(
    "cycle",
    ["G12 I0.75 D01 F12. Z-0.25", "G13 G91 Z-0.25 I0.4 K1.0 Q0.3 D01 L2 F15.",
     "G47 P0 (HAAS) X1. Y1. I0. J0.2 R0.05 Z-0.005 F15. E10.", "G150 P2000 Q0.1 R0.05 Z-0.5 F10. D01"],
    ids=["G12", "G13", "G47", "G150"],
)  # fmt: skip
def test_a_haas_cycle_block_moves_nothing_and_says_it_is_not_simulated(tmp_path: Path, cycle: str) -> None:
    result = run_json(tmp_path, lines("O01003 (cncmacro: dialect=haas)", *START, cycle, "G90 G00 Z1.", "M30"),
                      "O01003.nc")  # fmt: skip
    # the rapid to X1 Y1 Z0.1, then G00 Z1. from Z0.1 (0.9 in at 1000 in/min: 0.054 s); no move on line 4
    assert [mv["line"] for mv in result["moves"]] == [3, 5]
    assert result["moves"][1]["from"]["Z"] == pytest.approx(0.1)
    assert result["moves"][1]["time"] == pytest.approx(0.9 / 1000 * 60)
    name = cycle.split()[0]
    assert result["messages"] == [
        f"{name} is not simulated: the cycle's passes are not drawn or timed, and the tool is left at its start point"
    ]
    out = cli("check", str(tmp_path / "O01003.nc"))[1]
    assert out.count("information: ") == 1 and f"{name} is not simulated" in out and "[not-simulated]" in out
