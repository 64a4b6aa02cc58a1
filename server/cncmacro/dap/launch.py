"""Setting up a machine from a debug launch configuration.

The launch arguments are ``program`` (the file to run), ``dialect``, ``stopOnEntry``,
``machine`` (a machine file; by default the nearest ``.cncmacro.toml``), ``blockDelete``,
``set`` (presets, ``{"100": 5}`` or ``["100=5"]``), ``maxBlocks``, ``echoMotion`` (each
executed motion block to the debug console), ``noSave`` (leave ``#500–#999`` unsaved),
``stopAtEnd`` (stop once more where the program ends, ``M30``/``M02``, a lone subprogram's
``M99`` or its last block, so its final state can be looked at and stepped back from; default
true), ``repeat`` (a program that ends in M99 runs again from its start, as a control runs a main program; by default a
subprogram launched on its own ends at its M99 after one pass, as ``cncmacro run`` does) and
``noDebug`` ("Run Without Debugging": no stop at all, neither on entry, at breakpoints, alarms
nor the end).
The machine is set up as ``cncmacro run`` sets it up: the dialect comment in the file wins,
then the machine file, then the configuration, then fanuc; presets come after the persistent
variables; a launch that saves them holds their lock until the session saves them (at its
end, or a restart), so a ``cncmacro run`` meanwhile waits for it. Every mistake is a
``LaunchError`` with a message for the person.

A launch reads program files in its folders only (``Launched.scope``): the program's folder
(where the run finds the programs it calls), the machine file's folder, and the program itself.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..bilingual import detail
from ..dialects import DIALECTS, normalise_dialect
from ..library.files import ReadScope
from ..library.machine_file import parse_preset
from ..machine import Machine
from ..machine.setup import PreparedRun, SetupError, prepare_run


class LaunchError(ValueError):
    """The launch configuration cannot start a run."""


@dataclass(slots=True)
class LaunchConfig:
    """The launch arguments, checked."""

    program: Path
    dialect: str | None = None
    stop_on_entry: bool = False
    machine_file: Path | None = None
    block_delete: bool | None = None
    presets: dict[int, float] | None = None
    max_blocks: int | None = None
    echo_motion: bool = False
    no_save: bool = False
    stop_at_end: bool = True
    no_debug: bool = False
    repeat: bool = False

    @classmethod
    def from_arguments(cls, args: dict[str, Any]) -> LaunchConfig:
        program = args.get("program")
        if not isinstance(program, str) or not program:
            raise LaunchError("the launch configuration needs 'program': the file to run")
        for key, path in (("program", program), ("machine", args.get("machine"))):
            if isinstance(path, str) and "\x00" in path:  # no file system takes it: not a file name
                raise LaunchError(detail(f"'{key}' holds a NUL character, which no file name has",
                                         f"'{key}' 中含有 NUL 字符，文件名中不会有该字符"))  # fmt: skip
        dialect = args.get("dialect")
        if dialect is not None:
            named = normalise_dialect(dialect) if isinstance(dialect, str) else None
            if named is None:
                raise LaunchError(f"'dialect' must be one of {', '.join(DIALECTS)}, not {dialect!r}")
            dialect = named
        machine = args.get("machine")
        if machine is not None and not isinstance(machine, str):
            raise LaunchError("'machine' must be the path of a machine file")
        max_blocks = args.get("maxBlocks")
        if max_blocks is not None and (
            not isinstance(max_blocks, int) or isinstance(max_blocks, bool) or max_blocks < 1
        ):
            raise LaunchError("'maxBlocks' must be a whole number of at least 1")
        block_delete = args.get("blockDelete")
        if block_delete is not None and not isinstance(block_delete, bool):
            raise LaunchError("'blockDelete' must be true or false")
        stop_at_end = args.get("stopAtEnd", True)
        if not isinstance(stop_at_end, bool):
            raise LaunchError("'stopAtEnd' must be true or false")
        repeat = args.get("repeat")
        if repeat is not None and not isinstance(repeat, bool):
            shown = json.dumps(repeat, ensure_ascii=False)  # as the launch configuration wrote it
            raise LaunchError(detail(f"'repeat' must be true or false, not {shown}",
                                     f"'repeat' 必须是 true 或 false，而不是 {shown}"))  # fmt: skip
        no_debug = bool(args.get("noDebug", False))
        return cls(
            Path(program).resolve(), dialect, bool(args.get("stopOnEntry", False)),
            Path(machine).resolve() if machine else None, block_delete, _presets(args.get("set")), max_blocks,
            bool(args.get("echoMotion", False)), bool(args.get("noSave", False)), stop_at_end and not no_debug,
            no_debug, bool(repeat),
        )  # fmt: skip


def _presets(value: Any) -> dict[int, float]:
    if value is None:
        return {}
    items: list[str] = []
    if isinstance(value, dict):
        items = [f"{k}={v}" for k, v in value.items()]
    elif isinstance(value, list) and all(isinstance(v, str) for v in value):
        items = list(value)
    else:
        raise LaunchError('\'set\' must be an object such as {"100": 5} or a list such as ["100=5"]')
    try:
        return dict(parse_preset(s) for s in items)
    except ValueError as e:
        raise LaunchError(str(e).replace("--set", "set")) from None


@dataclass(slots=True)
class Launched:
    """A machine ready at the program's first block (with where its persistent variables
    live) and the configuration that launched it."""

    prepared: PreparedRun
    config: LaunchConfig

    @property
    def machine(self) -> Machine:
        return self.prepared.machine

    @property
    def scope(self) -> ReadScope:
        """Where the session may read the program files a client names (``source``, breakpoints)."""
        folders = [self.config.program.parent]
        machine_folder = self.machine.settings.folder
        if machine_folder:
            folders.append(Path(machine_folder))
        return ReadScope.of(folders, [self.config.program], self.machine.settings.extensions)

    def save(self) -> str | None:
        """Write ``#500–#999`` back unless ``noSave`` and let the next run have them (a launch
        that saves holds their lock until then); an error message when that failed."""
        if self.config.no_save:
            self.prepared.release()
            return None
        try:
            self.prepared.save()
        except OSError as e:
            return f"could not save the persistent variables to {self.prepared.persistent_file}: {e}"
        return None


def launch(config: LaunchConfig) -> Launched:
    """Read the program and the machine file and start the machine at the first block."""
    try:
        prepared = prepare_run(
            config.program, machine_file=config.machine_file, dialect=config.dialect, presets=config.presets,
            block_delete=config.block_delete, max_blocks=config.max_blocks, saving=not config.no_save,
            m99_ends_main=not config.repeat,
        )  # fmt: skip
    except SetupError as e:
        raise LaunchError(e.args[0] if e.args else str(e)) from None  # a Detail keeps its Chinese
    return Launched(prepared, config)
