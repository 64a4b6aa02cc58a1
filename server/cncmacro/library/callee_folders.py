"""The folders a call is looked up in beyond the calling file's own: one machine's program folders.

A control holds all its programs in one memory, so ``G65 P5100`` in ``main/O1000.nc`` runs
``O5100`` wherever the shop keeps that file beside it (``macros/O5100.nc``). The programs of one
machine are the program files read with one machine file (the nearest ``.cncmacro.toml``,
``machine_file.find_machine_file``): a call finds a program in the folder of any of them, after
the extra folders a person names (``cncmacro check --path``). A folder whose files are read with
another machine file (a sub-folder with its own ``.cncmacro.toml``) holds another machine's
programs and is never searched from outside it. ``cncmacro check`` gives the files it checks;
the language server gives the files of its workspace index, a search bounded by
``files.MAX_PROGRAM_FILES`` and ``files.MAX_FOLDER_ENTRIES``.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from pathlib import Path

__all__ = ["callee_folders"]


def callee_folders(extra: Sequence[str | Path], program_files: Iterable[str | Path]) -> list[str]:
    """The folders a call is looked up in after the calling file's own: ``extra`` first, then the
    folder of each of ``program_files`` (one machine's), in the order first met, each once."""
    folders = [str(f) for f in extra]
    folders += (str(Path(p).parent) for p in program_files)
    return [*dict.fromkeys(folders)]
