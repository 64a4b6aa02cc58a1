"""docs/debugging.md: the adapter builds the grammar parser when the client initializes, so the
first watch or console line that the fast path cannot read (``GOTO10``, an unfinished ``#1 GT``)
is answered at once, not after the parser is built (about 70–200 ms)."""

from __future__ import annotations

import io

import pytest

from cncmacro.dap.protocol import MessageWriter, Request
from cncmacro.dap.session import Session
from cncmacro.syntax import block_parser


def test_initialize_builds_the_grammar_parser(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(block_parser, "_idle", [])  # no parser built yet in this process
    session = Session(MessageWriter(io.BytesIO()))
    session.handle(Request(1, "initialize", {"adapterID": "cnc-macro"}))
    assert session.warming is not None
    session.warming.join(30)
    assert len(block_parser._idle) == 1  # one parser, ready for the first evaluate
