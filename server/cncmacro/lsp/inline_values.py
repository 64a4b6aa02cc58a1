"""Inline values while a debug session is paused: ``textDocument/inlineValue`` names, on each line
of the asked range, every variable the line reads or writes (``#100``, ``#[#1+2]``, ``#_NAME``)
as an expression for the editor to evaluate in the paused frame. VS Code hands each to the
debug adapter's ``evaluate`` (the interpreter's expression compiler, ``machine.evaluate``;
nothing is run as Python) and shows ``#100 = 6.5`` at the end of the line. The expressions come
from the syntax tree of each line (``syntax.walk``), in source order, each once per line; a line
of plain words (most of a CAM program) has no variable and is not walked."""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..syntax.nodes import IndirectVar, NamedVar, Var
from ..syntax.walk import iter_nodes

if TYPE_CHECKING:
    from .server import CncMacroServer

MAX_LINES = 2000  # a range longer than this is cut (an editor asks for what it shows)


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_INLINE_VALUE)
    def inline_value(ls: CncMacroServer, params: types.InlineValueParams) -> list[types.InlineValue]:
        doc = ls.documents.get(params.text_document.uri)
        encoding = ls.documents.encoding
        out: list[types.InlineValue] = []
        first = max(params.range.start.line, 0)
        last = min(params.range.end.line, len(doc.lines) - 1, first + MAX_LINES - 1)
        for line in range(first, last + 1):
            block = doc.block(line)
            if block is None or block.plain is not None:
                continue
            text = doc.line(line)
            seen: set[str] = set()
            for node in iter_nodes(block):
                if not isinstance(node, (Var, IndirectVar, NamedVar)):
                    continue
                expression = text[node.start : node.end]
                if expression in seen:
                    continue
                seen.add(expression)
                where = types.Range(
                    types.Position(line, encoding.to_client(text, node.start)),
                    types.Position(line, encoding.to_client(text, node.end)),
                )
                out.append(types.InlineValueEvaluatableExpression(range=where, expression=expression))
        return out
