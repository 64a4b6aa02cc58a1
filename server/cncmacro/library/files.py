"""Reading program files as controls and editors write them.

Files come as UTF-8 (with or without a BOM), as GBK/GB18030 from Chinese controls and
editors, with LF, CRLF or CR line breaks. Text is decoded UTF-8 first and GB18030 second; bytes
that neither accepts are kept as surrogate escapes, so nothing is lost when the text is
written back. A file with NUL bytes or mostly control characters is binary: it is reported,
not parsed.
"""

from __future__ import annotations

import codecs
from dataclasses import dataclass
from pathlib import Path

from ..bilingual import detail

# Program files are found by these endings (any case), or by an O-number name without one.
PROGRAM_SUFFIXES = frozenset({".nc", ".cnc", ".mac", ".prg", ".tap", ".eia"})


class BinaryFileError(Exception):
    """The file is not text; ``offset`` is where the first NUL (or the evidence) is. ``message``
    says so in English and in Chinese (``str`` of the error is the English)."""

    def __init__(self, path: str, offset: int) -> None:
        self.message = detail(
            f"{path}: binary file (byte at offset {offset} is not program text), not a program",
            f"{path}：二进制文件（偏移 {offset} 处的字节不是程序文本），不是程序",
        )
        super().__init__(self.message)
        self.path = path
        self.offset = offset


@dataclass(slots=True)
class SourceText:
    """Decoded file text and the encoding it was read with."""

    text: str
    encoding: str
    bom: bool = False


def decode_program(data: bytes, path: str = "<bytes>") -> SourceText:
    """Decode the bytes of a program file; raise ``BinaryFileError`` for a binary one."""
    if data.startswith(codecs.BOM_UTF8):
        return SourceText(data[3:].decode("utf-8", errors="surrogateescape"), "utf-8", True)
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        return _utf16_program(data, path)
    nul = data.find(b"\0")
    if nul >= 0:
        raise BinaryFileError(path, nul)
    sample = data[:8192]
    if sample:
        controls = sum(1 for b in sample if b < 32 and b not in (9, 10, 12, 13, 26))
        if controls * 10 > len(sample):
            first = next(i for i, b in enumerate(sample) if b < 32 and b not in (9, 10, 12, 13, 26))
            raise BinaryFileError(path, first)
    try:
        return SourceText(data.decode("utf-8"), "utf-8")
    except UnicodeDecodeError:
        pass
    try:
        return SourceText(data.decode("gb18030"), "gb18030")
    except UnicodeDecodeError:
        return SourceText(data.decode("utf-8", errors="surrogateescape"), "utf-8")


def _utf16_program(data: bytes, path: str) -> SourceText:
    """A file that starts with a UTF-16 byte-order mark. A real program decodes to mostly
    ASCII text with no NUL or control characters; anything else is binary data that happens
    to begin with those two bytes."""
    try:
        text = data.decode("utf-16")
    except UnicodeDecodeError as e:
        raise BinaryFileError(path, e.start) from None
    sample = text[:4096]
    for i, ch in enumerate(sample):
        if ch < " " and ch not in "\t\n\f\r\x1a":
            raise BinaryFileError(path, 2 + 2 * i)
    if sample and sum(1 for ch in sample if ch < "\x80") * 2 < len(sample):
        raise BinaryFileError(path, 2)
    return SourceText(text, "utf-16", True)


def read_program(path: str | Path) -> SourceText:
    """Read and decode a program file (``OSError`` and ``BinaryFileError`` pass through)."""
    p = Path(path)
    return decode_program(p.read_bytes(), str(p))


def encode_program(source: SourceText) -> bytes:
    """The bytes of ``source`` in the encoding it was read with (the inverse of decoding)."""
    prefix = b""
    if source.bom and source.encoding == "utf-8":
        prefix = codecs.BOM_UTF8
    if source.encoding == "utf-16":
        return source.text.encode("utf-16", errors="surrogatepass")
    return prefix + source.text.encode(source.encoding, errors="surrogateescape")


def is_program_file(path: Path) -> bool:
    """True for a file whose name says it holds a program: a known ending, or ``O1234``."""
    if path.suffix.lower() in PROGRAM_SUFFIXES:
        return True
    name = path.name
    return not path.suffix and len(name) >= 2 and name[0] in "Oo" and name[1:].isdigit()


def find_program_files(root: Path) -> list[Path]:
    """Program files under ``root`` (itself, if it is a file), sorted, hidden folders skipped;
    a link that leads out of ``root`` is skipped too."""
    if root.is_file():
        return [root]
    found = []
    for p in sorted(root.rglob("*")):
        if any(part.startswith(".") for part in p.relative_to(root).parts):
            continue
        if p.is_file() and is_program_file(p) and stays_inside(p, root):
            found.append(p)
    return found


def stays_inside(path: Path, folder: Path) -> bool:
    """True when ``path``, its links followed, is ``folder`` or inside it (with its links
    followed): a link in a workspace that leads elsewhere on the disk is not read."""
    try:
        return path.resolve().is_relative_to(folder.resolve())
    except (OSError, RuntimeError):  # a link loop
        return False
