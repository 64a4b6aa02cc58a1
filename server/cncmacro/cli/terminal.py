"""What the command line writes to a terminal: text in which a program, a file name or a
message can never move the cursor, change colours, set the window title or ring the bell.

A program's texts (``#3000``/``#3006`` messages, DPRNT output, comments quoted in a message)
and file names are shown as they are, except control characters: the C0 ones other than tab
and line feed, DEL and the C1 ones (``U+0080``–``U+009F``, among them the one-character CSI)
are written as ``\\x1b``, ``\\x9b``, and so are the marks that reorder what a terminal shows
(U+200E, U+200F, U+202A–U+202E, U+2066–U+2069: a right-to-left override makes ``gnp.exe`` of
``exe.png``), written ``\\u202e``. A file name is one field of a finding's line, so in it a
line feed and a tab are escaped too (``shown_name``): a file named ``a.nc\\nO1.nc:1:1: error:``
cannot forge a finding. The JSON and SARIF output writes them as JSON escapes
(``\\u001b``, ``\\u009b``), which a JSON reader turns back into the same text, and never writes
``NaN`` or ``Infinity``, which JSON does not have.

A stream whose encoding cannot write every character (a Chinese Windows writes a redirected
report in its code page, GBK, which has no ``✓`` or emoji) writes those it cannot as JSON's
``\\uNNNN`` escapes (``tolerant``), a pair of them above U+FFFF: the text stays readable, the
JSON stays valid and reads back as the same text, and nothing ends in an encoding error.
"""

from __future__ import annotations

import codecs
import io
import json
import re
from typing import Any, Protocol, TextIO

_CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u200e\u200f\u202a-\u202e\u2066-\u2069]")
_NAME_CONTROL = re.compile("[\x00-\x1f\x7f-\x9f\u200e\u200f\u202a-\u202e\u2066-\u2069]")
_JSON_CONTROL = re.compile("[\x7f-\x9f]")  # json.dumps escapes the C0 ones itself


def _escaped(m: re.Match[str]) -> str:
    c = ord(m.group())
    return f"\\x{c:02x}" if c < 0x100 else f"\\u{c:04x}"


def printable(text: str) -> str:
    """``text`` with its control characters (but tab and line feed) and reordering marks
    written as ``\\xNN`` and ``\\uNNNN``."""
    if text.isprintable():  # the usual case, at C speed (a reordering mark is not printable)
        return text
    return _CONTROL.sub(_escaped, text)


def shown_name(name: str) -> str:
    """A file name as one field of a line: ``printable``, and its line feeds and tabs escaped."""
    if name.isprintable():
        return name
    return _NAME_CONTROL.sub(_escaped, name)


def json_text(value: Any, **options: Any) -> str:
    """``value`` as JSON (non-ASCII text as it is, control characters escaped); ``ValueError``
    for a value that is not a finite number, which JSON cannot hold."""
    text = json.dumps(value, ensure_ascii=False, allow_nan=False, **options)
    return _JSON_CONTROL.sub(lambda m: f"\\u{ord(m.group()):04x}", text)


ESCAPE = "cncmacro-escape"  # the error handler that writes what the encoding lacks as \\uNNNN


def _escape_unencodable(error: UnicodeError) -> tuple[str, int]:
    if not isinstance(error, UnicodeEncodeError):
        raise error
    out = []
    for ch in error.object[error.start : error.end]:
        c = ord(ch)
        if c > 0xFFFF:  # as JSON writes it: a surrogate pair
            c -= 0x10000
            out.append(f"\\u{0xD800 + (c >> 10):04x}\\u{0xDC00 + (c & 0x3FF):04x}")
        else:
            out.append(f"\\u{c:04x}")
    return "".join(out), error.end


codecs.register_error(ESCAPE, _escape_unencodable)


def tolerant(stream: object) -> None:
    """Let ``stream`` (``sys.stdout``, ``sys.stderr``) write what its encoding lacks as escapes
    instead of failing, unless it writes UTF-8 (which has every character) or was told how."""
    if isinstance(stream, io.TextIOWrapper) and stream.errors == "strict":
        if codecs.lookup(stream.encoding).name != "utf-8":
            stream.reconfigure(errors=ESCAPE)


class TextOut(Protocol):
    """Where a report is written: a text stream, or a ``Printable`` one."""

    def write(self, text: str, /) -> int: ...


class Printable:
    """A text stream that writes everything through ``printable``."""

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream

    def write(self, text: str) -> int:
        if text != "\n":  # print() writes the line feed on its own
            text = printable(text)
        return self.stream.write(text)

    def flush(self) -> None:
        self.stream.flush()
