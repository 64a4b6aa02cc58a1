"""The open documents: each one a ``ParsedDocument`` kept up to date by incremental edits.

The ``ParsedDocument`` is the analysis's own (``WorkspaceAnalysis.document``), so each open
document is parsed once. An editor change is applied through the analysis, which edits the
cached parser in place (only the touched lines are parsed again);
the document's dialect is chosen again only when an edit touches the first lines, where the
``(cncmacro: dialect=...)`` comment lives. Each file is read with its own machine file
(``library/machine_files.py``: the nearest ``.cncmacro.toml`` above it), which is where its dialect
chain starts after its comment. Requests read single lines and blocks from here and
never rebuild the text.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from urllib.parse import quote, unquote_to_bytes, urlsplit

from lsprotocol import types
from pygls.uris import from_fs_path, to_fs_path

from ..analysis.indexes.block_memo import BlockMemo
from ..analysis.indexes.site_index import SiteIndex
from ..dialects.dialect import Dialect
from ..library.dialect_choice import HEADER_LINES
from ..library.machine_file import CallCode, MachineSettings
from ..library.machine_files import MachineFiles
from ..library.profiles import file_profile, profile_source
from ..library.programs import LoadedFile
from ..syntax.document import ParsedDocument, split_lines
from ..syntax.nodes import Block
from .positions import UTF16, Encoding


def uri_to_path(uri: str) -> str:
    """The file path of a ``file:`` URI (other schemes keep the URI itself). A NUL (``%00``)
    cannot be in a real file's path, and the system refuses every call with one: it stays
    written as ``%00``, so the document is analysed as the unsaved text it is. Percent-encoded
    bytes that are not UTF-8 (a GBK file name, as ``path_to_uri`` writes it) are the name's
    bytes, as the system gives them."""
    path = to_fs_path(uri) or uri
    if "\ufffd" in path and os.name == "posix" and uri[:5].lower() == "file:":
        raw = unquote_to_bytes(urlsplit(uri).path)
        try:
            raw.decode("utf-8")
        except UnicodeDecodeError:
            path = os.fsdecode(raw)
    return path.replace("\x00", "%00")


def path_to_uri(path: str) -> str:
    """The ``file:`` URI of a path; a name that is not UTF-8 (surrogate escapes) keeps its
    bytes, percent-encoded, so that ``uri_to_path`` gives the same path back."""
    try:
        return from_fs_path(path) or path
    except UnicodeEncodeError:
        return "file://" + quote(os.fsencode(path))


# an applied edit: (start line, start column, end line, end column, new text) in code points
Edit = tuple[int, int, int, int, str]


@dataclass
class OpenDocument:
    """One document open in the editor."""

    uri: str
    path: str
    version: int
    parsed: ParsedDocument
    dialect: Dialect
    sites: SiteIndex
    machine_file: Path | None = None  # the .cncmacro.toml it is read and analysed with

    @property
    def lines(self) -> list[str]:
        return self.parsed.lines

    def line(self, i: int) -> str:
        return self.parsed.lines[i] if 0 <= i < len(self.parsed.lines) else ""

    def block(self, i: int) -> Block | None:
        return self.parsed.block_at(i) if 0 <= i < len(self.parsed.lines) else None

    def as_loaded(self) -> LoadedFile:
        """The document as the program library sees a file (no copy of the text is made)."""
        return LoadedFile(self.path, self.parsed.lines, self.parsed.program, self.dialect.name)

    @property
    def folder(self) -> Path:
        return Path(self.path).parent


class Documents:
    """The open documents by URI, and the dialect choice: the machine files and the editor's
    setting."""

    def __init__(self) -> None:
        self.by_uri: dict[str, OpenDocument] = {}
        self.machines = MachineFiles()  # the .cncmacro.toml of each file
        self.setting_dialect: str | None = None  # from the editor's settings
        self.encoding: Encoding = UTF16  # the client's columns, agreed at initialize
        # what each block says by itself, shared by the documents' site indexes and static checks
        self.block_memo = BlockMemo()

    def reading_rule(self) -> tuple[str | None, int]:
        """What ``dialect_for`` and ``calls_for`` answer by besides a file's own text: the
        editor's dialect setting and the machine files as last read (``MachineFiles.generation``)."""
        return self.setting_dialect, self.machines.generation

    def dialect_for(self, lines: list[str], path: str) -> Dialect:
        """The dialect of the file at ``path`` with these lines, under its machine file."""
        return file_profile(lines, self.machines.settings_for(path), self.setting_dialect)

    def dialect_source(self, doc: OpenDocument) -> str:
        """Which link of the dialect chain decided for ``doc`` (``profile_source``)."""
        return profile_source(doc.parsed.lines, self.machines.settings(doc.machine_file), self.setting_dialect)

    def calls_for(self, path: str) -> dict[str, CallCode] | None:
        """The call codes of the machine file that the file at ``path`` is read with, if any."""
        machine = self.machines.settings_for(path)
        return machine.calls if machine is not None else None

    def machine_file_of(self, path: str) -> Path | None:
        """The machine file that ``path`` (a file or folder) is read with."""
        machines = self.machines
        return machines.path_in(path) if os.path.isdir(path) else machines.path_for(path)

    def extensions_for(self, path: str) -> frozenset[str]:
        """The endings of program files that the machine file of ``path`` (a file or folder) adds."""
        machine = self.machines.settings(self.machine_file_of(path))
        return machine.extensions if machine is not None else frozenset()

    def machine(self, doc: OpenDocument) -> MachineSettings | None:
        """The settings of ``doc``'s machine file (None: it has none, or a broken one)."""
        return self.machines.settings(doc.machine_file)

    def open(self, item: types.TextDocumentItem, parsed: ParsedDocument | None = None) -> OpenDocument:
        """Open ``item``; ``parsed`` is its text already parsed (by the analysis)."""
        parsed = parsed if parsed is not None else ParsedDocument(item.text)
        path = uri_to_path(item.uri)
        machine_file = self.machines.path_for(path)
        dialect = self.dialect_for(parsed.lines, path)
        doc = OpenDocument(
            item.uri,
            path,
            item.version,
            parsed,
            dialect,
            SiteIndex(parsed.blocks, dialect, self.calls_for(path), self.block_memo, parsed.partial),
            machine_file,
        )
        self.by_uri[item.uri] = doc
        return doc

    def moved(self, doc: OpenDocument, parsed: ParsedDocument, machine_file: Path | None) -> None:
        """``doc`` is now read with ``machine_file``, its text parsed anew in ``parsed`` (by the
        analysis of that machine file)."""
        doc.parsed, doc.machine_file = parsed, machine_file
        doc.dialect = self.dialect_for(parsed.lines, doc.path)
        doc.sites = SiteIndex(parsed.blocks, doc.dialect, self.calls_for(doc.path), self.block_memo)

    def change(
        self, params: types.DidChangeTextDocumentParams, apply: Callable[[OpenDocument, Edit], None] | None = None
    ) -> OpenDocument | None:
        """Apply an editor change; each edit (code-point columns, lines clamped to the text; a
        whole new text is an edit of the whole range) goes through ``apply``, which must edit
        ``doc.parsed`` (by default it is edited directly)."""
        doc = self.by_uri.get(params.text_document.uri)
        if doc is None:
            return None
        header_touched = False
        for change in params.content_changes:
            lines = doc.parsed.lines
            if isinstance(change, types.TextDocumentContentChangePartial):
                r = change.range
                sl = min(max(r.start.line, 0), len(lines) - 1)
                el = min(max(r.end.line, sl), len(lines) - 1)
                columns = self.encoding.to_code_points
                sc = columns(lines[sl], r.start.character) if r.start.line < len(lines) else 1 << 30
                ec = columns(lines[el], r.end.character) if r.end.line < len(lines) else 1 << 30
                sc = min(sc, len(lines[sl]))
                ec = min(ec, len(lines[el])) if el > sl else max(min(ec, len(lines[el])), sc)
                edit: Edit = (sl, sc, el, ec, change.text)
                header_touched = header_touched or r.start.line < HEADER_LINES
            else:
                edit = (0, 0, len(lines) - 1, len(lines[-1]), change.text)
                header_touched = True
            if apply is None:
                doc.parsed.apply_change(*edit)
            else:
                apply(doc, edit)
            if isinstance(change, types.TextDocumentContentChangePartial) and not doc.parsed.partial:
                doc.sites.replaced(doc.parsed.blocks, edit[0], edit[2] + 1, len(split_lines(change.text)))
            else:
                doc.sites = SiteIndex(
                    doc.parsed.blocks, doc.dialect, doc.sites.calls, self.block_memo, doc.parsed.partial
                )
        doc.version = params.text_document.version
        if header_touched:
            self._set_dialect(doc)
        return doc

    def _set_dialect(self, doc: OpenDocument) -> None:
        """Choose the document's dialect again; its jumps change with the dialect and the machine
        file's call codes (``machine/jump_words.py``)."""
        doc.dialect = self.dialect_for(doc.parsed.lines, doc.path)
        calls = self.calls_for(doc.path)
        if not doc.sites.reads_with(doc.dialect, calls):
            doc.sites = SiteIndex(doc.parsed.blocks, doc.dialect, calls, self.block_memo, doc.parsed.partial)

    def close(self, uri: str) -> OpenDocument | None:
        return self.by_uri.pop(uri, None)

    def get(self, uri: str) -> OpenDocument | None:
        """The open document ``uri``, or None: a request about a document that is not open (a
        client racing a close, a peek into a file it never opened) is answered with the
        method's empty result (``null``), quietly, by every feature that asks here."""
        return self.by_uri.get(uri)

    def rechoose_dialects(self) -> None:
        for doc in self.by_uri.values():
            self._set_dialect(doc)
