"""A document as the editor layer reads it: its text, parse, profile and site index (the
language server's ``OpenDocument`` is one)."""

from __future__ import annotations

from typing import Protocol

from ..analysis.indexes.workspace_index import OpenFile
from ..dialects.dialect import Dialect
from ..syntax.nodes import Block


class EditorDocument(OpenFile, Protocol):
    """An open document: ``OpenFile`` (path, lines, parse, site index) with its profile."""

    @property
    def dialect(self) -> Dialect: ...

    def line(self, i: int) -> str:
        """The text of line ``i``, or "" past the document's end."""
        ...

    def block(self, i: int) -> Block | None:
        """The block of line ``i``, or None past the document's end."""
        ...
