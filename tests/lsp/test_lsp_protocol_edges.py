"""The language server at the edges of the protocol, spoken to over stdio byte for byte (a
client library cannot send what these tests send): a wrong ``Content-Length`` costs one
message, or two when it runs into the next one's header, never the session; a body that is not
JSON, a request whose parameters do not fit and a request after ``shutdown`` are answered with
the errors JSON-RPC and LSP prescribe; a request about a document that is not open gets the
method's empty answer, quietly; ``exit`` without ``shutdown`` ends the process with 1."""

from __future__ import annotations

import json
import subprocess
import sys
import time
from typing import Any

INIT = {"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}, "rootUri": None}}
INITIALIZED = {"jsonrpc": "2.0", "method": "initialized", "params": {}}
SHUTDOWN = {"jsonrpc": "2.0", "id": 90, "method": "shutdown"}
EXIT = {"jsonrpc": "2.0", "method": "exit"}
HOVER_PARAMS = {"textDocument": {"uri": "file:///nowhere/O1.nc"}, "position": {"line": 0, "character": 0}}


def frame(message: dict[str, Any]) -> bytes:
    body = json.dumps(message).encode()
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def session(*messages: bytes | dict[str, Any], log: list[str] | None = None) -> tuple[int, list[dict[str, Any]]]:
    """Send ``messages`` (dicts are framed; bytes go as they are), then close the stream; the exit
    code and every message the server sent (and, in ``log``, what it wrote to stderr)."""
    p = subprocess.Popen([sys.executable, "-m", "cncmacro", "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                         stderr=subprocess.DEVNULL if log is None else subprocess.PIPE)  # fmt: skip
    assert p.stdin is not None and p.stdout is not None
    for m in messages:
        p.stdin.write(m if isinstance(m, bytes) else frame(m))
        p.stdin.flush()
        time.sleep(0.1)
    p.stdin.close()
    out = p.stdout.read()
    if log is not None and p.stderr is not None:
        log.append(p.stderr.read().decode(errors="replace"))
    code = p.wait(30)
    sent = []
    while out:
        head, _, rest = out.partition(b"\r\n\r\n")
        length = int(head.split(b"Content-Length:")[1].split(b"\r\n")[0])
        sent.append(json.loads(rest[:length]))
        out = rest[length:]
    return code, sent


def answer(sent: list[dict[str, Any]], request_id: int) -> dict[str, Any]:
    found = [m for m in sent if m.get("id") == request_id and "method" not in m]
    assert len(found) == 1, f"no single answer to request {request_id}: {sent}"
    return found[0]


def test_a_content_length_shorter_than_its_body_costs_that_message_only():
    short = b'Content-Length: 5\r\n\r\n{"jsonrpc": "2.0", "id": 5, "method": "shutdown"}'
    code, sent = session(INIT, INITIALIZED, short, SHUTDOWN, EXIT)
    assert answer(sent, 90)["result"] is None  # the stream is in step again
    assert code == 0


def test_a_content_length_longer_than_its_body_costs_that_message_and_the_next_only():
    # the length runs into the next message's header: both are lost, and the one after is answered
    body = json.dumps({"jsonrpc": "2.0", "id": 5, "method": "textDocument/hover", "params": HOVER_PARAMS}).encode()
    overlong = b"Content-Length: %d\r\n\r\n" % (len(body) + 30) + body
    swallowed = {"jsonrpc": "2.0", "id": 6, "method": "textDocument/hover", "params": HOVER_PARAMS}
    after = {"jsonrpc": "2.0", "id": 7, "method": "textDocument/hover", "params": HOVER_PARAMS}
    code, sent = session(INIT, INITIALIZED, overlong, swallowed, after, SHUTDOWN, EXIT)
    assert any(m.get("error", {}).get("code") == -32700 and m.get("id") is None for m in sent)
    assert not [m for m in sent if m.get("id") in (5, 6)]
    assert answer(sent, 7)["result"] is None  # a hover on a document not open: null
    assert answer(sent, 90)["result"] is None
    assert code == 0


def test_a_content_length_beyond_any_message_is_refused_and_reading_goes_on():
    huge = b"Content-Length: 99999999999999999999\r\n\r\n{}"
    code, sent = session(INIT, INITIALIZED, huge, SHUTDOWN, EXIT)
    assert any(m.get("error", {}).get("code") == -32600 and m.get("id") is None for m in sent)
    assert answer(sent, 90)["result"] is None
    assert code == 0


def test_a_body_that_is_not_json_is_answered_with_a_parse_error():
    code, sent = session(INIT, INITIALIZED, b"Content-Length: 9\r\n\r\n{not json", SHUTDOWN, EXIT)
    assert code == 0
    assert any(m.get("error", {}).get("code") == -32700 for m in sent)
    assert answer(sent, 90)["result"] is None


def test_a_request_whose_parameters_do_not_fit_gets_an_invalid_params_error():
    bad = {"jsonrpc": "2.0", "id": 7, "method": "textDocument/hover", "params": {"textDocument": 5}}
    code, sent = session(INIT, INITIALIZED, bad, SHUTDOWN, EXIT)
    assert answer(sent, 7)["error"]["code"] == -32602
    assert code == 0


def test_a_request_after_shutdown_gets_an_invalid_request_error():
    late = {"jsonrpc": "2.0", "id": 8, "method": "textDocument/hover", "params": HOVER_PARAMS}
    code, sent = session(INIT, INITIALIZED, SHUTDOWN, late, EXIT)
    assert answer(sent, 8)["error"]["code"] == -32600
    assert code == 0


def test_exit_without_shutdown_ends_the_process_with_1():
    code, _ = session(INIT, INITIALIZED, EXIT)
    assert code == 1


def test_a_message_nested_too_deeply_is_a_parse_error_and_the_server_lives_on():
    # 100,000 arrays inside each other: deeper than any decoder goes; it used to end the process
    deep = b'{"jsonrpc":"2.0","id":3,"method":"initialize","params":{"x":' + b"[" * 100_000 + b"]" * 100_000 + b"}}"
    code, sent = session(b"Content-Length: %d\r\n\r\n" % len(deep) + deep, INIT, INITIALIZED, SHUTDOWN, EXIT)
    refused = [m for m in sent if m.get("error", {}).get("code") == -32700 and m.get("id") is None]
    assert refused and "nested too deeply" in refused[0]["error"]["message"]
    assert "capabilities" in answer(sent, 1)["result"]  # the next message is served
    assert answer(sent, 90)["result"] is None
    assert code == 0


def test_messages_json_rpc_does_not_allow_get_an_invalid_request_error_and_the_session_goes_on():
    object_id = {"jsonrpc": "2.0", "id": {"a": 1}, "method": "textDocument/hover", "params": HOVER_PARAMS}
    array_id = {"jsonrpc": "2.0", "id": [4], "method": "textDocument/hover", "params": HOVER_PARAMS}
    no_version = {"id": 5, "method": "textDocument/hover", "params": HOVER_PARAMS}
    batch = b"Content-Length: 2\r\n\r\n[]"
    code, sent = session(INIT, INITIALIZED, object_id, array_id, no_version, batch, SHUTDOWN, EXIT)
    refused = [m["error"] for m in sent if m.get("id") is None and "error" in m]
    assert [e["code"] for e in refused] == [-32600] * 4
    assert "batch" in refused[3]["message"]
    assert not [m for m in sent if m.get("id") == 5]  # never served as a request
    assert answer(sent, 90)["result"] is None
    assert code == 0


def test_requests_before_a_successful_initialize_get_server_not_initialized():
    early = {"jsonrpc": "2.0", "id": 2, "method": "shutdown"}
    refused_init = {"jsonrpc": "2.0", "id": 3, "method": "initialize", "params": {"capabilities": 5}}
    text = {"uri": "file:///nowhere/O1.nc", "languageId": "cnc-macro", "version": 1, "text": "O1\nM30\n"}
    opened = {"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": text}}
    hover = {"jsonrpc": "2.0", "id": 4, "method": "textDocument/hover", "params": HOVER_PARAMS}
    code, sent = session(early, refused_init, opened, hover, INIT, SHUTDOWN, EXIT)
    assert answer(sent, 2)["error"]["code"] == -32002  # shutdown before initialize
    assert answer(sent, 3)["error"]["code"] == -32602  # an initialize whose parameters do not fit
    assert answer(sent, 4)["error"]["code"] == -32002  # and the document was not taken either
    assert not [m for m in sent if m.get("method") == "textDocument/publishDiagnostics"]
    assert "capabilities" in answer(sent, 1)["result"]
    assert answer(sent, 90)["result"] is None
    assert code == 0


NOT_OPEN = {"uri": "file:///nowhere/O1.nc"}
WHERE = {"textDocument": NOT_OPEN, "position": {"line": 0, "character": 0}}
LINES = {"start": {"line": 0, "character": 0}, "end": {"line": 3, "character": 0}}
OPTIONS = {"tabSize": 4, "insertSpaces": True}
ABOUT_A_DOCUMENT = {
    "textDocument/hover": WHERE,
    "textDocument/definition": WHERE,
    "textDocument/references": {**WHERE, "context": {"includeDeclaration": True}},
    "textDocument/documentHighlight": WHERE,
    "textDocument/completion": WHERE,
    "textDocument/signatureHelp": WHERE,
    "textDocument/prepareRename": WHERE,
    "textDocument/rename": {**WHERE, "newName": "N20"},
    "textDocument/prepareCallHierarchy": WHERE,
    "textDocument/documentSymbol": {"textDocument": NOT_OPEN},
    "textDocument/semanticTokens/full": {"textDocument": NOT_OPEN},
    "textDocument/semanticTokens/full/delta": {"textDocument": NOT_OPEN, "previousResultId": "1"},
    "textDocument/semanticTokens/range": {"textDocument": NOT_OPEN, "range": LINES},
    "textDocument/codeAction": {"textDocument": NOT_OPEN, "range": LINES, "context": {"diagnostics": []}},
    "textDocument/codeLens": {"textDocument": NOT_OPEN},
    "textDocument/inlayHint": {"textDocument": NOT_OPEN, "range": LINES},
    "textDocument/inlineValue": {
        "textDocument": NOT_OPEN,
        "range": LINES,
        "context": {"frameId": 1, "stoppedLocation": LINES},
    },
    "textDocument/foldingRange": {"textDocument": NOT_OPEN},
    "textDocument/formatting": {"textDocument": NOT_OPEN, "options": OPTIONS},
    "textDocument/rangeFormatting": {"textDocument": NOT_OPEN, "range": LINES, "options": OPTIONS},
}


def test_every_request_about_a_document_not_open_is_answered_with_null_quietly():
    # a client racing a close, or a peek into a file it never opened: no error, no traceback
    requests = [
        {"jsonrpc": "2.0", "id": 100 + k, "method": method, "params": params}
        for k, (method, params) in enumerate(ABOUT_A_DOCUMENT.items())
    ]
    log: list[str] = []
    code, sent = session(INIT, INITIALIZED, *requests, SHUTDOWN, EXIT, log=log)
    answers = {r["method"]: answer(sent, r["id"]) for r in requests}
    assert {m: a for m, a in answers.items() if a.get("result", "missing") is not None} == {}
    assert "not open" not in log[0] and "Traceback" not in log[0]
    assert code == 0
