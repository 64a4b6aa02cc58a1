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
shown escaped in the text output and on standard error (``terminal``). The groups of files
that calls connect (``call_groups.py``) are checked in ``--jobs`` processes (``check_jobs.py``,
the work itself in ``check_work.py``) with the same output as in one; ``--shard K/N`` checks
only the groups that fall to one of N machines.
"""

from __future__ import annotations

import argparse
import logging
import os
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import TextIO, TypeVar

from .. import __version__
from ..analysis.indexes import call_index
from ..bilingual import Detail, detail, in_language, is_chinese, pick
from ..library.callee_folders import callee_folders
from ..library.files import program_files_looked_for, search_program_files, shown_text
from ..library.machine_file import (
    MachineFileError,
    MachineSettings,
    common_note,
    find_machine_file,
    load_machine_file,
    standard_calls_note,
)
from ..library.profiles import typed_profile_wins
from .call_groups import FileKeys, join_groups, to_read_exactly
from .check_jobs import Shard, WorkerLost, Workers, default_jobs, in_shard, usable_jobs
from .check_work import Found, MachineWork, collect_left_behind, read_text
from .findings_report import FindingsReport
from .terminal import Printable

T = TypeVar("T")


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
    jobs: int = 1,
    shard: Shard | None = None,
    process_ends: bool = False,
) -> int:
    """Check every program file under ``paths``; print the findings; return the exit status.
    ``jobs`` processes do the work (``check_jobs.py``; 1: this process alone); with ``shard``
    only the call groups that fall to it are checked. With ``process_ends`` (the process's own
    command) what the last group left is not collected: the process ends next."""
    chinese = is_chinese(locale)
    shown_err = Printable(err)
    if max_blocks is not None and max_blocks < 1:
        print(pick(locale, "cncmacro check: --max-blocks must be at least 1", "cncmacro check：--max-blocks 至少为 1"),
              file=shown_err)  # fmt: skip
        return 2
    unreadable: set[Path] = set()

    def said(line: str) -> None:
        print(line, file=shown_err)

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
            if path in found_paths:
                continue
            found_paths[path] = searched
            # what cannot be read is said now, in the order of the paths; the text is read again
            lines: list[str] = []
            if read_text((path, searched), locale, lines) is None:
                unreadable.add(path)
                for line in lines:
                    said(line)
    by_machine: dict[Path | None, list[Found]] = {}
    nearest = _NearestMachineFile()
    for path, searched in found_paths.items():
        by_machine.setdefault(Path(machine) if machine else nearest(path), []).append((path, searched))
    checks: list[tuple[MachineWork, list[Found]]] = []
    for machine_file, files in by_machine.items():  # each file with the machine settings nearest to it
        try:
            work = _machine_work(machine_file, [f[0] for f in files], dialect, search_paths or [], locale,
                                 max_blocks, shown_err)  # fmt: skip
        except (MachineFileError, ValueError) as e:
            reason = e.located() if isinstance(e, MachineFileError) else e.args[0] if e.args else str(e)
            reason = in_language(reason, chinese)
            print(f"cncmacro check：{reason}" if chinese else f"cncmacro check: {reason}", file=shown_err)
            return 2
        checks.append((work, [f for f in files if f[0] not in unreadable]))

    report = FindingsReport(out, fmt, hints, __version__)
    # no more processes than batches: a check of a few files starts none (a worker that Windows
    # spawns costs half a second before its first file)
    jobs = max(1, min(jobs, -(-sum(len(files) for _, files in checks) // CHECK_BATCH)))
    out.flush()  # a worker started by fork would write again what waits in a buffer when it ends
    err.flush()
    if not _check_all(checks, jobs, report, unreadable, said, shard, process_ends):
        print(pick(locale, "cncmacro check: a checking process ended before it was done (killed, or out of memory?); "
                   "check with fewer --jobs, or with --jobs 1",
                   "cncmacro check：一个检查进程未完成就结束了（被终止或内存不足？）；请减少 --jobs，或使用 --jobs 1"),
              file=shown_err)  # fmt: skip
        return 2
    report.close()
    if missing or unreadable:
        return 2
    return 1 if report.errors else 0


def _check_all(checks: list[tuple[MachineWork, list[Found]]], jobs: int, report: FindingsReport,
               unreadable: set[Path], said: Callable[[str], None], shard: Shard | None,
               process_ends: bool) -> bool:  # fmt: skip
    """Check the files of each machine in ``jobs`` processes, reporting as they come; False when
    a checking process ended before it was done. With ``process_ends`` what the last group left
    is not collected: the process ends next."""
    try:
        with Workers([work for work, _ in checks], jobs) as workers:
            for at, (_, files) in enumerate(checks):
                _report_groups(workers, at, files, report, unreadable, said, shard)
    except WorkerLost:
        return False
    finally:
        if not process_ends:
            collect_left_behind()  # the last group's runs, which a process that goes on would keep
    return True


KEYS_BATCH = 64  # files a process looks at for their names and calls at a time
CHECK_BATCH = 16  # files (whole call groups, at least one) a process checks at a time


def _report_groups(workers: Workers, machine: int, files: list[Found], report: FindingsReport,
                   unreadable: set[Path], said: Callable[[str], None], shard: Shard | None) -> None:  # fmt: skip
    """Check the files of one machine: those that no call connects apart, each group's findings
    written as soon as it and the groups before it are done (only the groups of ``shard``)."""
    groups = [g for g in _call_groups(workers, machine, files, unreadable, said) if in_shard(g[0][0], shard)]
    said_once: set[str] = set()
    for results in workers.map(MachineWork.check, machine, _batches(groups)):
        for result in results:
            for line in result.said:
                said(line)
            for record in result.logged:
                _log_again(record, said_once)
            report.add(result.findings)


def _call_groups(workers: Workers, machine: int, files: list[Found], unreadable: set[Path],
                 said: Callable[[str], None]) -> list[list[Found]]:  # fmt: skip
    """``files`` in the groups that calls may connect (``call_groups.py``), the work spread over
    ``workers``. A file that can no longer be read is said, added to ``unreadable`` and left out."""
    if len(files) < 2:
        return [files] if files else []  # one file is one group: it is not read for its calls
    readable: list[Found] = []
    keys: list[FileKeys] = []
    answered = workers.map(MachineWork.keys, machine, _chunks(files, KEYS_BATCH))
    for batch, answers in zip(_chunks(files, KEYS_BATCH), answered, strict=True):
        for found, answer in zip(batch, answers, strict=True):
            if isinstance(answer, str):
                said(answer)
                unreadable.add(found[0])
            else:
                readable.append(found)
                keys.append(answer)
    exact = to_read_exactly(keys)
    names = workers.map(MachineWork.names, machine, _chunks([readable[i] for i in exact], KEYS_BATCH))
    for i, name in zip(exact, (n for batch in names for n in batch), strict=True):
        keys[i] = keys[i]._replace(names=name if name is not None else keys[i].names, maybe=None)
    by_path = dict(readable)
    return [[(path, by_path[path]) for path in group] for group in join_groups([f[0] for f in readable], keys)]


def _chunks(items: list[T], size: int) -> Iterator[list[T]]:
    for start in range(0, len(items), size):
        yield items[start : start + size]


def _batches(groups: list[list[Found]]) -> Iterator[list[list[Found]]]:
    """``groups`` in batches of whole groups of about ``CHECK_BATCH`` files."""
    batch: list[list[Found]] = []
    size = 0
    for group in groups:
        batch.append(group)
        size += len(group)
        if size >= CHECK_BATCH:
            yield batch
            batch, size = [], 0
    if batch:
        yield batch


def _log_again(record: logging.LogRecord, said_once: set[str]) -> None:
    """Log here what a worker logged while it checked a group. The index of the callers on disk
    warns once per process that makes one (each worker does, for a folder too big to index):
    that warning is given once, as one process gives it."""
    if record.name == call_index.log.name:
        if record.msg in said_once:
            return
        said_once.add(record.msg)
    logging.getLogger(record.name).handle(record)


class _NearestMachineFile:
    """``find_machine_file`` of program files, looked for once per folder: a file's is its
    folder's, but for a link, whose is that of the folder it leads to."""

    def __init__(self) -> None:
        self._of_folder: dict[Path, Path | None] = {}

    def __call__(self, path: Path) -> Path | None:
        if os.path.islink(path):  # False too when it cannot be looked at
            return find_machine_file(path)
        folder = path.parent
        if folder not in self._of_folder:
            self._of_folder[folder] = find_machine_file(folder)
        return self._of_folder[folder]


def _machine_work(machine_file: Path | None, files: list[Path], dialect: str | None, search_paths: list[str],
                  locale: str, max_blocks: int | None, err: Printable) -> MachineWork:  # fmt: skip
    """The work of checking ``files`` with the settings of ``machine_file``. What a person should
    know of the machine file is said on ``err``; ``MachineFileError`` or ``ValueError`` when it
    cannot be used."""
    settings = _machine_settings(machine_file)
    if machine_file is not None:
        settings = _noted(settings, machine_file, dialect, is_chinese(locale), err)
    checked = [*dict.fromkeys(str(path.parent) for path in files)]
    folders = [*checked, *search_paths]
    # the checked files are one machine's programs: a call finds a program in any of their folders
    callees = callee_folders(search_paths, files)
    work = MachineWork(settings, dialect, folders, callees, locale, max_blocks, frozenset(str(f) for f in files))
    work.workspace()  # a setting it refuses is said before any finding
    return work


def _machine_settings(machine_file: Path | None) -> MachineSettings:
    """The settings of ``machine_file`` (None: the defaults); ``MachineFileError`` says what is wrong."""
    return load_machine_file(machine_file) if machine_file is not None else MachineSettings()


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
    should know of the machine file (its profile overridden, the common ranges it adds, the
    ``[calls]`` its profile does not call) is said on
    ``err``, as notes that change no exit status."""
    shown = shown_text(str(machine_file))
    settings, overridden = typed_profile_wins(settings, typed, shown)
    for note in (overridden, common_note(settings, shown, typed), standard_calls_note(settings, shown, typed)):
        if note is not None:
            print(f"cncmacro：注意：{note.zh}" if chinese else f"cncmacro: note: {note}", file=err)
    return settings


def main_check(args: argparse.Namespace) -> int:
    return check_paths(
        args.paths, sys.stdout, sys.stderr, args.format, dialect=args.dialect, search_paths=args.path,
        locale=args.locale, max_blocks=args.max_blocks, machine=args.machine, hints=args.hints,
        jobs=default_jobs() if args.jobs is None else usable_jobs(args.jobs), shard=args.shard,
        process_ends=getattr(args, "ends_process", False),
    )  # fmt: skip
