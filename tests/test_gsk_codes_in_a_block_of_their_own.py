"""GSK980TDi codes its manual wants in a block of their own (docs/semantics.md §10.1):
"G22/G23代码不能与其它G代码及MST代码共段，否则发出报警" (§3.31 note 6: G22/G23 may not share a
block with another G code or an M, S, T code, else an alarm: the run stops, no number given);
"G12.1，G13.1，G16，G15要单独编为一段程序" (§3.9 note 1) and, for G51.2/G50.2, "以上指令请单独指定，
不要与其它程序指令共段执行" (§3.36 note 2) ask for a block of their own without an alarm: a
warning. Before, all of these ran silently."""

from __future__ import annotations

import json
from pathlib import Path

from cli_capture import cli
from running import lines


def _write(folder: Path, *body: str) -> Path:
    path = folder / "O0022.CNC"
    path.write_text(lines("O0022 (cncmacro: dialect=gsk980tdi)", *body, "M30"), encoding="utf-8")
    return path


def test_g22_beside_an_m_code_stops_the_run(tmp_path: Path) -> None:
    path = _write(tmp_path, "G22 X100 Z50 I-100 K-50", "G22 X100 Z50 I-100 K-50 M3")
    code, out, _ = cli("run", "--json", "--no-save", str(path))
    alarm = json.loads(out)["alarm"]
    assert code != 0 and alarm["line"] == 3 and alarm["number"] is None
    assert alarm["message"] == "G22 shares its block with M3: write G22 in a block of its own"
    _, checked, _ = cli("check", str(path))
    # column 25: M3 in "G22 X100 Z50 I-100 K-50 M3"; the G22 block alone (line 2) is fine
    assert (
        "O0022.CNC:3:25: error: G22 shares its block with M3: write G22 in a block of its own (alarm) "
        "[own-block]" in checked
    )
    assert ":2:" not in checked


def test_g12_1_beside_a_move_is_a_warning_and_the_run_goes_on(tmp_path: Path) -> None:
    path = _write(tmp_path, "G00 X20 Z5", "G12.1 G00 X10", "G13.1", "G51.2 P1 Q2 R0 A0", "G50.2")
    code, out, _ = cli("run", "--json", "--no-save", str(path))
    assert code == 0 and json.loads(out)["alarm"] is None
    _, checked, _ = cli("check", str(path))
    assert (
        "O0022.CNC:3:7: warning: G12.1 shares its block with G00: the control's manual wants G12.1 in a "
        "block of its own [own-block]" in checked
    )
    # G13.1 alone, and G51.2 with its own P, Q, R, A, are as the manual writes them
    assert checked.count("[own-block]") == 1
    _, zh, _ = cli("check", "--locale", "zh-CN", str(path))
    assert "G12.1 与 G00 同段：系统手册要求 G12.1 单独编为一段" in zh
