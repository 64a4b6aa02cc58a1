"""Files and configuration as shops have them, through ``cncmacro check`` and ``cncmacro run``
(docs/machine-file.md, docs/cli.md): programs stored as ``.txt``, a folder with no program,
codes the machine builder added (``[codes]``), common ranges beyond the profile's list, and
``--dialect`` against the machine file's profile."""

from __future__ import annotations

import time
from pathlib import Path

from cli_capture import cli

CALLER = "O0001\nM98 P1234\nM30\n"


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


# ---- 1. programs stored as .txt


def test_txt_program_that_starts_with_its_o_number_is_found_as_a_callee(tmp_path: Path) -> None:
    write(tmp_path, "MAIN.nc", CALLER)
    write(tmp_path, "O1234.txt", "\n(CUT POCKET)\nO1234\n#100=1\nM99\n")  # blank line and comment first
    code, out, err = cli("check", str(tmp_path))
    assert (code, out, err) == (0, "", "")


def test_txt_program_that_starts_with_percent_is_checked_in_a_folder(tmp_path: Path) -> None:
    write(tmp_path, "PART.txt", "%\nO0002\nG01 X\nM30\n%\n")
    code, out, _ = cli("check", str(tmp_path))
    assert code == 1 and "PART.txt:3:" in out and "[syntax]" in out


def test_txt_file_named_on_the_command_line_is_findable_as_a_callee(tmp_path: Path) -> None:
    main = write(tmp_path, "MAIN.nc", CALLER)
    sub = write(tmp_path, "1234.txt", "#100=1\nM99\n")  # no header: only its name says O1234
    code, out, _ = cli("check", str(main))
    assert code == 1 and "[program-not-found]" in out  # the folder alone does not make it a program
    assert cli("check", str(main), str(sub)) == (0, "", "")


def test_machine_file_extensions_make_txt_files_programs_for_check_and_run(tmp_path: Path) -> None:
    main = write(tmp_path, "MAIN.nc", "O0001\nM98 P1234\nG00 X#100\nM30\n")
    write(tmp_path, "1234.txt", "G00 X5.\n#100=7\nM99\n")  # starts like no program: the ending decides
    write(tmp_path, ".cncmacro.toml", 'extensions = ["TXT", ".min"]\n')
    assert cli("check", str(tmp_path)) == (0, "", "")
    code, out, _ = cli("run", "--no-save", str(main))
    assert code == 0 and "X5.000 -> X7.000" in out  # the run found the subprogram: X5 there, then X#100 = 7


def test_folder_without_programs_says_what_it_looked_for_and_exits_two(tmp_path: Path) -> None:
    write(tmp_path, "notes.txt", "G90 G54 is the start of every program\n")
    (tmp_path / "photo.bin").write_bytes(b"O1234\0\0\0")  # looks like a program, but binary
    write(tmp_path, "page.html", "<html>\n<body>O1234</body>\n")  # a tag, not a program name
    write(tmp_path, "print.ps", "%!PS-Adobe-3.0\n")  # % not alone on its line
    code, out, err = cli("check", str(tmp_path))
    assert code == 2 and out == ""
    assert "no program files in this folder" in err and ".nc" in err and "extensions" in err
    code, _, err = cli("check", "--locale", "zh-CN", str(tmp_path))
    assert code == 2 and "此文件夹中没有程序文件" in err


def test_bad_extensions_value_names_its_key(tmp_path: Path) -> None:
    write(tmp_path, "O0001.nc", "M30\n")
    write(tmp_path, ".cncmacro.toml", 'extensions = ["../x"]\n')
    code, _, err = cli("check", str(tmp_path))
    assert code == 2 and "'extensions' must be a list of file endings" in err


def test_search_reads_only_the_head_of_files_with_other_endings(tmp_path: Path) -> None:
    big = "G01 X1. Y1.\n" * 400_000  # 4.8 MB of text that does not start as a program
    for k in range(50):
        write(tmp_path, f"log{k}.txt", big)
    write(tmp_path, "O0001.nc", "M30\n")
    started = time.perf_counter()
    assert cli("check", str(tmp_path)) == (0, "", "")
    assert time.perf_counter() - started < 5  # reading 240 MB whole would take far longer


def test_callee_in_a_sibling_folder_of_the_checked_tree_is_found(tmp_path: Path) -> None:
    # a shop keeps main programs and macros in two folders of one machine; the control holds
    # them all in one memory, so the main program's G65 P5100 finds the macro next door
    mains, macros = tmp_path / "main", tmp_path / "macros"
    mains.mkdir()
    macros.mkdir()
    write(tmp_path, ".cncmacro.toml", 'base = "fanuc-30i"\n')
    write(mains, "O1001.nc", "O1001\nG65 P5100 A2.\n#101=#100\nM30\n")
    write(macros, "O5100.nc", "O5100\n#100=#1*3\nM99\n")
    assert cli("check", str(tmp_path)) == (0, "", "")
    assert cli("check", str(mains / "O1001.nc"), str(macros / "O5100.nc")) == (0, "", "")
    # the run goes through the macro with the caller's argument: 10/[#100-6] divides by zero,
    # #100 = A x 3 = 2 x 3 = 6, so 6 - 6 = 0 (alarm 112)
    write(mains, "O1001.nc", "O1001\nG65 P5100 A2.\n#101=10/[#100-6]\nM30\n")
    code, out, _ = cli("check", str(tmp_path))
    assert code == 1 and "O1001.nc:3:" in out and "[division-by-zero]" in out
    # named alone, the main program still does not see the other folder
    code, out, _ = cli("check", str(mains / "O1001.nc"))
    assert code == 1 and "[program-not-found]" in out


# ---- 2. codes the machine builder added


def test_codes_table_makes_a_builder_code_a_plain_code(tmp_path: Path) -> None:
    prog = write(tmp_path, "O0001.nc", "O0001\nG90 G00 X10.\nG120.1 P1 Q1\nG00 X20.\nM30\n")
    code, out, _ = cli("check", str(prog))
    assert code == 1 and "[unknown-g-code]" in out  # without the machine file: an unknown code
    write(tmp_path, ".cncmacro.toml", '[codes]\n"G120.1" = { en = "Pallet change position", zh = "托盘交换位置" }\n')
    assert cli("check", str(prog)) == (0, "", "")
    code, out, _ = cli("run", "--no-save", str(prog))
    # no move and no alarm at G120.1: X0 -> X10 on line 2, X10 -> X20 on line 4
    assert code == 0 and "moves (2)" in out and "X10.000 -> X20.000" in out and "alarm" not in out


def test_codes_table_refuses_a_code_that_also_calls(tmp_path: Path) -> None:
    write(tmp_path, "O0001.nc", "M30\n")
    write(tmp_path, ".cncmacro.toml", '[calls]\nG120 = 9010\n[codes]\nG120 = { en = "x" }\n')
    code, _, err = cli("check", str(tmp_path))
    assert code == 2 and "'codes.G120' is also in [calls]" in err


# ---- 3. common ranges the machine documents


def test_common_ranges_across_500_and_beyond_the_profile_are_taken_with_a_note(tmp_path: Path) -> None:
    write(tmp_path, ".cncmacro.toml", 'base = "fanuc-30i"\ncommon = [[100, 199], [400, 999], [900000, 907399]]\n')
    prog = write(tmp_path, "O0001.nc", "O0001\n#450=1\n#950=2\n#900001=3\n#907399=4\nM30\n")
    code, out, err = cli("check", str(prog))
    assert code == 0 and out == ""
    assert err == (f"cncmacro: note: {tmp_path / '.cncmacro.toml'}: common #900000-#907399: common variables of "
                   "this machine beyond fanuc-30i's list (#100-#499, #500-#999, #98000-#98499)\n")  # fmt: skip
    write(prog.parent, "O0001.nc", "O0001\n#300=1\n#907400=1\nM30\n")
    code, out, _ = cli("check", str(prog))
    assert code == 1 and out.count("[variable-number]") == 2  # #300 and #907400 are outside the machine's


def test_common_range_over_system_variables_names_the_overlap(tmp_path: Path) -> None:
    write(tmp_path, ".cncmacro.toml", "common = [[100, 199], [900, 1010]]\n")
    write(tmp_path, "O0001.nc", "M30\n")
    code, _, err = cli("check", str(tmp_path))
    assert code == 2 and "'common' #900-#1010 overlaps the system variables #1000" in err


def test_common_ranges_that_touch_are_one_range_kept_as_the_profile_keeps_it(tmp_path: Path) -> None:
    from cncmacro.library.machine_file import settings_from_mapping
    from cncmacro.library.profiles import machine_profile

    settings = settings_from_mapping({"common": [[100, 299], [300, 999], [200, 250]]})
    assert settings.common == ((100, 999),)
    kept = [(r.first, r.last, r.persistent) for r in machine_profile("fanuc-0i", settings).common_ranges]
    assert kept == [(100, 499, False), (500, 999, True)]  # #500-#999 still kept at power-off


# ---- 4. --dialect against the machine file's profile


def test_typed_dialect_wins_over_the_machine_file_with_a_note(tmp_path: Path) -> None:
    write(tmp_path, ".cncmacro.toml", 'base = "haas"\n')
    prog = write(tmp_path, "O0001.nc", "O0001\nG65 P[CUT]\nM30\n")  # a bracketed name: only gsk980tdi reads it
    write(tmp_path, "CUT.CNC", "M99\n")
    code, out, _ = cli("check", str(prog))
    assert code == 1 and out  # haas, as the machine file says
    code, out, err = cli("check", "--dialect", "gsk980tdi", str(prog))
    assert (code, out) == (0, "")
    toml = tmp_path / ".cncmacro.toml"
    assert err == f"cncmacro: note: --dialect gsk980tdi is used: it overrides haas, the profile that {toml} names\n"
    code, out, err = cli("check", "--locale", "zh-CN", "--dialect", "gsk980tdi", str(prog))
    assert "取代了" in err and "haas" in err


def test_typed_dialect_wins_in_run_too(tmp_path: Path) -> None:
    write(tmp_path, ".cncmacro.toml", 'base = "haas"\n')
    prog = write(tmp_path, "O0001.nc", "O0001\nG00 X1.\nM30\n")
    code, out, err = cli("run", "--no-save", "--json", "--dialect", "gsk980tdi", str(prog))
    assert code == 0 and '"dialect": "gsk980tdi"' in out and "overrides haas" in err


def test_file_comment_still_wins_over_typed_dialect(tmp_path: Path) -> None:
    prog = write(tmp_path, "O0001.nc", "(cncmacro: dialect=haas)\nO0001\nG65 P[CUT]\nM30\n")
    write(tmp_path, "CUT.CNC", "M99\n")
    code, out, _ = cli("check", "--dialect", "gsk980tdi", str(prog))
    assert code == 1 and out  # read as haas: no bracketed program names
