"""Reading program files as controls and editors write them.

Files come as UTF-8 (with or without a BOM), as GBK/GB18030 from Chinese controls and
editors, with LF, CRLF or CR line breaks. Text is decoded UTF-8 first and GB18030 second; bytes
that neither accepts are kept as surrogate escapes, so nothing is lost when the text is
written back. A file with NUL bytes or mostly control characters is binary: it is reported,
not parsed.

Only a regular file of at most ``MAX_PROGRAM_BYTES`` is read, and it is opened without
blocking: a pipe, a device (``/dev/zero``) or a folder is refused with a ``RefusedFileError``
before a byte is read, so a read never waits and never grows without end. A path that a client
names (an editor's file event, a debugger's request) is read with ``ReadScope``: a program
file under the folders the front end works in, a link that leads out of them not followed.
"""

from __future__ import annotations

import codecs
import os
import stat
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from ..bilingual import detail

# Program files are found by these endings (any case), or by an O-number name without one.
PROGRAM_SUFFIXES = frozenset({".nc", ".cnc", ".mac", ".prg", ".tap", ".eia"})
# Far beyond any program a control holds; a million-line CAM file is about 35 MB.
MAX_PROGRAM_BYTES = 64_000_000


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


class RefusedFileError(OSError):
    """A path that is not read as a program: not a regular file, too large, not a program
    file, or outside the folders it must be in. ``reason`` says why and ``message`` (the path,
    then the reason) too, in English and in Chinese (``str`` of the error is the English)."""

    def __init__(self, path: str | Path, en: str, zh: str) -> None:
        self.reason = detail(en, zh)
        self.message = detail(f"{path}: {en}", f"{path}：{zh}")
        super().__init__(self.message)
        self.path = str(path)


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


def read_program(path: str | Path, max_bytes: int = MAX_PROGRAM_BYTES) -> SourceText:
    """Read and decode a program file: a regular file of at most ``max_bytes``, opened without
    blocking (``RefusedFileError``, ``OSError`` and ``BinaryFileError`` pass through)."""
    return decode_program(_read_regular(str(path), max_bytes), str(path))


def _read_regular(path: str, max_bytes: int) -> bytes:
    _check_regular(path, os.stat(path), max_bytes)  # a device is never opened
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0))
    try:
        st = os.fstat(fd)
        _check_regular(path, st, max_bytes)  # what was opened, should the path have changed meanwhile
        chunks = []
        left = max_bytes + 1
        want = st.st_size + 1
        while left > 0:
            chunk = os.read(fd, min(left, want))
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
            want = 1 << 20
    finally:
        os.close(fd)
    if left <= 0:
        raise _too_large(path, max_bytes)  # it grew while being read
    return b"".join(chunks)


def _check_regular(path: str, st: os.stat_result, max_bytes: int) -> None:
    if not stat.S_ISREG(st.st_mode):
        raise RefusedFileError(path, "not a regular file (a folder, pipe or device is never read as a program)",
                               "不是普通文件（文件夹、管道或设备不会作为程序读取）")  # fmt: skip
    if st.st_size > max_bytes:
        raise _too_large(path, max_bytes)


def _too_large(path: str, max_bytes: int) -> RefusedFileError:
    mb = max_bytes / 1_000_000
    return RefusedFileError(path, f"larger than {mb:g} MB: not read as a program", f"大于 {mb:g} MB，不作为程序读取")


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
    """Program files under ``root`` (itself, if it is not a folder: a pipe or a device named
    outright is refused when read), sorted, hidden folders skipped; a link that leads out of
    ``root`` is skipped too."""
    if not root.is_dir():
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


@dataclass(frozen=True, slots=True)
class ReadScope:
    """Where the program files that a client names may be read: files with a program file's
    name under ``folders`` (a link that leads out of every one of them is not followed), and
    ``files``, real paths that are read whatever their name (the program a debug launch names).
    The language server's workspace folders and a debug launch's folders are such scopes."""

    folders: tuple[Path, ...]
    files: frozenset[str] = frozenset()

    @classmethod
    def of(cls, folders: Iterable[str | Path], files: Iterable[str | Path] = ()) -> ReadScope:
        return cls(tuple(dict.fromkeys(Path(f) for f in folders)), frozenset(os.path.realpath(f) for f in files))

    def refusal(self, path: str | Path) -> RefusedFileError | None:
        """Why ``path`` may not be read (the error that reading it raises), or None."""
        p = Path(path)
        if self.files and os.path.realpath(p) in self.files:
            return None
        if not is_program_file(p):
            return RefusedFileError(p, "not a program file", "不是程序文件")
        if not any(stays_inside(p, f) for f in self.folders):
            where = ", ".join(str(f) for f in self.folders) or "-"
            return RefusedFileError(p, f"not under {where} (a link that leads out of them is not followed)",
                                    f"不在 {where} 之下（不跟随指向其外的链接）")  # fmt: skip
        return None

    def read(self, path: str | Path) -> SourceText:
        """``read_program`` for a path in this scope; ``RefusedFileError`` for one outside it."""
        refused = self.refusal(path)
        if refused is not None:
            raise refused
        return read_program(path)
