"""The language server's stdio transport: JSON-RPC messages framed by ``Content-Length`` headers.

pygls's own loop is replaced here so that no message can break the session:

- a header is found wherever it starts on its line, so a body longer than its ``Content-Length``
  said (whose tail runs into the next header) costs that message, not every message after it; a
  ``Content-Length`` longer than its body reads on into the next message, and costs both (a
  reader of a byte stream cannot know the length was wrong before the bytes arrive);
- a body longer than ``MAX_BODY`` is read past in pieces, never held, and answered with an error
  (a header met on the way, the length having been wrong, is where reading goes on);
- a body that is not JSON is answered with a parse error (-32700), and a request whose
  parameters do not fit the method with an invalid-params error (-32602) for its id;
- a request after ``shutdown`` is answered with an invalid-request error (-32600), as the
  specification asks, instead of silence;
- ``exit`` ends the process with 0 after ``shutdown`` and 1 without it;
- a string that holds a lone surrogate (a file name that is not UTF-8, kept as the system gives
  it) is sent as ``library.files.shown_text`` shows it, so every message is valid Unicode.
"""

from __future__ import annotations

import asyncio
import json
import logging
import re
import threading
import time
from typing import TYPE_CHECKING, Any, BinaryIO

from pygls.exceptions import JsonRpcException, JsonRpcInvalidParams
from pygls.io_ import StdinAsyncReader, StdoutWriter

from ..library.files import shown_text

if TYPE_CHECKING:
    from .server import CncMacroServer

log = logging.getLogger(__name__)

MAX_BODY = 512 << 20  # bytes: far beyond any program an editor sends (a 1M-line file is ~35 MB)
_PIECE = 1 << 20
_CONTENT_LENGTH = re.compile(rb"Content-Length:[ \t]*(\d{1,20})", re.IGNORECASE)
PARSE_ERROR = -32700
INVALID_REQUEST = -32600
INVALID_PARAMS = -32602
SERVER_NOT_INITIALIZED = -32002


def serve_stdio(server: CncMacroServer, stdin: BinaryIO, stdout: BinaryIO) -> int:
    """Serve until the client says exit or closes the stream; the process's exit code."""
    server._stop_event = stop = threading.Event()
    reader = StdinAsyncReader(stdin, server.thread_pool)
    server.protocol.set_writer(UnicodeWriter(stdout))
    try:
        asyncio.run(_read_messages(server, reader, stop))
    except BrokenPipeError:
        log.error("the client went away")
    except SystemExit as e:  # ``exit``: 0 after ``shutdown``, 1 without
        return e.code if isinstance(e.code, int) else 0
    except KeyboardInterrupt:
        pass
    finally:
        server.shutdown()  # type: ignore[no-untyped-call]  # pygls's Server.shutdown has no annotations
    return 0


class UnicodeWriter(StdoutWriter):
    """pygls writes JSON with non-ASCII characters escaped, a lone surrogate too (``\\udcb3``),
    which a strict client rejects: such a message is written again with its strings shown."""

    def write(self, data: bytes) -> None:
        if b"\\ud" in data:
            data = _without_lone_surrogates(data)
        super().write(data)


def _without_lone_surrogates(data: bytes) -> bytes:
    head, sep, body = data.partition(b"\r\n\r\n")
    if not sep:
        return data
    try:
        message = json.loads(body)
    except ValueError:
        return data
    fixed = json.dumps(_shown(message)).encode("ascii")
    if fixed == body:
        return data
    head = _CONTENT_LENGTH.sub(b"Content-Length: %d" % len(fixed), head, count=1)
    return head + sep + fixed


def _shown(value: Any) -> Any:
    if isinstance(value, str):
        return shown_text(value)
    if isinstance(value, list):
        return [_shown(v) for v in value]
    if isinstance(value, dict):
        return {shown_text(k): _shown(v) for k, v in value.items()}
    return value


_CLOSED = ("closed", None, None)  # the client closed the stream


def _read_one(stdin: BinaryIO, carried: int | None) -> tuple[str, Any, int | None]:
    """On the reading thread: the next message, whole, in one call (so a message waits for one
    turn of a busy event loop, not one per header line): ``("body", bytes, None)``,
    ``("too long", length, carried)`` for a body over ``MAX_BODY`` read past (``carried``: the
    length in a header met on the way, where reading goes on), or ``_CLOSED``. ``carried``
    is such a length from the call before."""
    length = carried
    while True:  # the headers, up to the empty line
        line = stdin.readline(_PIECE)
        if not line:
            return _CLOSED
        m = _CONTENT_LENGTH.search(line)
        if m is not None:
            length = int(m.group(1))
        elif not line.strip() and length is not None:
            break
    if length > MAX_BODY:
        # Read past it a line (at most a piece) at a time; a header on the way (the length
        # was wrong, and the next message follows) is where reading goes on.
        left = length
        while left > 0:
            piece = stdin.readline(min(left, _PIECE))
            if not piece:
                return _CLOSED
            left -= len(piece)
            m = _CONTENT_LENGTH.search(piece)
            if m is not None:
                return ("too long", length, int(m.group(1)))
        return ("too long", length, None)
    body = stdin.read(length)
    if len(body) < length:
        return _CLOSED
    return ("body", body, None)


async def _read_messages(server: CncMacroServer, reader: StdinAsyncReader, stop: threading.Event) -> None:
    loop = asyncio.get_running_loop()
    carried: int | None = None  # a header found while reading past a body that was too long
    while not stop.is_set():
        kind, got, carried = await loop.run_in_executor(reader.executor, _read_one, reader.stdin, carried)
        if kind == "closed":
            return
        if kind == "too long":
            _answer_error(server, None, INVALID_REQUEST, f"message of {got} bytes is too long (at most {MAX_BODY})")
            continue
        try:
            data = json.loads(got)
        except ValueError as e:  # not JSON (or not UTF-8)
            _answer_error(server, None, PARSE_ERROR, f"not a JSON message: {e}")
            continue
        except RecursionError:  # arrays or objects nested deeper than the decoder goes
            _answer_error(server, None, PARSE_ERROR, "not a JSON message: nested too deeply")
            continue
        _handle(server, data)
        await asyncio.sleep(0)  # let the handlers' tasks run between messages


def _not_a_message(data: Any) -> str | None:
    """Why ``data`` is not a JSON-RPC 2.0 message the protocol carries, or None: LSP has no
    batches, every message names ``"jsonrpc": "2.0"``, and an id is a number or a string."""
    if isinstance(data, list):
        return "a batch of messages is not part of the Language Server Protocol: send them one by one"
    if not isinstance(data, dict):
        return "a message is a JSON object"
    if data.get("jsonrpc") != "2.0":
        return 'a message says "jsonrpc": "2.0"'
    request_id = data.get("id")
    if request_id is not None and (request_id.__class__ is bool or not isinstance(request_id, (int, str))):
        return "an id is a number or a string"
    return None


def _handle(server: CncMacroServer, data: Any) -> None:
    server.last_message_at = time.monotonic()
    protocol = server.protocol
    wrong = _not_a_message(data)
    if wrong is not None:
        _answer_error(server, None, INVALID_REQUEST, wrong)
        return
    request_id = data.get("id")
    method = data.get("method")
    is_request = method is not None and request_id is not None
    if is_request and protocol._shutdown and method != "exit":
        _answer_error(server, request_id, INVALID_REQUEST, "the server is shutting down")
        return
    if not server.initialize_accepted and method not in (None, "initialize", "exit"):
        if is_request:  # LSP: before initialize, a request is refused and a notification dropped
            _answer_error(server, request_id, SERVER_NOT_INITIALIZED, f"{method} before a successful initialize")
        return
    try:
        message = protocol.structure_message(data)
    except JsonRpcException as e:
        if is_request:
            code = INVALID_PARAMS if isinstance(e, JsonRpcInvalidParams) else e.code
            _answer_error(server, request_id, code, f"the parameters of {method} do not fit it")
        else:
            log.warning("message not understood: %s", e)
        return
    if method == "initialize":
        server.initialize_accepted = True
    try:
        protocol.handle_message(message)
    except Exception as e:  # a fault in one message must not end the session
        log.exception("handling a message failed")
        server.report_server_error(e, JsonRpcException)


def _answer_error(server: CncMacroServer, request_id: Any, code: int, message: str) -> None:
    server.protocol._send_data({"jsonrpc": "2.0", "id": request_id, "error": {"code": code, "message": message}})
