"""Inline values while a debug session is paused: on each line of a range, every variable the
line reads or writes (``#100``, ``#[#1+2]``, ``#_NAME``) as the expression an editor hands the
debug adapter to evaluate in the paused frame (``machine.evaluate``: nothing is run as Python),
showing ``#100 = 6.5`` at the end of the line. The expressions come from the syntax tree of each
line (``syntax.walk``), in source order, each once per line; a line of plain words (most of a
CAM program) has no variable and is not walked. A write-only variable (#3000) has no value to show
and is left out."""

from __future__ import annotations

from dataclasses import dataclass

from ..syntax.nodes import IndirectVar, NamedVar, Var
from ..syntax.walk import iter_nodes
from .source import EditorDocument
from .spans import Span

MAX_LINES = 2000  # a range longer than this is cut (an editor asks for what it shows)


@dataclass(frozen=True, slots=True)
class InlineExpression:
    """A variable written at ``span``, as the ``expression`` to evaluate."""

    span: Span
    expression: str


def inline_values(doc: EditorDocument, first: int, last: int) -> list[InlineExpression]:
    """The variables of lines ``first``..``last`` (within the document, and at most
    ``MAX_LINES`` of them), line by line."""
    first = max(first, 0)
    last = min(last, len(doc.lines) - 1, first + MAX_LINES - 1)
    out: list[InlineExpression] = []
    for line in range(first, last + 1):
        block = doc.block(line)
        if block is None or block.plain is not None:
            continue
        text = doc.line(line)
        seen: set[str] = set()
        for node in iter_nodes(block):
            if not isinstance(node, (Var, IndirectVar, NamedVar)) or _write_only(doc, node):
                continue
            expression = text[node.start : node.end]
            if expression not in seen:
                seen.add(expression)
                out.append(InlineExpression(Span(line, node.start, node.end), expression))
    return out


def _write_only(doc: EditorDocument, node: Var | IndirectVar | NamedVar) -> bool:
    """A variable that has no value to show: one the profile's table makes write-only (#3000,
    whose writing raises an alarm; a read of it is an error)."""
    if not isinstance(node, Var):
        return False
    row = doc.dialect.system_variable(node.number) if node.number >= 1000 else None
    return row is not None and row.access == "w"
