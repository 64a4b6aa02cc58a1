"""Columns in the position encoding agreed at ``initialize`` (docs/design.md, "Position
encodings"): the server picks from the client's ``general.positionEncodings`` the one it converts
cheapest (``utf-32``, then ``utf-16``, then ``utf-8``; ``utf-16`` when none is offered), reports it,
and reads and writes every column in it. Each feature is checked in the three encodings on lines
where they all differ: a Chinese comment, an emoji (outside the Basic Multilingual Plane) and a
tab before the code. The client here counts columns as a real one does: in the encoding the
server reported."""

from __future__ import annotations

from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient, client_capabilities

from .lsp_session import accept_registrations, close_file, config, diagnostics_for, open_file, published_where

pytestmark = pytest.mark.asyncio(loop_scope="module")

PREFIX = "(中文🔧)\t"  # 6 code points, 7 UTF-16 units, 13 UTF-8 bytes
CODECS = {"utf-8": ("utf-8", 1), "utf-16": ("utf-16-le", 2), "utf-32": ("utf-32-le", 4)}

# what the client offers -> what the server must pick
OFFERS: dict[str, list[str] | None] = {
    "utf-8": ["utf-8"],
    "utf-16": ["utf-8", "utf-16"],
    "utf-32": ["utf-8", "utf-16", "utf-32"],  # Neovim's and Helix's list
}


def capabilities(offer: list[str] | None) -> types.ClientCapabilities:
    """VS Code's capabilities, offering the encodings ``offer`` (none at all for ``None``)."""
    caps = client_capabilities("visual-studio-code")
    caps.general = types.GeneralClientCapabilities(position_encodings=offer)
    return caps


def col(text: str, cp: int, kind: str) -> int:
    """The column in encoding ``kind`` of code-point column ``cp`` of ``text`` (the client's count)."""
    codec, unit = CODECS[kind]
    return len(text[:cp].encode(codec)) // unit


def span(line: int, text: str, word: str, kind: str, nth: int = 0) -> tuple[int, int, int]:
    """(line, start, end) in encoding ``kind`` of the ``nth`` occurrence of ``word`` in ``text``."""
    at = -1
    for _ in range(nth + 1):
        at = text.index(word, at + 1)
    return line, col(text, at, kind), col(text, at + len(word), kind)


def where(r: types.Range) -> tuple[int, int, int]:
    assert r.start.line == r.end.line
    return r.start.line, r.start.character, r.end.character


@pytest_lsp.fixture(config=config(), scope="module", params=list(OFFERS))
async def client(lsp_client: LanguageClient, request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    root = tmp_path_factory.mktemp(f"enc_{request.param}")
    accept_registrations(lsp_client)
    result = await lsp_client.initialize_session(
        types.InitializeParams(
            capabilities=capabilities(OFFERS[request.param]),
            root_uri=root.as_uri(),
            workspace_folders=[types.WorkspaceFolder(uri=root.as_uri(), name=root.name)],
            locale="en",
        )
    )
    lsp_client.expected = request.param  # type: ignore[attr-defined]
    lsp_client.kind = str(result.capabilities.position_encoding or "utf-16")  # type: ignore[attr-defined]
    lsp_client.root = root  # type: ignore[attr-defined]
    yield
    await lsp_client.shutdown_session()


def setup(client: LanguageClient) -> tuple[str, Path]:
    """The encoding the server reported (the session's own) and the workspace folder."""
    assert client.kind == client.expected  # type: ignore[attr-defined]
    return client.kind, client.root  # type: ignore[attr-defined]


async def hover(client: LanguageClient, uri: str, line: int, character: int) -> types.Hover | None:
    return await client.text_document_hover_async(
        types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(line, character))
    )


async def test_hover_inside_a_variable_after_chinese_an_emoji_and_a_tab(client: LanguageClient) -> None:
    kind, root = setup(client)
    text = f"{PREFIX}#100=1"
    uri = open_file(client, root / "HOVER.nc", f"O0001\n{text}\nM30\n")
    line, start, end = span(1, text, "#100", kind)
    got = await hover(client, uri, 1, start + 2)
    close_file(client, uri)
    assert got is not None and isinstance(got.contents, types.MarkupContent)
    assert "#100" in got.contents.value and "common variable" in got.contents.value.lower()
    assert got.range is not None and where(got.range) == (line, start, end)


async def test_an_edit_after_chinese_an_emoji_and_a_tab_lands_where_the_editor_made_it(
    client: LanguageClient,
) -> None:
    kind, root = setup(client)
    text = f"{PREFIX}#100=1"
    uri = open_file(client, root / "EDIT.nc", f"O0001\n{text}\nM30\n")
    await diagnostics_for(client, uri, 1)
    _, start, end = span(1, text, "1", kind, nth=1)  # the final 1 (after the one of #100)
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(uri=uri, version=2),
            [types.TextDocumentContentChangePartial(
                range=types.Range(types.Position(1, start), types.Position(1, end)), text="#101")],
        )
    )  # fmt: skip
    edited = f"{PREFIX}#100=#101"
    got = await diagnostics_for(client, uri, 2)
    assert [d for d in got.diagnostics if d.code == "syntax"] == []  # the server has the editor's text
    line, s, e = span(1, edited, "#101", kind)
    shown = await hover(client, uri, 1, s + 1)
    close_file(client, uri)
    assert shown is not None and "#101" in str(shown.contents)
    assert shown.range is not None and where(shown.range) == (line, s, e)


async def test_diagnostic_ranges_after_chinese_an_emoji_and_a_tab(client: LanguageClient) -> None:
    kind, root = setup(client)
    text = f"{PREFIX}G01 X1 @"
    uri = open_file(client, root / "DIAG.nc", f"O0001\n{text}\nM30\n")
    got = await diagnostics_for(client, uri, 1)
    close_file(client, uri)
    (syntax,) = [d for d in got.diagnostics if d.code == "syntax"]
    assert where(syntax.range) == span(1, text, "@", kind)


async def test_diagnostics_of_a_file_not_open_and_their_related_place(client: LanguageClient) -> None:
    kind, root = setup(client)
    macro_text = f"{PREFIX}#3=#2/#1"
    (root / "O9300.nc").write_text(f"O9300\n{macro_text}\nM99\n", "utf-8")
    macro = (root / "O9300.nc").as_uri()
    call = f"{PREFIX}G65 P9300 A0 B2."
    main = open_file(client, root / "MAIN.nc", f"O0001\n{call}\nM30\n")
    got = await published_where(client, {macro: lambda items: any(d.code == "division-by-zero" for d in items)})
    close_file(client, main)
    (div,) = [d for d in got[macro] if d.code == "division-by-zero"]
    assert where(div.range) == (1, 0, col(macro_text, len(macro_text), kind))  # the block
    (rel,) = div.related_information or []
    assert rel.location.uri == main
    assert where(rel.location.range) == (1, 0, col(call, len(call), kind))  # the calling block


async def test_semantic_tokens_after_chinese_an_emoji_and_a_tab(client: LanguageClient) -> None:
    kind, root = setup(client)
    text = f"{PREFIX}#100=1"
    uri = open_file(client, root / "TOKENS.nc", f"O0001\n{text}\nM30\n")
    got = await client.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(types.TextDocumentIdentifier(uri))
    )
    close_file(client, uri)
    assert got is not None
    tokens, line, start = [], 0, 0
    data = got.data
    for k in range(0, len(data), 5):
        dl, ds, length = data[k : k + 3]
        line, start = line + dl, (start + ds if dl == 0 else ds)
        tokens.append((line, start, start + length))
    on_line = [t for t in tokens if t[0] == 1]
    assert on_line == [span(1, text, "#100", kind)]  # the comment is the grammar's to colour


async def test_rename_prepare_and_references_after_chinese_an_emoji_and_a_tab(client: LanguageClient) -> None:
    kind, root = setup(client)
    jump = f"{PREFIX}GOTO 10"
    text = f"O0001\nN10 #1=1\n{jump}\nM30\n"
    uri = open_file(client, root / "RENAME.nc", text)
    _, start, end = span(2, jump, "10", kind)
    at = types.Position(2, start + 1)
    prepared = await client.text_document_prepare_rename_async(
        types.PrepareRenameParams(types.TextDocumentIdentifier(uri), at)
    )
    renamed = await client.text_document_rename_async(types.RenameParams(types.TextDocumentIdentifier(uri), at, "30"))
    refs = await client.text_document_references_async(
        types.ReferenceParams(
            context=types.ReferenceContext(include_declaration=True),
            text_document=types.TextDocumentIdentifier(uri),
            position=at,
        )
    )
    close_file(client, uri)
    assert isinstance(prepared, types.Range) and where(prepared) == (2, start, end)
    assert renamed is not None and renamed.changes is not None
    edits = sorted((where(e.range), e.new_text) for e in renamed.changes[uri])
    assert edits == [((1, 0, 3), "N30"), ((2, start, end), "30")]
    assert refs is not None and sorted(where(r.range) for r in refs) == [(1, 0, 3), (2, start, end)]


async def test_inlay_hints_after_chinese_an_emoji_and_a_tab(client: LanguageClient) -> None:
    kind, root = setup(client)
    text = f"{PREFIX}G65 P9000 A1. B2."
    uri = open_file(client, root / "HINTS.nc", f"O0001\n{text}\nM30\n")
    got = await client.text_document_inlay_hint_async(
        types.InlayHintParams(
            types.TextDocumentIdentifier(uri), types.Range(types.Position(0, 0), types.Position(3, 0))
        )
    )
    close_file(client, uri)
    assert got is not None
    hints = sorted((h.position.line, h.position.character, h.label) for h in got)
    assert hints == [(1, span(1, text, "A1.", kind)[2], "#1"), (1, span(1, text, "B2.", kind)[2], "#2")]


async def test_code_action_edits_after_chinese_an_emoji_and_a_tab(client: LanguageClient) -> None:
    kind, root = setup(client)
    text = f"{PREFIX}G65 P9000 L0"
    uri = open_file(client, root / "ACTION.nc", f"O0001\n{text}\nM30\n")
    whole = types.Range(types.Position(1, 0), types.Position(1, col(text, len(text), kind)))
    got = await client.text_document_code_action_async(
        types.CodeActionParams(types.TextDocumentIdentifier(uri), whole, types.CodeActionContext(diagnostics=[]))
    )
    close_file(client, uri)
    assert got is not None
    edits = [
        (where(e.range), e.new_text)
        for a in got
        if isinstance(a, types.CodeAction) and a.edit is not None and a.edit.changes
        for e in a.edit.changes[uri]
    ]
    assert (span(1, text, "L0", kind), "L1") in edits


async def test_document_symbols_and_completion_after_chinese_an_emoji_and_a_tab(client: LanguageClient) -> None:
    kind, root = setup(client)
    head = f"O0001 {PREFIX}"
    typed = f"{PREFIX}#1=#50"
    tail = f"M30 {PREFIX}"
    uri = open_file(client, root / "SYMBOLS.nc", f"{head}\n{typed}\n{tail}")
    symbols = await client.text_document_document_symbol_async(
        types.DocumentSymbolParams(types.TextDocumentIdentifier(uri))
    )
    done = await client.text_document_completion_async(
        types.CompletionParams(types.TextDocumentIdentifier(uri), types.Position(1, col(typed, len(typed), kind)))
    )
    close_file(client, uri)
    assert symbols is not None
    (program,) = symbols
    assert isinstance(program, types.DocumentSymbol)
    assert where(program.selection_range) == (0, 0, col(head, len(head), kind))
    assert program.range.end == types.Position(2, col(tail, len(tail), kind))
    assert isinstance(done, types.CompletionList)
    (item,) = [i for i in done.items if i.label == "#5001"]
    assert isinstance(item.text_edit, types.TextEdit)
    assert where(item.text_edit.range) == span(1, typed, "#50", kind)


NEGOTIATED = [
    (["utf-8", "utf-16", "utf-32"], "utf-32"),
    (["utf-16", "utf-32"], "utf-32"),
    (["utf-8", "utf-16"], "utf-16"),
    (["utf-8"], "utf-8"),
    (["utf-32"], "utf-32"),
    (["latin-1"], "utf-16"),
    ([], "utf-16"),
    (None, "utf-16"),
]


@pytest.mark.parametrize(("offer", "picked"), NEGOTIATED)
async def test_the_encoding_picked_for_what_the_client_offers_is_the_one_used(
    offer: list[str] | None, picked: str, tmp_path: Path
) -> None:
    client = await config().start()
    accept_registrations(client)
    try:
        result = await client.initialize_session(
            types.InitializeParams(capabilities=capabilities(offer), root_uri=tmp_path.as_uri())
        )
        kind = str(result.capabilities.position_encoding or "utf-16")
        text = f"{PREFIX}#100=1"
        uri = open_file(client, tmp_path / "PICKED.nc", f"O0001\n{text}\nM30\n")
        line, start, end = span(1, text, "#100", kind)
        got = await hover(client, uri, 1, start + 2)
        assert kind == picked
        assert got is not None and got.range is not None and where(got.range) == (line, start, end)
    finally:
        await client.shutdown_session()
