"""The tokens of a block's code as the block grammar's own lexer cuts them (``block.lark``, the
contextual lexer of its LALR parser): what the formatter rewrites, so that it never guesses where
a word, a keyword or a string starts. The code is a prepared line (``lines.prepare``: comments,
``;`` and a block delete already blanked out), columns are the line's own.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass

from lark import Lark, LarkError

from .grammar import _load_grammar


@dataclass(frozen=True, slots=True)
class CodeToken:
    """A terminal of the grammar: ``kind`` is its name in ``block.lark`` (``LETTER``, ``NUMBER``,
    ``VARNUM``, ``GOTO``, ``RELOP``, ``DPRNT_ARGS``, …), ``text`` as written."""

    kind: str
    text: str
    start: int
    end: int


_lexer: Lark | None = None
_lock = threading.Lock()


def code_tokens(code: str) -> list[CodeToken] | None:
    """The tokens of ``code`` in order, or None when the grammar does not read it."""
    global _lexer
    with _lock:
        if _lexer is None:
            _lexer = Lark(_load_grammar(), parser="lalr", lexer="contextual", maybe_placeholders=False)
        try:
            return [
                CodeToken(t.type, str(t), t.start_pos or 0, t.end_pos or 0)
                for t in _lexer.parse_interactive(code).iter_parse()
            ]
        except (LarkError, RecursionError):
            return None
