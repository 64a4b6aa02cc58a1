"""The workspace's program files are read once per change (ARCHITECTURE.md, "the one reader"):
the language server's workspace index, the analysis's program library and its index of callers
all read through one ``FileCache``, and ``cncmacro check``'s analysis reads each file once too."""

from __future__ import annotations

import io
import re
import sys
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import pytest

from cncmacro.analysis.indexes.site_index import SiteIndex
from cncmacro.analysis.indexes.workspace_index import WorkspaceIndex
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.cli.check import check_paths
from cncmacro.dialects import get_dialect
from cncmacro.library import files
from cncmacro.library.programs import FoundProgram, LoadedFile, ProgramLibrary
from cncmacro.syntax.document import ParsedDocument

MAIN = "O0001\nG65 P9100 A1.\nM30\n"
OTHER = "O0002\nG65 P9100 A2.\nM98 P9200\nM30\n"
MACRO = "O9100\n#100=#1*2\nM98 P9200\nM99\n"
SUB = "O9200\n#101=1\nM99\n"


@pytest.fixture
def reads(monkeypatch: pytest.MonkeyPatch) -> Counter[str]:
    """How often each file was read, wherever in the package it was read from."""
    counted: Counter[str] = Counter()
    original = files.read_program

    def read_program(path: str | Path, max_bytes: int | None = files.MAX_PROGRAM_BYTES) -> files.SourceText:
        counted[Path(path).name] += 1
        return original(path, max_bytes)

    for name, module in list(sys.modules.items()):
        if name.startswith("cncmacro") and getattr(module, "read_program", None) is original:
            monkeypatch.setattr(module, "read_program", read_program)
    return counted


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    for name, text in {"O0001.nc": MAIN, "O0002.nc": OTHER, "O9100.nc": MACRO, "O9200.nc": SUB}.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    return tmp_path


@dataclass
class Document:
    """An open document as an editor's server keeps it."""

    path: str
    parsed: ParsedDocument
    sites: SiteIndex

    @property
    def lines(self) -> list[str]:
        return self.parsed.lines

    def as_loaded(self) -> LoadedFile:
        return LoadedFile(self.path, self.parsed.lines, self.parsed.program, None)


def test_the_server_reads_each_workspace_file_once_per_change(workspace: Path, reads: Counter[str]) -> None:
    opened: list[Document] = []
    index = WorkspaceIndex(lambda: opened, lambda lines, path: get_dialect("fanuc"))
    assert index.scan([str(workspace)]) == 4
    analysis = WorkspaceAnalysis(search_paths=[str(workspace)], workspace_folders=[str(workspace)], files=index.disk)
    macro = str(workspace / "O9100.nc")
    analysis.open(macro, MACRO, 1)
    parsed = analysis.document(macro)
    assert parsed is not None
    opened.append(Document(macro, parsed, SiteIndex(parsed.blocks)))
    result = analysis.analyze(macro)
    assert result is not None and result.values[macro]  # run through its callers on disk
    found = index.find_program(opened[0], 9200, None)  # a hover on its call
    assert found is not None and Path(found.file.path).name == "O9200.nc"
    assert sum(len(f.sites.writes(101)) for f in index.file_sites()) == 1
    assert reads == Counter({"O0001.nc": 1, "O0002.nc": 1, "O9100.nc": 1, "O9200.nc": 1})

    (workspace / "O9200.nc").write_text(SUB.replace("#101=1", "#101=22"), encoding="utf-8")
    index.reload(str(workspace / "O9200.nc"))  # the editor's file event, as the server passes it on
    analysis.file_changed(str(workspace / "O9200.nc"))
    assert analysis.analyze(macro) is not None
    assert index.find_program(opened[0], 9200, None) is not None
    assert reads == Counter({"O0001.nc": 1, "O0002.nc": 1, "O9100.nc": 1, "O9200.nc": 2})


def test_check_reads_each_file_once(workspace: Path, reads: Counter[str]) -> None:
    analysis = WorkspaceAnalysis(search_paths=[str(workspace)], workspace_folders=[str(workspace)])
    macro = str(workspace / "O9100.nc")
    analysis.open(macro, MACRO)
    result = analysis.analyze(macro)
    assert result is not None and result.values[macro]
    assert reads == Counter({"O0001.nc": 1, "O0002.nc": 1, "O9100.nc": 1, "O9200.nc": 1})  # O9100 by the callers' index


def test_a_program_no_header_holds_is_searched_for_once_until_a_file_changes(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # a hover or go-to-definition on the P of a call to O5555, which no file holds: the first one
    # reads the folder's files for an O5555 header; later ones do not read them again, until a file
    # event in that folder (a file that now holds O5555 is then found)
    searched: list[Path] = []
    original = ProgramLibrary._header_in

    def header_in(
        self: ProgramLibrary, folder: Path, number: int, header: re.Pattern[str], near: LoadedFile | None
    ) -> tuple[FoundProgram | None, bool]:
        searched.append(folder)
        return original(self, folder, number, header, near)

    monkeypatch.setattr(ProgramLibrary, "_header_in", header_in)
    index = WorkspaceIndex(lambda: [], lambda lines, path: get_dialect("fanuc"))
    index.scan([str(workspace)])
    main = str(workspace / "O0001.nc")
    caller = Document(main, ParsedDocument(MAIN), SiteIndex(ParsedDocument(MAIN).blocks))
    assert index.find_program(caller, 5555, None) is None
    assert searched == [workspace]
    assert index.find_program(caller, 5555, None) is None
    assert index.find_program(caller, 5555, None) is None
    assert searched == [workspace]  # not read again
    (workspace / "macros.nc").write_text("O5555\nM99\n", encoding="utf-8")
    index.reload(str(workspace / "macros.nc"))  # the editor's file event
    found = index.find_program(caller, 5555, None)
    assert found is not None and Path(found.file.path).name == "macros.nc"


def test_a_folder_is_listed_once_for_every_look_up_until_a_file_comes_or_goes(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # hovers and go-to-definitions on calls: each makes a library, and they share the folders'
    # listings; saving a file changes no listing, a file created or deleted there does
    from cncmacro.library import programs

    listed: list[Path] = []
    original = programs.program_files_in

    def program_files_in(folder: Path, extensions: frozenset[str]):  # type: ignore[no-untyped-def]
        listed.append(folder)
        return original(folder, extensions)

    monkeypatch.setattr(programs, "program_files_in", program_files_in)
    index = WorkspaceIndex(lambda: [], lambda lines, path: get_dialect("fanuc"))
    index.scan([str(workspace)])
    main = str(workspace / "O0001.nc")
    caller = Document(main, ParsedDocument(MAIN), SiteIndex(ParsedDocument(MAIN).blocks))
    for _ in range(3):
        found = index.find_program(caller, 9200, None)
        assert found is not None and Path(found.file.path).name == "O9200.nc"
    assert listed == [workspace]
    (workspace / "O9200.nc").write_text(SUB.replace("#101=1", "#101=2"), encoding="utf-8")
    index.reload(str(workspace / "O9200.nc"))  # saved: the same files are there
    assert index.find_program(caller, 9200, None) is not None
    assert listed == [workspace]
    (workspace / "O9300.nc").write_text("O9300\nM99\n", encoding="utf-8")
    index.reload(str(workspace / "O9300.nc"))  # created: found at once
    found = index.find_program(caller, 9300, None)
    assert found is not None and Path(found.file.path).name == "O9300.nc"
    assert listed == [workspace, workspace]
    (workspace / "O9300.nc").unlink()
    index.reload(str(workspace / "O9300.nc"))  # deleted: not found any more
    assert index.find_program(caller, 9300, None) is None


def test_the_folders_listed_ahead_at_start_serve_the_first_look_up(
    workspace: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the language server lists the folders a call looks in on a thread at start: the first
    # hover on a call then finds its program without listing a folder
    from cncmacro.library import programs

    index = WorkspaceIndex(lambda: [], lambda lines, path: get_dialect("fanuc"))
    index.scan([str(workspace)])
    ahead = index.folders_to_list()
    assert ahead is not None
    ahead.list_folders()
    listed: list[Path] = []
    original = programs.program_files_in

    def program_files_in(folder: Path, extensions: frozenset[str]):  # type: ignore[no-untyped-def]
        listed.append(folder)
        return original(folder, extensions)

    monkeypatch.setattr(programs, "program_files_in", program_files_in)
    caller = Document(str(workspace / "O0001.nc"), ParsedDocument(MAIN), SiteIndex(ParsedDocument(MAIN).blocks))
    found = index.find_program(caller, 9200, None)
    assert found is not None and Path(found.file.path).name == "O9200.nc"
    assert listed == []


def test_a_check_of_a_folder_reads_no_file_again_for_its_callers(workspace: Path, reads: Counter[str]) -> None:
    """``cncmacro check`` reads each file to say at once what cannot be read, then for the calls
    it makes, then to check it. A file's callers among the files checked are checked beside it
    (``cli/call_groups.py``), so the index of callers on disk reads none of them again. O9200,
    which makes no call but whose number a call names, is read once more for its exact O number."""
    out, err = io.StringIO(), io.StringIO()
    assert check_paths([str(workspace)], out, err) == 0, out.getvalue() + err.getvalue()
    assert reads == Counter({"O0001.nc": 3, "O0002.nc": 3, "O9100.nc": 3, "O9200.nc": 4})


def test_a_scan_reads_each_file_once_and_a_second_scan_reads_them_again(workspace: Path, reads: Counter[str]) -> None:
    # the index's scan (the editor's start, or its folders changing) reads every program once;
    # scanned again after a file changed on disk, it holds the file's new text
    index = WorkspaceIndex(lambda: [], lambda lines, path: get_dialect("fanuc"))
    assert index.scan([str(workspace)]) == 4
    assert reads == Counter({"O0001.nc": 1, "O0002.nc": 1, "O9100.nc": 1, "O9200.nc": 1})
    (workspace / "O9200.nc").write_text("O9200\n#101=2\n#102=3\nM99\n", encoding="utf-8")
    assert index.scan([str(workspace)]) == 4
    assert reads["O9200.nc"] == 2 and index.files[str(workspace / "O9200.nc")].lines[2] == "#102=3"
