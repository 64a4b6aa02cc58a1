"""Looking a program up by its number in a huge folder is bounded (docs/design.md, the program
library): a program whose file is named otherwise is searched for by its O header in at most
``MAX_PROGRAM_FILES`` files of the folder, a number searched for in vain is not searched for again
while the folder's listing stands (a hover on a call to a missing program in a folder of 100,000
files took 10 s every time), and a program written into an open document is found at once."""

from __future__ import annotations

import time
from pathlib import Path

from cncmacro.library.files import MAX_PROGRAM_FILES
from cncmacro.library.programs import ProgramLibrary


def _folder(tmp_path: Path, count: int) -> Path:
    folder = tmp_path / "library"
    folder.mkdir()
    for k in range(count):  # file names that name no program: only the headers say which
        (folder / f"P{k:06d}.nc").write_text(f"O{1000 + k % 8000}\nG01 X{k}. F100\nM99\n", encoding="utf-8")
    return folder


def test_a_missing_program_is_searched_for_in_a_bounded_number_of_files_and_once(tmp_path: Path, monkeypatch):
    folder = _folder(tmp_path, MAX_PROGRAM_FILES + 2_000)
    library = ProgramLibrary([folder])
    read: list[str] = []
    text = library.disk.text
    monkeypatch.setattr(library.disk, "text", lambda path: read.append(path) or text(path))
    assert library.find_number(9999) is None
    assert len(read) == MAX_PROGRAM_FILES  # not the 7,000 of the folder
    began = time.process_time()
    assert library.find_number(9999) is None
    assert len(read) == MAX_PROGRAM_FILES and time.process_time() - began < 0.05  # not searched again


def test_a_header_written_into_an_open_document_is_found_after_a_search_in_vain(tmp_path: Path):
    folder = _folder(tmp_path, 10)
    library = ProgramLibrary([folder])
    assert library.find_number(9999) is None
    library.add_text(str(folder / "NEW.nc"), "O9999\nM99\n")
    found = library.find_number(9999)
    assert found is not None and Path(found.file.path).name == "NEW.nc"


def test_a_file_event_outside_a_full_workspace_index_reads_nothing(tmp_path: Path):
    # a branch switch touches every file of a folder of 100,000: each event for a file the index
    # does not hold read and parsed it (about 14 ms each, 25 minutes in all) and grew the index
    from cncmacro.analysis.indexes.workspace_index import WorkspaceIndex
    from cncmacro.dialects import get_dialect

    folder = _folder(tmp_path, MAX_PROGRAM_FILES + 300)
    index = WorkspaceIndex(lambda: [], lambda lines, path: get_dialect("fanuc-0i"))
    assert index.scan([str(folder)]) == MAX_PROGRAM_FILES
    outside = sorted(str(p) for p in folder.iterdir() if str(p) not in index.files)
    assert len(outside) == 300
    began = time.process_time()  # the processor's time: the machine may be busy with other work
    for path in outside:
        assert index.reload(path) is None
    assert len(index.files) == MAX_PROGRAM_FILES and not any(p in index.files for p in outside)
    assert time.process_time() - began < 1.0  # 300 events; reading each took about 4 s
    inside = next(iter(index.files))
    Path(inside).write_text("O4321\nM99\n", encoding="utf-8")
    index.reload(inside)  # a file the index holds is read again
    assert index.files[inside].program.unit_numbered(4321) is not None
