"""An open document for the editor layer's tests, without a language server: the text parsed,
read with a profile, and its site index made (what ``lsp/documents.py`` keeps per document)."""

from __future__ import annotations

from dataclasses import dataclass

from cncmacro.analysis.indexes.site_index import SiteIndex
from cncmacro.dialects import Dialect, get_dialect
from cncmacro.library.programs import LoadedFile
from cncmacro.syntax.document import ParsedDocument
from cncmacro.syntax.nodes import Block


@dataclass
class Document:
    path: str
    parsed: ParsedDocument
    dialect: Dialect
    sites: SiteIndex

    @property
    def lines(self) -> list[str]:
        return self.parsed.lines

    def line(self, i: int) -> str:
        return self.parsed.lines[i] if 0 <= i < len(self.parsed.lines) else ""

    def block(self, i: int) -> Block | None:
        return self.parsed.block_at(i) if 0 <= i < len(self.parsed.lines) else None

    def as_loaded(self) -> LoadedFile:
        return LoadedFile(self.path, self.parsed.lines, self.parsed.program, self.dialect.name)


def document(*lines: str, profile: str = "fanuc", path: str = "/shop/part.nc") -> Document:
    """The document of ``lines``, read with ``profile``."""
    parsed = ParsedDocument("\n".join(lines))
    dialect = get_dialect(profile)
    return Document(path, parsed, dialect, SiteIndex(parsed.blocks, dialect))
