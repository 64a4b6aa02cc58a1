"""The machine file's ``[limits]`` as a user meets it on the command line (docs/semantics.md §11):
``cncmacro run`` stops at the over-travel alarm with the move cut at the limit, ``cncmacro check``
puts each finding on its line, and the rapid rate ``[limits]`` gives times the rapids."""

from __future__ import annotations

import json
from pathlib import Path

from cli_capture import cli

MACHINE = """\
[variables]
5221 = -300.0
5222 = -200.0
5223 = -100.0

[limits]
travel = { X = [-500, 0], Y = [-400, 0], Z = [-450, 0] }
feed = 5000
rapid = 30000
spindle = 8000
tools = [1, 24]
"""
PROGRAM = """\
O0001
G90 G54 G00 X0 Y0
G01 X250. F10000
S9000 M03
T30 M06
X320.
M30
"""


def _folder(tmp_path: Path) -> Path:
    (tmp_path / ".cncmacro.toml").write_text(MACHINE, encoding="utf-8")
    (tmp_path / "O0001.nc").write_text(PROGRAM, encoding="utf-8")
    return tmp_path / "O0001.nc"


def test_run_json_stops_at_the_over_travel_on_x_plus_after_the_g54_shift(tmp_path):
    code, out, _ = cli("run", "--json", "--no-save", str(_folder(tmp_path)))
    r = json.loads(out)
    assert code == 1 and r["status"] == "alarm"
    # machine X = program X - 300: X320 is machine X20, 20 mm past the + limit; stopped at program X300
    assert (r["alarm"]["number"], r["alarm"]["line"]) == (500, 6)
    assert "X+ over travel" in r["alarm"]["message"] and "20.000 mm past" in r["alarm"]["message"]
    moves = r["moves"]
    assert moves[-1]["line"] == 6 and moves[-1]["to"]["X"] == 300.0  # where the toolpath marks the alarm
    # G00 X0 Y0 from X0 Y0: 0 s; G01 250 mm at F10000 clamped at 5000: 250 / 5000 * 60 = 3 s;
    # X250 -> X300 at the same clamped feed: 50 / 5000 * 60 = 0.6 s
    assert [round(mv["time"], 6) for mv in moves] == [0.0, 3.0, 0.6]
    assert any("S9000" in m for m in r["messages"]) and any("T30" in m for m in r["messages"])


def test_run_text_says_the_over_travel_in_chinese(tmp_path):
    code, out, _ = cli("run", "--no-save", "--locale", "zh-CN", str(_folder(tmp_path)))
    assert code == 1 and "X 轴+向超程" in out and "超出+向限位" in out


def test_check_puts_each_limit_finding_on_its_line(tmp_path):
    code, out, _ = cli("check", "--format", "json", str(_folder(tmp_path)))
    found = [(d["line"], d["code"], d["severity"]) for d in json.loads(out)]
    assert code == 1
    assert found == [(4, "spindle-limit", "warning"), (5, "unknown-tool", "error"), (6, "over-travel", "error")]


def test_the_rapid_rate_of_limits_times_the_rapids(tmp_path):
    (tmp_path / ".cncmacro.toml").write_text("[limits]\nrapid = 30000\n", encoding="utf-8")
    f = tmp_path / "O0002.nc"
    f.write_text("O0002\nG90 G00 X300. Z150.\nM30\n", encoding="utf-8")
    code, out, _ = cli("run", "--json", "--no-save", str(f))
    # every axis at 30000 mm/min: X's 300 mm is the slowest, 300 / 30000 * 60 = 0.6 s
    assert code == 0 and json.loads(out)["moves"][0]["time"] == 0.6


def test_a_bad_limit_exits_2_naming_its_key(tmp_path):
    (tmp_path / ".cncmacro.toml").write_text("[limits]\ntravel = { X = [0, -500] }\n", encoding="utf-8")
    f = tmp_path / "O0003.nc"
    f.write_text("O0003\nM30\n", encoding="utf-8")
    code, _, err = cli("run", str(f))
    assert code == 2 and "'limits.travel.X'" in err and "(line 2)" in err
