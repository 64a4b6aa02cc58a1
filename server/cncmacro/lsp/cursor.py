"""The place a request points at: the document, the line, the code-point column and the block.

Every position-based request starts here; only the line under the cursor is read.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from lsprotocol import types

from ..syntax.nodes import Block
from .documents import OpenDocument
from .positions import to_client, to_code_points

if TYPE_CHECKING:
    from .server import CncMacroServer


@dataclass(slots=True)
class Cursor:
    doc: OpenDocument
    line: int
    column: int
    text: str
    block: Block
    utf16: bool

    def range(self, start: int, end: int, line: int | None = None) -> types.Range:
        """A client range for code-point columns on ``line`` (the cursor's line by default)."""
        ln = self.line if line is None else line
        text = self.text if line is None else self.doc.line(ln)
        return types.Range(
            types.Position(ln, to_client(text, start, self.utf16)), types.Position(ln, to_client(text, end, self.utf16))
        )


def cursor_at(server: CncMacroServer, uri: str, position: types.Position) -> Cursor | None:
    doc = server.documents.get(uri)
    block = doc.block(position.line)
    if block is None:
        return None
    text = doc.line(position.line)
    col = to_code_points(text, position.character, server.documents.utf16)
    return Cursor(doc, position.line, col, text, block, server.documents.utf16)


def doc_range(doc: OpenDocument, line: int, start: int, end: int, utf16: bool) -> types.Range:
    text = doc.line(line)
    return types.Range(
        types.Position(line, to_client(text, start, utf16)), types.Position(line, to_client(text, end, utf16))
    )
