"""Walking the syntax tree of one block: every node, or the nodes under a column.

Editors ask "what is at this column" and "where is every ``#100``"; both are answered from the
cached block of a line, without reading any other line.
"""

from __future__ import annotations

from collections.abc import Iterator

from .nodes import (
    Assign,
    Binary,
    Block,
    Bracket,
    CornerWord,
    Do,
    End,
    Expr,
    FunctionCall,
    Goto,
    If,
    IndirectVar,
    Item,
    NamedVar,
    Number,
    Output,
    Relation,
    Unary,
    Var,
    While,
    Word,
)

# Every node carries ``start`` and ``end``.
Node = Item | Expr


def children(node: Node) -> tuple[Node, ...]:
    """The direct children of a node, in source order."""
    if isinstance(node, (Number, Var)):
        return ()
    if isinstance(node, IndirectVar):
        return (node.index,)
    if isinstance(node, NamedVar):
        return (node.index,) if node.index is not None else ()
    if isinstance(node, Unary):
        return (node.operand,)
    if isinstance(node, (Binary, Relation)):
        return (node.left, node.right)
    if isinstance(node, Bracket):
        return (node.inner,)
    if isinstance(node, FunctionCall):
        return node.args
    if isinstance(node, Word):
        return (node.value,) if node.value is not None else ()
    if isinstance(node, CornerWord):
        return (node.value,)
    if isinstance(node, Assign):
        return (node.target, node.value)
    if isinstance(node, If):
        if node.m99 is not None:  # [cond] M99 P n: the P word holds the target
            return (node.condition, *node.m99)
        rest = node.goto if node.goto is not None else node.then
        return (node.condition, rest) if rest is not None else (node.condition,)
    if isinstance(node, While):
        return (node.condition, node.loop)
    if isinstance(node, (Do, End)):
        return (node.loop,)
    if isinstance(node, Goto):
        return (node.target,)
    if isinstance(node, Output):
        return tuple(p.variable for p in node.parts if p.variable is not None)
    return ()


def iter_nodes(block: Block) -> Iterator[Node]:
    """Every node of the block's words and statements, parents before children."""
    stack: list[Node] = [*reversed(block.statements), *reversed(block.corners), *reversed(block.words)]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(reversed(children(node)))


def nodes_at(block: Block, column: int) -> list[Node]:
    """The nodes whose range holds ``column`` (or ends right at it), outermost first."""
    path: list[Node] = []
    level: tuple[Node, ...] = (*block.words, *block.corners, *block.statements)
    while True:
        hit = None
        for node in level:
            if node.start <= column < node.end:
                hit = node
                break
        if hit is None:
            for node in level:
                if node.end == column:
                    hit = node
                    break
        if hit is None:
            return path
        path.append(hit)
        level = children(hit)
