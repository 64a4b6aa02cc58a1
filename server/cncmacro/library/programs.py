"""Finding the program that a call names, across the files of a workspace.

``G65 P9100``, ``M98 P0040`` and (on gsk980tdi) ``G65 P[CUT]`` name a program. It is looked
up first among the O programs of the calling file, then in the calling file's folder and each
extra folder, in order: a file named after the number (``O9100.nc``, ``O9100.CNC``,
``9100.nc``, ``O9100``), then any program file whose text has an ``O9100`` header. The program
files of a folder are the ones ``files.is_program_file`` knows (with the machine file's
``extensions``), and every file given to the library by its text (a file named on the command
line, a document open in the editor), whatever its name. A bracketed
name is a file name (``CUT.CNC``), or an O number when it looks like one (``P[O1004]``).
Only files inside those folders are ever read: a name with a path in it is never found, and a
link in a folder that leads out of it (and out of every extra folder) is not followed. Files are
read as any file found in a folder is (``files.read_program``): regular files only, up to
``MAX_PROGRAM_BYTES``; one that is not read is not found. A control holds the programs of its
own memory only: a library told which profile each file is read in (``profile_of``, the name of
``profiles.file_profile``'s answer) finds, for a call, only the programs of files read in the
calling file's profile. So in one folder a FANUC program's ``M98 P2000`` does not find an
``O2000.nc`` marked ``(cncmacro: dialect=gsk980tdi)``, another machine's program, nor does that
GSK980TDi program find the folder's unmarked files (read in the folder's profile); a folder of
one control finds what it always found. Files on disk are read through a
``FileCache`` (``file_cache.py``), which a library may share with others (the language server's
workspace index, the call index), so that a file is read and parsed once until it changes.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from ..bilingual import Detail, detail
from ..dialects import get_dialect
from ..syntax.block_parser import BlockCache, shared_cache
from ..syntax.program import Program, ProgramUnit
from .dialect_choice import HEADER_LINES, dialect_from_text
from .file_cache import FileCache, LoadedFile, load_text
from .files import (
    MAX_PROGRAM_FILES,
    SkippedFileError,
    name_suffix,
    o_number,
    program_files_in,
    shown_text,
    stays_inside,
)

__all__ = ["FileCache", "FoundProgram", "LoadedFile", "ProgramLibrary", "is_program_name", "load_text"]

ON_CONTROL = "(on the control)"  # the path suffix of a program kept on the control
_NAME_OK = re.compile(r"^[\w+\-.\u4e00-\u9fff]+$")


def is_program_name(name: str) -> bool:
    """Whether a bracketed name (``P[CUT]``) is one the control accepts: letters (Chinese
    too), digits, ``+ - _ .``, not starting with ``.`` (seed 001 P[] format two, seed 000
    §3.28.3); any other character is an alarm (291 here, the seeds give no number). A name
    with ``..`` or a path in it is never one."""
    name = name.strip()
    return bool(_NAME_OK.match(name)) and not name.startswith(".") and ".." not in name


@dataclass(slots=True)
class FoundProgram:
    """An O program inside a loaded file."""

    file: LoadedFile
    unit: ProgramUnit

    @property
    def label(self) -> str:
        """How a person names it: ``O9100``, or the file name for a program without header."""
        if self.unit.number is not None:
            return f"O{self.unit.number:04d}"
        return Path(self.file.path).stem


ListingKey = tuple[Path, tuple[Path, ...], frozenset[str]]  # a folder, the library's folders, the endings


@dataclass(frozen=True, slots=True)
class Listing:
    """The program files on disk of a folder, in order, and by their lower-case stem."""

    files: list[Path]
    stems: dict[str, list[Path]]


def forget_listings(listings: dict[ListingKey, Listing], path: str) -> None:
    """A file (or folder) at ``path`` changed on disk: the listings it may have changed go (its
    folder's, when the file came or went there; every one under a folder)."""
    target = Path(path)
    below = os.path.join(path, "")
    exists = os.path.lexists(path)
    for key in [k for k in list(listings) if k[0] == target.parent or k[0] == target or str(k[0]).startswith(below)]:
        if key[0] != target.parent or (target in listings[key].files) != exists:
            del listings[key]


def _by_stem(files: list[Path]) -> dict[str, list[Path]]:
    stems: dict[str, list[Path]] = {}
    for p in files:
        name = p.name
        suffix = name_suffix(name)
        stems.setdefault((name[: -len(suffix)] if suffix else name).lower(), []).append(p)
    return stems


def _header_pattern(number: int) -> re.Pattern[str]:
    """An O``number`` header at the start of a line, or after the end of the program before it
    (``M99O0810``): how a file holds the program whatever its name."""
    return re.compile(rf"(?m)(?:^[ \t/%]*(?:N\d+[ \t]*)?|M0*(?:99|30|2)[ \t]*)O0*{number}(?!\d)", re.I)


class ProgramLibrary:
    """The programs a run may call. ``folders`` are searched after the calling file's own
    folder; ``texts`` maps paths to text that replaces the file on disk (open editors);
    ``files`` reads the files on disk (a cache of its own when none is given); ``absent`` the
    numbers searched for in vain by header, per folder (its own when none is given);
    ``profile_of`` the name of the profile a file (its lines, its path) is read in: a call finds
    only the programs of its own file's profile, its machine's (None: every program is found)."""

    def __init__(
        self,
        folders: Sequence[str | Path] | None = None,
        texts: dict[str, str] | None = None,
        cache: BlockCache | None = None,
        files: FileCache | None = None,
        extensions: frozenset[str] = frozenset(),
        absent: dict[Path, set[int]] | None = None,
        listings: dict[ListingKey, Listing] | None = None,
        profile_of: Callable[[list[str], str], str] | None = None,
    ) -> None:
        self.folders = [Path(f) for f in folders or []]
        self.extensions = extensions  # the machine file's endings of program files
        self.texts = dict(texts or {})
        self.cache = cache if cache is not None else shared_cache
        self.disk = files if files is not None else FileCache(self.cache)
        self._files: dict[str, LoadedFile | None] = {}
        self._listing: dict[Path, list[Path]] = {}
        self._stems: dict[Path, dict[str, list[Path]]] = {}  # folder -> lower-case stem -> its files
        # folder -> the numbers its files' headers were searched for in vain, kept as the listing is;
        # ``absent``, when given, is kept by the owner across libraries, which drops a folder's entry
        # when a file there changes (the language server's workspace index)
        self._absent: dict[Path, set[int]] = absent if absent is not None else {}
        self._given: set[str] = set(self.texts)  # files given by their text: programs whatever their name
        # the program files on disk of each folder and their stems; ``listings``, when given, is
        # kept by the owner across libraries, which drops a folder's entry when a file comes or
        # goes there (the language server's workspace index: a hover or look-up lists no folder)
        self._disk_listings: dict[ListingKey, Listing] = listings if listings is not None else {}
        self.unread: dict[str, Detail] = {}  # files that could not be read, and why
        self.profile_of = profile_of
        self._profiles: dict[tuple[str, tuple[str, ...]], str] = {}  # each file's profile, by its head
        self.elsewhere: dict[str, str] = {}  # files passed over as another machine's, and their profile

    # ---- files
    def load(self, path: str | Path) -> LoadedFile | None:
        """The parsed file at ``path``; None when it cannot be read or is binary."""
        key = str(path)
        if key in self._files:
            return self._files[key]
        text = self.texts.get(key)
        if text is None:
            try:
                loaded = self.disk.load(key)
            except OSError as e:  # a file a DNC program holds open on Windows, one we may not read
                self._files[key] = None
                shown, why = shown_text(key), e.strerror or str(e)
                self.unread[key] = detail(f"{shown} could not be read: {why}", f"无法读取 {shown}：{why}")
                return None
            except SkippedFileError as e:
                self._files[key] = None
                self.unread[key] = e.message
                return None
        else:
            loaded = load_text(key, text, self.cache)
        self._files[key] = loaded
        return loaded

    def add_text(self, path: str, text: str) -> LoadedFile:
        """Load ``text`` as the content of ``path`` (a file given on the command line or open
        in the editor)."""
        self.texts[path] = text
        self._files.pop(path, None)
        self._absent.pop(Path(path).parent, None)  # its text may now hold a header searched for
        self._give(path)
        loaded = self.load(path)
        assert loaded is not None
        return loaded

    def add_parsed(self, path: str, lines: list[str], program: Program) -> LoadedFile:
        """Register a file that the caller keeps parsed (a document open in an editor): it
        replaces the file on disk, and nothing is read or parsed again."""
        self.texts.pop(path, None)
        self._absent.pop(Path(path).parent, None)  # its text may now hold a header searched for
        self._give(path)
        loaded = self._files[path] = LoadedFile(path, lines, program, dialect_from_text(lines))
        return loaded

    def _give(self, path: str) -> None:
        """``path`` is a program of its folder from now on, whatever its name."""
        if path not in self._given:
            self._given.add(path)
            folder = Path(path).parent
            self._listing.pop(folder, None)
            self._stems.pop(folder, None)
            self._absent.pop(folder, None)

    def read_from_disk(self) -> tuple[list[str], list[str]]:
        """What this library's answers rest on: the files it read (or failed to read) from disk
        and the folders it listed. Files registered by ``add_parsed`` are among the first: the
        caller knows which of them it keeps itself."""
        files = [p for p, f in self._files.items() if p not in self.texts and (f is None or not f.on_control)]
        return files, [str(f) for f in self._listing]

    def sees(self, path: str) -> bool:
        """Whether a change on disk at ``path`` (a file, or a folder and all below it) may change
        this library's answers: it read the file or tried to, or it listed the file's folder and
        the file came or went there, or it searched that folder's headers for a number in vain
        (the file's header may hold it now). A file it never looked at changes nothing."""
        if path in self._files:
            return True
        below = os.path.join(path, "")
        if any(k.startswith(below) for k in self._files) or any(
            str(f) == path or str(f).startswith(below) for f in self._listing
        ):
            return True
        target = Path(path)
        listed = self._listing.get(target.parent)
        if listed is None:
            return False
        if (target in listed) != os.path.isfile(path):
            return True
        searched = self._absent.get(target.parent)
        if not searched or target not in listed[:MAX_PROGRAM_FILES]:
            return False
        try:
            text = self.texts.get(path) or self.disk.text(path)
        except (OSError, SkippedFileError):
            return True
        return any(_header_pattern(n).search(text) for n in searched)

    def _stems_in(self, folder: Path) -> dict[str, list[Path]]:
        """The program files of ``folder`` by their lower-case stem (the whole name when it has
        no ending), so that a program is found by its number without a walk of the folder."""
        stems = self._stems.get(folder)
        if stems is None:
            files = self._folder_files(folder)
            on_disk = self._on_disk(folder)
            stems = self._stems[folder] = on_disk.stems if files is on_disk.files else _by_stem(files)
        return stems

    def _folder_files(self, folder: Path) -> list[Path]:
        files = self._listing.get(folder)
        if files is None:
            files = self._on_disk(folder).files
            given = [p for p in self._given if Path(p).parent == folder]
            if given:
                listed = {str(p) for p in files}
                files = files + sorted(Path(p) for p in given if p not in listed)
            self._listing[folder] = files
        return files

    def list_folders(self) -> None:
        """List each of the library's folders now, into the ``listings`` it shares (the language
        server does so in the background at start, before the first hover on a call needs them)."""
        for folder in self.folders:
            self._on_disk(folder)

    def _on_disk(self, folder: Path) -> Listing:
        """The program files on disk in ``folder`` (kept in ``listings``)."""
        key = (folder, tuple(self.folders), self.extensions)
        listing = self._disk_listings.get(key)
        if listing is None:
            allowed = [folder, *self.folders]
            # a file that is no link is in ``folder``, which is allowed: only a link is followed to
            # see where it leads (a folder of 100,000 files resolved each twice: 6 s)
            files = [p for p, link in program_files_in(folder, self.extensions)
                     if not link or any(stays_inside(p, f) for f in allowed)]  # fmt: skip
            listing = self._disk_listings[key] = Listing(files, _by_stem(files))
        return listing

    def _search_folders(self, near: LoadedFile | None) -> list[Path]:
        folders: list[Path] = []
        if near is not None:
            folders.append(Path(near.path).parent)
        for f in self.folders:
            if f not in folders:
                folders.append(f)
        return folders

    # ---- lookup
    def on_machine(self, found: LoadedFile, near: LoadedFile | None) -> bool:
        """Whether a call in ``near`` may run a program of ``found``: the two files are read in
        one profile, so they are programs of one machine's memory (see the module docstring).
        A file of another profile is noted in ``elsewhere`` for the message of a program not
        found."""
        if self.profile_of is None or near is None or found.path == near.path:
            return True
        theirs = self._profile(found)
        if theirs == self._profile(near):
            return True
        self.elsewhere[found.path] = theirs
        return False

    def _profile(self, file: LoadedFile) -> str:
        """The profile ``file`` is read in, by ``profile_of``: of the lines the library holds for
        its path when ``file`` comes without them (a check's view of the file it checks). Kept
        by path and first lines, where a dialect comment may be (an edit may change it)."""
        assert self.profile_of is not None
        lines = file.lines
        if not lines:
            held = self._files.get(file.path)
            lines = held.lines if held is not None else lines
        key = (file.path, tuple(lines[:HEADER_LINES]))
        name = self._profiles.get(key)
        if name is None:
            name = self._profiles[key] = self.profile_of(lines, file.path)
        return name

    def find_number(self, number: int, near: LoadedFile | None = None) -> FoundProgram | None:
        """The program O``number``, searched as the module docstring says."""
        if near is not None:
            unit = near.program.unit_numbered(number)
            if unit is not None:
                return FoundProgram(near, unit)
        folders = self._search_folders(near)
        for folder in folders:
            for p in self._named_for(folder, number):
                found = self._unit_in(p, number, near)
                if found is not None:
                    return found
        header = _header_pattern(number)
        for folder in folders:
            absent = self._absent.setdefault(folder, set())
            if number in absent:  # searched in vain before: a folder of 100,000 files is not read again
                continue
            found, held = self._header_in(folder, number, header, near)
            if found is not None:
                return found
            if not held:  # no file there holds it, of any machine (another may look for it)
                absent.add(number)
        return None

    def _header_in(
        self, folder: Path, number: int, header: re.Pattern[str], near: LoadedFile | None
    ) -> tuple[FoundProgram | None, bool]:
        """O``number`` in a file of ``folder`` whatever its name, by its header: the first
        ``MAX_PROGRAM_FILES`` files only, so that a lookup in a huge folder stays bounded; and
        whether a file there holds it, if only another machine's."""
        held = False
        for p in self._folder_files(folder)[:MAX_PROGRAM_FILES]:
            loaded = self._files.get(str(p))
            if loaded is None:
                text = self.texts.get(str(p))
                if text is None:
                    try:
                        text = self.disk.text(str(p))
                    except (OSError, SkippedFileError):
                        continue
                if not header.search(text):
                    continue
                loaded = self.load(p)  # parsed from the text just searched (the cache keeps it)
                if loaded is None:
                    continue
            unit = loaded.program.unit_numbered(number)
            if unit is None:
                continue
            held = True
            if self.on_machine(loaded, near):
                return FoundProgram(loaded, unit), held
        return None, held

    def control_program(self, number: int) -> FoundProgram:
        """O``number`` as a program kept on the control (a machine file's
        ``programs_on_control``) and found in no folder: a program that returns at once. A file
        in the workspace with that number (a stub that sets what the callers read) wins over it,
        because ``find_number`` finds it first."""
        path = f"O{number:04d} {ON_CONTROL}"
        loaded = self._files.get(path)
        if loaded is None:
            loaded = load_text(path, f"O{number:04d}\nM99\n", self.cache)
            loaded.on_control = True
            self._files[path] = loaded
        unit = loaded.program.unit_numbered(number)
        assert unit is not None
        return FoundProgram(loaded, unit)

    def find_name(self, name: str, near: LoadedFile | None = None) -> FoundProgram | None:
        """A program named by a bracketed name (``P[CUT]``): a file name, or ``O1004``."""
        name = name.strip()
        number = o_number(name)
        if number is not None:
            return self.find_number(number, near)
        if not is_program_name(name):
            return None
        wanted = name.lower()
        for folder in self._search_folders(near):
            for p in self._folder_files(folder):
                if p.stem.lower() == wanted or p.name.lower() == wanted:
                    loaded = self.load(p)
                    if loaded is not None and self.on_machine(loaded, near):
                        return FoundProgram(loaded, loaded.program.named_units()[0])
        return None

    def _named_for(self, folder: Path, number: int) -> list[Path]:
        """The files of ``folder`` whose name spells program ``number`` (``O1234.nc``, ``1234``)."""
        names = {f"o{number:04d}", f"o{number}", f"{number:04d}", f"{number}", f"o{number:08d}"}
        stems = self._stems_in(folder)
        return sorted(p for name in names for p in stems.get(name, ()))

    def unread_for(self, number: int, near: LoadedFile | None = None) -> Detail | None:
        """Why a file named for program ``number`` was not found by ``find_number``: it could
        not be read (a DNC program holding it open, a binary or too large a file), or it is
        another machine's program (``on_machine``), for the message of a program not found:
        the file is there."""
        for folder in self._search_folders(near):
            for p in self._named_for(folder, number):
                why = self.unread.get(str(p))
                if why is not None:
                    return why
                other = self.elsewhere.get(str(p))
                if other is not None:
                    shown, title = shown_text(str(p)), get_dialect(other).title
                    return detail(f"{shown} is a {title} program, another machine's",
                                  f"{shown} 是 {title} 的程序，属于另一台机床")  # fmt: skip
        return None

    def _unit_in(self, path: Path, number: int, near: LoadedFile | None) -> FoundProgram | None:
        loaded = self.load(path)
        if loaded is None or not self.on_machine(loaded, near):
            return None
        unit = loaded.program.unit_numbered(number)
        if unit is None:
            first = loaded.program.units[0]
            if first.number is not None:
                return None  # the file names another program in its header
            unit = first
        return FoundProgram(loaded, unit)
