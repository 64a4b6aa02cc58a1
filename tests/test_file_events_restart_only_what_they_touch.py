"""docs/design.md "Files changed on disk": a file saved, created or deleted on disk starts the runs
again only when what they rest on may have changed: a file the library read, or a file that
came or went in a folder it listed, or a header that may now hold a number searched for in vain,
or a file that calls an open program (or did). Saving any other program of a shop's folder of
thousands leaves the analysis as it is, and its findings unchanged."""

from __future__ import annotations

from pathlib import Path

from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.library.machine_file import MachineSettings

MACRO = ["O9100 (HOLES)", "#10=360/[#11-6]", "G01 X#10 F#9", "M99"]


def write(path: Path, text: str) -> str:
    path.write_text(text, encoding="utf-8")
    return str(path)


def workspace(folder: Path) -> WorkspaceAnalysis:
    return WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000), workspace_folders=[str(folder)])


def findings(ws: WorkspaceAnalysis, path: str) -> list[tuple[int, str]]:
    result = ws.analyze(path)
    assert result is not None
    return [(d.line + 1, d.code) for d in result.diagnostics.get(path, []) if d.severity != "hint"]


def test_saving_a_program_no_run_reads_leaves_the_runs_as_they_are(tmp_path):
    main = write(tmp_path / "O0001.nc", "O0001\nG90 G00 X0 Y0\nG65 P9100 K7. F100.\nM30\n")
    write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    other = write(tmp_path / "O5555.nc", "O5555\nG00 X1. Y1.\nM30\n")
    ws = workspace(tmp_path)
    ws.open(main, Path(main).read_text(encoding="utf-8"), 1)
    assert findings(ws, main) == []
    runs = list(ws.runs.values())
    write(Path(other), "O5555\nG00 X2. Y2.\nG01 Z-1. F50.\nM30\n")  # another part's program, edited and saved
    ws.file_changed(other)
    assert findings(ws, main) == []
    assert [r is s for r, s in zip(ws.runs.values(), runs, strict=True)] == [True]  # not started again


def test_saving_the_called_macro_on_disk_runs_again_with_its_new_text(tmp_path):
    main = write(tmp_path / "O0001.nc", "O0001\nG90 G00 X0 Y0\nG65 P9100 K7. F100.\nM30\n")
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    ws = workspace(tmp_path)
    ws.open(main, Path(main).read_text(encoding="utf-8"), 1)
    assert findings(ws, main) == []
    # K is #6, not #11: #11 is vacant, 360/[0-6] is fine; now the macro divides by [#6-7] = 0
    write(Path(macro), "O9100 (HOLES)\n#10=360/[#6-7]\nG01 X#10 F#9\nM99\n")
    ws.file_changed(macro)
    result = ws.analyze(main)
    assert result is not None
    assert [(d.line + 1, d.code) for d in result.diagnostics.get(macro, []) if d.severity != "hint"] == [
        (2, "division-by-zero")
    ]


def test_a_program_saved_with_a_call_of_the_open_macro_becomes_its_caller(tmp_path):
    macro = write(tmp_path / "O9100.nc", "\n".join(MACRO) + "\n")
    other = write(tmp_path / "O0002.nc", "O0002\nG00 X0 Y0\nM30\n")
    ws = workspace(tmp_path)
    ws.open(macro, Path(macro).read_text(encoding="utf-8"), 1)
    assert findings(ws, macro) == []  # alone: #11 is unknown, not vacant
    # saved with a call of the open macro: its run now starts there, with #11 = 6 (H): 360/0
    write(Path(other), "O0002\nG00 X0 Y0\nG65 P9100 H6. F100.\nM30\n")
    ws.file_changed(other)
    assert findings(ws, macro) == [(2, "division-by-zero")]


def test_a_header_that_now_holds_the_number_searched_for_in_vain_is_found(tmp_path):
    main = write(tmp_path / "MAIN.nc", "O0001\nG90 G00 X0 Y0\nM98 P7777\nM30\n")
    sub = write(tmp_path / "SUB.nc", "O1234\nG01 X1. F100.\nM99\n")
    ws = workspace(tmp_path)
    ws.open(main, Path(main).read_text(encoding="utf-8"), 1)
    assert findings(ws, main) == [(3, "program-not-found")]
    write(Path(sub), "O7777\nG01 X1. F100.\nM99\n")  # the same file, its program renumbered
    ws.file_changed(sub)
    assert findings(ws, main) == []


def test_a_called_program_created_beside_the_caller_is_found(tmp_path):
    main = write(tmp_path / "MAIN.nc", "O0001\nG90 G00 X0 Y0\nM98 P7777\nM30\n")
    ws = workspace(tmp_path)
    ws.open(main, Path(main).read_text(encoding="utf-8"), 1)
    assert findings(ws, main) == [(3, "program-not-found")]
    created = write(tmp_path / "O7777.nc", "O7777\nG01 X1. F100.\nM99\n")
    ws.file_changed(created)
    assert findings(ws, main) == []
    Path(created).unlink()
    ws.file_changed(created)
    assert findings(ws, main) == [(3, "program-not-found")]
