"""Machine settings: the workspace's ``.cncmacro.toml``, read with ``tomllib``.

Every key is optional (docs/design.md "Machine settings")::

    dialect = "gsk980tdi"
    common = [100, 499]            # the volatile common range (default 100-199)
    decimal_point = "increment"    # or "calculator" (default): how X10 without a point is read
    block_delete = true            # skip blocks that start with '/'
    persistent_file = ".cncmacro-vars.json"   # keeps #500-#999 between runs (a path inside this folder)
    max_blocks = 1000000           # the analysis budget per run
    date = 20261122                # the clock (#3011, #3012) when runs must be repeatable
    time = 153000

    [variables]                    # preset values: offsets, counters, commons
    2001 = 0.5
    100 = 3

    [calls]                        # codes that call programs (seed 001, seed 003 ch. 8)
    G100 = 9010                    # like G65 P9010
    M50 = 9020
    M60 = { program = 9001, call = "subprogram" }   # like M98 P9001
    T = 9000                       # every T code calls O9000 (the T value in #149)

    [skip]                         # where the G31 skip signal fires
    Z = -12.5

    [severity]                     # diagnostic code = error|warning|information|hint|off
    macro-alarm = "error"

Errors are reported as ``MachineFileError`` with the file and the key, never as a crash.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path, PureWindowsPath

import tomllib

from ..bilingual import Detail, detail
from ..dialects import DIALECTS, normalise_dialect

MACHINE_FILE_NAME = ".cncmacro.toml"
PERSISTENT_FILE_NAME = ".cncmacro-vars.json"
DEFAULT_MAX_BLOCKS = 1_000_000
SEVERITY_VALUES = ("error", "warning", "information", "hint", "off")


class MachineFileError(ValueError):
    """A machine file that cannot be used, with a message that names the file and key (its
    argument is a ``Detail``: English, with the Chinese beside it)."""


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
    common: tuple[int, int] = (100, 199)
    decimal_point: str = "calculator"
    block_delete: bool = False
    persistent_file: str | None = None
    max_blocks: int = DEFAULT_MAX_BLOCKS
    date: int | None = None
    time: int | None = None
    variables: dict[int, float] = field(default_factory=dict)
    calls: dict[str, CallCode] = field(default_factory=dict)
    skip: dict[str, float] = field(default_factory=dict)
    severity: dict[str, str] = field(default_factory=dict)
    folder: str | None = None

    def with_presets(self, presets: dict[int, float]) -> MachineSettings:
        """These settings with more preset variables (later ones win)."""
        merged = dict(self.variables)
        merged.update(presets)
        return replace(self, variables=merged)

    def persistent_path(self) -> Path | None:
        if self.persistent_file is None:
            return None
        p = Path(self.persistent_file)
        if not p.is_absolute() and self.folder:
            p = Path(self.folder) / p
        return p


def load_machine_file(path: str | Path) -> MachineSettings:
    """Read a machine file; ``MachineFileError`` says what is wrong."""
    p = Path(path)
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except OSError as e:
        reason = e.strerror or e
        raise MachineFileError(detail(f"{p}: cannot read the machine file ({reason})",
                                      f"{p}：无法读取机床设置文件（{reason}）")) from e  # fmt: skip
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
        raise MachineFileError(detail(f"{p}: not a valid TOML file: {e}", f"{p}：不是有效的 TOML 文件：{e}")) from e
    return settings_from_mapping(data, str(p), folder=str(p.parent))


def find_machine_file(start: str | Path) -> Path | None:
    """The nearest ``.cncmacro.toml`` in ``start`` (a folder or file) or a folder above it."""
    p = Path(start).resolve()
    folder = p if p.is_dir() else p.parent
    for d in (folder, *folder.parents):
        candidate = d / MACHINE_FILE_NAME
        if candidate.is_file():
            return candidate
    return None


def settings_from_mapping(
    data: dict[str, object], source: str = "settings", folder: str | None = None
) -> MachineSettings:
    """Settings from a parsed TOML table (also used for a debugger launch configuration)."""

    def fail(key: str, what: Detail) -> MachineFileError:
        return MachineFileError(detail(f"{source}: '{key}' {what}", f"{source}：'{key}' {what.zh}"))

    known = {"dialect", "common", "decimal_point", "block_delete", "persistent_file", "max_blocks", "date", "time",
             "variables", "calls", "skip", "severity"}  # fmt: skip
    for key in data:
        if key not in known:
            names = ", ".join(sorted(known))
            raise fail(key, detail(f"is not a machine setting (known: {names})",
                                   f"不是机床设置项（可用的有：{names}）"))  # fmt: skip
    kw: dict[str, object] = {"folder": folder}
    if "dialect" in data:
        d = normalise_dialect(str(data["dialect"]))
        if d is None:
            names = ", ".join(DIALECTS)
            raise fail("dialect", detail(f"must be one of {names}", f"必须是 {names} 之一"))
        kw["dialect"] = d
    if "common" in data:
        c = data["common"]
        if not (
            isinstance(c, list) and len(c) == 2 and all(isinstance(x, int) for x in c) and 100 <= c[0] <= c[1] < 500
        ):
            raise fail("common", detail("must be two numbers such as [100, 199] (within #100-#499)",
                                        "必须是两个数，如 [100, 199]（在 #100-#499 之内）"))  # fmt: skip
        kw["common"] = (c[0], c[1])
    if "decimal_point" in data:
        if data["decimal_point"] not in ("calculator", "increment"):
            raise fail("decimal_point", detail('must be "calculator" or "increment"',
                                               '必须是 "calculator" 或 "increment"'))  # fmt: skip
        kw["decimal_point"] = data["decimal_point"]
    if "block_delete" in data:
        if not isinstance(data["block_delete"], bool):
            raise fail("block_delete", detail("must be true or false", "必须是 true 或 false"))
        kw["block_delete"] = data["block_delete"]
    if "persistent_file" in data:
        pf = str(data["persistent_file"])
        if not pf or Path(pf).is_absolute() or PureWindowsPath(pf).is_absolute() or ".." in Path(pf).parts:
            raise fail("persistent_file", detail("must be a file name or a path inside the machine file's folder",
                                                 "必须是文件名，或机床设置文件所在文件夹之内的路径"))  # fmt: skip
        kw["persistent_file"] = pf
    for key in ("max_blocks", "date", "time"):
        if key in data:
            v = data[key]
            if not isinstance(v, int) or isinstance(v, bool) or v < 0:
                raise fail(key, detail("must be a whole number", "必须是非负整数"))
            kw[key] = v
    if "variables" in data:
        kw["variables"] = _variables(data["variables"], fail)
    if "calls" in data:
        kw["calls"] = _calls(data["calls"], fail)
    if "skip" in data:
        s = data["skip"]
        if not isinstance(s, dict) or not all(isinstance(v, (int, float)) for v in s.values()):
            raise fail("skip", detail("must map axis letters to positions", "必须是 轴地址 = 位置 形式的表"))
        kw["skip"] = {str(k).upper(): float(v) for k, v in s.items()}
    if "severity" in data:
        kw["severity"] = _severity(data["severity"], fail)
    return MachineSettings(**kw)  # type: ignore[arg-type]


def _variables(table: object, fail) -> dict[int, float]:  # type: ignore[no-untyped-def]
    if not isinstance(table, dict):
        raise fail("variables", detail("must be a table of number = value", "必须是 变量号 = 数值 形式的表"))
    out: dict[int, float] = {}
    for k, v in table.items():
        key = str(k).lstrip("#")
        if not key.isdigit():
            raise fail(f"variables.{k}", detail("is not a variable number", "不是变量号"))
        if not isinstance(v, (int, float)) or isinstance(v, bool):
            raise fail(f"variables.{k}", detail("must be a number", "必须是数值"))
        out[int(key)] = float(v)
    return out


def _calls(table: object, fail) -> dict[str, CallCode]:  # type: ignore[no-untyped-def]
    if not isinstance(table, dict):
        raise fail("calls", detail("must be a table of code = program", "必须是 代码 = 程序号 形式的表"))
    out: dict[str, CallCode] = {}
    for k, v in table.items():
        code = str(k).upper()
        if not (code == "T" or (code[:1] in ("G", "M") and code[1:].replace(".", "", 1).isdigit())):
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


def _severity(table: object, fail) -> dict[str, str]:  # type: ignore[no-untyped-def]
    """``[severity]``: diagnostic code -> a severity or ``off``. Whether each code exists is
    checked where the diagnostics are made (the analysis layer knows the codes)."""
    if not isinstance(table, dict):
        raise fail("severity", detail("must be a table of diagnostic code = severity",
                                      "必须是 诊断代码 = 严重程度 形式的表"))  # fmt: skip
    out: dict[str, str] = {}
    for k, v in table.items():
        if not isinstance(v, str) or v.strip().lower() not in SEVERITY_VALUES:
            values = ", ".join(SEVERITY_VALUES)
            raise fail(f"severity.{k}", detail(f"must be one of {values} (not {v!r})",
                                               f"必须是 {values} 之一（不能是 {v!r}）"))  # fmt: skip
        out[str(k)] = v.strip().lower()
    return out


def _code_key(code: str) -> str:
    """``G0100`` and ``G100`` are one code: the key is the letter and the number's value."""
    if code == "T":
        return code
    value = float(code[1:])
    return f"{code[0]}{value:g}"


def parse_preset(text: str) -> tuple[int, float]:
    """``100=5`` or ``#2001=0.5`` from ``--set``; ``ValueError`` with a plain message."""
    name, sep, value = text.partition("=")
    name = name.strip().lstrip("#")
    if not sep or not name.isdigit():
        raise ValueError(detail(f"--set {text!r}: write it as NUMBER=VALUE, e.g. --set 100=5",
                                f"--set {text!r}：应写成 变量号=数值，例如 --set 100=5"))  # fmt: skip
    try:
        v = float(value)
    except ValueError:
        raise ValueError(detail(f"--set {text!r}: {value.strip()!r} is not a number",
                                f"--set {text!r}：{value.strip()!r} 不是数值")) from None  # fmt: skip
    if v != v or v in (float("inf"), float("-inf")):
        raise ValueError(detail(f"--set {text!r}: the value must be a finite number",
                                f"--set {text!r}：数值必须是有限数"))  # fmt: skip
    return int(name), v
