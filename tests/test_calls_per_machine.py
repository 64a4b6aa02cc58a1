"""A call finds only a program of its own machine (docs/cli.md, docs/editor.md "Where a call
finds its program"): a control runs the programs of its own memory, and a file whose dialect
comment names another control is another machine's program, though it lies in the same folder.
``cncmacro run`` and ``cncmacro check`` (its runs and its grouping of the files) decide it by the
rule of the program library, ``ProgramLibrary.on_machine``: the calling and the called file are
read in one profile; a file without a comment is read in its folder's profile.

The folder of each test (no machine file: fanuc-0i)::

    O1000.nc   O1000 (FANUC MAIN): #100=2 (line 2), M98 P2000 (line 3), M30
    O2000.nc   O2000 (cncmacro: dialect=gsk980tdi): #101=1/[#100-2] (line 2), M99

Run as O1000's subprogram, O2000 would divide by #100-2 = 2-2 = 0 (alarm 112) on its line 2.
"""

from __future__ import annotations

import json
from pathlib import Path

from cli_capture import cli
from cncmacro.cli.call_groups import file_keys, join_groups
from cncmacro.library.machine_file import MachineSettings

FANUC_MAIN = "O1000 (FANUC MAIN)\n#100=2\nM98 P2000\nM30\n"
GSK_SUB = "O2000 (cncmacro: dialect=gsk980tdi)\n#101=1/[#100-2]\nM99\n"


def _folder(tmp_path: Path, sub: str = GSK_SUB) -> tuple[Path, Path]:
    main, called = tmp_path / "O1000.nc", tmp_path / "O2000.nc"
    main.write_text(FANUC_MAIN, encoding="utf-8")
    called.write_text(sub, encoding="utf-8")
    return main, called


def _found(*args: str) -> list[tuple[str, int, str]]:
    _code, out, _err = cli("check", "--format", "json", *args)
    return sorted((Path(d["file"]).name, d["line"], d["code"]) for d in json.loads(out) if d["severity"] != "hint")


def test_run_does_not_run_a_gsk980tdi_program_as_a_fanuc_subprogram(tmp_path: Path) -> None:
    main, _ = _folder(tmp_path)
    code, out, _ = cli("run", "--json", str(main))
    r = json.loads(out)
    # the FANUC control has no O2000 in its memory: alarm 76 at the call (line 3), #100=2 set
    assert code == 1 and r["alarm"]["number"] == 76 and r["alarm"]["line"] == 3
    assert "O2000.nc is a GSK980TDi program, another machine's" in r["alarm"]["message"]
    assert r["variables"] == {"100": 2.0}


def test_check_of_a_gsk980tdi_program_does_not_run_it_from_a_fanuc_caller(tmp_path: Path) -> None:
    _main, called = _folder(tmp_path)
    # O2000 checked alone: no caller of its machine, it runs on its own (#100 unknown): no alarm
    assert _found(str(called)) == []
    # the folder: O1000's call finds nothing (line 3), O2000 divides by nothing known
    assert _found(str(tmp_path)) == [("O1000.nc", 3, "program-not-found")]


def test_a_folder_of_one_control_calls_as_before(tmp_path: Path) -> None:
    _main, called = _folder(tmp_path, GSK_SUB.replace("(cncmacro: dialect=gsk980tdi)", "(FANUC SUB)"))
    # both FANUC: O2000 runs as O1000's subprogram and divides by 2-2 = 0 on its line 2
    assert _found(str(called)) == [("O2000.nc", 2, "division-by-zero")]
    assert _found(str(tmp_path)) == [("O2000.nc", 2, "division-by-zero")]


def test_check_does_not_group_a_fanuc_caller_with_a_gsk980tdi_program(tmp_path: Path) -> None:
    main, called = _folder(tmp_path)
    settings = MachineSettings()
    keys = [file_keys(p, p.read_text(encoding="utf-8"), settings, None) for p in (main, called)]
    # O1000's M98 P2000 names the file O2000.nc, read in gsk980tdi: two machines, two groups
    assert [k.profile for k in keys] == ["fanuc-0i", "gsk980tdi"]
    assert join_groups([main, called], keys) == [[main], [called]]
    plain = [file_keys(p, t, settings, None) for p, t in ((main, FANUC_MAIN), (called, "O2000\n#101=1\nM99\n"))]
    assert join_groups([main, called], plain) == [[main, called]]  # one control: one group, as before
