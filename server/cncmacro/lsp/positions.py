"""Columns between the editor and the parser, in the position encoding agreed at ``initialize``.

The syntax tree counts columns in code points (Python's string indices). The client counts them
in the encoding the server picked from its ``general.positionEncodings`` (LSP 3.17):

- ``utf-32`` is code points: nothing to convert, so it is picked whenever the client offers it;
- ``utf-16`` differs only on lines with a character outside the Basic Multilingual Plane (an
  emoji; Chinese is inside it): picked next;
- ``utf-8`` differs on every line that is not pure ASCII (a Chinese comment): picked only when
  the client offers neither of the others;
- a client that offers none of them (or nothing) gets ``utf-16``, the protocol's default.

Every column the server reads from or sends to the client goes through one ``Encoding``
(``Documents.encoding``); a line of pure ASCII is never converted. A column inside a character
(half a surrogate pair, a byte inside a UTF-8 sequence) is read as the end of that character.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from lsprotocol import types

from ..ide.spans import Region, Span

_ASTRAL = re.compile("[\U00010000-\U0010ffff]")
_CONTINUATION = bytes(range(0x80, 0xC0))  # the bytes of a UTF-8 sequence after its first


class Encoding:
    """Code points: the client's columns are the parser's (``utf-32``)."""

    kind: str = types.PositionEncodingKind.Utf32.value

    def plain(self, line: str) -> bool:
        """True when the client's columns on ``line`` are its code-point columns."""
        return True

    def to_code_points(self, line: str, column: int) -> int:
        """The code-point column of the client's ``column`` on ``line`` (within the line)."""
        return min(max(column, 0), len(line))

    def to_client(self, line: str, column: int) -> int:
        """The client's column of the code-point ``column`` on ``line``."""
        return column

    def range(self, line: int, text: str, start: int, end: int) -> types.Range:
        """The client's range of code-point columns ``start``..``end`` on ``line`` (its ``text``)."""
        if self.plain(text):
            return types.Range(types.Position(line, start), types.Position(line, end))
        return types.Range(
            types.Position(line, self.to_client(text, start)), types.Position(line, self.to_client(text, end))
        )

    def __repr__(self) -> str:
        return f"<position encoding {self.kind}>"


class _Utf16(Encoding):
    kind = types.PositionEncodingKind.Utf16.value

    def plain(self, line: str) -> bool:
        return line.isascii() or _ASTRAL.search(line) is None

    def to_code_points(self, line: str, column: int) -> int:
        if self.plain(line):
            return min(max(column, 0), len(line))
        units = 0
        for i, ch in enumerate(line):
            if units >= column:
                return i
            units += 2 if ord(ch) > 0xFFFF else 1
        return len(line)

    def to_client(self, line: str, column: int) -> int:
        if self.plain(line):
            return column
        return column + len(_ASTRAL.findall(line, 0, max(column, 0)))


class _Utf8(Encoding):
    kind = types.PositionEncodingKind.Utf8.value

    def plain(self, line: str) -> bool:
        return line.isascii()

    def to_code_points(self, line: str, column: int) -> int:
        if line.isascii() or column <= 0:
            return min(max(column, 0), len(line))
        data = line.encode("utf-8", "surrogatepass")
        if column >= len(data):
            return len(line)
        return len(data[:column].translate(None, _CONTINUATION))  # the characters begun before it

    def to_client(self, line: str, column: int) -> int:
        if line.isascii() or column <= 0:
            return column
        return len(line[:column].encode("utf-8", "surrogatepass")) + max(column - len(line), 0)


UTF32 = Encoding()
UTF16 = _Utf16()
UTF8 = _Utf8()
PREFERENCE = (UTF32, UTF16, UTF8)  # the cheapest first


def negotiate(offered: Sequence[str] | None) -> Encoding:
    """The encoding for a client that offers ``offered`` (``general.positionEncodings``)."""
    for encoding in PREFERENCE:
        if offered and encoding.kind in offered:
            return encoding
    return UTF16


def client_span(encoding: Encoding, line: Callable[[int], str], span: Span) -> types.Range:
    """The client's range of ``span`` (``line``: the text of a line by its number)."""
    return encoding.range(span.line, line(span.line), span.start, span.end)


def client_region(encoding: Encoding, line: Callable[[int], str], region: Region) -> types.Range:
    """The client's range of ``region`` (``line``: the text of a line by its number)."""
    return types.Range(
        types.Position(region.start_line, encoding.to_client(line(region.start_line), region.start_column)),
        types.Position(region.end_line, encoding.to_client(line(region.end_line), region.end_column)),
    )
