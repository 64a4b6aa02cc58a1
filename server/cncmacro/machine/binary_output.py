"""BPRNT's binary record (FANUC custom macro B's ``BPRNT[ a #b[c] ... ]``, docs/semantics.md §5):
the bytes the control sends, and the line a run shows for them.

Unlike DPRNT's text, BPRNT sends each variable as a binary number: its value times 10^c, rounded
to a whole number, in 4 bytes (32 bits, a negative in two's complement), the highest byte first;
a vacant variable is sent as 00000000h. Its characters go in ISO code, whose bit 8 is the even
parity bit (a ``*`` is a space, A0h), and a LF (0Ah) ends the record. No reader is at the other
end of the line in a run: it shows the record as one line that says what it is, the bytes in
hex (a value's four as one word) and what they hold (the characters in quotes, each value as
the whole number sent).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from decimal import ROUND_HALF_UP, Decimal

from ..bilingual import Detail, detail

# a piece of the record: literal characters, or a variable's value (None: vacant; NaN: unknown,
# in an analysis run) with its number of decimal places ``c``
Piece = str | tuple[float | None, int]

BPRNT = "BPRNT"  # the subject of the output note of a BPRNT record (a DPRNT line's has none)
END_OF_BLOCK = 0x0A  # ISO's EOB, LF
_WORD = 1 << 32


def iso_byte(ch: str) -> int:
    """``ch`` in ISO code: its 7-bit code with bit 8 set where that makes the count of ones even."""
    code = ord(ch) & 0x7F
    return code | 0x80 if bin(code).count("1") % 2 else code


def scaled(value: float | None, places: int) -> int | None:
    """The whole number BPRNT sends for ``value`` with ``places`` decimals: value x 10^places,
    rounded half away from zero, as the 32-bit word holds it (two's complement, read back signed);
    0 for vacant, None for an unknown value."""
    if value is None:
        return 0
    if not math.isfinite(value):  # unknown (NaN)
        return None
    whole = int(Decimal(repr(value)).scaleb(places).quantize(Decimal(1), rounding=ROUND_HALF_UP))
    whole %= _WORD
    return whole - _WORD if whole >= _WORD // 2 else whole


def bprnt_record(pieces: Iterable[Piece]) -> Detail:
    """The line a run shows for the record of ``pieces`` (English, Chinese): ``BPRNT binary
    record, 19 bytes: C3 A0 AF D8 0004DC1E 59 000002D3 4D 00000018 0A ("C /X" 318494 "Y" 723
    "M" 24 LF)``."""
    hexes: list[str] = []
    said: list[str] = []
    count = 1  # the LF at the end
    for piece in pieces:
        if isinstance(piece, str):
            hexes.extend(f"{iso_byte(ch):02X}" for ch in piece)
            said.append(f'"{piece}"')
            count += len(piece)
        else:
            n = scaled(*piece)
            hexes.append("????????" if n is None else f"{n % _WORD:08X}")
            said.append("?" if n is None else str(n))
            count += 4
    hexes.append(f"{END_OF_BLOCK:02X}")
    shown = " ".join(hexes)
    held = " ".join([*said, "LF"])
    return detail(
        f"BPRNT binary record, {count} bytes: {shown} ({held})",
        f"BPRNT 二进制记录，{count} 字节：{shown}（{held}）",
    )
