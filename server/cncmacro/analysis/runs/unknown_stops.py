"""What the analysis says where a run stops on a value only the machine has (an ``unknown-value``
note, machine/unknown_values.py), and the values it can be given instead.

The note names the variables of the block the machine keeps (commons kept at power-off, offsets)
and the two places a value can come from: ``[variables]`` in the machine file, or the
persistent-variable file the machine file names (``persistent_file``), which the analysis
reads as ``cncmacro run`` does. The run stopped there, not the program: the blocks after it are
not "not executed" (``unknown_stop``).
"""

from __future__ import annotations

import logging
from collections.abc import Iterable

from ...dialects import Dialect
from ...library.machine_file import MachineFileError, MachineSettings
from ...library.persistence import PersistentFileError, load_persistent
from ...machine import Machine
from ...machine.expressions import VariableKinds
from ...machine.status import RunStatus
from ...machine.unknown_values import assigned, is_kept, variables_in
from ...planner.alarms import UNKNOWN_VALUE

log = logging.getLogger(__name__)


def named_persistent_values(settings: MachineSettings) -> dict[int, float]:
    """The values of the persistent file the machine file names (none without one). A file that
    cannot be read or is damaged gives none: its values stay unknown, and ``cncmacro run``,
    which reads it too, says why."""
    try:
        path = settings.persistent_path()
        return load_persistent(path) if path is not None else {}
    except (MachineFileError, PersistentFileError, OSError) as e:
        log.info("the persistent file is not used by the analysis: %s", e)
        return {}


def unknown_value_text(text: str, earlier: Iterable[tuple[int, str]], kinds: VariableKinds,
                       dialect: Dialect) -> tuple[str, str]:  # fmt: skip
    """The note (English, Chinese) for a run stopped on block ``text`` by an unknown value. It
    names at most three kept variables the block's value comes from: the block's own that no
    ``earlier`` block (that ran before it in its file: (line, text), nearest first) assigned,
    and through each ``#n=...`` of those blocks, the variables of its expression, with its line."""
    wanted: dict[int, int | None] = dict.fromkeys(variables_in(text))  # variable -> the line it is read on
    for line, before in earlier:
        a = assigned(before)
        if a is not None and a[0] in wanted:
            del wanted[a[0]]
            for n in variables_in(a[1]):
                wanted.setdefault(n, line)
    kept = [(n, line) for n, line in wanted.items() if is_kept(n, kinds, dialect)][:3]
    if not kept:
        which = "on a value the machine keeps (a common kept at power-off, an offset)"
        which_zh = "取决于机床上保存的数值（断电保持的公共变量、补偿值）"
    else:
        names = ", ".join(f"#{n}" if line is None else f"#{n} (line {line + 1})" for n, line in kept)
        names_zh = "、".join(f"#{n}" if line is None else f"#{n}（第 {line + 1} 行）" for n, line in kept)
        if all(line is None for _, line in kept):
            which, which_zh = f"on {names}, which the machine keeps", f"取决于 {names_zh}，其值保存在机床上"
        else:
            which = f"on a value computed from {names}, which the machine keeps"
            which_zh = f"取决于由 {names_zh} 算出的值，其值保存在机床上"
    en = (
        f"the analysis run stops here: this block depends {which} and this folder does not give; "
        "set it under [variables] in .cncmacro.toml (or in the persistent file it names) to check further"
    )
    zh = (
        f"分析运行在此停止：本程序段{which_zh}，而文件夹中没有给出；在 .cncmacro.toml 的 [variables]"
        "（或它指定的断电保持变量文件）中给出该值即可继续检查"
    )
    return en, zh


def unknown_stop(m: Machine) -> list[tuple[str, int]]:
    """Where a run stopped on an unknown value: (file, line) of the block and of each call
    that led to it; none when it did not. What follows each in its file was not reached because
    the run stopped, not because the program never goes there."""
    a = m.alarm
    if m.status != RunStatus.ALARM or a is None or a.subject != UNKNOWN_VALUE:
        return []
    return [(a.file, a.line), *((c.file, c.line) for c in a.chain)]


def after_a_stop(stops: list[tuple[str, int]], file: str, first: int) -> bool:
    """Whether lines from ``first`` on in ``file`` come after one of the ``stops``."""
    return any(f == file and first > line for f, line in stops)
