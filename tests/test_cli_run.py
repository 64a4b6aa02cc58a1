"""``cncmacro run``: docs/design.md's command-line contract (text, JSON, presets, machine file,
budget and exit status), and every bundled example runs."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from cli_capture import cli

ROOT = Path(__file__).resolve().parent.parent


@pytest.mark.parametrize(
    ("name", "status"),
    [
        ("fanuc/bolt_circle.nc", "completed"),
        ("fanuc/while_loop.nc", "completed"),
        ("fanuc/subprogram_main.nc", "completed"),
        ("fanuc/O9100.nc", "alarm"),  # run on its own, the macro misses its arguments: #3000
        ("fanuc/O0040.nc", "completed"),  # a subprogram run on its own: one pass, up to its M99
        ("fanuc/contour_g41.nc", "completed"),
        ("gsk980tdi/O0100.nc", "completed"),
        ("gsk980tdi/O9580.nc", "completed"),
        ("gsk980tdi/ellipse_turning.nc", "completed"),
        ("gsk980tdi/thread_parabola.nc", "completed"),
        ("gsk980tdi/shaft_g71.nc", "completed"),
    ],
)
def test_every_example_runs(examples, name, status):
    code, out, err = cli("run", "--json", "--max-blocks", "20000", str(examples / name))
    result = json.loads(out)
    assert result["status"] == status, result["alarm"]
    assert code == {"completed": 0, "alarm": 1, "limit": 3}[status]
    assert err == ""


def test_json_contract(examples):
    code, out, _ = cli("run", "--json", "--set", "100=5", "--set", "#2001=0.5", str(examples / "fanuc/bolt_circle.nc"))
    r = json.loads(out)
    assert code == 0
    assert set(r) >= {"status", "alarm", "blocks", "variables", "moves"}
    assert r["status"] == "completed" and r["alarm"] is None and r["blocks"] > 0
    assert r["variables"]["100"] == 5 and r["variables"]["2001"] == 0.5
    assert all(v is not None for v in r["variables"].values())
    first = r["moves"][0]
    assert set(first) >= {"file", "line", "mode", "from", "to"} and first["line"] >= 1


def test_json_moves_one_to_a_line(examples):
    _code, out, _ = cli("run", "--json", str(examples / "fanuc/bolt_circle.nc"))
    r = json.loads(out)
    move_lines = [line for line in out.splitlines() if line.lstrip().startswith('{"file"')]
    assert len(move_lines) == len(r["moves"]) > 10  # a move is one line a person can read or diff
    assert json.loads(move_lines[0].strip().rstrip(",")) == r["moves"][0]
    assert out.splitlines()[1] == ' "dialect": "fanuc-0i",'  # the rest stays indented
    # the machine the run was made on (a plot draws a lathe otherwise)
    assert r["dialect"] == "fanuc-0i" and r["lathe"] is False
    assert "lathe_axes" not in r  # a mill has no spindle axis to draw


def test_json_names_a_lathes_axes_so_a_plot_draws_it_as_a_lathe(examples):
    """On a lathe the run says which axis is the spindle's (Z, drawn across with its centre line),
    which is radial (X, drawn up) and that X is programmed as a diameter."""
    _code, out, _ = cli("run", "--json", str(examples / "gsk980tdi/shaft_g71.nc"))
    r = json.loads(out)
    assert (r["dialect"], r["lathe"]) == ("gsk980tdi", True)
    assert r["lathe_axes"] == {"spindle": "Z", "radial": "X", "diameter": True}


def test_json_arc_moves_carry_their_centre(tmp_path):
    """A G02/G03 move gets ``centre`` (axis letters as in ``from``/``to``); no other move has
    the key, and the text output shows moves as before."""
    f = tmp_path / "O0003.nc"
    f.write_text("O0003\nG90 G17 G00 X10. Y0\nG03 X0 Y10. I-10. F100\nG02 X10. Y0 R-10.\nG01 X0\nM30\n")
    code, out, _ = cli("run", "--json", str(f))
    moves = json.loads(out)["moves"]
    assert code == 0 and [mv["mode"] for mv in moves] == ["G00", "G03", "G02", "G01"]
    assert moves[1]["centre"] == {"X": 0.0, "Y": 0.0, "Z": 0.0, "A": 0.0}
    assert moves[2]["centre"] == {"X": 10.0, "Y": 10.0, "Z": 0.0, "A": 0.0}  # the longer arc
    assert "centre" not in moves[0] and "centre" not in moves[3]
    code, out, _ = cli("run", str(f))
    assert code == 0 and "G03  X10.000 Y0.000 -> X0.000 Y10.000  F100" in out


def test_alarm_in_json_and_text(tmp_path):
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\n#1=1\nG65 P9000\nM30\nO9000\n#3000=7(NO X GIVEN)\nM99\n", encoding="utf-8")
    code, out, _ = cli("run", "--json", str(f))
    r = json.loads(out)
    assert code == 1 and r["status"] == "alarm"
    assert r["alarm"]["number"] == 3007 and r["alarm"]["message"] == "NO X GIVEN" and r["alarm"]["line"] == 6
    assert r["variables"] == {"1": 1.0}
    code, out, _ = cli("run", str(f))
    assert code == 1
    assert "ALARM 3007: NO X GIVEN" in out and f"called from O0001 (main) at {f}:3" in out


def test_text_output_shows_moves_and_variables(tmp_path):
    f = tmp_path / "O0002.nc"
    f.write_text("O0002\nG90 G01 X10. Y5. F200\n#100=#5001\nDPRNT[X#5001[33]]\nM30\n", encoding="utf-8")
    code, out, _ = cli("run", str(f))
    assert code == 0
    assert "O0002.nc:2     G01  X0.000 Y0.000 -> X10.000 Y5.000  F200" in out
    assert "DPRNT  X10.000" in out
    assert "#100 = 10" in out and "status: completed after 4 blocks" in out


def test_budget_and_exit_status_3(tmp_path):
    f = tmp_path / "loop.nc"
    f.write_text("N1 #1=#1+1\nGOTO 1\n", encoding="utf-8")
    code, out, _ = cli("run", "--json", "--max-blocks", "500", str(f))
    r = json.loads(out)
    assert code == 3 and r["status"] == "limit" and r["blocks"] == 500


def test_machine_file_and_persistent_variables(tmp_path):
    (tmp_path / ".cncmacro.toml").write_text(
        'dialect = "gsk980tdi"\npersistent_file = "vars.json"\ndate = 20260301\n[variables]\n2001 = 0.25\n',
        encoding="utf-8",
    )
    f = tmp_path / "O0003.nc"
    f.write_text("#500=#500+1\n#100=#2001\n#101=#3011\nIF[#500==1]THEN #102=1\nM30\n", encoding="utf-8")
    for expected in (1, 2):
        code, out, _ = cli("run", "--json", str(f))
        r = json.loads(out)
        assert code == 0 and r["variables"]["500"] == expected
    assert r["variables"]["100"] == 0.25 and r["variables"]["101"] == 20260301
    assert json.loads((tmp_path / "vars.json").read_text())["variables"] == {"500": 2.0}
    cli("run", "--no-save", str(f))
    assert json.loads((tmp_path / "vars.json").read_text())["variables"] == {"500": 2.0}


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--set", "100"], "NUMBER=VALUE"),
        (["--set", "100=abc"], "not a number"),
        (["--set", "5001=3"], "computed by the machine"),
        (["--set", "77=3"], "not a variable"),
        (["--machine", "missing.toml"], "cannot read the machine file"),
        (["--max-blocks", "0"], "at least 1"),
    ],
)
def test_bad_usage_exits_2_with_a_message(tmp_path, args, message):
    f = tmp_path / "O0001.nc"
    f.write_text("M30\n", encoding="utf-8")
    code, out, err = cli("run", *args, str(f))
    assert code == 2 and message in err and out == ""


def test_unreadable_and_binary_files_exit_2(tmp_path):
    b = tmp_path / "blob.nc"
    b.write_bytes(b"\x00\x01\x02binary")
    code, _, err = cli("run", str(b))
    assert code == 2 and "binary" in err
    code, _, err = cli("run", str(tmp_path / "nope.nc"))
    assert code == 2 and "nope.nc" in err


def test_bad_machine_file_exits_2(tmp_path):
    (tmp_path / ".cncmacro.toml").write_text("dialect = 'okuma'\n", encoding="utf-8")
    f = tmp_path / "O0001.nc"
    f.write_text("M30\n", encoding="utf-8")
    code, _, err = cli("run", str(f))
    assert code == 2 and "dialect" in err


def test_python_dash_m_entry_point(examples):
    r = subprocess.run(
        [sys.executable, "-m", "cncmacro", "run", "--no-save", str(examples / "gsk980tdi/O0100.nc")],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert r.returncode == 0 and "status: completed" in r.stdout


def test_a_missing_program_is_named_plainly_in_both_languages(tmp_path):
    missing = str(tmp_path / "O0404.nc")
    code, out, err = cli("run", "--no-save", missing)
    assert (code, out, err.strip()) == (2, "", f"cncmacro run: there is no file {missing}")
    code, _out, err = cli("run", "--no-save", "--locale", "zh-CN", missing)
    assert (code, err.strip()) == (2, f"cncmacro run：文件 {missing} 不存在")


def test_stdin_runs_an_editors_unsaved_text_under_the_files_name(tmp_path):
    # the file on disk says #1=3; the editor's text says #1=7 and calls O9001 beside the file
    (tmp_path / "O0001.nc").write_text("O0001\n#1=3\nM30\n", encoding="utf-8")
    (tmp_path / "O9001.nc").write_text("O9001\n#100=#24*2\nM99\n", encoding="utf-8")
    unsaved = "O0001\n#1=7\nG65 P9001 X#1\nM30\n"
    done = subprocess.run(
        [sys.executable, "-m", "cncmacro", "run", "--no-save", "--json", "--stdin", str(tmp_path / "O0001.nc")],
        input=unsaved.encode("gbk"), capture_output=True, check=False, timeout=60,
    )  # fmt: skip
    result = json.loads(done.stdout)
    assert (done.returncode, result["status"]) == (0, "completed")
    assert result["variables"] == {"1": 7.0, "100": 14.0}


def test_an_m00_stop_names_its_own_line(tmp_path):
    # line 3 is #3006 (its message names line 3), line 4 the M00: its stop names line 4, not the
    # line after it (5), where the run goes on
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\n#1=1\n#3006=1 (CHECK PART)\nM00\n#2=1\nM30\n", encoding="utf-8")
    code, out, _err = cli("run", str(f))
    assert code == 0
    assert "stop at O0001.nc:3: CHECK PART" in out
    assert "stop at O0001.nc:4: M00 program stop" in out
