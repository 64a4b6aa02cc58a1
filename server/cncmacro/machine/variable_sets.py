"""The variables of a run as sets: presets before it (``--set``, the machine file), the values kept
at power-off, and the variables a run ends with (docs/design.md's ``variables``).

``VariableSets`` is that part of ``Machine`` (machine.py); reading and writing one variable by
number is ``VariableAccess`` (variables.py).
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

from ..bilingual import Detail, detail
from ..dialects.alarms import MAX_VALUE
from ..dialects.describe import describe_system_variable
from .alarms import MacroAlarm

if TYPE_CHECKING:
    from ..dialects import Dialect
    from .expressions import VariableKinds

Value = float | None


class VariableSets:
    """Presets, kept values and a run's final variables (module docstring)."""

    dialect: Dialect
    kinds: VariableKinds
    L: list[Value]
    C: list[Value]
    S: dict[int, Value]
    preset_system: set[int]
    written_system: set[int]
    frames: list[Any]

    if TYPE_CHECKING:

        def read_system(self, n: int) -> Value: ...

        def set_signal_word(self, param: str, value: Value) -> None: ...

    def apply_presets(self, presets: dict[int, float]) -> None:
        """Set variables before the run (``--set``, the machine file). Offsets and other
        stored system variables may be preset even where a program may not write them;
        computed ones (positions, modal codes) may not. ``ValueError`` says why."""
        for n, v in presets.items():
            if v is not None and not -MAX_VALUE <= v <= MAX_VALUE:
                raise ValueError(detail(f"#{n} = {v:g} is beyond what a variable holds (±{MAX_VALUE:g})",
                                        f"#{n} = {v:g} 超出变量可保存的范围（±{MAX_VALUE:g}）"))  # fmt: skip
            kind = self.kinds.kind(n)
            if kind == "local":
                self.L[n] = v
            elif kind in ("common", "persistent"):
                self.C[n] = v
            elif kind == "extended":
                self.S[n] = v
            elif kind == "system":
                row = self.dialect.system_variable(n)
                assert row is not None
                if row.source == "alias":
                    self.S[int(row.param) + n - row.first] = v
                elif row.source == "bits":  # the signals it is made of
                    self.set_signal_word(row.param, v)
                elif row.source in ("store", "date", "time", "timer"):
                    self.S[n] = v
                else:
                    described = {lang: describe_system_variable(self.dialect, n, lang) for lang in ("en", "zh-CN")}
                    en, zh = (d.text if d is not None else "" for d in described.values())  # ``{axis}`` filled in
                    axis_first = re.match(r"第\d+轴（[^）]*）[^（；]*", zh)  # 第2轴（Y）程序段终点位置
                    short_zh = axis_first.group() if axis_first else zh.split("；")[0].split("（")[0]
                    name = Detail(en.split(";")[0].split(" (")[0], short_zh)
                    raise ValueError(detail(f"#{n} ({name}) is computed by the machine and cannot be preset",
                                            f"#{n}（{name.zh}）由机床计算，不能预设"))  # fmt: skip
                self.preset_system.add(n)
            else:
                raise ValueError(detail(
                    f"#{n} is not a variable of {self.dialect.title} that can be preset "
                    "(local #1-#33, common and persistent variables, offsets and other stored system variables can)",
                    f"#{n} 不是 {self.dialect.title} 可预设的变量"
                    "（可预设局部变量 #1～#33、公共变量与断电保持变量、刀补等存储型系统变量）"))  # fmt: skip

    def load_persistent(self, values: dict[int, float]) -> None:
        """Put back the values kept at power-off (the machine's persistent common ranges)."""
        for n, v in values.items():
            kind = self.kinds.kind(n)
            if kind == "persistent":
                self.C[n] = v
            elif kind == "extended" and any(n in r for r in self.kinds.persistent):
                self.S[n] = v

    def persistent_values(self) -> dict[int, float]:
        out: dict[int, float] = {}
        for n in self.kinds.persistent_numbers():
            v = self.C[n] if n < 1000 else self.S.get(n)
            if v is not None:
                out[n] = v
        return out

    def variables(self) -> dict[int, float]:
        """docs/design.md's ``variables``: non-vacant level-0 locals, commons and persistent, and
        the system variables that were preset or written (vacant ones are absent)."""
        out: dict[int, float] = {}
        level0 = self.frames[0].locals if self.frames else self.L
        for n in range(1, 34):
            v = level0[n]
            if v is not None:
                out[n] = v
        for r in self.kinds.ranges:
            for n in range(r.first, r.last + 1):
                v = self.C[n] if n < 1000 else self.S.get(n)
                if v is not None:
                    out[n] = v
        for n in sorted(self.preset_system | self.written_system):
            try:
                v = self.read_system(n)
            except MacroAlarm:
                continue
            if v is not None:
                out[n] = v
        return dict(sorted(out.items()))
