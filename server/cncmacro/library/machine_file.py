"""Machine settings: the workspace's ``.cncmacro.toml``, read with ``tomllib`` (``tomli`` on
Python 3.10).

Every key is optional (docs/design.md "Machine settings")::

    dialect = "gsk980tdi"
    common = [100, 499]            # the volatile common range (default 100-199)
    extensions = [".txt", ".min"]  # more endings of program files (files.is_program_file)
    decimal_point = "increment"    # or "calculator" (default): how X10 without a point is read
    block_delete = true            # skip blocks that start with '/'
    persistent_file = ".cncmacro-vars.json"   # keeps #500-#999 between runs (a path inside this folder)
    max_blocks = 1000000           # the analysis budget per run
    date = 20261122                # the clock (#3011, #3012) when runs must be repeatable
    time = 153000

    [variables]                    # preset values: offsets, counters, commons
    2001 = 0.5
    100 = 3

    [codes]                        # plain codes the machine builder added, with their text for hover
    "G120.1" = { en = "Pallet change position", zh = "托盘交换位置" }

    [calls]                        # codes that call programs (seed 001, seed 003 ch. 8)
    G100 = 9010                    # like G65 P9010
    M50 = 9020
    M60 = { program = 9001, call = "subprogram" }   # like M98 P9001
    T = 9000                       # every T code calls O9000 (the T value in #149)

    [skip]                         # the part a G31 touches (skip_model.py)
    Z = -12.5                      # planes, bores, bosses, or contacts = [...] in order
    bore = { X = 0, Y = 0, diameter = 50 }

    [[system_variables]]           # variables this machine adds or describes anew
    number = 1100                  # or numbers = [1100, 1115]
    access = "r"                   # r, w or rw (default rw)
    en = "Pallet clamped (PMC signal)"
    zh = "托盘已夹紧（PMC 信号）"

    [severity]                     # diagnostic code = error|warning|information|hint|off
    macro-alarm = "error"

    [timing]                       # the cycle time's data (timing_settings.py)
    rapid = { X = 30000, Z = 24000 }
    tool_change = 2.5

    [limits]                       # what the machine can do (limits_settings.py)
    travel = { X = [-500, 0], Y = [-400, 0], Z = [-450, 0] }
    feed = 10000
    tools = [1, 24]

Errors are reported as ``MachineFileError`` with the file and the key (and, where it is known,
the line), never as a crash: the file is read as untrusted (docs/design.md "Untrusted folders and
files"), a regular file of at most ``MAX_MACHINE_FILE_BYTES`` in UTF-8, tables nested no deeper
than the parser can go, digits only ASCII ones, and a value is shown in a message only briefly.
"""

from __future__ import annotations

import os
import re
import stat
import sys
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from functools import partial
from pathlib import Path, PureWindowsPath
from typing import Literal, TypedDict, cast

if sys.version_info >= (3, 11):
    import tomllib
else:  # the same reader, from PyPI, before it joined the standard library
    import tomli as tomllib

from ..bilingual import Detail, detail, listed
from ..dialects import DEFAULT_DIALECT, Dialect, choices_text, get_dialect, normalise_dialect
from ..dialects.alarms import MAX_VALUE
from ..dialects.describe import code_key
from ..dialects.tables import CodeDoc, SystemVariable
from ..dialects.timing import TimingChanges
from .files import SkippedFileError, read_bytes
from .limits_settings import MachineLimits, read_limits
from .persistence import led_outside
from .skip_model import SkipModel, read_skip
from .timing_settings import timing_changes
from .toml_numbers import finite_number

MACHINE_FILE_NAME = ".cncmacro.toml"
PERSISTENT_FILE_NAME = ".cncmacro-vars.json"
DEFAULT_MAX_BLOCKS = 1_000_000
# §8 "Arcs": the arc radius tolerance (mm) where the machine file gives none; FANUC's parameter
# 3410 is the machine builder's and has no published value: 0.02 mm passes every arc a CAM
# system rounds to 0.001 and still finds an end point or centre that is wrong
DEFAULT_ARC_TOLERANCE = 0.02
SEVERITY_VALUES = ("error", "warning", "information", "hint", "off")
MAX_MACHINE_FILE_BYTES = 1_000_000  # a machine file is a few hundred bytes


class MachineFileError(ValueError):
    """A machine file that cannot be used, with a message that names the file and key (its
    argument is a ``Detail``: English, with the Chinese beside it). ``line`` is the 0-based line
    the problem is on and ``key`` the setting it is about, where they are known (else None)."""

    def __init__(self, message: Detail, line: int | None = None, key: str | None = None) -> None:
        super().__init__(message)
        self.line = line
        self.key = key

    def located(self) -> Detail:
        """The message with its line (``... (line 3)``), for a reader that is not shown the file
        (a terminal, a debug launch's error); the editor puts the message on the line instead."""
        message = self.args[0]
        zh = message.zh if isinstance(message, Detail) else str(message)
        if self.line is None:
            return detail(str(message), zh)
        return detail(f"{message} (line {self.line + 1})", f"{zh}（第 {self.line + 1} 行）")


@dataclass(frozen=True, slots=True)
class CallCode:
    """A G, M or T code that calls a program: ``macro`` (like G65, a new local level) or
    ``subprogram`` (like M98)."""

    program: int
    call: str = "macro"


@dataclass(frozen=True)
class MachineSettings:
    """The settings of the simulated machine. ``folder`` is where relative paths start."""

    dialect: str | None = None
    # the machine's common ranges (None: every range the profile allows)
    common: tuple[tuple[int, int], ...] | None = None
    # the common ranges each part system (path) of a multi-path control keeps its own; the machine's
    # other commons are shared by the part systems (``part_system_commons``; empty: not said)
    part_system_commons: tuple[tuple[int, int], ...] = ()
    program_digits: int | None = None
    programs_on_control: tuple[tuple[int, int], ...] = ()
    system_variables: tuple[SystemVariable, ...] = ()
    decimal_point: str = "calculator"
    block_delete: bool = False
    # §10.5 the machine checks that a G71/G72 shape is monotone (FANUC's parameter, always on):
    # a shape that is not is then an error, not a warning
    shape_monotone_check: bool = False
    # §8 "Arcs" the arc radius tolerance in mm (FANUC's parameter 3410; 0: not checked)
    arc_tolerance: float = DEFAULT_ARC_TOLERANCE
    # cutter radius compensation's start-up and cancel: type "A" or "B" (FANUC parameter 5003 #0 SUP)
    cutter_startup: str = "A"
    # what offset D holds: the cutter's "radius" or its "diameter" (Haas Setting 40, Tool Offset Measure)
    cutter_offset: str = "radius"
    # §10.1 what the GSK980TDi's chamfer word L measures: "I" its own length (the default), "II" the
    # distance from each end to the intersection (state parameter №181.0)
    chamfer_type: str = "I"
    persistent_file: str | None = None
    max_blocks: int = DEFAULT_MAX_BLOCKS
    date: int | None = None
    time: int | None = None
    variables: dict[int, float] = field(default_factory=dict)
    calls: dict[str, CallCode] = field(default_factory=dict)
    skip: SkipModel = field(default_factory=SkipModel)
    severity: dict[str, str] = field(default_factory=dict)
    folder: str | None = None
    timing: TimingChanges = field(default_factory=TimingChanges)  # [timing]: changes to the profile's
    lathe: bool = False  # the profile's lathe form (``lathe = true``: fanuc-30i's lathes)
    extensions: frozenset[str] = frozenset()  # more endings of program files (``.txt``), lower case
    codes: tuple[CodeDoc, ...] = ()  # [codes]: plain G and M codes of this machine, with their text
    limits: MachineLimits | None = None  # [limits]: the machine's travel, feed, spindle, tools; None: unchecked
    # the 0-based line of ``common`` in the file (where the editor shows ``common_note``)
    common_line: int | None = field(default=None, compare=False)
    # the 0-based line of the ``[calls]`` table (where the editor shows ``standard_calls_note``)
    calls_line: int | None = field(default=None, compare=False)

    def with_presets(self, presets: dict[int, float]) -> MachineSettings:
        """These settings with more preset variables (later ones win)."""
        merged = dict(self.variables)
        merged.update(presets)
        return replace(self, variables=merged)

    def persistent_path(self) -> Path | None:
        """Where ``persistent_file`` is. Its folders and the file itself are followed where they
        are links, and what they lead to must still be inside the machine file's folder (the
        key was checked as written when the file was read): ``MachineFileError`` otherwise."""
        if self.persistent_file is None:
            return None
        p = Path(self.persistent_file)
        if p.is_absolute() or not self.folder:
            return p
        p = Path(self.folder) / p
        target = led_outside(p, Path(self.folder))
        if target is not None:
            root = Path(os.path.realpath(self.folder))
            raise MachineFileError(detail(
                f"'persistent_file' {self.persistent_file!r} leads through a link to {target}, "
                f"outside the machine file's folder {root}",
                f"'persistent_file' {self.persistent_file!r} 经链接指向 {target}，"
                f"在机床设置文件所在文件夹 {root} 之外"))  # fmt: skip
        return p


class _SettingsFields(TypedDict, total=False):
    """The fields of ``MachineSettings`` a mapping gives, as they are gathered."""

    dialect: str | None
    common: tuple[tuple[int, int], ...] | None
    part_system_commons: tuple[tuple[int, int], ...]
    program_digits: int | None
    programs_on_control: tuple[tuple[int, int], ...]
    system_variables: tuple[SystemVariable, ...]
    decimal_point: str
    block_delete: bool
    shape_monotone_check: bool
    arc_tolerance: float
    cutter_startup: str
    cutter_offset: str
    chamfer_type: str
    persistent_file: str | None
    max_blocks: int
    date: int | None
    time: int | None
    variables: dict[int, float]
    calls: dict[str, CallCode]
    skip: SkipModel
    severity: dict[str, str]
    folder: str | None
    timing: TimingChanges
    lathe: bool
    extensions: frozenset[str]
    codes: tuple[CodeDoc, ...]
    limits: MachineLimits | None


# what makes the error for a key of a mapping: the key and what is wrong with its value
_Fail = Callable[[str, Detail], MachineFileError]
_WHOLE_NUMBER_KEYS: tuple[Literal["max_blocks", "date", "time"], ...] = ("max_blocks", "date", "time")


def load_machine_file(path: str | Path) -> MachineSettings:
    """Read a machine file; ``MachineFileError`` says what is wrong."""
    p = Path(path)
    try:
        data = read_bytes(p, MAX_MACHINE_FILE_BYTES)
    except SkippedFileError as e:
        raise MachineFileError(detail(f"{e.message} (the machine file)", f"{e.message.zh}（机床设置文件）")) from e
    except OSError as e:
        reason = e.strerror or e
        raise MachineFileError(detail(f"{p}: cannot read the machine file ({reason})",
                                      f"{p}：无法读取机床设置文件（{reason}）")) from e  # fmt: skip
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        line = data.count(b"\n", 0, e.start)
        raise MachineFileError(detail(f"{p}: not UTF-8 text (byte 0x{data[e.start]:02x} on line {line + 1})",
                                      f"{p}：不是 UTF-8 文本（第 {line + 1} 行的字节 0x{data[e.start]:02x}）"),
                               line) from e  # fmt: skip
    try:
        parsed = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        where = re.search(r"at line (\d+)", str(e))
        raise MachineFileError(detail(f"{p}: not a valid TOML file: {e}", f"{p}：不是有效的 TOML 文件：{e}"),
                               int(where.group(1)) - 1 if where else None) from e  # fmt: skip
    except RecursionError as e:
        raise MachineFileError(detail(f"{p}: not a usable TOML file: its tables or arrays are nested too deeply",
                                      f"{p}：无法使用的 TOML 文件：表或数组嵌套过深")) from e  # fmt: skip
    except ValueError as e:  # tomllib lets through, e.g., a number too long to convert
        long = re.search(r"[0-9_]{4000,}", text)  # Python's limit on converting digits (4300)
        if long is not None:
            line = text.count("\n", 0, long.start())
            raise MachineFileError(detail(f"{p}: a number of {len(long.group())} digits, "
                                          "more than any setting can use",
                                          f"{p}：数字有 {len(long.group())} 位，超出任何设置可用的范围"),
                                   line) from e  # fmt: skip
        raise MachineFileError(detail(f"{p}: not a usable TOML file: {e}", f"{p}：无法使用的 TOML 文件：{e}")) from e
    try:
        settings = settings_from_mapping(parsed, str(p), folder=str(p.parent))
    except MachineFileError as e:
        if e.line is None and e.key is not None:
            e.line = _line_of(text, e.key)
        raise
    except (RecursionError, OverflowError, ValueError, TypeError) as e:  # a value no check foresaw
        raise MachineFileError(detail(f"{p}: a value cannot be used: {type(e).__name__}: {_brief(str(e))}",
                                      f"{p}：有无法使用的值：{type(e).__name__}：{_brief(str(e))}")) from e  # fmt: skip
    if settings.common is not None:
        settings = replace(settings, common_line=_line_of(text, "common"))
    return settings if not settings.calls else replace(settings, calls_line=_line_of(text, "calls"))


def _line_of(text: str, key: str) -> int | None:
    """The 0-based line where the setting ``key`` (``calls.G100``, ``system_variables[2].en``)
    is written: the line of the key inside its table (the first one after the table's line),
    else the table's line, else None."""
    nth = re.search(r"\[(\d+)\]", key)  # the 1-based row of an array of tables
    table, _, inner = re.sub(r"\[\d+\]", "", key).partition(".")
    lines = text.splitlines()

    def find(name: str, start: int, end: int = len(lines)) -> int | None:
        word = rf"""(?:{re.escape(name)}|"{re.escape(name)}"|'{re.escape(name)}')"""
        pattern = re.compile(rf"^\s*(?:\[\[?\s*)?{word}\s*[=.\]]")
        return next((k for k in range(start, end) if pattern.match(lines[k])), None)

    first = find(table, 0)
    for _ in range(int(nth.group(1)) - 1 if nth else 0):
        first = find(table, first + 1) if first is not None else None
    if first is None or not inner:
        return first
    end = next((k for k in range(first + 1, len(lines)) if lines[k].lstrip().startswith("[")), len(lines))
    for name in (inner, inner.rpartition(".")[0]):  # ``calls.M60.call``: the line of M60
        found = find(name, first, end) if name else None
        if found is not None:
            return found
    return first


def _brief(value: object, limit: int = 60) -> str:
    """``value`` as a message shows it: short, and never by walking a nested table or list."""
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, list):
        return "a list"
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 1] + "…"


def find_machine_file(start: str | Path) -> Path | None:
    """The nearest ``.cncmacro.toml`` in ``start`` (a folder or file) or a folder above it. Any
    entry of that name but a folder counts: one that is not a regular file is an error when it is
    read, not silently passed over."""
    try:
        p = Path(start).resolve()
    except (OSError, RuntimeError):  # a link loop: the folders as written
        p = Path(os.path.abspath(start))
    folder = p if os.path.isdir(p) else p.parent
    for d in (folder, *folder.parents):
        candidate = d / MACHINE_FILE_NAME
        try:
            mode = os.stat(candidate).st_mode
        except OSError:
            continue
        if not stat.S_ISDIR(mode):
            return candidate
    return None


# the keys that are true or false
_SWITCH_KEYS: tuple[Literal["block_delete", "shape_monotone_check"], ...] = ("block_delete", "shape_monotone_check")


def settings_from_mapping(
    data: dict[str, object], source: str = "settings", folder: str | None = None
) -> MachineSettings:
    """Settings from a parsed TOML table (also used for a debugger launch configuration)."""

    def fail(key: str, what: Detail) -> MachineFileError:
        shown = key if len(key) <= 60 else key[:59] + "…"
        return MachineFileError(detail(f"{source}: '{shown}' {what}", f"{source}：'{shown}' {what.zh}"), key=key)

    known = {"base", "dialect", "common", "part_system_commons", "program_digits", "programs_on_control",
             "system_variables", "decimal_point", "block_delete", "shape_monotone_check", "arc_tolerance",
             "cutter_startup", "cutter_offset", "chamfer_type", "persistent_file",
             "max_blocks", "date", "time", "variables", "calls", "skip", "severity", "timing", "lathe", "extensions",
             "codes", "limits"}  # fmt: skip
    for key in data:
        if key not in known:
            names = ", ".join(sorted(known))
            raise fail(key, detail(f"is not a machine setting (known: {names})",
                                   f"不是机床设置项（可用的有：{names}）"))  # fmt: skip
    kw: _SettingsFields = {"folder": folder}
    if "base" in data and "dialect" in data:
        raise fail("dialect", detail("names the profile as 'base' does: keep one of them",
                                     "与 'base' 一样指定系统类型，只保留其中一个"))  # fmt: skip
    for key in ("base", "dialect"):
        if key in data:
            value = data[key]
            d = normalise_dialect(value) if isinstance(value, str) else None
            if d is None:
                raise fail(key, detail(f"must be {choices_text()} (not {_brief(value)})",
                                       f"必须是 {choices_text(zh=True)}（不能是 {_brief(value)}）"))  # fmt: skip
            kw["dialect"] = d
    if "lathe" in data:
        kw["lathe"] = _lathe(data["lathe"], str(kw.get("dialect") or DEFAULT_DIALECT), fail)
    if "common" in data:
        kw["common"] = _common(data["common"], str(kw.get("dialect") or DEFAULT_DIALECT), fail)
    if "part_system_commons" in data:
        kw["part_system_commons"] = _part_system_commons(
            data["part_system_commons"], str(kw.get("dialect") or DEFAULT_DIALECT), kw.get("common"), fail
        )
    readers: dict[str, Callable[[object, _Fail], object]] = {
        "extensions": _extensions, "program_digits": _program_digits, "programs_on_control": _program_ranges,
        "system_variables": _system_variables, "decimal_point": _decimal_point, "arc_tolerance": _arc_tolerance,
        "cutter_startup": _cutter_startup, "cutter_offset": _cutter_offset,
        "chamfer_type": partial(_chamfer_type, profile=str(kw.get("dialect") or DEFAULT_DIALECT)),
    }  # fmt: skip
    for key, read in readers.items():  # the keys whose value is read by itself
        if key in data:
            cast("dict[str, object]", kw)[key] = read(data[key], fail)
    for key in _SWITCH_KEYS:
        if key in data:
            kw[key] = _boolean(data[key], key, fail)
    if "persistent_file" in data:
        pf = data["persistent_file"]
        if (not isinstance(pf, str) or not pf or "\0" in pf or Path(pf).is_absolute()
                or PureWindowsPath(pf).is_absolute() or ".." in Path(pf).parts):  # fmt: skip
            raise fail("persistent_file", detail("must be a file name or a path inside the machine file's folder",
                                                 "必须是文件名，或机床设置文件所在文件夹之内的路径"))  # fmt: skip
        kw["persistent_file"] = pf
    for key in _WHOLE_NUMBER_KEYS:
        if key in data:
            kw[key] = _whole_number(key, data[key], fail)
    if "variables" in data:
        kw["variables"] = _variables(data["variables"], fail)
    if "calls" in data:
        kw["calls"] = _calls(data["calls"], fail)
    if "codes" in data:
        kw["codes"] = _codes(data["codes"], kw.get("calls", {}), fail)
    if "skip" in data:
        kw["skip"] = read_skip(data["skip"], fail)
    if "severity" in data:
        kw["severity"] = _severity(data["severity"], fail)
    if "timing" in data:
        kw["timing"] = timing_changes(data["timing"], fail)
    if "limits" in data:
        profile = get_dialect(str(kw.get("dialect") or DEFAULT_DIALECT))
        if kw.get("lathe") and profile.lathe_variant is not None:  # ``lathe = true``: its lathe form's axes
            profile = profile.lathe_variant
        axes = profile.axes
        kw["limits"], kw["timing"] = read_limits(data["limits"], kw.get("timing", {}), axes, fail)
    return MachineSettings(**kw)


def _extensions(value: object, fail: _Fail) -> frozenset[str]:
    """``extensions``: endings of this machine's program files beyond the known ones (``.txt``),
    each with or without its dot, any case."""
    bad = detail('must be a list of file endings such as [".txt", ".min"]',
                 '必须是文件扩展名的列表，如 [".txt", ".min"]')  # fmt: skip
    if not isinstance(value, list):
        raise fail("extensions", bad)
    out: set[str] = set()
    for item in value:
        ending = item.strip().lower() if isinstance(item, str) else ""
        ending = ending if ending.startswith(".") else f".{ending}"
        if not re.fullmatch(r"\.[\w-]{1,15}", ending) or not ending.isascii():
            raise fail("extensions", bad)
        out.add(ending)
    return frozenset(out)


def _program_digits(v: object, fail: _Fail) -> int:
    """``program_digits``: a whole number from 4 to 8."""
    if not isinstance(v, int) or isinstance(v, bool) or not 4 <= v <= 8:
        raise fail("program_digits", detail("must be a whole number from 4 to 8", "必须是 4 到 8 之间的整数"))
    return v


def _arc_tolerance(v: object, fail: _Fail) -> float:
    """``arc_tolerance``: how far apart (mm) an arc's start and end may be from its centre, 0 to 1."""
    if not isinstance(v, (int, float)) or isinstance(v, bool) or not 0.0 <= v <= 1.0:
        raise fail("arc_tolerance", detail("must be a number of mm from 0 to 1 (0: not checked)",
                                           "必须是 0 到 1 之间的毫米数（0：不检查）"))  # fmt: skip
    return float(v)


def _cutter_startup(v: object, fail: _Fail) -> str:
    """``cutter_startup``: "A" or "B", how cutter radius compensation starts and cancels."""
    if v not in ("A", "B"):
        raise fail("cutter_startup", detail(f'must be "A" or "B" (not {_brief(v)})',
                                            f'必须是 "A" 或 "B"（不能是 {_brief(v)}）'))  # fmt: skip
    return str(v)


def _cutter_offset(v: object, fail: _Fail) -> str:
    """``cutter_offset``: "radius" or "diameter", what a D offset holds."""
    if v not in ("radius", "diameter"):
        raise fail("cutter_offset", detail(f'must be "radius" or "diameter" (not {_brief(v)})',
                                           f'必须是 "radius" 或 "diameter"（不能是 {_brief(v)}）'))  # fmt: skip
    return str(v)


def _decimal_point(point: object, fail: _Fail) -> str:
    """``decimal_point``: "calculator" or "increment"."""
    if not isinstance(point, str) or point not in ("calculator", "increment"):
        raise fail("decimal_point", detail('must be "calculator" or "increment"',
                                           '必须是 "calculator" 或 "increment"'))  # fmt: skip
    return point


def _boolean(value: object, key: str, fail: _Fail) -> bool:
    """A key that is true or false."""
    if not isinstance(value, bool):
        raise fail(key, detail("must be true or false", "必须是 true 或 false"))
    return value


def _lathe(value: object, profile: str, fail: _Fail) -> bool:
    """``lathe = true``: the profile's lathe form (docs/machine-file.md). Only a profile that has
    one takes it; a lathe profile is a lathe already, and ``false`` keeps the profile as it is."""
    value = _boolean(value, "lathe", fail)
    base = get_dialect(profile)
    if value and not base.lathe and base.lathe_variant is None:
        raise fail("lathe", detail(f"is not a setting of {profile}, which has no lathe form "
                                   "(a FANUC 0i lathe is base = \"fanuc-0i-lathe\"; the 30i's is base = \"fanuc-30i\")",
                                   f"不适用于 {profile}：它没有车床形式（FANUC 0i 车床请用 base = \"fanuc-0i-lathe\"；"
                                   "30i 车床为 base = \"fanuc-30i\"）"))  # fmt: skip
    if not value and base.lathe:
        raise fail("lathe", detail(f"cannot be false: {profile} is a lathe", f"不能为 false：{profile} 是车床"))
    return value


def _chamfer_type(value: object, fail: _Fail, profile: str) -> str:
    """``chamfer_type``: "I" or "II", what the chamfer word L measures (GSK980TDi §3.11.1, state
    parameter №181.0); only a profile with that word takes it."""
    if get_dialect(profile).chamfer_words is None:
        raise fail("chamfer_type", detail(
            f"is not a setting of {profile}, which has no chamfer word L (the GSK980TDi's: base = \"gsk980tdi\")",
            f"不适用于 {profile}：它没有倒角代码 L（GSK980TDi 的：base = \"gsk980tdi\"）"))  # fmt: skip
    if value not in ("I", "II"):
        raise fail("chamfer_type", detail(f'must be "I" or "II" (not {_brief(value)})',
                                          f'必须是 "I" 或 "II"（不能是 {_brief(value)}）'))  # fmt: skip
    return str(value)


def _common(value: object, profile: str, fail: _Fail) -> tuple[tuple[int, int], ...]:
    """``common``: a list of ``[first, last]`` ranges, or the older single ``[first, last]`` below
    #500 (the volatile range; the profile's #500-#999 stay). The machine file describes the real
    machine, so a range beyond the profile's list is taken (an OKK 30i's #900000-#907399) as long as
    it is no local variable (below #100) and overlaps none of the profile's system variables;
    ranges that overlap or touch are one range."""
    dialect = get_dialect(profile)
    bad = detail("must be a list of ranges such as [[100, 499], [500, 999]], each from #100 up",
                 "必须是变量号范围的列表，如 [[100, 499], [500, 999]]，且每个范围从 #100 起")  # fmt: skip

    def pair(x: object) -> tuple[int, int] | None:
        if isinstance(x, list) and len(x) == 2 and all(isinstance(v, int) and not isinstance(v, bool) for v in x):
            return (x[0], x[1]) if 100 <= x[0] <= x[1] <= 99_999_999 else None
        return None

    if not isinstance(value, list) or not value:
        raise fail("common", bad)
    single = pair(value)
    if single is not None:
        if single[1] >= 500:
            raise fail("common", bad)
        ranges = [single, *((r.first, r.last) for r in dialect.common_ranges if r.persistent)]
    else:
        ranges = []
        for x in value:
            p = pair(x)
            if p is None:
                raise fail("common", bad)
            ranges.append(p)
    merged: list[tuple[int, int]] = []
    for first, last in sorted(ranges):
        if merged and first <= merged[-1][1] + 1:
            merged[-1] = (merged[-1][0], max(last, merged[-1][1]))
        else:
            merged.append((first, last))
    for first, last in merged:
        for row in dialect.system_variables():
            if row.first <= last and first <= row.last:
                held = f"#{row.first}" if row.first == row.last else f"#{row.first}-#{row.last}"
                raise fail("common", detail(
                    f"#{first}-#{last} overlaps the system variables {held} of {dialect.name} ({row.en}): "
                    "a common range cannot hold them",
                    f"#{first}-#{last} 与 {dialect.name} 的系统变量 {held}（{row.zh}）重叠："
                    "公共变量范围不能包含它们"))  # fmt: skip
    return tuple(merged)


def _part_system_commons(
    value: object, profile: str, common: tuple[tuple[int, int], ...] | None, fail: _Fail
) -> tuple[tuple[int, int], ...]:
    """``part_system_commons``: the ranges of commons each part system keeps its own (a list of
    ``[first, last]``, empty for none), each inside the machine's commons (``common``, else the
    profile's ranges). On a multi-path control parameters decide how many of #100-#199 and
    #500-#999 the paths share (Mitsubishi M70/M80: docs/machine-file.md)."""
    dialect = get_dialect(profile)
    ranges = common if common is not None else tuple((r.first, r.last) for r in dialect.common_ranges)
    shown = ", ".join(f"#{a}-#{b}" for a, b in ranges)
    bad = detail(f"must be a list of ranges such as [[100, 149]], each inside the machine's commons ({shown})",
                 f"必须是变量号范围的列表，如 [[100, 149]]，且每个范围都在本机床的公共变量（{shown}）之内")  # fmt: skip
    if not isinstance(value, list):
        raise fail("part_system_commons", bad)
    out: list[tuple[int, int]] = []
    for x in value:
        if not (isinstance(x, list) and len(x) == 2 and all(isinstance(v, int) and not isinstance(v, bool) for v in x)):
            raise fail("part_system_commons", bad)
        first, last = x
        if not (first <= last and any(a <= first and last <= b for a, b in ranges)):
            raise fail("part_system_commons", bad)
        out.append((first, last))
    return tuple(sorted(out))


def common_beyond_profile(settings: MachineSettings, profile: str | None = None) -> Detail | None:
    """A note on the common ranges of ``settings`` that the profile (``profile``, else the machine
    file's, else the default) does not list, so that a person sees what the machine file added;
    None when it adds none."""
    if settings.common is None:
        return None
    dialect = get_dialect(profile or settings.dialect or DEFAULT_DIALECT)
    added: list[tuple[int, int]] = []
    for first, last in settings.common:
        at = first
        for r in sorted(dialect.common_ranges, key=lambda r: r.first):
            if r.last < at or r.first > last:
                continue
            if r.first > at:
                added.append((at, r.first - 1))
            at = max(at, r.last + 1)
        if at <= last:
            added.append((at, last))
    if not added:
        return None
    ranges = [f"#{a}-#{b}" for a, b in added]
    profile_ranges = [r.text() for r in dialect.common_ranges]
    return detail(f"{listed('en', ranges)}: common variables of this machine beyond {dialect.name}'s list "
                  f"({listed('en', profile_ranges)})",
                  f"{listed('zh', ranges)}：本机床在 {dialect.name} 所列范围（{listed('zh', profile_ranges)}）"
                  "之外的公共变量")  # fmt: skip


def common_note(settings: MachineSettings, shown: str, profile: str | None = None) -> Detail | None:
    """The note on the common ranges the machine file at ``shown`` adds to the profile
    (``common_beyond_profile``), as ``cncmacro check`` prints it and the editor shows it on the
    machine file; None when it adds none."""
    added = common_beyond_profile(settings, profile)
    if added is None:
        return None
    return detail(f"{shown}: common {added}", f"{shown}：common {added.zh}")


def standard_calls(settings: MachineSettings, dialect: Dialect) -> tuple[str, ...]:
    """The ``[calls]`` G codes that are the profile's own G codes where the profile lets no such
    code call a program (``Dialect.standard_g_calls`` off: GSK980TDi manual §3.32, "when the
    code set equals a standard G code, the function is disabled"): they are no calls, the
    standard code runs (``profiles.profile_settings``)."""
    if dialect.standard_g_calls or not settings.calls:
        return ()
    own = set()
    for doc in dialect.g_codes():
        try:
            own.add(float(doc.code[1:]))
        except ValueError:
            continue
    return tuple(k for k in settings.calls if k[0] == "G" and float(k[1:]) in own)


def standard_calls_note(settings: MachineSettings, shown: str, profile: str | None = None) -> Detail | None:
    """The note on the ``[calls]`` entries of the machine file at ``shown`` that the profile
    (``profile``, else the machine file's, else the default) does not call (``standard_calls``),
    as ``cncmacro check`` prints it and the editor shows it on the machine file; None when there
    are none."""
    dialect = get_dialect(profile or settings.dialect or DEFAULT_DIALECT)
    codes = standard_calls(settings, dialect)
    if not codes:
        return None
    en, zh = listed("en", codes), listed("zh", codes)
    return detail(
        f"{shown}: [calls] {en}: {dialect.title} does not call a program for a standard G code of its own "
        f"(a code set equal to a standard G code is disabled); {en} runs as the standard code",
        f"{shown}：[calls] {zh}：{dialect.title} 的标准 G 代码不能设为宏程序调用（设定值与标准 G 代码相同时"
        f"本功能自动无效），{zh} 按标准 G 代码执行",
    )


def _program_ranges(value: object, fail: _Fail) -> tuple[tuple[int, int], ...]:
    """``programs_on_control``: ``"O9000-O9999"``, ``"O8000"`` or a number, in a list."""
    bad = detail('must be a list of program numbers or ranges such as ["O9000-O9999", "O8000"]',
                 '必须是程序号或程序号范围的列表，如 ["O9000-O9999", "O8000"]')  # fmt: skip
    if not isinstance(value, list):
        raise fail("programs_on_control", bad)
    out: list[tuple[int, int]] = []
    for item in value:
        if isinstance(item, int) and not isinstance(item, bool):
            first = last = item
        elif isinstance(item, str):
            parts = [s.strip().upper().lstrip("O") for s in item.split("-")]
            if len(parts) not in (1, 2) or not all(_digits(s) and len(s) <= 8 for s in parts):
                raise fail("programs_on_control", bad)
            first, last = int(parts[0]), int(parts[-1])
        else:
            raise fail("programs_on_control", bad)
        if not 0 <= first <= last <= 99_999_999:
            raise fail("programs_on_control", bad)
        out.append((first, last))
    return tuple(out)


_ACCESS = ("r", "w", "rw")


def _system_variables(value: object, fail: _Fail) -> tuple[SystemVariable, ...]:
    """``[[system_variables]]``: ``number`` (or ``numbers = [first, last]``), ``access``,
    ``en``, ``zh``, and optionally ``unit``."""
    if not isinstance(value, list) or not all(isinstance(x, dict) for x in value):
        raise fail("system_variables", detail("must be a list of tables ([[system_variables]])",
                                              "必须是表的列表（[[system_variables]]）"))  # fmt: skip
    out: list[SystemVariable] = []
    for k, row in enumerate(value, start=1):
        where = f"system_variables[{k}]"
        unknown = sorted(set(row) - {"number", "numbers", "access", "en", "zh", "unit"})
        if unknown:
            keys = "number, numbers, access, en, zh, unit"
            raise fail(f"{where}.{unknown[0]}", detail(f"is not a key of a system variable ({keys})",
                                                       f"不是系统变量的设置项（{keys}）"))  # fmt: skip
        if "number" in row and isinstance(row["number"], int) and not isinstance(row["number"], bool):
            first = last = row["number"]
        elif ("numbers" in row and isinstance(row["numbers"], list) and len(row["numbers"]) == 2
              and all(isinstance(v, int) and not isinstance(v, bool) for v in row["numbers"])):  # fmt: skip
            first, last = row["numbers"]
        else:
            raise fail(where, detail("needs number = N or numbers = [first, last]",
                                     "需要“number = 变量号”或“numbers = [起始号,结束号]”"))  # fmt: skip
        if not 1000 <= first <= last <= 99_999_999:
            raise fail(where, detail("system variables are numbered from #1000 up", "系统变量号从 #1000 开始"))
        access = row.get("access", "rw")
        if access not in _ACCESS:
            raise fail(f"{where}.access", detail('must be "r", "w" or "rw"', '必须是 "r"、"w" 或 "rw"'))
        en = row.get("en")
        if not isinstance(en, str) or not en.strip():
            raise fail(f"{where}.en", detail("must say what the variable is, in English", "必须用英文说明该变量"))
        zh = row.get("zh", en)
        unit = row.get("unit", "")
        if not isinstance(zh, str) or not isinstance(unit, str):
            raise fail(where, detail("zh and unit must be text", "zh 和 unit 必须是文字"))
        out.append(SystemVariable(first, last, access, "signals", en.strip(), zh.strip() or en.strip(), unit))
    return tuple(out)


def _whole_number(key: str, v: object, fail: _Fail) -> int:
    """``max_blocks``, ``date`` or ``time``: a whole number, 0 or more (``max_blocks`` 1 or more)."""
    if not isinstance(v, int) or isinstance(v, bool) or v < 0:
        raise fail(key, detail("must be a whole number", "必须是非负整数"))
    if key == "max_blocks" and v < 1:  # a budget of no block runs nothing, and says the budget ran out
        raise fail(key, detail("must be at least 1 (the blocks an analysis run may run)",
                               "必须不小于 1（一次分析运行可执行的程序段数）"))  # fmt: skip
    return v


def _variables(table: object, fail: _Fail) -> dict[int, float]:
    if not isinstance(table, dict):
        raise fail("variables", detail("must be a table of number = value", "必须是“变量号 = 数值”形式的表"))
    out: dict[int, float] = {}
    for k, v in table.items():
        key = str(k).lstrip("#")
        if not _digits(key) or len(key) > 8:
            raise fail(f"variables.{k}", detail("is not a variable number", "不是变量号"))
        number = finite_number(v)  # a number a variable can hold
        if number is None or abs(number) > MAX_VALUE:
            raise fail(f"variables.{k}", detail(
                f"must be a finite number a variable holds (±{MAX_VALUE:g} at most)",
                f"必须是变量可保存的有限数值（绝对值不超过 {MAX_VALUE:g}）"))  # fmt: skip
        out[int(key)] = number
    return out


def _calls(table: object, fail: _Fail) -> dict[str, CallCode]:
    if not isinstance(table, dict):
        raise fail("calls", detail("must be a table of code = program", "必须是“代码 = 程序号”形式的表"))
    out: dict[str, CallCode] = {}
    for k, v in table.items():
        code = str(k).upper()
        if not (code == "T" or (code[:1] in ("G", "M") and _digits(code[1:].replace(".", "", 1))
                                and len(code) <= 10)):  # fmt: skip
            raise fail(f"calls.{k}", detail("must be a G or M code (G100, M50) or T",
                                            "必须是 G 或 M 代码（G100、M50）或 T"))  # fmt: skip
        default = "subprogram" if code == "T" else "macro"
        if isinstance(v, int) and not isinstance(v, bool):
            out[_code_key(code)] = CallCode(v, default)
        elif isinstance(v, dict) and isinstance(v.get("program"), int):
            call = v.get("call", default)
            if call not in ("macro", "subprogram"):
                raise fail(f"calls.{k}.call", detail('must be "macro" or "subprogram"',
                                                     '必须是 "macro" 或 "subprogram"'))  # fmt: skip
            out[_code_key(code)] = CallCode(int(v["program"]), str(call))
        else:
            raise fail(f"calls.{k}", detail("must be a program number or {program = N, call = ...}",
                                            "必须是程序号或 {program = N, call = ...}"))  # fmt: skip
    return out


def _codes(table: object, calls: dict[str, CallCode], fail: _Fail) -> tuple[CodeDoc, ...]:
    """``[codes]``: plain G and M codes the machine builder added (``"G120.1" = { en = "...", zh =
    "..." }``): no call, no motion, no alarm; ``en`` and ``zh`` are what hover says of them."""
    if not isinstance(table, dict):
        raise fail("codes", detail('must be a table of code = { en = "...", zh = "..." }',
                                   '必须是表，每项形如 G120.1 = { en = "...", zh = "..." }'))  # fmt: skip
    out: list[CodeDoc] = []
    for k, v in table.items():
        code = str(k).strip().upper()
        number = code[1:]
        if not ((code[:1] == "G" and re.fullmatch(r"\d{1,4}(\.\d)?", number))
                or (code[:1] == "M" and re.fullmatch(r"\d{1,8}", number))):  # fmt: skip
            raise fail(f"codes.{k}", detail("must be a G code (G120, G120.1) or an M code without a decimal point",
                                            "必须是 G 代码（G120、G120.1）或不带小数点的 M 代码"))  # fmt: skip
        if _code_key(code) in calls:
            raise fail(f"codes.{k}", detail("is also in [calls]: a code either calls a program or is a plain code",
                                            "同时出现在 [calls] 中：一个代码要么调用程序，要么是普通代码"))  # fmt: skip
        if not isinstance(v, dict) or not isinstance(v.get("en"), str) or not v["en"].strip():
            raise fail(f"codes.{k}", detail('must say what the code does: { en = "...", zh = "..." }',
                                            '必须说明该代码的作用：{ en = "...", zh = "..." }'))  # fmt: skip
        unknown = sorted(set(v) - {"en", "zh"})
        zh = v.get("zh", v["en"])
        if unknown or not isinstance(zh, str):
            raise fail(f"codes.{k}", detail("takes en and zh, both text", "只接受 en 和 zh，且都必须是文字"))
        en = v["en"].strip()
        out.append(CodeDoc(code_key(code[0], float(number)), "", en, zh.strip() or en))
    return tuple(out)


def _severity(table: object, fail: _Fail) -> dict[str, str]:
    """``[severity]``: diagnostic code -> a severity or ``off``. Whether each code exists is
    checked where the diagnostics are made (the analysis layer knows the codes)."""
    if not isinstance(table, dict):
        raise fail("severity", detail("must be a table of diagnostic code = severity",
                                      "必须是“诊断代码 = 严重程度”形式的表"))  # fmt: skip
    out: dict[str, str] = {}
    for k, v in table.items():
        if not isinstance(v, str) or v.strip().lower() not in SEVERITY_VALUES:
            values = ", ".join(SEVERITY_VALUES)
            raise fail(f"severity.{k}", detail(f"must be one of {values} (not {_brief(v)})",
                                               f"必须是 {values} 之一（不能是 {_brief(v)}）"))  # fmt: skip
        out[str(k)] = v.strip().lower()
    return out


def _digits(text: str) -> bool:
    """Whether ``text`` is ASCII digits (``str.isdigit`` takes ``²`` and ``٣`` too)."""
    return text.isascii() and text.isdigit()


def _code_key(code: str) -> str:
    """``G0100`` and ``G100`` are one code: the key is the letter and the number's value."""
    if code == "T":
        return code
    value = float(code[1:])
    return f"{code[0]}{value:g}"


def parse_preset(text: str) -> tuple[int, float]:
    """``100=5`` or ``#2001=0.5`` from ``--set`` (the ``#`` may be left out; spaces around the
    parts are allowed); ``ValueError`` with a plain message that shows the expected form."""
    form = detail("write it as NUMBER=VALUE, e.g. --set 100=5 or --set '#100=5'",
                  "应写成“变量号=数值”，例如 --set 100=5 或 --set '#100=5'")  # fmt: skip
    name, sep, value = text.partition("=")
    name = name.strip()
    name = name[1:].strip() if name.startswith("#") else name
    if not sep or not name.isascii() or not name.isdigit():
        raise ValueError(detail(f"--set {text!r}: {form}", f"--set {text!r}：{form.zh}"))
    try:
        v = float(value)
    except ValueError:
        raise ValueError(detail(f"--set {text!r}: {value.strip()!r} is not a number; {form}",
                                f"--set {text!r}：{value.strip()!r} 不是数值；{form.zh}")) from None  # fmt: skip
    if v != v or v in (float("inf"), float("-inf")):
        raise ValueError(detail(f"--set {text!r}: the value must be a finite number; {form}",
                                f"--set {text!r}：数值必须是有限数；{form.zh}"))  # fmt: skip
    return int(name), v
