"""``build_server`` registers the editor's features from one list, ``lsp/server.py``'s ``FEATURES``
(ARCHITECTURE.md "A new LSP feature"): a module of ``lsp/`` that adds handlers and is missing from
it would answer nothing, and a name in it without its module would stop the server starting."""

from __future__ import annotations

import ast
from pathlib import Path

from cncmacro.lsp.server import FEATURES

LSP = Path(__file__).resolve().parents[2] / "server" / "cncmacro" / "lsp"


def _adds_handlers(tree: ast.Module) -> bool:
    """A module that defines ``register`` or calls a server's ``feature``/``command`` to add a handler."""
    if any(isinstance(n, ast.FunctionDef) and n.name == "register" for n in tree.body):
        return True
    return any(
        isinstance(n, ast.Call) and isinstance(n.func, ast.Attribute) and n.func.attr in ("feature", "command")
        for n in ast.walk(tree)
    )


def test_every_lsp_module_that_adds_handlers_is_in_the_feature_list() -> None:
    adding = {
        p.stem
        for p in LSP.glob("*.py")
        if p.name != "server.py" and _adds_handlers(ast.parse(p.read_text(encoding="utf-8"), filename=p.name))
    }
    listed = set(FEATURES)
    assert adding == listed, f"not in FEATURES: {adding - listed}; in FEATURES, adding no handler: {listed - adding}"
    assert len(FEATURES) == len(set(FEATURES))  # each registered once


def test_every_feature_of_the_list_has_its_register() -> None:
    for name in FEATURES:
        tree = ast.parse((LSP / f"{name}.py").read_text(encoding="utf-8"))
        assert any(isinstance(n, ast.FunctionDef) and n.name == "register" for n in tree.body), name
