"""The machine files of a session over workspace folders (the language server's): which
``.cncmacro.toml`` each file is read with, and what each one says.

The rule is ``cncmacro check``'s and ``cncmacro run``'s: a file in a workspace folder is read with
the nearest ``.cncmacro.toml`` above it (``library.machine_file.find_machine_file``), none
meaning the defaults (in a session without workspace folders, every file). A file outside every
workspace folder, or a document that is no file on disk (an unsaved one), is read with the first
workspace folder's. Where the nearest one is, is kept per folder (a file that is a link is
looked up by itself, as ``find_machine_file`` follows it), and each machine file is read once;
both are forgotten when any machine file changes on disk (``forget``), where the nearest
one is also when the workspace folders change (``set_roots``). A machine file that cannot be
used is kept with its problem, never raised: the files below it get the defaults, and the
language server shows the problem on it (``lsp/reports.py``).
"""

from __future__ import annotations

import logging
import os
from dataclasses import dataclass
from pathlib import Path

from ..bilingual import detail
from .files import stays_inside
from .machine_file import MachineFileError, MachineSettings, find_machine_file, load_machine_file

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class MachineFileState:
    """One machine file: where it is (None: there is none), its settings (None when there is
    none or it cannot be used) and what is wrong with it."""

    path: Path | None = None
    settings: MachineSettings | None = None
    problem: MachineFileError | None = None


def read_machine_file(path: Path | None) -> MachineFileState:
    """The machine file at ``path``; a broken one is logged and kept with its problem."""
    if path is None:
        return MachineFileState()
    try:
        return MachineFileState(path, load_machine_file(path))
    except MachineFileError as e:
        log.warning("%s", e)
        return MachineFileState(path, None, e)
    except Exception as e:  # a fault of the checker must not stop the server either
        log.exception("reading %s failed", path)
        return MachineFileState(path, None, MachineFileError(detail(f"{path}: cannot be used ({e!r})",
                                                                    f"{path}：无法使用（{e!r}）")))  # fmt: skip


class MachineFiles:
    """See the module docstring. Used from the editor's thread (the analysis thread reads the
    settings it was given, not this)."""

    def __init__(self) -> None:
        self.roots: list[Path] = []  # the workspace folders
        self.generation = 0  # counts the times what it knew was dropped (``set_roots``, ``forget``)
        self._nearest: dict[str, Path | None] = {}  # a folder (or a linked file) -> its machine file
        self._read: dict[Path, MachineFileState] = {}

    def set_roots(self, roots: list[str]) -> None:
        """The workspace folders (at ``initialize``, and when the editor's change)."""
        self.roots = [Path(r) for r in roots if r]
        self._nearest.clear()
        self.generation += 1

    def path_for(self, file: str) -> Path | None:
        """The machine file that ``file`` (a path, or an unsaved document's URI) is read with."""
        if os.path.isabs(file):
            return self.path_in(file if os.path.islink(file) else os.path.dirname(file))
        return self.first()

    def first(self) -> Path | None:
        """The first workspace folder's machine file."""
        return self.path_in(str(self.roots[0])) if self.roots else None

    def path_in(self, key: str) -> Path | None:
        """The machine file of the files in the folder ``key`` (or of the file ``key``)."""
        if key not in self._nearest:
            inside = any(stays_inside(Path(key), root) for root in self.roots)
            if inside or not self.roots:
                self._nearest[key] = find_machine_file(key)
            else:
                self._nearest[key] = self.first()
        return self._nearest[key]

    def state(self, path: Path | None) -> MachineFileState:
        """What the machine file at ``path`` says (read the first time it is asked for)."""
        if path is None:
            return MachineFileState()
        got = self._read.get(path)
        if got is None:
            got = self._read[path] = read_machine_file(path)
        return got

    def settings(self, path: Path | None) -> MachineSettings | None:
        """The settings of the machine file at ``path`` (None: none there, or it is broken)."""
        return self.state(path).settings

    def settings_for(self, file: str) -> MachineSettings | None:
        """The settings ``file`` is read with."""
        return self.settings(self.path_for(file))

    def forget(self) -> None:
        """A machine file changed on disk: look for each and read each again when asked."""
        self._nearest.clear()
        self._read.clear()
        self.generation += 1
