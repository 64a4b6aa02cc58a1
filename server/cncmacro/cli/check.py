"""``cncmacro check``: report the diagnostics of program files, as text, JSON or SARIF.

The files are grouped by their machine settings (``--machine``, else the ``.cncmacro.toml``
nearest to each file, else the defaults) and each group is opened in a ``WorkspaceAnalysis``
with its own settings (call codes, presets, severities): syntax, the static checks, and what bounded
runs of the machine find (from each program nothing calls; called programs through their
callers, also those on disk in the checked files' folders and the search paths, whose own
findings are not printed). A call finds its program in the folder of any checked file (one
machine's programs, held in one memory on the control) and in the search paths. Hints
(``not-executed``) are printed only with ``--hints``. Exit status: 0 when no
error was found, 1 when one was, 2 on bad usage or unreadable input (a missing path, a binary
file, a folder or file that cannot be read, a folder in which no file is a program, a file found
in a folder that is larger than ``MAX_PROGRAM_BYTES`` or is no regular file, a bad machine
file). Whatever is not read is named on standard error; the others are still checked.
``--dialect`` wins over the machine file's profile, and what a person should know of a
machine file (that override, the common ranges it adds to the profile's) is a note on standard
error. A file name that is not UTF-8 is written as
``files.shown_text`` shows it (SARIF's URIs keep its bytes). ``--locale zh-CN`` writes the
messages and what goes to standard error in Chinese; the format around them
(``file:line:col: severity: message [code]``, the JSON and SARIF keys and values other than the
message) is a contract and stays as it is. Control characters in file names and messages are
shown escaped in the text output and on standard error (``terminal``).
"""

from __future__ import annotations

import argparse
import gc
import logging
import sys
from collections.abc import Callable
from functools import partial
from pathlib import Path
from typing import TextIO

from .. import __version__
from ..analysis import Diagnostic
from ..analysis.faults import FILE, internal_error
from ..analysis.indexes.call_index import CallIndex
from ..analysis.workspace import WorkspaceAnalysis
from ..bilingual import Detail, detail, in_language, is_chinese, pick
from ..library.callee_folders import callee_folders
from ..library.file_cache import FileCache
from ..library.files import (
    MAX_PROGRAM_BYTES,
    SkippedFileError,
    program_files_looked_for,
    read_program,
    search_program_files,
    shown_text,
)
from ..library.machine_file import (
    MachineFileError,
    MachineSettings,
    common_note,
    find_machine_file,
    load_machine_file,
)
from ..library.profiles import typed_profile_wins
from ..syntax.document import ParsedDocument
from .call_groups import call_groups
from .findings_report import FindingsReport
from .terminal import Printable

log = logging.getLogger(__name__)


def check_paths(
    paths: list[str],
    out: TextIO,
    err: TextIO,
    fmt: str = "text",
    *,
    dialect: str | None = None,
    search_paths: list[str] | None = None,
    locale: str = "en",
    max_blocks: int | None = None,
    machine: str | None = None,
    hints: bool = False,
) -> int:
    """Check every program file under ``paths``; print the findings; return the exit status."""
    chinese = is_chinese(locale)
    shown_err = Printable(err)
    if max_blocks is not None and max_blocks < 1:
        print(pick(locale, "cncmacro check: --max-blocks must be at least 1", "cncmacro check：--max-blocks 至少为 1"),
              file=shown_err)  # fmt: skip
        return 2
    unreadable: set[Path] = set()

    def read(path: Path) -> str | None:
        """The text of a program file; None, said once on standard error, when it cannot be read."""
        text = None if path in unreadable else _read(path, found_paths[path], locale, shown_err)
        if text is None:
            unreadable.add(path)
        return text

    missing = False
    found_paths: dict[Path, bool] = {}  # each program file, and whether it was found in a folder
    for arg in paths:
        root = Path(arg)
        try:
            root.stat()
        except OSError as e:
            shown, why = shown_text(arg), e.strerror or e
            if isinstance(e, (FileNotFoundError, NotADirectoryError)):
                en, zh = f"cncmacro: {shown}: no such file or folder", f"cncmacro：{shown}：文件或文件夹不存在"
            else:
                en, zh = f"cncmacro: {shown}: cannot read: {why}", f"cncmacro：{shown}：无法读取：{why}"
            print(pick(locale, en, zh), file=shown_err)
            missing = True
            continue
        try:
            found, problems = _program_files(root, machine)
        except MachineFileError as e:
            reason = in_language(e.located(), chinese)
            print(f"cncmacro check：{reason}" if chinese else f"cncmacro check: {reason}", file=shown_err)
            return 2
        for problem in problems:
            print(f"cncmacro：{problem.zh}" if chinese else f"cncmacro: {problem}", file=shown_err)
            missing = True
        searched = root.is_dir()  # a file named on the command line is read whole
        for path in found:
            found_paths.setdefault(path, searched)
            read(path)  # what cannot be read is said now, in the order of the paths; the text is read again
    by_machine: dict[Path | None, list[Path]] = {}
    for path in found_paths:
        by_machine.setdefault(Path(machine) if machine else find_machine_file(path), []).append(path)
    checks: list[_MachineCheck] = []
    for machine_file, files in by_machine.items():  # each file with the machine settings nearest to it
        try:
            checks.append(_machine_check(machine_file, files, dialect, search_paths or [], locale, max_blocks,
                                         shown_err))  # fmt: skip
        except (MachineFileError, ValueError) as e:
            said: str = e.located() if isinstance(e, MachineFileError) else e.args[0] if e.args else str(e)
            reason = in_language(said, chinese)
            print(f"cncmacro check：{reason}" if chinese else f"cncmacro check: {reason}", file=shown_err)
            return 2

    report = FindingsReport(out, fmt, hints, __version__)
    for files, settings, fresh in checks:
        # files that no call connects are checked apart, and their findings printed at once
        for group in call_groups(files, read, settings, dialect):
            texts = [(path, text) for path in group if (text := read(path)) is not None]
            if texts:
                report.add(analyse_files(texts, fresh, locale))
            gc.collect()  # the group's runs and machines, which refer to each other
    report.close()
    if missing or unreadable:
        return 2
    return 1 if report.errors else 0


_MachineCheck = tuple[list[Path], MachineSettings, Callable[[], WorkspaceAnalysis]]


def _machine_check(machine_file: Path | None, files: list[Path], dialect: str | None, search_paths: list[str],
                   locale: str, max_blocks: int | None, err: Printable) -> _MachineCheck:  # fmt: skip
    """``files``, the settings of ``machine_file`` they are checked with and what makes a fresh
    workspace for a group of them (one index of the callers on disk and one reading of the files
    there for all). What a person should know of the machine file is said on ``err``;
    ``MachineFileError`` or ``ValueError`` when it cannot be used."""
    settings = _machine_settings(machine_file)
    if machine_file is not None:
        settings = _noted(settings, machine_file, dialect, is_chinese(locale), err)
    checked = [*dict.fromkeys(str(path.parent) for path in files)]
    folders = [*checked, *search_paths]
    # the checked files are one machine's programs: a call finds a program in any of their folders
    callees = callee_folders(search_paths, files)
    disk = FileCache()
    index = CallIndex(folders, settings, dialect, locale, files=disk)
    workspace = partial(WorkspaceAnalysis, settings=settings, dialect=dialect, search_paths=callees, locale=locale,
                        max_blocks=max_blocks, severities=settings.severity, workspace_folders=folders, files=disk,
                        call_index=index)  # fmt: skip
    workspace()  # a setting it refuses is said before any finding
    return files, settings, workspace


def _machine_settings(machine_file: Path | None) -> MachineSettings:
    """The settings of ``machine_file`` (None: the defaults); ``MachineFileError`` says what is wrong."""
    return load_machine_file(machine_file) if machine_file is not None else MachineSettings()


def _read(path: Path, searched: bool, locale: str, err: Printable) -> str | None:
    """The text of the program file ``path`` (one found by searching a folder up to
    ``MAX_PROGRAM_BYTES``), or None when it is not read, which is said on ``err``."""
    try:
        return read_program(path, MAX_PROGRAM_BYTES if searched else None).text
    except SkippedFileError as e:
        print(f"cncmacro：{e.message.zh}" if is_chinese(locale) else f"cncmacro: {e}", file=err)
    except OSError as e:
        why, shown = e.strerror or e, shown_text(str(path))
        print(pick(locale, f"cncmacro: {shown}: cannot read: {why}", f"cncmacro：{shown}：无法读取：{why}"), file=err)
    return None


def _program_files(root: Path, machine: str | None) -> tuple[list[Path], list[Detail]]:
    """The program files under ``root`` (``root`` itself when it is a file: a file named on the
    command line is a program whatever its name), with the endings that the machine file
    (``machine``, else the one nearest to ``root``) adds, and what was not read or not found.
    ``MachineFileError`` when that machine file cannot be used."""
    extensions = _machine_settings(Path(machine) if machine else find_machine_file(root)).extensions
    found = search_program_files(root, extensions=extensions)
    if found.files or found.skipped:
        return found.files, found.skipped
    return [], [_no_programs(str(root), extensions)]


def _no_programs(folder: str, extensions: frozenset[str]) -> Detail:
    """What to say of a folder in which no file is a program (``files.is_program_file``)."""
    shown, looked = shown_text(folder), program_files_looked_for(extensions)
    return detail(f"{shown}: no program files in this folder (looked for {looked}); a machine whose programs end "
                  'otherwise names the ending in .cncmacro.toml: extensions = [".txt"]',
                  f"{shown}：此文件夹中没有程序文件（查找的是{looked.zh}）；程序使用其他扩展名时，"
                  '请在 .cncmacro.toml 中设定 extensions = [".txt"]')  # fmt: skip


def _noted(
    settings: MachineSettings, machine_file: Path, typed: str | None, chinese: bool, err: Printable
) -> MachineSettings:
    """The settings to check with when ``typed`` is the command line's ``--dialect``; what a person
    should know of the machine file (its profile overridden, the common ranges it adds) is said on
    ``err``, as notes that change no exit status."""
    shown = shown_text(str(machine_file))
    settings, overridden = typed_profile_wins(settings, typed, shown)
    for note in (overridden, common_note(settings, shown, typed)):
        if note is not None:
            print(f"cncmacro：注意：{note.zh}" if chinese else f"cncmacro: note: {note}", file=err)
    return settings


def analyse_files(
    files: list[tuple[Path, str]], workspace: Callable[[], WorkspaceAnalysis], locale: str
) -> list[Diagnostic]:
    """The diagnostics of ``files`` analysed together in a workspace from ``workspace``. Should
    the checker itself fail there (a bug, not a mistake in a program), each file is analysed again
    on its own in a fresh workspace, so that one file that trips the checker costs only its own
    findings: it gets an ``internal-error`` diagnostic, the others are reported as usual.

    The files are parsed before their workspace is made: parsing freezes what is alive for the
    cycle collector (``collector_paused``), and a workspace frozen with its runs in it (which
    refer to each other) would stay in memory after its group is done."""
    try:
        docs = [(str(path), ParsedDocument(text)) for path, text in files]
        ws = workspace()
        for name, doc in docs:
            ws.open(name, doc, 0)
        result = ws.analyze(docs[0][0])
        assert result is not None  # nothing cancels it
        return [d for diags in result.diagnostics.values() for d in diags]
    except Exception:
        log.exception("checking %d files together failed: checking them one by one", len(files))
    found: list[Diagnostic] = []
    for path, text in files:
        try:
            doc = ParsedDocument(text)
            alone = workspace()
            alone.open(str(path), doc, 0)
            result = alone.analyze(str(path))
            assert result is not None
            found += [d for diags in result.diagnostics.values() for d in diags]
        except Exception as e:
            found.append(internal_error(str(path), 0, FILE, e, locale))
    return found


def main_check(args: argparse.Namespace) -> int:
    return check_paths(
        args.paths, sys.stdout, sys.stderr, args.format, dialect=args.dialect, search_paths=args.path,
        locale=args.locale, max_blocks=args.max_blocks, machine=args.machine, hints=args.hints,
    )  # fmt: skip
