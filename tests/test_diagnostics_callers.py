"""docs/semantics.md §5 Calls, docs/design.md "Entry points": a program opened or checked alone is
analysed through its callers on disk in the workspace folders, with their arguments; a program
nothing calls runs on its own; nothing outside the workspace folders and search paths is read."""

from __future__ import annotations

import builtins
import pathlib
import subprocess
import sys
from pathlib import Path

from cncmacro.analysis.diagnostics import Diagnostic
from cncmacro.analysis.runs import run_checks
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.library.machine_file import MachineSettings

ROOT = Path(__file__).resolve().parent.parent

# Run on its own (no caller reaches it) the macro's arguments are unknown, not vacant: line 2's
# check raises nothing, and the move by #10 (from #11) stops the run with a hint on line 4
ALONE = (4, "unknown-value")
MACRO = [
    "O9100 (HOLES)",
    "IF[#11 EQ #0] THEN #3000=1(HOLE COUNT MISSING)",
    "#10=360/[#11-6]",
    "G01 X#10 F#9",
    "M99",
]


def main_calling(call: str, after: str = "") -> str:
    return "\n".join(["O0001", "G90 G54 G00 X0 Y0", call, after, "M30"]) + "\n"


def workspace(folders: list[Path], **kw: object) -> WorkspaceAnalysis:
    return WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000),
                             workspace_folders=[str(f) for f in folders], **kw)  # type: ignore[arg-type]  # fmt: skip


def write(path: Path, text: str) -> str:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return str(path)


def open_alone(ws: WorkspaceAnalysis, path: str) -> list[Diagnostic]:
    ws.open(path, Path(path).read_text(encoding="utf-8"), 1)
    result = ws.analyze(path)
    assert result is not None
    return result.diagnostics.get(path, [])


def codes(diags: list[Diagnostic]) -> list[tuple[int, str]]:
    # the hints left out but ``unknown-value``, by which a macro shows it ran on its own (``ALONE``)
    return [(d.line + 1, d.code) for d in diags if d.severity != "hint" or d.code == "unknown-value"]


def test_5_calls_a_macro_opened_alone_runs_through_its_caller_on_disk(tmp_path):
    write(tmp_path / "MAIN.nc", main_calling("G65 P9100 H6 F100."))
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    diags = open_alone(workspace([tmp_path]), macro)
    assert codes(diags) == [(3, "division-by-zero")]  # 360/[6-6]: only the caller's H6 does that
    [zero] = [d for d in diags if d.code == "division-by-zero"]
    assert [(Path(r.file).name, r.line + 1) for r in zero.related] == [("MAIN.nc", 3)]
    assert "O0001:3 (G65)" in zero.message
    # without the workspace the macro runs on its own, with unknown arguments
    alone = open_alone(WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000)), macro)
    assert codes(alone) == [ALONE]


def test_5_calls_a_macro_is_reached_through_a_second_level_call(tmp_path):
    write(tmp_path / "MAIN.nc", main_calling("G65 P9000 H6 F80."))
    write(tmp_path / "O9000.nc", "O9000 (MIDDLE)\nG65 P9100 H#11 F#9\nM99\n")
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    diags = open_alone(workspace([tmp_path]), macro)
    assert codes(diags) == [(3, "division-by-zero")]
    [zero] = [d for d in diags if d.code == "division-by-zero"]
    assert [(Path(r.file).name, r.line + 1) for r in zero.related] == [("O9000.nc", 2), ("MAIN.nc", 3)]


def test_5_calls_an_open_main_reaches_the_macro_through_a_macro_on_disk(tmp_path):
    main = write(tmp_path / "MAIN.nc", main_calling("G65 P9000 H6 F80."))
    write(tmp_path / "O9000.nc", "O9000 (MIDDLE)\nG65 P9100 H#11 F#9\nM99\n")
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    ws = workspace([tmp_path])
    ws.open(main, Path(main).read_text(encoding="utf-8"), 1)
    diags = open_alone(ws, macro)
    assert codes(diags) == [(3, "division-by-zero")]
    assert [Path(k[0]).name for k in ws.runs] == ["MAIN.nc"]  # the open main's run, no second one


def test_5_calls_callers_that_only_call_each_other_leave_the_macro_to_run_on_its_own(tmp_path):
    write(tmp_path / "O9000.nc", "O9000\nG65 P9001\nG65 P9100 H6 F1.\nM99\n")
    write(tmp_path / "O9001.nc", "O9001\nG65 P9000\nM99\n")
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    assert codes(open_alone(workspace([tmp_path]), macro)) == [ALONE]


def test_5_calls_findings_of_a_caller_on_disk_stay_out_of_the_result(tmp_path):
    write(tmp_path / "MAIN.nc", main_calling("G65 P9100 H5 F100.", "#5=1/0"))
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    ws = workspace([tmp_path])
    ws.open(macro, Path(macro).read_text(encoding="utf-8"), 1)
    result = ws.analyze(macro)
    assert result is not None
    assert codes(result.diagnostics[macro]) == []  # H5: no alarm, no division by zero
    assert list(result.diagnostics) == [macro]  # MAIN's own division by zero is not reported here
    assert 2 in result.values[macro]  # the run through MAIN executed the macro's lines


def test_5_calls_an_open_callers_unsaved_text_wins_over_the_file_on_disk(tmp_path):
    main = write(tmp_path / "MAIN.nc", main_calling("G65 P9100 H6 F100."))  # on disk: H6
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    ws = workspace([tmp_path])
    ws.open(main, main_calling("G65 P9100 H4 F100."), 1)  # in the editor: H4, not saved
    assert codes(open_alone(ws, macro)) == []
    write(tmp_path / "MAIN.nc", main_calling("G01 X1. F100."))  # on disk: no call at all
    ws2 = workspace([tmp_path])
    ws2.open(main, main_calling("G65 P9100 H6 F100."), 1)  # in the editor: calls with H6
    assert codes(open_alone(ws2, macro)) == [(3, "division-by-zero")]


def test_5_calls_a_caller_outside_the_workspace_folders_is_never_read(tmp_path, monkeypatch):
    folder = tmp_path / "ws"
    sibling = tmp_path / "other"
    write(sibling / "MAIN.nc", main_calling("G65 P9100 H6 F100."))  # would reach O9100 through the search path
    macro = write(folder / "O9100.nc", "\n".join(MACRO) + "\n")
    read: list[str] = []
    real_open, real_read_bytes = builtins.open, pathlib.Path.read_bytes

    def spy_open(file, *a, **kw):  # type: ignore[no-untyped-def]
        read.append(str(file))
        return real_open(file, *a, **kw)

    def spy_read_bytes(self):  # type: ignore[no-untyped-def]
        read.append(str(self))
        return real_read_bytes(self)

    monkeypatch.setattr(builtins, "open", spy_open)
    monkeypatch.setattr(pathlib.Path, "read_bytes", spy_read_bytes)
    diags = open_alone(workspace([folder], search_paths=[str(folder)]), macro)
    assert codes(diags) == [ALONE]  # runs on its own: the sibling's call is not used
    assert not [p for p in read if str(sibling) in p]
    # the same caller inside a workspace folder is used
    diags = open_alone(workspace([folder, sibling], search_paths=[str(folder)]), macro)
    assert codes(diags) == [(3, "division-by-zero")]


def test_5_calls_a_program_that_nothing_calls_still_runs_on_its_own(tmp_path):
    write(tmp_path / "MAIN.nc", main_calling("G65 P9200 H6"))  # calls another program
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    assert codes(open_alone(workspace([tmp_path]), macro)) == [ALONE]


def test_5_calls_a_subprogram_called_with_a_count_in_p_is_reached_through_its_caller(tmp_path):
    write(tmp_path / "MAIN.nc", main_calling("#100=3", "M98 P20040"))
    sub = write(tmp_path / "O0040.nc", "O0040\n#101=1/[#100-3]\nM99\n")
    assert codes(open_alone(workspace([tmp_path]), sub)) == [(2, "division-by-zero")]


def test_5_calls_a_gsk_program_named_by_its_file_is_reached_through_p_name(tmp_path):
    (tmp_path / ".cncmacro.toml").write_text('dialect = "gsk980tdi"\n', encoding="utf-8")
    write(tmp_path / "MAIN.cnc", "O0001\nG65 P[CUT] A4\nM30\n")
    cut = write(tmp_path / "CUT.CNC", "#2=1/[#1-4]\nM99\n")
    ws = WorkspaceAnalysis(settings=MachineSettings(dialect="gsk980tdi"), workspace_folders=[str(tmp_path)])
    assert codes(open_alone(ws, cut)) == [(1, "division-by-zero")]


def test_5_calls_a_gsk_program_after_the_dialect_comment_is_reached_through_p_name(tmp_path):
    write(tmp_path / "MAIN.cnc", "(cncmacro: dialect=gsk980tdi)\nO0001\nG65 P[CUT] A4\nM30\n")
    cut = write(tmp_path / "CUT.CNC", "(cncmacro: dialect=gsk980tdi)\nO0005 (CUT)\n#2=1/[#1-4]\nM99\n")
    ws = WorkspaceAnalysis(settings=MachineSettings(dialect="gsk980tdi"), workspace_folders=[str(tmp_path)])
    assert codes(open_alone(ws, cut)) == [(3, "division-by-zero")]


def test_5_calls_an_edit_in_the_macro_resumes_the_callers_run(tmp_path, monkeypatch):
    """The caller on disk runs 120 blocks before the call: an edit in the macro takes its run
    back to a checkpoint before the macro first ran, not to the start, and the result is the
    result of an analysis from scratch."""
    monkeypatch.setattr(run_checks, "CHUNK", 10)
    motion = "\n".join(f"G01 X{k}. Y1. F100." for k in range(120))
    write(tmp_path / "MAIN.nc", main_calling(motion + "\nG65 P9100 H5 F100."))
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    ws = workspace([tmp_path])
    assert codes(open_alone(ws, macro)) == []
    [run] = ws.runs.values()
    assert Path(run.entry.file.path).name == "MAIN.nc"
    restarts: list[int] = []
    rewinds: list[int] = []
    original_restart, original_back_to = run_checks.EntryRun.restart, run_checks.EntryRun.back_to
    monkeypatch.setattr(run_checks.EntryRun, "restart", lambda self: (restarts.append(1), original_restart(self))[1])
    monkeypatch.setattr(run_checks.EntryRun, "back_to",
                        lambda self, step, *a: (rewinds.append(step), original_back_to(self, step, *a))[1])  # fmt: skip
    ws.change(macro, 2, 0, 2, len(MACRO[2]), "#10=360/[#11-5]", 2)
    result = ws.analyze(macro)
    assert result is not None
    assert restarts == [] and rewinds and min(rewinds) > 100  # resumed near the call, not from the start
    assert codes(result.diagnostics[macro]) == [(3, "division-by-zero")]
    scratch = workspace([tmp_path])
    scratch.open(macro, ws.document(macro).text, 2)  # type: ignore[union-attr]
    again = scratch.analyze(macro)
    assert again is not None
    assert result.diagnostics == again.diagnostics
    assert {f: v for f, v in result.values.items() if v} == {f: v for f, v in again.values.items() if v}


def test_5_calls_a_file_changed_on_disk_is_read_again(tmp_path):
    main = write(tmp_path / "MAIN.nc", main_calling("G65 P9100 H5 F100."))
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    ws = workspace([tmp_path])
    assert codes(open_alone(ws, macro)) == []
    write(Path(main), main_calling("G65 P9100 H6 F100.") + "(NOW H6)\n")
    ws.file_changed(main)
    result = ws.analyze(macro)
    assert result is not None and codes(result.diagnostics[macro]) == [(3, "division-by-zero")]
    Path(main).unlink()
    ws.file_changed(main)
    result = ws.analyze(macro)
    assert result is not None and codes(result.diagnostics[macro]) == [ALONE]


def run_cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cncmacro", *args], capture_output=True, text=True, timeout=120,
                          cwd=ROOT)  # fmt: skip


def test_5_calls_checking_the_bolt_circle_macro_alone_finds_nothing():
    r = run_cli("check", "--hints", "examples/fanuc/O9100.nc")
    assert (r.returncode, r.stdout, r.stderr) == (0, "", "")


def test_5_calls_check_prints_only_the_requested_files_findings(tmp_path):
    main = write(tmp_path / "MAIN.nc", main_calling("G65 P9100 H5 F100.", "#5=1/0"))
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    r = run_cli("check", macro)
    assert (r.returncode, r.stdout) == (0, "")  # MAIN is analysed (no alarm 3001) but its error is not printed
    r = run_cli("check", main)
    assert r.returncode == 1 and r.stdout.startswith(f"{main}:4:1: error:") and "[division-by-zero]" in r.stdout
    write(tmp_path / "MAIN.nc", main_calling("G65 P9100 H6 F100."))
    r = run_cli("check", macro)
    assert r.returncode == 1 and r.stdout.startswith(f"{macro}:3:1: error:") and "MAIN.nc" not in r.stdout
