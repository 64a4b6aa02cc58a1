"""Debug Adapter Protocol messages: Content-Length framing and typed message classes.

A message on the wire is a header block (``Content-Length: N`` and a blank line) followed by
N bytes of UTF-8 JSON. ``read_message`` returns the next one as a ``Request`` (the only kind a
client sends us) or raises ``ProtocolError`` for a damaged one; ``MessageWriter`` numbers and
writes ``Response`` and ``Event`` messages from any thread, one whole message at a time.
"""

from __future__ import annotations

import json
import threading
from dataclasses import dataclass, field
from typing import Any, BinaryIO

MAX_MESSAGE = 64 * 1024 * 1024
MAX_HEADER_LINE = 1024  # bytes: ``Content-Length: 67108864`` is 24; a longer line is no header
_SKIP_PIECE = 64 * 1024


class ProtocolError(Exception):
    """The stream holds something that is not a DAP message; ``fatal`` when it cannot go on."""

    def __init__(self, message: str, fatal: bool = False, seq: int | None = None, command: str | None = None) -> None:
        super().__init__(message)
        self.fatal = fatal
        self.seq = seq  # set when the message can still be answered
        self.command = command


@dataclass(slots=True)
class Request:
    """A client's request: ``command`` and its ``arguments``."""

    seq: int
    command: str
    arguments: dict[str, Any] = field(default_factory=dict)

    @classmethod
    def from_json(cls, data: Any) -> Request:
        if not isinstance(data, dict) or data.get("type") != "request":
            raise ProtocolError("the message is not a request")
        seq = data.get("seq")
        command = data.get("command")
        arguments = data.get("arguments") or {}
        if not isinstance(seq, int) or not isinstance(command, str) or not isinstance(arguments, dict):
            raise ProtocolError(
                "a request needs an integer seq, a command and object arguments",
                seq=seq if isinstance(seq, int) else None,
                command=command if isinstance(command, str) else None,
            )
        return cls(seq, command, arguments)


@dataclass(slots=True)
class Response:
    """The answer to one request."""

    request_seq: int
    command: str
    success: bool = True
    body: dict[str, Any] | None = None
    message: str | None = None

    def to_json(self, seq: int) -> dict[str, Any]:
        out: dict[str, Any] = {
            "seq": seq, "type": "response", "request_seq": self.request_seq, "command": self.command,
            "success": self.success,
        }  # fmt: skip
        if self.message is not None:
            out["message"] = self.message
        if self.body is not None:
            out["body"] = self.body
        return out


@dataclass(slots=True)
class Event:
    """Something the adapter tells the client unasked (stopped, output, terminated, ...)."""

    event: str
    body: dict[str, Any] | None = None

    def to_json(self, seq: int) -> dict[str, Any]:
        out: dict[str, Any] = {"seq": seq, "type": "event", "event": self.event}
        if self.body is not None:
            out["body"] = self.body
        return out


def read_message(stream: BinaryIO) -> Request | None:
    """The next request, or None at the end of the stream."""
    length = None
    while True:
        line = stream.readline(MAX_HEADER_LINE)
        if not line:
            return None
        if len(line) == MAX_HEADER_LINE and not line.endswith(b"\n"):
            if not _read_past_line(stream):
                return None
            raise ProtocolError(f"a header line longer than {MAX_HEADER_LINE} bytes was passed over")
        text = line.decode("ascii", errors="replace").strip()
        if not text:
            if length is None:
                continue  # stray blank lines between messages
            break
        name, _, value = text.partition(":")
        if name.strip().lower() == "content-length":
            try:
                length = int(value.strip())
            except ValueError:
                raise ProtocolError(f"bad Content-Length header: {text}", fatal=True) from None
    if not 0 <= length <= MAX_MESSAGE:
        raise ProtocolError(f"Content-Length {length} is out of range", fatal=True)
    body = stream.read(length)
    if len(body) < length:
        return None
    try:
        data = json.loads(body.decode("utf-8"))
    except (UnicodeDecodeError, ValueError) as e:
        raise ProtocolError(f"the message is not JSON: {e}") from None
    except RecursionError:
        raise ProtocolError("the message is nested too deeply to read") from None
    return Request.from_json(data)


def _read_past_line(stream: BinaryIO) -> bool:
    """Read past the rest of a line a piece at a time, never holding it; False at the end of the stream."""
    while True:
        piece = stream.readline(_SKIP_PIECE)
        if not piece:
            return False
        if piece.endswith(b"\n"):
            return True


class MessageWriter:
    """Writes numbered messages to a binary stream; safe to call from several threads."""

    def __init__(self, stream: BinaryIO) -> None:
        self.stream = stream
        self.seq = 0
        self.lock = threading.Lock()

    def send(self, message: Response | Event) -> None:
        with self.lock:
            self.seq += 1
            payload = json.dumps(message.to_json(self.seq), ensure_ascii=False, allow_nan=False).encode("utf-8")
            try:
                self.stream.write(b"Content-Length: %d\r\n\r\n" % len(payload) + payload)
                self.stream.flush()
            except (BrokenPipeError, ValueError, OSError):
                pass  # the client has gone; the read loop ends on its own
