"""``cncmacro run`` as a newcomer meets it: every axis the program commands in the text output,
no persistent-variable file left beside a program that keeps nothing, a subprogram run on its
own that stops after one pass and says who calls it, and a plain sentence for a folder or a
file that cannot be run."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from cli_capture import cli

ROOT = Path(__file__).resolve().parents[2]


# ---------------------------------------------------------------- every commanded axis


def test_a_pocket_shows_every_axis_it_commands_and_never_an_empty_arrow(tmp_path):
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\nG91 G28 Z0\nG90 G00 X0 Y0\nZ5.\nG01 Z-2. F100\nX20.\nG00 Z5.\nM30\n", encoding="utf-8")
    code, out, _ = cli("run", "--no-save", str(f))
    assert code == 0
    moves = [line.split(None, 1)[1] for line in out.splitlines() if line.startswith("  O0001.nc:")]
    assert moves == [
        "G00  Z0.000 -> Z0.000",  # G28 through Z0 to the reference point: Z only, so far
        "G00  Z0.000 -> Z0.000",
        "G00  X0.000 Y0.000 Z0.000 -> X0.000 Y0.000 Z0.000",  # Y stays at 0 and is shown all the same
        "G00  X0.000 Y0.000 Z0.000 -> X0.000 Y0.000 Z5.000",
        "G01  X0.000 Y0.000 Z5.000 -> X0.000 Y0.000 Z-2.000  F100",
        "G01  X0.000 Y0.000 Z-2.000 -> X20.000 Y0.000 Z-2.000  F100",
        "G00  X20.000 Y0.000 Z-2.000 -> X20.000 Y0.000 Z5.000",
    ]
    assert "->  " not in out and " A" not in out  # the fourth axis is never mentioned, never shown


def test_an_axis_first_named_among_the_moves_left_out_stays_shown_after_them(tmp_path):
    f = tmp_path / "O0003.nc"
    loop = "#1=0\nWHILE[#1 LT 600]DO1\nG01 X#1 F500\n#1=#1+1\nEND1\n"
    f.write_text(f"O0003\n{loop}G00 Y0\n{loop}M30\n", encoding="utf-8")
    code, out, _ = cli("run", "--no-save", str(f))
    assert code == 0 and "moves (1201):" in out and "  ... 201 more moves ...\n" in out
    assert "G01  X0.000 -> X1.000  F500" in out  # the first moves: X only, so far
    last = [line for line in out.splitlines() if line.startswith("  O0003.nc:")][-1]
    assert last.endswith("G01  X598.000 Y0.000 -> X599.000 Y0.000  F500")  # Y0 was named in the middle


def test_an_axis_named_in_a_subprogram_among_the_moves_left_out_stays_shown_after_them(tmp_path):
    # the moves left out come from two files: the axis is found in the one that names it, in a
    # plain line and in one that is not (lower case, a variable)
    loop = "#1=0\nWHILE[#1 LT 600]DO1\nG01 X#1 F500\n#1=#1+1\nEND1\n"
    (tmp_path / "O0100.nc").write_text("O0100\n#2=3.\nG01 y#2\nM99\n", encoding="utf-8")
    (tmp_path / "O0200.nc").write_text("O0200\nG00 Z0\nM99\n", encoding="utf-8")
    f = tmp_path / "O0004.nc"
    f.write_text(f"O0004\n{loop}M98 P100\nM98 P200\n{loop}M30\n", encoding="utf-8")
    code, out, _ = cli("run", "--no-save", str(f))
    assert code == 0 and "moves (1202):" in out and "  ... 202 more moves ...\n" in out
    assert "G01  X0.000 -> X1.000  F500" in out  # the first moves: X only, so far
    last = [line for line in out.splitlines() if line.startswith("  O0004.nc:")][-1]
    assert last.endswith("G01  X598.000 Y3.000 Z0.000 -> X599.000 Y3.000 Z0.000  F500")


def test_a_lathe_program_shows_x_and_z_only(tmp_path):
    f = tmp_path / "O0002.nc"
    f.write_text("(cncmacro: dialect=gsk980tdi)\nO0002\nG00 X0 Z0\nG01 W-10. F0.2\nM30\n", encoding="utf-8")
    code, out, _ = cli("run", "--no-save", str(f))
    assert code == 0
    assert "G00  X0.000 Z0.000 -> X0.000 Z0.000" in out
    assert "G01  X0.000 Z0.000 -> X0.000 Z-10.000  F0.2" in out


# ---------------------------------------------------------------- the persistent-variable file


def _names(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


def test_the_persistent_variable_file_is_written_only_when_a_variable_changed(tmp_path):
    plain = tmp_path / "O0001.nc"
    plain.write_text("O0001\n#100=1\nG00 X1.\nM30\n", encoding="utf-8")
    assert cli("run", str(plain))[0] == 0
    assert _names(tmp_path) == ["O0001.nc"]  # nothing kept: no file, no lock file beside the program

    counter = tmp_path / "O0002.nc"
    counter.write_text("O0002\n#500=1\nM30\n", encoding="utf-8")
    assert cli("run", str(counter))[0] == 0
    vars_file = tmp_path / ".cncmacro-vars.json"
    assert json.loads(vars_file.read_text(encoding="utf-8"))["variables"] == {"500": 1.0}

    kept = '{"variables": {"500": 1.0, "501": 7.5}}\n'  # written by hand, not as a run writes it
    vars_file.write_text(kept, encoding="utf-8")
    code, out, _ = cli("run", str(plain))
    assert code == 0 and "#501 = 7.5" in out  # read, and not written back
    assert vars_file.read_text(encoding="utf-8") == kept  # left as it was
    code, _, _ = cli("run", str(counter))  # the same value again: nothing changed
    assert vars_file.read_text(encoding="utf-8") == kept


# ---------------------------------------------------------------- a subprogram run on its own


def test_a_subprogram_run_alone_stops_after_one_pass_and_names_its_callers(examples):
    code, out, err = cli("run", "--no-save", str(examples / "fanuc/O0040.nc"))
    assert (code, err) == (0, "")
    assert "moves (4):" in out and "status: completed after 6 blocks" in out
    assert (
        "O0040.nc ends in M99: it is a subprogram, which returns to the program that calls it. "
        "Run on its own it stopped at the M99 after one pass (--repeat runs it again from its start, "
        "as a control runs a main program that ends in M99)."
    ) in out
    assert "called by: subprogram_main.nc (O2000)" in out

    code, out, _ = cli("run", "--no-save", "--locale", "zh-CN", str(examples / "fanuc/O0040.nc"))
    assert code == 0
    assert (
        "O0040.nc 以 M99 结束：这是子程序，执行完返回调用它的程序。单独运行时执行一遍后在 M99 处停止"
        "（--repeat 则像数控系统执行以 M99 结束的主程序那样从头再次运行）。"
    ) in out
    assert "调用它的程序：subprogram_main.nc（O2000）" in out


def test_a_subprogram_nobody_calls_says_so_and_repeat_keeps_the_controls_loop(tmp_path):
    f = tmp_path / "O0040.nc"
    f.write_text("O0040\nG91 G01 X1. F100\nM99\n", encoding="utf-8")
    code, out, _ = cli("run", "--no-save", str(f))
    assert code == 0 and "moves (1):" in out
    assert "no program in its folder calls it" in out
    code, out, _ = cli("run", "--no-save", "--locale", "zh-CN", str(f))
    assert code == 0 and "同一文件夹中没有调用它的程序" in out

    code, out, _ = cli("run", "--no-save", "--repeat", "--max-blocks", "100", str(f))
    assert code == 3 and "moves (50):" in out and "ends in M99" not in out
    code, out, _ = cli("run", "--no-save", "--json", str(f))
    result = json.loads(out)
    assert (code, result["status"], len(result["moves"])) == (0, "completed", 1)
    assert any("ends in M99" in m for m in result["messages"])


# ---------------------------------------------------------------- what cannot be run


def test_a_folder_is_named_plainly_in_both_languages(examples):
    code, out, err = cli("run", str(examples))
    assert (code, out) == (2, "")
    assert err.strip() == (
        f"cncmacro run: {examples} is a folder, not a program file: run one of the programs in it "
        f"(cncmacro run {examples / 'FILE'}), or check them all with cncmacro check {examples}"
    )
    code, _, err = cli("run", "--locale", "zh-CN", str(examples))
    assert code == 2
    assert err.strip() == (
        f"cncmacro run：{examples} 是文件夹，不是程序文件：请运行其中的一个程序"
        f"（cncmacro run {examples / 'FILE'}），或用 cncmacro check {examples} 检查其中的全部程序"
    )
    assert _names(examples.parent) == ["examples"]  # nothing written for a run that never started


def test_unreadable_and_binary_files_are_sentences_not_error_numbers(tmp_path, monkeypatch):
    blob = tmp_path / "blob.nc"
    blob.write_bytes(b"\x00\x01\x02binary")
    code, _, err = cli("run", str(blob))
    assert (code, err.strip()) == (
        2, f"cncmacro run: {blob}: binary file (byte at offset 0 is not program text), not a program"
    )  # fmt: skip
    code, _, err = cli("run", "--locale", "zh-CN", str(blob))
    assert (code, err.strip()) == (2, f"cncmacro run：{blob}：二进制文件（偏移 0 处的字节不是程序文本），不是程序")

    locked = tmp_path / "O0001.nc"
    locked.write_text("O0001\nM30\n", encoding="utf-8")

    def refuse(path, max_bytes):
        raise PermissionError(13, "Permission denied", str(path))

    monkeypatch.setattr("cncmacro.library.files.read_bytes", refuse)
    code, _, err = cli("run", str(locked))
    assert (code, err.strip()) == (2, f"cncmacro run: cannot read the program {locked}: permission denied")
    code, _, err = cli("run", "--locale", "zh-CN", str(locked))
    assert (code, err.strip()) == (2, f"cncmacro run：无法读取程序 {locked}：没有读取权限")


def test_the_command_line_itself_names_a_folder_plainly(examples):
    done = subprocess.run(
        [sys.executable, "-m", "cncmacro", "run", str(examples)], capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 2 and "Errno" not in done.stderr and "is a folder" in done.stderr
