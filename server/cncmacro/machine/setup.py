"""Setting up a machine to run a program file, as ``cncmacro run`` and the debugger both do.

The machine file is the one given, else the nearest ``.cncmacro.toml`` above the program;
the dialect follows docs/design.md's chain (the file's ``(cncmacro: dialect=..)`` comment, then
the machine file, then the caller's setting, then fanuc); ``#500–#999`` come from the
persistent file (the machine file's ``persistent_file``, else ``.cncmacro-vars.json`` beside
the program; a link to it is followed) and the presets are applied after them. A run that
will save them holds the file's lock (``persistence_lock``) from before it reads them until
``PreparedRun.save`` has written them back, so runs that share the file take turns; values in
the file that this machine does not hold (the 30i's ``#98000–`` under a 0i profile) are
written back as they were. The file is written only when the run changed a persistent
variable (a run that keeps nothing leaves no file beside the program; a file whose values did
not change is left as it is), for ``cncmacro run`` and the debugger alike; the lock file is
deleted when the run lets the file go, whether it saved or not.
Every mistake a person can make here
(an unreadable or binary program, a bad machine file, a damaged persistent file, a preset of
a variable that cannot be preset) is a ``SetupError`` whose message says what is wrong.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field, replace
from pathlib import Path

from ..bilingual import Detail, detail
from ..library.files import SkippedFileError, decode_program, read_program
from ..library.machine_file import (
    PERSISTENT_FILE_NAME,
    MachineFileError,
    MachineSettings,
    find_machine_file,
    load_machine_file,
)
from ..library.persistence import PersistentFileError, load_persistent, persistent_target, save_persistent
from ..library.persistence_lock import LOCK_WAIT, PersistentLock, lock_persistent
from ..library.profiles import file_profile, typed_profile_wins
from ..library.programs import ProgramLibrary
from .machine import Machine


def _home(program: Path, settings: MachineSettings) -> Path:
    """The folder a default persistent file's link may lead within: the machine file's folder when
    the program is in it, else the program's own."""
    if settings.folder:
        folder = Path(settings.folder)
        if Path(os.path.realpath(program)).is_relative_to(Path(os.path.realpath(folder))):
            return folder
    return program.parent


class SetupError(ValueError):
    """The program, machine file, persistent file or presets cannot start a run."""


@dataclass(slots=True)
class PreparedRun:
    """A machine at the first block of its program, and where its persistent variables live."""

    machine: Machine
    persistent_file: Path
    kept: dict[int, float] = field(default_factory=dict)  # the file's values this machine does not hold
    lock: PersistentLock | None = None
    saved: bool = False
    stored: dict[int, float] = field(default_factory=dict)  # the file's values when the run started
    notes: list[Detail] = field(default_factory=list)  # what the person should know of the setup

    def save(self) -> None:
        """Write ``#500–#999`` back atomically, once, when the run changed one of them, and let
        the next run have the file (``OSError`` passes through). A run that changed none writes
        nothing."""
        if self.saved:
            return
        self.saved = True
        try:
            values = {**self.kept, **self.machine.persistent_values()}
            if values != self.stored:
                save_persistent(self.persistent_file, values)
        finally:
            self.release()

    def release(self) -> None:
        """Let the next run have the file without writing it, deleting the lock file: nothing
        of the lock is left beside the programs once the run is over."""
        if self.lock is not None:
            self.lock.remove()
            self.lock = None


def machine_settings(program: Path, machine_file: Path | str | None = None) -> MachineSettings:
    """The settings of the given machine file, else of the nearest one above ``program``."""
    try:
        if machine_file is not None:
            return load_machine_file(machine_file)
        found = find_machine_file(program)
        return load_machine_file(found) if found is not None else MachineSettings()
    except MachineFileError as e:
        raise SetupError(e.located()) from None  # its text and line, with the Chinese beside it


def prepare_run(
    program: Path,
    *,
    machine_file: Path | str | None = None,
    dialect: str | None = None,
    presets: dict[int, float] | None = None,
    search_paths: list[Path] | None = None,
    block_delete: bool | None = None,
    max_blocks: int | None = None,
    data: bytes | None = None,
    saving: bool = True,
    wait: float = LOCK_WAIT,
    m99_ends_main: bool = False,
    typed: bool = False,
) -> PreparedRun:
    """Read ``program`` and its machine settings and start a machine at its first block.
    ``data`` is the program's content when it does not come from the file (an editor's unsaved
    text): the file's path still names it and says where its called programs are. A run that
    is ``saving`` waits at most ``wait`` seconds for the persistent file's lock and holds it
    until ``save`` or ``release``. ``m99_ends_main`` ends the run at an ``M99`` of the main
    program (a subprogram run on its own, one pass) instead of running it again from its start
    as a control does. ``typed``: ``dialect`` is what a person typed on the command line, which
    wins over the machine file's profile (``typed_profile_wins``; its note is kept in ``notes``)."""
    try:
        source = read_program(program, max_bytes=None) if data is None else decode_program(data, str(program))
    except SkippedFileError as e:  # binary, a folder, a FIFO: its message names the file and says so
        raise SetupError(e.message) from None
    except OSError as e:
        if isinstance(e, FileNotFoundError):
            raise SetupError(detail(f"there is no file {program}", f"文件 {program} 不存在")) from None
        if isinstance(e, PermissionError):
            why = detail("permission denied", "没有读取权限")
        else:
            reason = e.strerror or str(e)  # the system's words, as other readers of files give them
            why = detail(f"{reason}", f"{reason}")
        raise SetupError(
            detail(f"cannot read the program {program}: {why}", f"无法读取程序 {program}：{why.zh}")
        ) from None
    settings = machine_settings(program, machine_file)
    notes: list[Detail] = []
    if typed and settings.folder is not None:
        where = str(machine_file) if machine_file is not None else str(find_machine_file(program))
        settings, overridden = typed_profile_wins(settings, dialect, where)
        notes += [overridden] if overridden is not None else []
    if block_delete is not None:
        settings = replace(settings, block_delete=block_delete)
    if max_blocks is not None:
        settings = replace(settings, max_blocks=max_blocks)
    profile = file_profile(source.text, settings, dialect)
    library = ProgramLibrary(search_paths or [], extensions=settings.extensions,
                             profile_of=lambda lines, _path: file_profile(lines, settings, dialect).name)  # fmt: skip
    machine = Machine(profile, settings, library, m99_ends_main=m99_ends_main)
    if machine.preset_problems:
        raise SetupError(machine.preset_problems[0])
    try:
        named = settings.persistent_path()
        if named is not None:
            persistent = persistent_target(named, saving)
        else:  # the default beside the program: a link may lead only within the machine's folder
            persistent = persistent_target(program.parent / PERSISTENT_FILE_NAME, saving, _home(program, settings))
        lock = lock_persistent(persistent, wait) if saving else None
    except (MachineFileError, PersistentFileError) as e:
        raise SetupError(e.args[0]) from None  # keeps a Chinese text
    prepared = PreparedRun(machine, persistent, lock=lock, notes=notes)
    try:
        stored = load_persistent(persistent)
        held = set(machine.kinds.persistent_numbers())
        prepared.stored = stored
        prepared.kept = {n: v for n, v in stored.items() if n not in held}
        machine.load_persistent(stored)
        machine.apply_presets(presets or {})
        machine.start_file(str(program), source.text)
    except (PersistentFileError, ValueError) as e:
        prepared.release()
        raise SetupError(e.args[0] if e.args else str(e)) from None  # keeps a Chinese text
    except BaseException:
        prepared.release()
        raise
    return prepared


def prepare_text_run(
    text: str,
    name: str,
    *,
    dialect: str | None = None,
    presets: dict[int, float] | None = None,
    max_blocks: int | None = None,
    m99_ends_main: bool = False,
) -> Machine:
    """A machine at the first block of a program that is only text (``name`` names it): with no
    folder there is no machine file, no persistent-variable file and no called program on disk,
    so nothing is read and the default settings hold (``#500–#999`` start vacant). The text is
    taken as ``decode_program`` takes a file's bytes (a binary one is refused); every mistake is a
    ``SetupError``."""
    try:
        source = decode_program(text.encode("utf-8", errors="surrogateescape"), name)
    except SkippedFileError as e:
        raise SetupError(e.message) from None
    settings = MachineSettings() if max_blocks is None else replace(MachineSettings(), max_blocks=max_blocks)
    profile = file_profile(source.text, settings, dialect)
    machine = Machine(
        profile, settings, ProgramLibrary([], extensions=settings.extensions), m99_ends_main=m99_ends_main
    )
    try:
        machine.apply_presets(presets or {})
        machine.start_file(name, source.text)
    except ValueError as e:
        raise SetupError(e.args[0] if e.args else str(e)) from None  # keeps a Chinese text
    return machine
