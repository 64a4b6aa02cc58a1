"""What the checker, the runs and the language server may read and write: only program files
under the workspace folders, the ``--path`` folders and the checked file's own folder. A
program name with a path in it is ``program-not-found`` and never read; a link that leads out
of those folders is not followed; a machine file cannot point the persistent variables
outside its folder; a file event for a path outside the workspace is ignored; and the debug
adapter shows program files only."""

from __future__ import annotations

import io
import json
import subprocess
import sys
from pathlib import Path

import pytest

from cncmacro.analysis.indexes.workspace_index import WorkspaceIndex
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.dap.protocol import MessageWriter, Request
from cncmacro.dap.session import Session
from cncmacro.library.files import find_program_files
from cncmacro.library.machine_file import MachineFileError, load_machine_file
from cncmacro.library.programs import ProgramLibrary
from cncmacro.lsp.documents import Documents

SECRET = "O8100 (SECRET)\n#100=42\nM99\n"


def cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cncmacro", *args], capture_output=True, text=True, timeout=120)


@pytest.fixture
def outside(tmp_path: Path) -> Path:
    """A folder beside the workspace holding a program the workspace must not read."""
    folder = tmp_path / "outside"
    folder.mkdir()
    (folder / "O8100.nc").write_text(SECRET, encoding="utf-8")
    (folder / "passwd").write_text("root:x:0:0\n", encoding="utf-8")
    return folder


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    folder = tmp_path / "workspace"
    folder.mkdir()
    return folder


def analyse(path: Path, text: str) -> list[tuple[int, str, str]]:
    ws = WorkspaceAnalysis()
    ws.open(str(path), text, 1)
    result = ws.analyze(str(path))
    assert result is not None
    return [(d.line, d.code, d.message) for d in result.diagnostics.get(str(path), []) if d.code != "not-executed"]


@pytest.mark.parametrize("name", ["../../etc/passwd", "../outside/passwd", "./../outside/O8100", "/etc/passwd"])
def test_a_program_name_with_a_path_is_refused_and_never_read(workspace: Path, outside: Path, name: str) -> None:
    main = workspace / "O0001.nc"
    text = f"(cncmacro: dialect=gsk980tdi)\nO0001\nG65 P[{name}]\nM30\n"
    found = analyse(main, text)
    assert [(line, code) for line, code, _ in found] == [(2, "program-number")]  # '/' is not a name character
    library = ProgramLibrary([workspace])
    assert library.find_name(name) is None
    assert not any("outside" in key or "passwd" in key for key in library._files)


def test_a_link_that_leads_out_of_the_workspace_is_not_followed(workspace: Path, outside: Path) -> None:
    (workspace / "O8100.nc").symlink_to(outside / "O8100.nc")
    (workspace / "inside.nc").write_text("O0002\nM30\n", encoding="utf-8")
    (workspace / "O0003.nc").symlink_to(workspace / "inside.nc")  # a link within the workspace is fine
    main = workspace / "O0001.nc"
    text = "O0001\nG65 P8100\nM30\n"
    assert [(line, code) for line, code, _ in analyse(main, text)] == [(1, "program-not-found")]
    assert [p.name for p in find_program_files(workspace)] == ["O0003.nc", "inside.nc"]
    main.write_text(text, encoding="utf-8")
    r = cli("run", "--no-save", "--json", str(main))
    assert json.loads(r.stdout)["alarm"]["number"] == 76  # program not found, on the control too
    assert "100" not in json.loads(r.stdout)["variables"]


def test_an_extra_path_folder_is_searched_and_its_links_stay_inside_it(workspace: Path, outside: Path) -> None:
    main = workspace / "O0001.nc"
    main.write_text("O0001\nG65 P8100\nM30\n", encoding="utf-8")
    r = cli("run", "--no-save", "--json", "--path", str(outside), str(main))
    assert json.loads(r.stdout)["variables"]["100"] == 42.0  # an explicit --path folder is allowed


@pytest.mark.parametrize("value", ["/tmp/vars.json", "../vars.json", "sub/../../vars.json", "C:\\\\vars.json", ""])
def test_a_machine_files_persistent_file_must_stay_in_its_folder(workspace: Path, value: str) -> None:
    machine = workspace / ".cncmacro.toml"
    machine.write_text(f'persistent_file = "{value}"\n', encoding="utf-8")
    with pytest.raises(MachineFileError, match="persistent_file"):
        load_machine_file(machine)
    main = workspace / "O0001.nc"
    main.write_text("O0001\n#500=1\nM30\n", encoding="utf-8")
    r = cli("run", str(main))
    assert r.returncode == 2 and "persistent_file" in r.stderr


def test_a_persistent_file_in_a_subfolder_is_allowed(workspace: Path) -> None:
    (workspace / ".cncmacro.toml").write_text('persistent_file = "state/vars.json"\n', encoding="utf-8")
    main = workspace / "O0001.nc"
    main.write_text("O0001\n#500=#500+1\nM30\n", encoding="utf-8")
    assert cli("run", str(main)).returncode == 0
    assert json.loads((workspace / "state" / "vars.json").read_text("utf-8"))["variables"] == {"500": 1.0}


def test_the_workspace_index_reads_no_file_outside_its_folders(workspace: Path, outside: Path) -> None:
    (workspace / "O0001.nc").write_text("O0001\nM30\n", encoding="utf-8")
    (workspace / "O8100.nc").symlink_to(outside / "O8100.nc")
    documents = Documents()
    index = WorkspaceIndex(documents.by_uri.values, documents.dialect_for)
    assert index.scan([str(workspace)]) == 1
    index.reload(str(outside / "O8100.nc"))  # a file event for a path outside the workspace
    index.reload(str(workspace / "O8100.nc"))  # and for the link
    assert sorted(Path(p).name for p in index.files) == ["O0001.nc"]


def test_the_analysis_never_reads_or_writes_the_persistent_file(workspace: Path) -> None:
    vars_file = workspace / ".cncmacro-vars.json"
    vars_file.write_text('{"variables": {"500": 7.0}}\n', encoding="utf-8")
    before = vars_file.stat().st_mtime_ns
    main = workspace / "O0001.nc"
    found = analyse(main, "O0001\n#1=1/[#500-7]\n#500=#500+1\nM30\n")
    assert [(line, code) for line, code, _ in found] == []  # #500 is vacant (0) in the analysis, not 7
    assert vars_file.stat().st_mtime_ns == before
    assert [p.name for p in workspace.iterdir()] == [vars_file.name]


def test_the_debug_adapter_shows_program_files_only(workspace: Path, outside: Path) -> None:
    (workspace / "O0001.nc").write_text("O0001\nM30\n", encoding="utf-8")
    out = io.BytesIO()
    session = Session(MessageWriter(out))
    for seq, path in enumerate([workspace / "O0001.nc", outside / "passwd"], start=1):
        session.handle(Request(seq, "source", {"source": {"path": str(path)}}))
    replies = [json.loads(part[: part.rfind(b"}") + 1]) for part in out.getvalue().split(b"\r\n\r\n")[1:]]
    assert [r["success"] for r in replies] == [True, False]
    assert replies[0]["body"]["content"] == "O0001\nM30\n"
    assert "root:" not in json.dumps(replies[1]) and "not a program file" in replies[1]["message"]
