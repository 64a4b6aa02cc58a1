"""What the command line writes to a terminal: text in which a program, a file name or a
message can never move the cursor, change colours, set the window title or ring the bell.

A program's texts (``#3000``/``#3006`` messages, DPRNT output, comments quoted in a message)
and file names are shown as they are, except control characters: the C0 ones other than tab
and line feed, DEL and the C1 ones (``U+0080``–``U+009F``, among them the one-character CSI)
are written as ``\\x1b``, ``\\x9b``. The JSON and SARIF output writes them as JSON escapes
(``\\u001b``, ``\\u009b``), which a JSON reader turns back into the same text, and never writes
``NaN`` or ``Infinity``, which JSON does not have.
"""

from __future__ import annotations

import json
import re
from typing import Any, Protocol, TextIO

_CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f]")
_JSON_CONTROL = re.compile("[\x7f-\x9f]")  # json.dumps escapes the C0 ones itself


def printable(text: str) -> str:
    """``text`` with its control characters (but tab and line feed) written as ``\\xNN``."""
    if text.isprintable():  # the usual case, at C speed
        return text
    return _CONTROL.sub(lambda m: f"\\x{ord(m.group()):02x}", text)


def json_text(value: Any, **options: Any) -> str:
    """``value`` as JSON (non-ASCII text as it is, control characters escaped); ``ValueError``
    for a value that is not a finite number, which JSON cannot hold."""
    text = json.dumps(value, ensure_ascii=False, allow_nan=False, **options)
    return _JSON_CONTROL.sub(lambda m: f"\\u{ord(m.group()):04x}", text)


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
