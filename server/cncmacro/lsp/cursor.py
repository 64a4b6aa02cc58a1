"""The place a request points at: the document, the line, the code-point column and the block.

Every position-based request starts here; only the line under the cursor is read.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from lsprotocol import types

from ..syntax.nodes import Block
from .documents import OpenDocument
from .positions import Encoding

if TYPE_CHECKING:
    from .server import CncMacroServer


@dataclass(slots=True)
class Cursor:
    doc: OpenDocument
    line: int
    column: int
    text: str
    block: Block
    encoding: Encoding

    def range(self, start: int, end: int, line: int | None = None) -> types.Range:
        """A client range for code-point columns on ``line`` (the cursor's line by default)."""
        if line is None:
            return self.encoding.range(self.line, self.text, start, end)
        return self.encoding.range(line, self.doc.line(line), start, end)


def cursor_at(server: CncMacroServer, uri: str, position: types.Position) -> Cursor | None:
    doc = server.documents.get(uri)
    if doc is None:  # not open: every request on a cursor answers null (documents.py)
        return None
    block = doc.block(position.line)
    if block is None:
        return None
    text = doc.line(position.line)
    encoding = server.documents.encoding
    return Cursor(doc, position.line, encoding.to_code_points(text, position.character), text, block, encoding)


def doc_range(doc: OpenDocument, line: int, start: int, end: int, encoding: Encoding) -> types.Range:
    """The client range of code-point columns ``start``..``end`` on ``line`` of ``doc``."""
    return encoding.range(line, doc.line(line), start, end)
