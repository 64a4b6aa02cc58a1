"""What to tell a person whose run stopped at the M99 of a subprogram run on its own.

A program that ends in M99 is a subprogram: run on its own (``m99_ends_main``), the machine
stops at that M99 after one pass instead of running it again from its start as a control runs
a main program. ``cncmacro run`` and the debugger both say so in the same sentence, in English
or Chinese, naming how to get the control's loop (``--repeat`` on the command line, ``"repeat":
true`` in a launch configuration), and name the programs in the file's folder that call it (by
file name and O number), found as ``cncmacro check`` finds a program's callers on disk.
"""

from __future__ import annotations

from pathlib import Path

from ...bilingual import is_chinese, pick
from ...machine import Machine
from ..indexes.call_index import CallIndex
from ..indexes.caller_entries import CallerSearch

RUN_REPEAT = "--repeat"  # how ``cncmacro run`` asks for the control's loop
LAUNCH_REPEAT = '"repeat": true'  # how a debug launch configuration asks for it


def subprogram_text(path: Path, locale: str | None, repeat: str = RUN_REPEAT) -> str:
    """Why a program that ends in M99 stopped there: it is a subprogram, run on its own;
    ``repeat`` is how the person asks to run it again from its start."""
    name = path.name
    return pick(locale,
                f"{name} ends in M99: it is a subprogram, which returns to the program that calls it. "
                f"Run on its own it stopped at the M99 after one pass ({repeat} runs it again from its start, "
                "as a control runs a main program that ends in M99).",
                f"{name} 以 M99 结束：这是子程序，执行完返回调用它的程序。单独运行时执行一遍后在 M99 处停止"
                f"（{repeat} 则像数控系统执行以 M99 结束的主程序那样从头再次运行）。")  # fmt: skip


def callers_text(machine: Machine, path: Path, dialect: str | None, locale: str | None) -> str:
    """The programs in ``path``'s folder that call the program ``machine`` ran, or that none does."""
    found = machine.frames[0].found
    index = CallIndex([str(path.parent)], machine.settings, dialect, locale or "en", files=machine.library.disk)
    callers = CallerSearch(machine.library, index, {}).callers(found)
    chinese = is_chinese(locale)
    named = []
    for c in callers:
        name = Path(c.file.path).name
        if c.unit.number is not None:
            name += f"（{c.label}）" if chinese else f" ({c.label})"
        named.append(name)
    if chinese:
        return f"调用它的程序：{'、'.join(named)}" if named else "同一文件夹中没有调用它的程序"
    return f"called by: {', '.join(named)}" if named else "no program in its folder calls it"


def subprogram_remarks(
    machine: Machine, path: Path, dialect: str | None, locale: str | None, repeat: str = RUN_REPEAT
) -> list[str]:
    """The subprogram sentence and its callers, for a run that ``ended_by_main_m99``."""
    return [subprogram_text(path, locale, repeat), callers_text(machine, path, dialect, locale)]
