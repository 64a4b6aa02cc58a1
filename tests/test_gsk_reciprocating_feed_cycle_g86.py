"""GSK980TDi's independent reciprocating feed cycle G86 (programming manual §3.23.11;
docs/semantics.md §10.3): `G86 Z(start) A(end) I(stroke) R(advance) F`. Z feeds at F to the start,
then forward I, back I − R, forward I, … until the end, then back to the start, all at F in
mm/min even under G99 ("G86 指令速度不受 G99 影响"). I of 0 and I below R are the manual's alarms
(no number given). Before, the Z word was a rapid to Z5 and nothing else moved."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from cli_capture import cli, run_json
from running import lines

HEAD = ("O0086 (cncmacro: dialect=gsk980tdi)", "G00 X20 Z10")


def alarmed(folder: Path, text: str) -> dict[str, Any]:
    """``cncmacro run --json`` of ``text``, a run that stops with an alarm: its alarm."""
    path = folder / "O0086.CNC"
    path.write_text(text, encoding="utf-8")
    code, out, _ = cli("run", "--json", "--no-save", str(path))
    assert code != 0
    alarm: dict[str, Any] = json.loads(out)["alarm"]
    return alarm


def test_g86_feeds_to_its_start_then_strokes_to_its_end_and_back(tmp_path: Path) -> None:
    # G99 with no S: a per-revolution feed would be no feed at all; G86 is per minute whatever
    result = run_json(tmp_path, lines(*HEAD, "G99 G86 Z5 A0 I3 R1 F100", "M30"), "O0086.CNC")
    assert result["alarm"] is None
    moves = [mv for mv in result["moves"] if mv["line"] == 3]
    # from Z10: feed to the start Z5; forward 3 (Z2); back 3 - 1 = 2 (Z4); forward 3 (Z1); back 2
    # (Z3); forward 3 would pass the end Z0, so to Z0; back to the start Z5
    assert [mv["to"]["Z"] for mv in moves] == [5.0, 2.0, 4.0, 1.0, 3.0, 0.0, 5.0]
    assert all(mv["kind"] == "feed" and mv["pass_of"] == "G86" and mv["to"]["X"] == 20.0 for mv in moves)
    # at F100 mm/min a millimetre takes 0.6 s: 5 + 3 + 2 + 3 + 2 + 3 + 5 = 23 mm, 13.8 s
    assert abs(sum(mv["time"] for mv in moves) - 13.8) < 1e-9


def test_g86_with_a_stroke_of_zero_is_an_alarm(tmp_path: Path) -> None:
    # "G86 指令中 I 为 0 时，系统发出报警"
    alarm = alarmed(tmp_path, lines(*HEAD, "G86 Z5 A0 I0 R0 F100", "M30"))
    assert alarm["line"] == 3 and alarm["number"] is None
    assert alarm["message"] == "G86: the stroke I is 0"


def test_g86_with_a_stroke_below_its_advance_is_an_alarm_in_run_and_check(tmp_path: Path) -> None:
    # "R：…输入值大于 I 值时系统发出报警"; "G86 指令中 I 小于 R 值时，系统发出报警"
    text = lines(*HEAD, "G86 Z5 A0 I1 R2 F100", "M30")
    alarm = alarmed(tmp_path, text)
    assert alarm["line"] == 3
    assert alarm["message"] == "G86: the stroke I1 is less than the advance R2"
    _, out, _ = cli("check", str(tmp_path / "O0086.CNC"))
    assert "O0086.CNC:3:1: error: G86: the stroke I1 is less than the advance R2 (alarm) [cycle-block]" in out
    _, zh, _ = cli("check", "--locale", "zh-CN", str(tmp_path / "O0086.CNC"))
    assert "G86：每次进刀量 I1 小于每次前进量 R2" in zh


def test_g86_without_an_advance_oscillates_until_g86_1_and_is_not_drawn(tmp_path: Path) -> None:
    # R0, the end 5 mm away and strokes of 2: the cycle never reaches its end
    result = run_json(tmp_path, lines(*HEAD, "G86 Z5 A0 I2 R0 F100", "G86.1", "M30"), "O0086.CNC")
    assert result["alarm"] is None
    assert [mv["to"]["Z"] for mv in result["moves"] if mv["line"] == 3] == [5.0]
    assert any("G86 with R0" in m for m in result["messages"])
