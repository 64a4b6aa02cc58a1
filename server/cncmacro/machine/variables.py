"""Reading and writing any variable by number (docs/semantics.md §2, §6, §8).

``L`` is the current level's locals (index 1–33), ``C`` the commons and persistent variables
(index 100–999), ``S`` the stored system variables (offsets, counters, signals). Live system
variables (modal codes, positions, the clock) are computed from the machine state whenever
they are read; which is which comes from the dialect's table, row by row. Compiled blocks read
locals and commons directly; everything else comes through here. ``named_number`` says which
number a FANUC 30i name ``[#_NAME[n]]`` stands for.
"""

from __future__ import annotations

import datetime as _dt
import math
from typing import TYPE_CHECKING, Any

from ..bilingual import detail
from ..dialects.alarms import MAX_VALUE, NAME_SUBSCRIPT, NO_VARIABLE_NAME, OVERFLOW, VARIABLE_NUMBER, WRITE_PROTECTED
from ..dialects.tables import SKIP_POSITIONS, SystemVariable
from ..planner.numbers import round_half_away
from .alarms import MacroAlarm, macro_alarm_number
from .unknown_values import KEPT_GROUPS, UNKNOWN, is_input_row, kept_extended, position_unknown, touch_unknown

if TYPE_CHECKING:
    from ..dialects import Dialect
    from ..library.machine_file import MachineSettings
    from ..planner.planner import Planner
    from .expressions import VariableKinds

Value = float | None


def named_number(dialect: Dialect, name: str, subscript: Value, has_subscript: bool) -> int:
    """The number ``[#_NAME]`` or ``[#_NAME[subscript]]`` stands for on ``dialect``
    (docs/semantics.md §2): ``[#_NAME]`` is the name's first number, ``[#_NAME[n]]`` the n-th
    from it. A name the dialect does not have is alarm 1098; a subscript that is missing where
    the name covers several numbers, given where it covers one, vacant, or outside 1 to their
    count is alarm 1099. The subscript is rounded as a variable number is."""
    row = dialect.variable_name(name)
    if row is None:
        raise MacroAlarm(
            NO_VARIABLE_NAME,
            detail(f"#_{name}: {dialect.title} has no variable of that name",
                   f"#_{name}：{dialect.title} 没有这个变量名"),
        )  # fmt: skip
    if not row.indexed:
        if has_subscript:
            raise MacroAlarm(
                NAME_SUBSCRIPT,
                detail(f"#_{name} is the single variable #{row.first}: it takes no subscript [n]",
                       f"#_{name} 即单个变量 #{row.first}，不能带下标 [n]"),
            )  # fmt: skip
        return row.first
    if not has_subscript:
        raise MacroAlarm(
            NAME_SUBSCRIPT,
            detail(f"#_{name} needs a subscript: #_{name}[n] with n from 1 to {row.count}",
                   f"#_{name} 需要下标：#_{name}[n]，n 为 1～{row.count}"),
        )  # fmt: skip
    if subscript is None:
        raise MacroAlarm(
            NAME_SUBSCRIPT,
            detail(f"#_{name}[]: the subscript is vacant; it must be 1 to {row.count}",
                   f"#_{name}[]：下标为空，必须为 1～{row.count}"),
        )  # fmt: skip
    if not -MAX_VALUE <= subscript <= MAX_VALUE:
        raise MacroAlarm(
            NAME_SUBSCRIPT,
            detail(f"#_{name}[{subscript:g}]: the subscript must be 1 to {row.count}",
                   f"#_{name}[{subscript:g}]：下标必须为 1～{row.count}"),
        )  # fmt: skip
    n = int(round_half_away(subscript))
    if not 1 <= n <= row.count:
        raise MacroAlarm(
            NAME_SUBSCRIPT,
            detail(f"#_{name}[{n}]: the subscript must be 1 to {row.count}",
                   f"#_{name}[{n}]：下标必须为 1～{row.count}"),
        )  # fmt: skip
    return row.first + n - 1


def out_of_range(n: int, value: float) -> MacroAlarm:
    """Alarm 111 for ``#n = value`` with a value beyond ``MAX_VALUE`` (every write raises it)."""
    return MacroAlarm(OVERFLOW, detail(f"#{n} = {value}: the value is out of range", f"#{n} = {value}：数值超出范围"))


class StopRequest(Exception):
    """Raised by ``#3006=n(text)``: the run pauses with ``message`` after this block."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


class VariableAccess:
    """The variable part of the machine (a mixin of ``Machine``)."""

    dialect: Dialect
    kinds: VariableKinds
    L: list[Value]
    C: list[Value]
    S: dict[int, Value]
    planner: Planner
    settings: MachineSettings
    kept_unknown: bool
    start_date: int
    start_time: int
    written_system: set[int]
    frames: list[Any]

    def _row(self, n: int) -> SystemVariable:
        row = self.dialect.system_variable(n)
        if row is None:
            raise MacroAlarm(
                VARIABLE_NUMBER,
                self.dialect.missing_variable(n),
            )
        return row

    # ---------------------------------------------------------------- any variable
    def variable_number(self, index: Value) -> int:
        """The number ``#[index]`` names: rounded half away from zero (vacant is #0)."""
        if index is None:
            return 0
        if abs(index) > MAX_VALUE:  # an unknown (NaN) index: round_half_away says so
            raise MacroAlarm(VARIABLE_NUMBER, detail("variable number out of range", "变量号超出范围"))
        return int(round_half_away(index))

    def read(self, index: Value) -> Value:
        """The value of ``#[index]``."""
        n = self.variable_number(index)
        kind = self.kinds.kind(n)
        if kind == "local":
            return self.L[n]
        if kind in ("common", "persistent"):
            return self.C[n]
        if kind == "vacant":
            return None
        if kind == "indirect9":
            return self.read(self.C[n - 9000])
        if kind == "system":
            return self.read_system(n)
        if kind == "extended":
            return self.S.get(n, UNKNOWN if self.kept_unknown and kept_extended(self.kinds, n) else None)
        raise MacroAlarm(
            VARIABLE_NUMBER,
            self.dialect.missing_variable(n),
        )

    def write(self, index: Value, value: Value, message: str | None = None) -> None:
        """``#[index] = value``, with every check the control makes."""
        n = self.variable_number(index)
        if value is not None and not -MAX_VALUE <= value <= MAX_VALUE and value == value:  # NaN: unknown, kept
            raise out_of_range(n, value)
        kind = self.kinds.kind(n)
        if kind == "local":
            self.L[n] = value
        elif kind in ("common", "persistent"):
            self.C[n] = value
        elif kind == "vacant":
            raise MacroAlarm(
                WRITE_PROTECTED,
                detail("#0 is always vacant and cannot be written", "#0 总是空变量，不能写入"),
            )
        elif kind == "indirect9":
            self.write(self.C[n - 9000], value, message)
        elif kind == "system":
            self.write_system(n, value, message)
        elif kind == "extended":
            self.S[n] = value
        else:
            raise MacroAlarm(
                VARIABLE_NUMBER,
                self.dialect.missing_variable(n),
            )

    # ---------------------------------------------------------------- system variables
    def read_system(self, n: int) -> Value:
        row = self._row(n)
        if row.access == "w":
            raise MacroAlarm(VARIABLE_NUMBER, detail(f"#{n} can only be written, not read", f"#{n} 只能写不能读"))
        source = row.source
        k = n - row.first
        if source == "store":
            machine_has = row.group in KEPT_GROUPS or is_input_row(row.group, row.access)
            return self.S.get(n, UNKNOWN if self.kept_unknown and machine_has else row.default)
        if source == "bits":
            return self.signal_word(row.param)
        if source == "alias":
            target = int(row.param) + k
            target_row = self.dialect.system_variable(target)
            if target_row is not None and self.kept_unknown and target_row.group in KEPT_GROUPS:
                return self.S.get(target, UNKNOWN)
            return self.S.get(target, target_row.default if target_row else 0.0)
        if source in ("modal", "code", "position"):  # the planner's state (planner/planner.py)
            if source == "code" and row.param == "T" and self.kept_unknown and self.planner.codes.get("T") is None:
                return UNKNOWN  # the tool loaded before the program commands one: the machine knows it
            skip = source == "position" and row.param in SKIP_POSITIONS
            if skip and touch_unknown(self.kept_unknown, self.settings.skip):
                return UNKNOWN  # where a G31 touched: the machine finds it, a [skip] table says it here
            if source == "position" and position_unknown(self.kept_unknown, self.planner, row.param, k):
                return UNKNOWN  # a position with an offset the folder does not give (planner/whereabouts.py)
            return self.planner.read(source, row.param, row.default, k)
        if source == "timer":
            return self.timer_value(n, row.param)
        if source == "constant":
            return row.default
        if source == "main":
            number = self.frames[0].found.unit.number if self.frames else None
            return float(number) if number is not None else None
        if source == "date":
            return self.S.get(n, float(self.date_time()[0]))
        if source == "time":
            return self.S.get(n, float(self.date_time()[1]))
        return self.S.get(n, row.default)

    def write_system(self, n: int, value: Value, message: str | None = None) -> None:
        row = self._row(n)
        if row.access == "r":
            raise MacroAlarm(WRITE_PROTECTED, detail(f"#{n} is read-only", f"#{n} 是只读变量，不能写入"))
        source = row.source
        if source == "alarm":
            k = int(round_half_away(value or 0.0))
            raise MacroAlarm(
                macro_alarm_number(k, self.dialect, f"#{n}={k}"),
                message or detail(f"macro alarm #{n}={k}", f"宏程序报警 #{n}={k}"),
            )
        if source == "stop":
            raise StopRequest(message or f"#{n}={round_half_away(value or 0.0):g}")
        self.written_system.add(n)
        if source == "bits":
            self.set_signal_word(row.param, value)
        elif source == "alias":
            self.S[int(row.param) + (n - row.first)] = value
        elif source == "timer":
            self.set_timer(n, row.param, value or 0.0)
        else:
            self.S[n] = value

    # ---------------------------------------------------------------- signal words
    def signal_word(self, param: str) -> Value:
        """The single-bit signals a ``bits`` row names (``first:count``) read as one number: the
        sum of #(first + i) × 2^i (FANUC 0i: "#1032 … the sum of #[1000+i] x 2^i"); a 32-bit
        word is signed, bit 31 its sign. Unknown when a bit is."""
        first, count = _bits_param(param)
        total = 0.0
        for i in range(count):
            bit = self.read_system(first + i)
            if bit is not None and bit != bit:
                return bit
            if bit:
                total += 2.0**i
        return total - 2.0**32 if count == 32 and total >= 2.0**31 else total

    def set_signal_word(self, param: str, value: Value) -> None:
        """Write the single-bit signals a ``bits`` row names from one number: bit i of its whole
        value (two's complement for a negative one) to #(first + i)."""
        first, count = _bits_param(param)
        word = int(round_half_away(value or 0.0)) & ((1 << count) - 1)
        for i in range(count):
            self.S[first + i] = float(word >> i & 1)
            self.written_system.add(first + i)

    # ---------------------------------------------------------------- the clock
    def timer_value(self, n: int, param: str) -> float:
        """Timer ``#n``: what was written to it plus the simulated time since, in the row's unit
        (``param`` ``ms``, ``s`` or ``h``). A ``param`` with a count (``ms/2147483648``, FANUC's
        #3001, docs/semantics.md §8) counts whole units, the steps the timer has made, and returns
        to 0 at that count."""
        unit, _, wrap = param.partition("/")
        base = self.S.get(n, 0.0) or 0.0
        seconds = self.planner.clock - self.timer_marks.get(n, 0.0)
        scale = {"ms": 1000.0, "s": 1.0, "h": 1.0 / 3600.0}.get(unit, 1.0)
        if not wrap:
            return base + seconds * scale
        steps = math.floor(seconds * scale + 1e-9)  # 2 ms summed from floats may read 1.9999999999999998
        return math.fmod(base + steps, float(wrap))

    def set_timer(self, n: int, unit: str, value: float) -> None:
        self.S[n] = value
        self.timer_marks[n] = self.planner.clock

    timer_marks: dict[int, float]

    def date_time(self) -> tuple[int, int]:
        """(YYYYMMDD, HHMMSS) at the current simulated time."""
        d = self.start_date
        t = self.start_time
        start = _dt.datetime(d // 10000, max(1, d // 100 % 100), max(1, d % 100), t // 10000 % 24, t // 100 % 100 % 60,
                             t % 100 % 60)  # fmt: skip
        now = start + _dt.timedelta(seconds=self.planner.clock)
        return now.year * 10000 + now.month * 100 + now.day, now.hour * 10000 + now.minute * 100 + now.second


def _bits_param(param: str) -> tuple[int, int]:
    """A ``bits`` row's param, ``first:count``."""
    first, count = param.split(":")
    return int(first), int(count)
