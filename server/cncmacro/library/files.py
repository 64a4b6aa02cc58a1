"""Reading program files as controls and editors write them.

Files come as UTF-8 (with or without a BOM), as GBK/GB18030 from Chinese controls and
editors, with LF, CRLF or CR line breaks. Text is decoded UTF-8 first and GB18030 second; bytes
that neither accepts are kept as surrogate escapes, so nothing is lost when the text is
written back. A file with NUL bytes or mostly control characters is binary: it is reported,
not parsed.

A workspace is anybody's folder, so everything here is read as untrusted (docs/design.md
"Untrusted folders and files"). Files are opened in one place, ``read_bytes``: only regular
files (a FIFO or a device is never waited on), and a file found by searching a folder only up to
``MAX_PROGRAM_BYTES``; anything else is a ``SkippedFileError`` that says why. Folders are searched
without recursion, so any depth is fine; a folder that cannot be read is named in the result, not
raised. A search for a workspace index stops at ``MAX_PROGRAM_FILES`` program files and
``MAX_FOLDER_ENTRIES`` entries, saying so, and the index reads ``MAX_INDEX_BYTES`` in all. A file
name that is not UTF-8 (a GBK name from a Chinese Windows zip) is kept as the system gives it
(surrogate escapes), so that the file can be read; ``shown_text`` turns it into text for people
and JSON.

A path that a client names (an editor's file event, a debugger's ``source`` or breakpoint) is
read with ``ReadScope``: a program file under the folders the front end works in (a link that
leads out of them not followed), or a file the scope names outright (the program a debug launch
runs), up to ``MAX_NAMED_BYTES``; anything else is a ``RefusedFileError`` that says why.
"""

from __future__ import annotations

import codecs
import os
import re
import stat
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from ..bilingual import Detail, detail

# Program files are found by these endings (any case), the endings a machine file adds
# (``extensions``), an O-number name without one, or text that starts as a program does.
PROGRAM_SUFFIXES = frozenset({".nc", ".cnc", ".mac", ".prg", ".tap", ".eia"})
# How much of a file with another ending is read to see whether it starts as a program does: ``%``,
# ``O1234`` or ``<NAME>`` after blank lines and comments (a GSK or DNC folder of ``.txt`` programs)
HEAD_BYTES = 512
# ``%`` alone on its line, ``O1234`` (not ``O1st``), or a program name ``<CUT-1.NC>`` (upper case,
# as a control writes it: ``<html>`` and ``<?xml`` are no programs)
_PROGRAM_HEADER = re.compile(rb"(?:%[ \t]*(?:\r?\n|\r|$)|[Oo]\d+(?![\w.])|<[A-Z0-9_][A-Z0-9_.+\-]*>)")
# A name that spells a program number: O, or no O, then digits (``O1234``, ``o0040``, ``1234``).
_O_NUMBER = re.compile(r"([Oo]?)(\d+)")
MAX_NUMBER_DIGITS = 8  # the longest program number of any control (O12345678)
# A program file found by searching a folder (not one named by the person) is read up to this
# size: a larger one is skipped and named. 8 MB is some 250,000 lines.
MAX_PROGRAM_BYTES = 8_000_000
MAX_PROGRAM_FILES = 5_000  # program files a search for a workspace index takes
MAX_FOLDER_ENTRIES = 100_000  # folder entries such a search looks at (a workspace folder of "/")
MAX_INDEX_BYTES = 32_000_000  # program text a workspace index reads in all (some 10 s of parsing)
MAX_NAMED_BYTES = 64_000_000  # a file a client names: far beyond any program (a million CAM lines is 35 MB)


class SkippedFileError(Exception):
    """A file that is not read as a program: binary, too large, or not a regular file.
    ``message`` says why in English and in Chinese (``str`` of the error is the English)."""

    def __init__(self, path: str, message: Detail) -> None:
        super().__init__(message)
        self.message = message
        self.path = path


class BinaryFileError(SkippedFileError):
    """The file is not text; ``offset`` is where the first NUL (or the evidence) is."""

    def __init__(self, path: str, offset: int) -> None:
        shown = shown_text(path)
        super().__init__(path, detail(
            f"{shown}: binary file (byte at offset {offset} is not program text), not a program",
            f"{shown}：二进制文件（偏移 {offset} 处的字节不是程序文本），不是程序",
        ))  # fmt: skip
        self.offset = offset


class FileTooLargeError(SkippedFileError):
    """The file is larger than what may be read of it (``size`` > ``limit`` bytes)."""

    def __init__(self, path: str, size: int, limit: int) -> None:
        shown = shown_text(path)
        super().__init__(path, detail(
            f"{shown}: {size:,} bytes, over the limit of {limit:,}: not read",
            f"{shown}：{size:,} 字节，超过 {limit:,} 字节的上限：未读取",
        ))  # fmt: skip
        self.size = size
        self.limit = limit


class NotAFileError(SkippedFileError):
    """The path is a FIFO, a device, a socket or a folder: nothing a program is kept in."""

    def __init__(self, path: str, mode: int) -> None:
        shown = shown_text(path)
        what, zh = _KINDS.get(stat.S_IFMT(mode), ("not a regular file", "不是普通文件"))
        super().__init__(path, detail(f"{shown}: {what}: not read", f"{shown}：{zh}：未读取"))


_KINDS = {
    stat.S_IFIFO: ("a FIFO (named pipe), not a file", "是命名管道（FIFO），不是文件"),
    stat.S_IFCHR: ("a device, not a file", "是设备，不是文件"),
    stat.S_IFBLK: ("a device, not a file", "是设备，不是文件"),
    stat.S_IFSOCK: ("a socket, not a file", "是套接字，不是文件"),
    stat.S_IFDIR: ("a folder, not a file", "是文件夹，不是文件"),
}
# O_NONBLOCK: a FIFO swapped in after the check still opens at once; O_NOCTTY: a terminal
# never becomes this process's
_OPEN_FLAGS = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0) | getattr(os, "O_BINARY", 0)


def read_bytes(path: str | Path, max_bytes: int | None) -> bytes:
    """The bytes of the regular file at ``path``: the one place files are opened for reading.
    Anything but a regular file is a ``NotAFileError`` (looked at before it is opened, and again
    once it is open, so that nothing can block); a file of more than ``max_bytes`` (None: no
    limit) is a ``FileTooLargeError``. ``OSError`` passes through."""
    name = os.fspath(path)
    mode = os.stat(name).st_mode
    if not stat.S_ISREG(mode):
        raise NotAFileError(name, mode)
    fd = os.open(name, _OPEN_FLAGS)
    with open(fd, "rb", closefd=True) as f:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise NotAFileError(name, st.st_mode)
        if max_bytes is None:
            return f.read()
        if st.st_size > max_bytes:
            raise FileTooLargeError(name, st.st_size, max_bytes)
        data = f.read(max_bytes + 1)  # a file that grew since is found too large here
        if len(data) > max_bytes:
            raise FileTooLargeError(name, max(len(data), st.st_size), max_bytes)
        return data


@dataclass(slots=True)
class SourceText:
    """Decoded file text and the encoding it was read with."""

    text: str
    encoding: str
    bom: bool = False


# the control characters that mark binary data: all below a space but tab, line feed, form
# feed, carriage return and the DOS end of file (Ctrl-Z)
_CONTROL_BYTES = bytes(b for b in range(32) if b not in (9, 10, 12, 13, 26))


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
        controls = len(sample) - len(sample.translate(None, _CONTROL_BYTES))
        if controls * 10 > len(sample):
            first = next(i for i, b in enumerate(sample) if b in _CONTROL_BYTES)
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


def read_program(path: str | Path, max_bytes: int | None = MAX_PROGRAM_BYTES) -> SourceText:
    """Read and decode a program file (``OSError`` and ``SkippedFileError`` pass through). A
    file the person named (on the command line, in a launch, a breakpoint's file) is read
    whole with ``max_bytes=None``; a file found by searching a folder only up to the limit."""
    return decode_program(read_bytes(path, max_bytes), os.fspath(path))


def encode_program(source: SourceText) -> bytes:
    """The bytes of ``source`` in the encoding it was read with (the inverse of decoding)."""
    prefix = b""
    if source.bom and source.encoding == "utf-8":
        prefix = codecs.BOM_UTF8
    if source.encoding == "utf-16":
        return source.text.encode("utf-16", errors="surrogatepass")
    return prefix + source.text.encode(source.encoding, errors="surrogateescape")


def o_number(name: str, bare: bool = False) -> int | None:
    """The program number that ``name`` spells, ``O1234`` or ``o1234`` (1 to 8 digits), or None.
    With ``bare`` the O may be left out: a file's stem (``1234.nc`` is named after O1234, as
    ``ProgramLibrary.find_number`` looks for it); a bracketed name (``P[O1004]``) needs it."""
    m = _O_NUMBER.fullmatch(name)
    if m is None or len(m.group(2)) > MAX_NUMBER_DIGITS or not (m.group(1) or bare):
        return None
    return int(m.group(2))


def is_program_file(path: Path, extensions: frozenset[str] = frozenset()) -> bool:
    """True for a file that holds a program: the one rule of which files are programs, for the
    checker's folder search, the callee search of a run, the editor and the debugger. Its name
    says so (a known ending, one of the machine file's ``extensions``, or ``O1234`` without an
    ending: an O and digits, however many, ``O123456789`` is read though it names no number), or
    its first ``HEAD_BYTES`` do (``starts_like_program``)."""
    if _named_as_program(path, extensions):
        return True
    return starts_like_program(path)


def program_files_looked_for(extensions: frozenset[str] = frozenset()) -> Detail:
    """What ``is_program_file`` takes for a program, for a person told that a folder has none."""
    endings = ", ".join(sorted(PROGRAM_SUFFIXES | extensions))
    return detail(
        f"files ending in {endings} (any case), files named O1234 without an ending, and files whose text "
        "starts with %, O1234 or <NAME>",
        f"扩展名为 {endings}（不分大小写）的文件、无扩展名的 O1234 文件，以及内容以 %、O1234 或 <名称> 开头的文件",
    )


def _named_as_program(path: Path, extensions: frozenset[str]) -> bool:
    return _name_is_program(path.name, extensions)


def name_suffix(name: str) -> str:
    """A file name's ending as ``PurePath.suffix`` has it (``O1.nc``: ``.nc``; ``.nc``, ``a.``:
    none), without making a path: a folder of 100,000 files is listed in a third of the time."""
    i = name.rfind(".")
    return name[i:] if 0 < i < len(name) - 1 else ""


def _name_is_program(name: str, extensions: frozenset[str]) -> bool:
    suffix = name_suffix(name)
    lowered = suffix.lower()
    if lowered in PROGRAM_SUFFIXES or lowered in extensions:
        return True
    m = _O_NUMBER.fullmatch(name)
    return not suffix and m is not None and bool(m.group(1))


def starts_like_program(path: Path) -> bool:
    """Whether the regular file at ``path`` starts as a program does: ``%``, ``O1234`` or a
    ``<NAME>`` header after blank lines and comments. Only its first ``HEAD_BYTES`` are read; a
    file with a NUL there (binary), one that is no regular file or cannot be read is not one."""
    try:
        head = _read_head(path)
    except OSError:
        return False
    if b"\0" in head:
        return False
    at = 3 if head.startswith(codecs.BOM_UTF8) else 0
    while at < len(head):  # past blank lines and comments: ``( ... )`` to its close, ``;`` to the line's end
        byte = head[at : at + 1]
        if byte.isspace():
            at += 1
        elif byte in (b"(", b";"):
            ends = [e for e in (head.find(b")" if byte == b"(" else b"\n", at), head.find(b"\n", at)) if e >= 0]
            if not ends:
                return False
            at = min(ends) + 1
        else:
            return _PROGRAM_HEADER.match(head, at) is not None
    return False


def _read_head(path: Path) -> bytes:
    """The first ``HEAD_BYTES`` of the regular file at ``path`` (``b""`` for anything else, and
    for a file that says it is empty: the files of ``/proc`` are never read)."""
    name = os.fspath(path)
    st = os.stat(name)
    if not stat.S_ISREG(st.st_mode) or st.st_size == 0:  # an empty file, or one of /proc's
        return b""
    fd = os.open(name, _OPEN_FLAGS)
    with open(fd, "rb", closefd=True) as f:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            return b""
        return f.read(HEAD_BYTES) or b""  # None: nothing to read yet (a non-blocking read)


@dataclass(slots=True)
class FolderSearch:
    """The program files a search found (sorted), what it could not read (folders, as
    messages), and whether it looked everywhere (False when a limit stopped it)."""

    files: list[Path] = field(default_factory=list)
    skipped: list[Detail] = field(default_factory=list)
    complete: bool = True


def search_program_files(
    root: Path, max_files: int | None = None, max_entries: int | None = None, extensions: frozenset[str] = frozenset()
) -> FolderSearch:
    """Program files under ``root`` (itself, if it is not a folder: a file the person names is a
    program whatever its name), as ``is_program_file`` knows them (``extensions``: the machine
    file's), hidden folders and files
    skipped, links to folders not followed, a link to a file only when it stays inside
    ``root``. The folders are walked one after another, never by recursion, so any depth is
    fine (a path too long for the system is a folder that cannot be read). A folder that cannot
    be read is named in ``skipped``; the search stops after ``max_files`` program files or
    ``max_entries`` folder entries (None: no limit), saying so."""
    found = FolderSearch()
    if not os.path.isdir(root):
        found.files.append(root)
        return found
    shown = shown_text(str(root))
    entries = 0
    pending = [root]
    while pending and found.complete:
        folder = pending.pop()
        inside: list[Path] = []
        try:
            with os.scandir(folder) as listing:
                for entry in listing:
                    entries += 1
                    if max_entries is not None and entries > max_entries:
                        found.complete = False
                        found.skipped.append(detail(
                            f"{shown}: more than {max_entries:,} entries: the search for program files stopped there",
                            f"{shown}：条目超过 {max_entries:,} 个：程序文件的查找到此为止"))  # fmt: skip
                        break
                    path = _program_entry(entry, root, inside, extensions)
                    if path is None:
                        continue
                    if max_files is not None and len(found.files) == max_files:
                        found.complete = False
                        found.skipped.append(detail(
                            f"{shown}: more than {max_files:,} program files: only the first {max_files:,} are read",
                            f"{shown}：程序文件超过 {max_files:,} 个：只读取前 {max_files:,} 个"))  # fmt: skip
                        break
                    found.files.append(path)
        except OSError as e:
            reason = e.strerror or str(e)
            where = shown_text(str(folder))
            found.skipped.append(detail(
                f"{where}: cannot read the folder ({reason}): its program files are not read",
                f"{where}：无法读取文件夹（{reason}）：其中的程序文件未读取"))  # fmt: skip
        pending.extend(sorted(inside, reverse=True))  # depth first, in name order
    found.files.sort()
    return found


def _program_entry(entry: os.DirEntry[str], root: Path, folders: list[Path], extensions: frozenset[str]) -> Path | None:
    """The path of ``entry`` when it is a program file to read; a folder to search is added
    to ``folders`` (not a hidden one, not a link)."""
    if entry.name.startswith("."):
        return None
    path = Path(entry.path)
    try:
        link = entry.is_symlink()
        if entry.is_dir():
            if not link:
                folders.append(path)
            return None
        is_file = entry.is_file()
    except OSError:
        link, is_file = True, True  # cannot be looked at: reading it says why
    if is_file and is_program_file(path, extensions) and (not link or stays_inside(path, root)):
        return path
    return None


def find_program_files(root: Path, extensions: frozenset[str] = frozenset()) -> list[Path]:
    """Program files under ``root`` (itself, if it is a file), sorted, as ``search_program_files``
    finds them without limits (folders that cannot be read are left out)."""
    return search_program_files(root, extensions=extensions).files


def program_files_in(folder: Path, extensions: frozenset[str] = frozenset()) -> list[tuple[Path, bool]]:
    """The program files directly in ``folder`` (not below it), as ``is_program_file`` knows them
    (``extensions``: the machine file's), sorted as paths sort, each with whether it is a link
    (the listing says so without asking the disk again); none when it cannot be read, at most
    ``MAX_FOLDER_ENTRIES`` entries looked at."""
    found: list[tuple[str, str, bool]] = []
    try:
        with os.scandir(folder) as listing:
            for k, entry in enumerate(listing):
                if k >= MAX_FOLDER_ENTRIES:
                    break
                try:
                    if entry.is_file() and (
                        _name_is_program(entry.name, extensions) or starts_like_program(Path(entry.path))
                    ):  # is_program_file
                        found.append((os.path.normcase(entry.name), entry.path, entry.is_symlink()))
                except OSError:
                    continue
    except OSError:
        return []
    found.sort()  # one folder's files: by name, as pathlib orders them (case-folded on Windows)
    return [(Path(path), link) for _, path, link in found]


def stays_inside(path: Path, folder: Path) -> bool:
    """True when ``path``, its links followed, is ``folder`` or inside it (with its links
    followed): a link in a workspace that leads elsewhere on the disk is not read."""
    try:
        return path.resolve().is_relative_to(folder.resolve())
    except (OSError, RuntimeError):  # a link loop
        return False


_ESCAPES = re.compile("[\udc80-\udcff]+|[\ud800-\udfff]")


def shown_text(text: str) -> str:
    """``text`` fit to show and to write as UTF-8: the bytes that a file name (or file) kept as
    surrogate escapes are decoded as GB18030, as program text is, where they read as it (the
    GBK name ``\\xb3\\xcc\\xd0\\xf2.nc`` shows as ``程序.nc``), else each becomes U+FFFD."""
    if text.isascii():
        return text
    return _ESCAPES.sub(_shown_bytes, text)


def _shown_bytes(m: re.Match[str]) -> str:
    run = m.group()
    if not "\udc80" <= run[0] <= "\udcff":
        return "\ufffd"  # a lone surrogate that is no escaped byte
    return bytes(ord(c) - 0xDC00 for c in run).decode("gb18030", errors="replace")


class RefusedFileError(SkippedFileError):
    """A path a client named that is not read: not a program file, or outside the folders it
    must be in. ``reason`` says why without the path."""

    def __init__(self, path: str | Path, en: str, zh: str) -> None:
        shown = shown_text(os.fspath(path))
        super().__init__(os.fspath(path), detail(f"{shown}: {en}", f"{shown}：{zh}"))
        self.reason = detail(en, zh)


@dataclass(frozen=True, slots=True)
class ReadScope:
    """Where the program files that a client names may be read: files with a program file's
    name under ``folders`` (a link that leads out of every one of them is not followed), and
    ``files``, real paths that are read whatever their name (the program a debug launch names).
    The language server's workspace folders and a debug launch's folders are such scopes."""

    folders: tuple[Path, ...]
    files: frozenset[str] = frozenset()
    extensions: frozenset[str] = frozenset()  # the machine file's endings of program files

    @classmethod
    def of(
        cls, folders: Iterable[str | Path], files: Iterable[str | Path] = (), extensions: frozenset[str] = frozenset()
    ) -> ReadScope:
        return cls(tuple(dict.fromkeys(Path(f) for f in folders)), frozenset(os.path.realpath(f) for f in files),
                   extensions)  # fmt: skip

    def refusal(self, path: str | Path) -> RefusedFileError | None:
        """Why ``path`` may not be read (the error that reading it raises), or None."""
        p = Path(path)
        if self.files and os.path.realpath(p) in self.files:
            return None
        if not is_program_file(p, self.extensions):
            return RefusedFileError(p, "not a program file", "不是程序文件")
        if not any(stays_inside(p, f) for f in self.folders):
            where = ", ".join(shown_text(str(f)) for f in self.folders) or "-"
            return RefusedFileError(p, f"not under {where} (a link that leads out of them is not followed)",
                                    f"不在 {where} 之下（不跟随指向其外的链接）")  # fmt: skip
        return None

    def read(self, path: str | Path, max_bytes: int | None = MAX_NAMED_BYTES) -> SourceText:
        """``read_program`` for a path in this scope; ``RefusedFileError`` for one outside it."""
        refused = self.refusal(path)
        if refused is not None:
            raise refused
        return read_program(path, max_bytes)
