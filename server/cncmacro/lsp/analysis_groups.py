"""The language server's analyses: one ``WorkspaceAnalysis`` per machine file in use.

As ``cncmacro check`` makes one analysis per group of files, each open document is in the
analysis of its own machine file (``OpenDocument.machine_file``, the nearest ``.cncmacro.toml``
above it; None for the defaults), which holds it: the server's ``Documents`` show its
``ParsedDocument``, so each document is parsed once. With one machine file there is one
analysis. A call in an analysis looks for its program in the folders of the workspace's program
files read with its machine file (the workspace index's ``callee_folders``, the rule
``cncmacro check`` follows). Each analysis has its machine file's settings with the editor's over them
(``options``); every one reads the files on disk through the workspace index's cache. A
machine file created, changed or deleted moves the documents whose nearest one changed to the
analysis of their new one (``regroup``). An analysis left without documents goes, but the last
one, which keeps what it knows of the workspace for the next document.

Nothing here takes the analysis lock: the diagnostics engine (``diagnostics.py``) calls these
inside its ``editing()``, or on the worker thread that holds the lock.
"""

from __future__ import annotations

from collections.abc import Callable, Container, Iterator
from pathlib import Path
from typing import Any

from ..analysis.warm_up import warm_up
from ..analysis.workspace import WorkspaceAnalysis
from ..library.file_cache import FileCache
from .disk_watch import DiskStamps
from .documents import Documents, OpenDocument
from .settings import Settings, merged_severities, valid_severities


class AnalysisGroups:
    """See the module docstring."""

    def __init__(
        self, documents: Documents, files: FileCache, callee_folders: Callable[[Path | None], list[str]]
    ) -> None:
        self.documents = documents
        self._files = files
        self._callee_folders = callee_folders  # where a call looks beyond its file's folder, per machine file
        self._folders: list[str] = []
        self.locale = "en"
        self.editor = Settings()  # the editor's settings in force
        self.analyses: dict[Path | None, WorkspaceAnalysis] = {None: self._made(None)}

    def _made(self, machine_file: Path | None) -> WorkspaceAnalysis:
        return WorkspaceAnalysis(search_paths=self._callee_folders(machine_file), workspace_folders=self._folders,
                                 locale=self.locale, files=self._files, memo=self.documents.block_memo)  # fmt: skip

    def _find_callees(self) -> None:
        """Program files came, went or moved to another machine file: each analysis's calls look
        in the folders of its machine's programs as they are now."""
        for machine_file, analysis in self.analyses.items():
            analysis.set_search_paths(self._callee_folders(machine_file))

    def start(self, machine_file: Path | None, folders: list[str], locale: str) -> None:
        """A fresh analysis for the session (at ``initialize``, before any document opens), for
        ``machine_file`` (the first workspace folder's)."""
        self._folders, self.locale = list(folders), locale
        self.analyses = {}
        self.of(machine_file)

    def warm_up(self) -> None:
        """Analyse a short program under the settings of the session's first analysis
        (``analysis/warm_up.py``): at ``initialize``, once the editor's settings apply."""
        for analysis in self.analyses.values():
            warm_up(analysis.settings, analysis.dialect_setting, self.locale)
            return

    def configure(self, editor: Settings) -> None:
        """The editor's settings, or a machine file, changed: each analysis gets its machine
        file's settings and the editor's again."""
        self.editor = editor
        for machine_file, analysis in self.analyses.items():
            analysis.configure(**self.options(machine_file))

    def options(self, machine_file: Path | None) -> dict[str, Any]:
        """The settings of the analysis of ``machine_file``: the file's, and the editor's over them."""
        machine = self.documents.machines.settings(machine_file)
        editor = self.editor
        severities = valid_severities(merged_severities(machine, editor))
        return {
            "settings": machine,
            "dialect": editor.dialect,
            "max_blocks": editor.run_budget,
            "severities": severities,
        }

    def __getitem__(self, machine_file: Path | None) -> WorkspaceAnalysis:
        """The analysis of the documents read with ``machine_file`` (one of them is open)."""
        return self.analyses[machine_file]

    def __iter__(self) -> Iterator[WorkspaceAnalysis]:
        return iter(self.analyses.values())

    def of(self, machine_file: Path | None) -> WorkspaceAnalysis:
        """The analysis of the documents read with ``machine_file`` (made at the first one)."""
        analysis = self.analyses.get(machine_file)
        if analysis is None:
            for unused in [k for k, a in self.analyses.items() if not a.docs]:
                del self.analyses[unused]  # the one kept when its last document left, say
            analysis = self.analyses[machine_file] = self._made(machine_file)
            analysis.configure(**self.options(machine_file))
        return analysis

    def left(self, machine_file: Path | None) -> None:
        """A document left the analysis of ``machine_file``: without documents, it goes (but the
        last one, which keeps what it knows of the workspace for the next document)."""
        analysis = self.analyses.get(machine_file)
        if analysis is not None and not analysis.docs and len(self.analyses) > 1:
            del self.analyses[machine_file]

    def regroup(self, reading: Container[str]) -> list[str]:
        """Machine files changed on disk: each open document whose nearest one is another now
        moves to that one's analysis, with its text and version (one being read, ``reading``,
        only notes it: it is handed to its analysis once read). The paths of those moved."""
        documents = self.documents
        documents.machines.forget()
        self._find_callees()
        moved = []
        for doc in documents.by_uri.values():
            machine_file = documents.machines.path_for(doc.path)
            if doc.uri in reading:  # read with the machine file it has once read in full
                doc.machine_file = machine_file
                continue
            if machine_file == doc.machine_file:
                continue
            before = doc.machine_file
            self.analyses[before].close(doc.path)
            self._hand_over(doc, doc.parsed.text, machine_file)
            self.left(before)
            moved.append(doc.path)
        return moved

    def opened(self, doc: OpenDocument) -> None:
        """``doc``, read in full, joins the analysis of its machine file, which parses it."""
        self._hand_over(doc, doc.parsed, doc.machine_file)

    def _hand_over(self, doc: OpenDocument, text: Any, machine_file: Path | None) -> None:
        analysis = self.of(machine_file)
        analysis.open(doc.path, text, doc.version)
        parsed = analysis.document(doc.path)
        assert parsed is not None
        self.documents.moved(doc, parsed, machine_file)

    def files_changed(self, paths: list[str]) -> None:
        """Files changed on disk (created, changed, deleted)."""
        self._find_callees()
        for analysis in self.analyses.values():
            for path in paths:
                analysis.file_changed(path)

    def folders_changed(self, folders: list[str]) -> None:
        """The editor's workspace folders changed: callers are looked for in the new ones."""
        self._folders = list(folders)
        self._find_callees()
        for analysis in self.analyses.values():
            analysis.set_workspace_folders(folders)

    def record_reads(self, disk: DiskStamps, started: int) -> None:
        """Keep the stamps of the files the analyses have read from disk (not their open ones)."""
        libraries: list[object] = []
        paths: list[str] = []
        for analysis in self.analyses.values():
            files, folders = analysis.library.read_from_disk()
            own = analysis.docs
            paths += [*(f for f in files if f not in own), *folders]
            libraries.append(analysis.library)
        disk.record(libraries, list(dict.fromkeys(paths)), started)
