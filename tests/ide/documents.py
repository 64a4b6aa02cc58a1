"""An open document for the editor layer's tests, without a language server: the text parsed,
read with a profile, and its site index made, as ``lsp/documents.py``'s ``OpenDocument``."""

from __future__ import annotations

from cncmacro.analysis.indexes.site_index import SiteIndex
from cncmacro.dialects import get_dialect
from cncmacro.lsp.documents import OpenDocument
from cncmacro.syntax.document import ParsedDocument


def document(*lines: str, profile: str = "fanuc", path: str = "/shop/part.nc") -> OpenDocument:
    """The document of ``lines``, read with ``profile``: the language server's own kind of open
    document, made without a server."""
    parsed = ParsedDocument("\n".join(lines))
    dialect = get_dialect(profile)
    sites = SiteIndex(parsed.blocks, dialect)
    return OpenDocument(uri="file://" + path, path=path, version=1, parsed=parsed, dialect=dialect, sites=sites)
