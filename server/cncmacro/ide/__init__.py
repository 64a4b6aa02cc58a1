"""The editor's features without the protocol: each module answers one question an editor asks
(what folds, the outline, the uses of the name under the cursor, the variables of a line) as a
plain function over a document (``source.EditorDocument``) and the analysis, and returns plain
data: small frozen dataclasses whose positions are lines and code-point columns
(``spans.py``), or the analysis's own types. Nothing here imports pygls or lsprotocol; the
language server (``lsp/``) registers the handlers, turns the protocol's parameters into these
arguments and the answers into the protocol's types, its columns through ``lsp/positions.py``.
"""
