"""What the analysis says where a run stops on a value only the machine has (an ``unknown-value``
note, machine/unknown_values.py), and the values it can be given instead.

The note names the variables of the block the machine keeps (commons kept at power-off, offsets)
and the two places a value can come from: ``[variables]`` in the machine file, or the
persistent-variable file the machine file names (``persistent_file``), which the analysis
reads as ``cncmacro run`` does; or the random number it depends on (``RAND``, ``SRAND``), for
which no value can be given. The run stopped there, not the program: the blocks after it are
not "not executed" (``unknown_stop``). Where the branch is the program's own guard (one side
nothing but its macro alarm, machine/guards.py) the run went on along the other side: the note
says so (``guard_opening``), and the alarm block it did not run is not "not executed" either
(``passed_guards``).
"""

from __future__ import annotations

import logging
import re
from collections.abc import Callable, Iterable

from ...dialects import Dialect
from ...library.machine_file import MachineFileError, MachineSettings
from ...library.persistence import PersistentFileError, load_persistent
from ...library.programs import FoundProgram
from ...machine import Machine
from ...machine.calls import letters_for_local
from ...machine.expressions import VariableKinds
from ...machine.guards import GUARD, LOOP, UNKNOWN_NOTE
from ...machine.status import RunStatus
from ...machine.unknown_values import assigned, is_input, is_kept, is_skip_position, is_tool, variables_in
from ...planner.alarms import UNKNOWN_VALUE
from ...syntax.nodes import Number
from .line_reads import draws

log = logging.getLogger(__name__)
_COMMENT = re.compile(r"\([^)]*\)?")  # a comment, to its ")" or the line's end
_RETURN_OR_END = re.compile(r"M\s*0*(?:99|30|2)(?![\d.])", re.IGNORECASE)  # may hold M99, M30 or M02
# how a note opens (English, Chinese): where the run stops on an unknown, and where it went past
# the program's own guard on one (machine/guards.py)
STOP_OPENING = ("the analysis run stops here: this block depends", "分析运行在此停止：本程序段取决于")
GUARD_OPENING = (
    "the analysis run goes on past this guard, on the side that does not raise the program's own alarm, as the "
    "machine passes it in production: the condition depends",
    "分析运行沿不触发程序自身报警的一侧越过此保护判断继续（机床在生产中通过该判断）：条件取决于",
)
# how the note of such a guard on a random number opens: the control draws another number on each
# run, so it is no value the machine passes in production (``_random_number``)
RANDOM_GUARD_OPENING = (
    "the analysis run goes on past this guard, on the side that does not raise the program's own alarm: the "
    "condition depends",
    "分析运行沿不触发程序自身报警的一侧越过此保护判断继续：条件取决于",
)
# how the note of a WHILE loop whose condition is unknown opens (machine/guards.py, unknown_loop_pass)
LOOP_OPENING = (
    "the analysis run goes through this WHILE loop once and then leaves it, so that its body and what follows "
    "are checked; the machine repeats it as its condition says, which depends",
    "分析运行执行此 WHILE 循环一次后离开，以便检查循环体及其后的程序段；机床按条件重复执行，该条件取决于",
)


def runs_as_macro(found: FoundProgram) -> bool:
    """Whether ``found``, run on its own, is a macro or subprogram checked without its caller: it
    returns with M99 and has no M30 or M02. Its arguments are then unknown, not vacant
    (``Machine.unknown_from_caller``): the alarms it would reach only because no caller passed them
    are not the program's. Only the lines that may hold such a word are read."""
    returns = ends = False
    lines, blocks = found.file.lines, found.file.program.blocks
    for i in _lines_with_m(lines, found.unit.start, min(found.unit.end, len(blocks), len(lines))):
        if _RETURN_OR_END.search(lines[i]) is None:
            continue
        for w in blocks[i].words:
            if w.letter == "M" and isinstance(w.value, Number):
                v = w.value.value
                returns = returns or v == 99.0
                ends = ends or v in (30.0, 2.0)
    return returns and not ends


def _lines_with_m(lines: list[str], start: int, end: int) -> list[int]:
    """The lines of ``start`` .. ``end`` with an ``M`` or ``m``, in order: found in their text
    joined, a letter at a time (a pattern tried on each line of a 1M-line file took 0.3 s, this
    30 ms)."""
    text = "\n".join(lines[start:end])
    at: list[int] = []
    for letter in "Mm":
        i = text.find(letter)
        while i >= 0:
            at.append(i)
            i = text.find(letter, i + 1)
    found: list[int] = []
    line, counted = start, 0
    for i in sorted(at):
        line += text.count("\n", counted, i)
        counted = i
        if not found or found[-1] != line:
            found.append(line)
    return found


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
                       dialect: Dialect, arguments: bool,
                       unknown: Callable[[int], bool] = lambda n: True,
                       opening: tuple[str, str] = STOP_OPENING, called: bool = False) -> tuple[str, str]:  # fmt: skip
    """The note (English, Chinese) for a run stopped on block ``text`` by an unknown value. It
    names at most three variables the block's value comes from: the block's own that no
    ``earlier`` block (that ran before it in its file: (line, text), nearest first) assigned,
    and through each ``#n=...`` of those blocks, the variables of its expression, with its line;
    the ones the machine keeps and, in a macro checked without its caller (``arguments``), the
    arguments #1–#33 a call would pass and the commons cleared at power-off (#100–#199) its caller
    may set, each of them still ``unknown`` where the run stopped (a
    tool number the program has set since is not). Where the value was read through ``#[...]``,
    whose number only the run knows, and no such variable is left, the note names that read; where
    a random number (``RAND``, ``SRAND``) comes in, that it cannot be foreseen. ``opening`` is how
    the note starts: ``STOP_OPENING``, or ``GUARD_OPENING`` for a guard the run went past. ``called``:
    the block runs in a macro a G65/G66 of the run called, whose arguments still unknown came from
    values its caller did not know (named with their letters)."""
    wanted, indirect, through, touched, drawn = _sources(text, earlier, dialect)

    def probed_here(n: int) -> bool:  # where a G31 stopped: #5061…, or GSK's #995… once a G31 wrote it
        return is_skip_position(n, dialect) and (n in touched or not is_kept(n, kinds, dialect))

    def from_caller(n: int) -> bool:  # an argument, or a common its caller may set (#100-#199)
        return arguments and (1 <= n <= 33 or kinds.kind(n) == "common")

    named = [(n, line) for n, line in wanted.items()
             if (is_kept(n, kinds, dialect) or is_input(n, dialect) or is_skip_position(n, dialect)
                 or is_position(n, dialect) or from_caller(n) or (called and 1 <= n <= 33)) and unknown(n)]  # fmt: skip
    if drawn and (not named or opening == GUARD_OPENING):  # a guard on a draw: no production value
        return _random_number(drawn[0], opening)
    if not named and indirect:
        return _read_through(through, opening)
    handed = [(n, line) for n, line in named[:3] if called and 1 <= n <= 33 and not from_caller(n)]
    kept = [(n, line) for n, line in named[:3] if not from_caller(n) and (n, line) not in handed]
    passed = [(n, line) for n, line in named[:3] if 1 <= n <= 33 and from_caller(n)]
    set_before = [(n, line) for n, line in named[:3] if from_caller(n) and not 1 <= n <= 33]
    parts, parts_zh = [], []
    tool = [(n, line) for n, line in kept if is_tool(n, dialect)]
    inputs = [(n, line) for n, line in kept if is_input(n, dialect)]
    probed = [(n, line) for n, line in kept if probed_here(n)]
    positions = [(n, line) for n, line in kept if is_position(n, dialect) and not is_skip_position(n, dialect)]
    kept = [(n, line) for n, line in kept
            if not is_tool(n, dialect) and not is_input(n, dialect) and not probed_here(n)
            and not is_position(n, dialect)]  # fmt: skip
    if kept:
        names, names_zh = _names(kept)
        parts.append(f"{names}, which the machine keeps")
        parts_zh.append(f"机床上保存的 {names_zh}")
    if inputs:
        names, names_zh = _names(inputs)
        one = len(inputs) == 1
        parts.append(f"{names}, {'an input signal' if one else 'input signals'} the machine sends")
        parts_zh.append(f"机床送来的输入信号 {names_zh}")
    if tool:
        names, names_zh = _names(tool)
        parts.append(f"{names}, the tool loaded before the program commands one")
        parts_zh.append(f"程序指令换刀前主轴上的刀具 {names_zh}")
    if probed:
        names, names_zh = _names(probed)
        parts.append(f"{names}, where the probe's G31 touched")
        parts_zh.append(f"测头 G31 接触到的位置 {names_zh}")
    if handed:
        names, names_zh = _names(handed, letters=True)
        parts.append(f"{names}, which the call passes from a value the machine has")
        parts_zh.append(f"调用时由机床上的数值传入的自变量 {names_zh}")
    if positions:
        names, names_zh = _names(positions)
        parts.append(
            f"{names}, a position or offset in force the machine has: it adds an offset this folder does "
            "not give (or follows a G30, or a G92/G50 where the tool's place is not known), so the check "
            "assumes no value for it"
        )
        parts_zh.append(
            f"机床上有而检查中没有的位置或当前补偿 {names_zh}"
            "（它包含本文件夹未给出的工件坐标系偏置或刀具补偿，或在位置未知处执行了 G30、G92/G50，检查不假定其值）"
        )
    if passed:
        names, names_zh = _names(passed, letters=True)
        parts.append(f"{names}, which a caller passes")
        parts_zh.append(f"调用者传递的自变量 {names_zh}")
    if set_before:
        names, names_zh = _names(set_before)
        parts.append(f"{names}, which a caller sets before the call")
        parts_zh.append(f"调用者在调用前设定的 {names_zh}")
    if not parts:
        which, which_zh = (
            "on a value the machine keeps (a common kept at power-off, an offset), which the check assumes "
            "nothing about",
            "机床上保存的数值（断电保持的公共变量、补偿值），检查不对其作任何假定",
        )
    elif any(line is not None for _, line in named[:3]):
        which, which_zh = "on a value computed from " + " and ".join(parts), "由" + "和".join(parts_zh) + "算出的值"
    else:
        which, which_zh = "on " + " and ".join(parts), "和".join(parts_zh)
    tail, tail_zh = _tail(
        bool(kept or positions or handed), bool(passed), bool(set_before), bool(tool), bool(inputs), bool(probed)
    )
    return f"{opening[0]} {which}; {tail}", f"{opening[1]}{which_zh}；{tail_zh}"


def _tail(kept: bool, passed: bool, set_before: bool, tool: bool, inputs: bool, probed: bool) -> tuple[str, str]:
    """What the note says can be done (English, Chinese), by what the value came from: a kept
    value, an argument a caller passes, a common a caller sets, the tool loaded, an input signal,
    where a probe touched."""
    if probed and not kept and not passed and not tool and not inputs:
        tail = (
            "only the machine finds it; a [skip] table in .cncmacro.toml says where the probe touches, to check further"
        )
        tail_zh = "只有机床能测得该值；在 .cncmacro.toml 的 [skip] 表中给出测头接触的位置即可继续检查"
    elif tool and not kept and not passed:
        tail = "no tool change (T_ M06) comes before it in this run, so the tool in the spindle is not known here"
        tail_zh = "本次运行中它之前没有换刀（T_ M06），因此这里不知道主轴上的刀具"
    elif inputs and not kept and not passed and not tool:
        tail = "this folder does not give it; set it under [variables] in .cncmacro.toml to check further"
        tail_zh = "文件夹中没有给出该值；在 .cncmacro.toml 的 [variables] 中给出即可继续检查"
    elif passed and not kept:
        tail = (
            "checked without its caller, this macro has no arguments; a program in the folder that calls it has it "
            "checked with the caller's"
        )
        tail_zh = "单独检查时没有调用者传递自变量；文件夹中有调用它的程序时，会以调用者的自变量检查它"
    elif set_before and not kept:
        tail = (
            "checked without its caller, this subprogram does not have what its caller sets; a program in the "
            "folder that calls it has it checked with the caller's values"
        )
        tail_zh = "单独检查时没有调用者设定的值；文件夹中有调用它的程序时，会以调用者设定的值检查它"
    else:
        tail = (
            "this folder does not give it; set it under [variables] in .cncmacro.toml (or in the persistent file "
            "it names) to check further"
        )
        tail_zh = (
            "文件夹中没有给出该值；在 .cncmacro.toml 的 [variables]（或它指定的断电保持变量文件）中给出即可继续检查"
        )
    return tail, tail_zh


def _sources(
    text: str, earlier: Iterable[tuple[int, str]], dialect: Dialect
) -> tuple[dict[int, int | None], bool, int | None, set[int], list[int | None]]:
    """The variables block ``text``'s value comes from (variable -> the line of the assignment
    that reads it, None for the block's own), through the assignments of ``earlier``; whether a
    ``#[...]`` read comes in, and the line of the assignment it is in (None: the block itself);
    which of them a G31 wrote (``Dialect.skip_commons``: GSK's #995…), whose assignments before
    that G31 are not followed; and the lines where a random number is drawn on the way (None: the
    block itself)."""
    own = assigned(text)
    expression = own[1] if own else text
    wanted: dict[int, int | None] = dict.fromkeys(variables_in(expression))
    indirect, where = "#[" in expression, None
    stored = frozenset(n for _, n in dialect.skip_commons)
    touched: set[int] = set()
    skip = _skip_code(dialect) if stored else None
    drawn: list[int | None] = [None] if draws(expression) else []
    for line, before in earlier:
        if skip is not None and not stored.isdisjoint(wanted) and skip.search(_COMMENT.sub("", before)):
            touched |= stored.intersection(wanted)
        a = assigned(before)
        if a is not None and a[0] in wanted and a[0] not in touched:
            del wanted[a[0]]
            if not indirect and "#[" in a[1]:
                indirect, where = True, line
            if draws(a[1]):
                drawn.append(line)
            for n in variables_in(a[1]):
                wanted.setdefault(n, line)
    return wanted, indirect, where, touched, drawn


def _skip_code(dialect: Dialect) -> re.Pattern[str]:
    """A pattern that finds one of the profile's skip codes (``G31``, ``G031``, ``G31.``) in a
    block's text."""
    codes = []
    for code in sorted(dialect.skip_codes):
        whole, _, fraction = f"{code:g}".partition(".")
        codes.append(f"0*{whole}" + (rf"\.{fraction}0*" if fraction else r"(?:\.0*)?"))
    return re.compile(rf"G\s*(?:{'|'.join(codes)})(?![\d.])", re.IGNORECASE)


def _random_number(line: int | None, opening: tuple[str, str]) -> tuple[str, str]:
    """The note of a stop on a random number (``RAND``, ``SRAND``, drawn on ``line``; None: the
    block's own), of a guard the run went past on one (``GUARD_OPENING``: the control takes either
    side, as the draw falls) or of a WHILE loop on one (``LOOP_OPENING``: how many times it runs
    is not foreseen). A draw is no value the machine keeps: nothing can be given for it."""
    where = f" (line {line + 1})" if line is not None else ""
    where_zh = f"（第 {line + 1} 行）" if line is not None else ""
    en = f"on a random number (RAND, SRAND){where}, which the control draws as the program runs"
    zh = f"随机数（RAND、SRAND）{where_zh}，由系统在程序运行时产生"
    if opening == GUARD_OPENING:
        return (
            f"{RANDOM_GUARD_OPENING[0]} {en}, so the control takes either side: it raises the program's own alarm "
            "on some draws and goes on on others; what follows is checked as the draws that go on run it",
            f"{RANDOM_GUARD_OPENING[1]}{zh}，系统可能走任一侧：某些随机值触发程序自身报警，其他随机值则继续执行；"
            "其后的程序段按继续执行时的情况检查",
        )
    if opening == LOOP_OPENING:
        return (
            f"{opening[0]} {en}; no check can foresee how many times the loop runs",
            f"{opening[1]}{zh}；检查无法预知循环执行的次数",
        )
    return (
        f"{opening[0]} {en}; no check can foresee it, so what the block decides with it is not judged",
        f"{opening[1]}{zh}；检查无法预知其值，因此不判断本程序段据此所作的决定",
    )


def _read_through(line: int | None, opening: tuple[str, str]) -> tuple[str, str]:
    """The note of a stop on a value read through ``#[...]`` (on ``line``; None: the block's own)."""
    where = f" (line {line + 1})" if line is not None else ""
    where_zh = f"（第 {line + 1} 行）" if line is not None else ""
    return (
        f"{opening[0]} on a value read through #[...]{where}, a variable whose "
        "number the run works out (an offset or a common the machine keeps); set it under [variables] in "
        ".cncmacro.toml (or in the persistent file it names) to check further",
        f"{opening[1]}经 #[...] 读取的值{where_zh}，其变量号在运行时算出"
        "（机床上保存的补偿值或公共变量）；在 .cncmacro.toml 的 [variables]"
        "（或它指定的断电保持变量文件）中给出即可继续检查",
    )


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


def is_position(n: int, dialect: Dialect) -> bool:
    """Whether system variable ``#n`` reads a position or the tool offset in force (#5001…, #5021…,
    #5041…, #5081…: a row of source ``"position"``), which may add an offset the folder lacks
    (machine/unknown_values.py's ``position_unknown``)."""
    row = dialect.system_variable(n)
    return row is not None and row.source == "position"


def is_guard_note(kind: str, subject: str | None) -> bool:
    """Whether a run's note of ``kind`` and ``subject`` says it went past the program's own guard
    on an unknown value, or through a WHILE loop on one once (machine/guards.py)."""
    return kind == UNKNOWN_NOTE and subject in (GUARD, LOOP)


def guard_opening(subject: str | None) -> tuple[str, str]:
    """How the note of a guard (``GUARD_OPENING``) or of a loop (``LOOP_OPENING``) the run went past opens."""
    return LOOP_OPENING if subject == LOOP else GUARD_OPENING


def passed_guards(m: Machine) -> list[tuple[str, int]]:
    """(file, line) of each alarm block a run did not run where it went past the program's own
    guard on an unknown value (machine/guards.py). The machine may take that side (a count not
    yet set on the machine): the range of unreached lines that holds it is not "not executed"."""
    return [(n.file, n.skipped) for n in m.notes if n.skipped is not None and is_guard_note(n.kind, n.subject)]


def holds_one(lines: list[tuple[str, int]], file: str, first: int, last: int) -> bool:
    """Whether lines ``first`` to ``last`` of ``file`` hold one of ``lines``."""
    return any(f == file and first <= line <= last for f, line in lines)


def _names(found: list[tuple[int, int | None]], letters: bool = False) -> tuple[str, str]:
    """``#706 (line 2), #20 (T)``: each variable, its argument letter and the line it is read on."""
    en, zh = [], []
    for n, line in found:
        letter = letters_for_local(n)[0] if letters else None
        tags = [t for t in (letter, None if line is None else f"line {line + 1}") if t]
        tags_zh = [t for t in (letter, None if line is None else f"第 {line + 1} 行") if t]
        en.append(f"#{n}" + (f" ({', '.join(tags)})" if tags else ""))
        zh.append(f"#{n}" + (f"（{'，'.join(tags_zh)}）" if tags_zh else ""))
    return ", ".join(en), "、".join(zh)
