"""The shape of a dialect's data: system variables, G/M codes, functions and alarms.

Every dialect module (``fanuc_data``, ``gsk980tdi_data``, ``profiles/fanuc_30i``) fills these records;
nothing here runs a program. A ``SystemVariable`` row covers one number or a range of consecutive numbers
with the same meaning, says who may read and write it, and names the ``source`` the machine
takes its value from. The sources form a small fixed vocabulary that the machine layer
understands (see ``SOURCES``); descriptions are written in English and Chinese for a
programmer to read on hover.
"""

from __future__ import annotations

from dataclasses import dataclass

# Where a system variable's value comes from. ``k`` below is ``number - first`` of the row.
SOURCES = {
    "store": "a value the machine keeps (offsets, counters, signals); preset by the machine file",
    "alarm": "#3000: writing raises a macro alarm",
    "stop": "#3006: writing stops with a message, like M00",
    "timer": "a timer that advances with simulated time (param: 'ms', 's' or 'h'; 'ms/2147483648': one that counts "
    "whole milliseconds and returns to 0 at 2147483648)",
    "date": "the date as YYYYMMDD",
    "time": "the time of day as HHMMSS",
    "modal": "the modal G code of a group (param: the group's name in MODAL_GROUPS)",
    "code": "the last F, S, T, M, D, H, B, N, O or P value (param: the letter)",
    "position": "an axis position (param: 'end', 'machine', 'current', 'skip', 'skip_programmed', 'tool', 'servo', "
    "'handle'); axis k+1",
    "alias": "another number for a stored variable (param: the number that k = 0 maps to)",
    "constant": "a fixed value that nothing changes: the row's default (vacant for #3100, π, e)",
    "main": "the number of the main program (the O number the run started in)",
    "bits": "the single-bit signals #first… read and written at once as one number, bit i the signal"
    " #(first + i) (param: 'first:count'; a 32-bit word is signed, bit 31 its sign)",
}

# The ``position`` kinds that read where the last G31 stopped: with the tool offset in force there
# (FANUC's table: "included", as the current position #5041…) or as programmed (Haas's, as its #5041).
SKIP_POSITIONS = frozenset({"skip", "skip_programmed"})

# The modal groups a ``modal`` row may name, with the code each holds at power-on.
MODAL_GROUPS = {
    "motion": 0.0,  # G00 G01 G02 G03 ...
    "plane": 17.0,  # G17 G18 G19 (a lathe starts in G18, set by the dialect's switches)
    "distance": 90.0,  # G90 G91
    "stroke": 22.0,  # G22 G23
    "feed": 94.0,  # G94 G95 (lathe: G98 G99)
    "units": 21.0,  # G20 G21
    "cutter": 40.0,  # G40 G41 G42
    "length": 49.0,  # G43 G44 G49
    "canned": 80.0,  # G73 .. G89
    "return": 98.0,  # G98 G99 (mill)
    "scaling": 50.0,  # G50 G51
    "macro": 67.0,  # G66 G67
    "spindle": 97.0,  # G96 G97
    "wcs": 54.0,  # G54 .. G59
    "cutting": 64.0,  # G61 .. G64
    "rotation": 69.0,  # G68 G69
    "mirror": 50.1,  # G50.1 G51.1
    "polar": 15.0,  # G15 G16
}

# How a hover names each modal group of a G code's row (``CodeDoc.group``), in English (the name
# itself) and Chinese.
MODAL_GROUP_NAMES: dict[str, tuple[str, str]] = {
    "motion": ("motion", "运动（插补）"),
    "plane": ("plane", "平面选择"),
    "distance": ("distance", "绝对/增量"),
    "stroke": ("stroke", "存储行程检测"),
    "feed": ("feed", "进给方式"),
    "units": ("units", "英制/公制"),
    "cutter": ("cutter", "刀具半径补偿"),
    "length": ("length", "刀具长度补偿"),
    "canned": ("canned", "固定循环"),
    "return": ("return", "固定循环返回平面"),
    "scaling": ("scaling", "比例缩放"),
    "macro": ("macro", "宏程序模态调用"),
    "spindle": ("spindle", "恒线速度控制"),
    "wcs": ("wcs", "工件坐标系"),
    "cutting": ("cutting", "切削方式"),
    "rotation": ("rotation", "坐标旋转"),
    "mirror": ("mirror", "可编程镜像"),
    "polar": ("polar", "极坐标指令"),
}


@dataclass(frozen=True, slots=True)
class SystemVariable:
    """One system variable, or a range of them that share a meaning.

    ``access`` is ``"r"``, ``"w"`` or ``"rw"``. ``en`` and ``zh`` describe the variable; in a
    range they may use ``{axis}`` (X, Y, Z, 4th, 5th from ``k``), ``{index}`` (``k + 1``,
    e.g. the offset number) and ``{diameter}`` (a lathe's "on the diameter", on the X axis
    only). ``unit`` is shown on hover (``mm``, ``s``, ``ms``, ``h``, or empty; a rotary axis's
    ``mm`` is read as degrees: ``describe``). ``group`` sorts variables into the debugger's
    scopes: ``signals``, ``tool``, ``work``, ``alarm``, ``time``, ``control``, ``counters``, ``modal``, ``position``.
    ``default`` is the value before anything sets it (None for vacant).
    """

    first: int
    last: int
    access: str
    group: str
    en: str
    zh: str
    unit: str = ""
    source: str = "store"
    param: str = ""
    default: float | None = 0.0

    def __contains__(self, number: int) -> bool:
        return self.first <= number <= self.last


# the imaginary tool nose directions 0-9 (docs/semantics.md §12, "Tool nose radius compensation"):
# for each number, where the imaginary tool nose lies from the nose radius centre, as the signs of
# its (X, Z) components (X radial), each times the radius; 0 and 9 put the programmed point on the centre
IMAGINARY_TIPS: tuple[tuple[int, int], ...] = (
    (0, 0), (1, 1), (1, -1), (-1, -1), (-1, 1), (0, 1), (1, 0), (0, -1), (-1, 0), (0, 0),
)  # fmt: skip


@dataclass(frozen=True, slots=True)
class LatheOffsets:
    """Where a lathe keeps tool offset n (#base + n): ``axes`` holds (axis letter, geometry base,
    wear base) for each axis the offset shifts, ``radius`` the (geometry, wear) bases of the tool
    nose radius and ``tip`` the base of the imaginary tool nose direction. A T code's offset number
    selects them (planner/tool_offsets.py); ``G10 P`` writes them (planner/one_shot.py), and ``G10 P0``
    the workpiece shift where ``p0_work_shift`` says so. ``tips``
    gives each imaginary tool nose direction's place from the nose centre (``IMAGINARY_TIPS``)."""

    axes: tuple[tuple[str, int, int], ...]
    radius: tuple[int, int]
    tip: int
    tips: tuple[tuple[int, int], ...] = IMAGINARY_TIPS
    # ``G10 P0 X(U) Z(W)`` (no L) writes the workpiece shift, which a control with G54-G59 keeps as
    # the external work offset (FANUC's lathe G10 format); False: P0 is no offset of the control
    p0_work_shift: bool = False


@dataclass(frozen=True, slots=True)
class CommonRange:
    """A range of common variables ``#first``–``#last``; ``persistent`` ones keep their values
    when the power is off (FANUC #500–#999), the others are cleared (#100–#499)."""

    first: int
    last: int
    persistent: bool

    def __contains__(self, number: int) -> bool:
        return self.first <= number <= self.last

    def text(self) -> str:
        return f"#{self.first}-#{self.last}"


@dataclass(frozen=True, slots=True)
class SystemVariableName:
    """A system variable name (FANUC 30i): ``[#_NAME]`` is ``#first``. A name that covers
    several numbers takes a subscript: ``[#_NAME[n]]`` is ``#(first + n - 1)`` for n from 1 to
    ``last - first + 1``. ``name`` is written without ``#_`` (``ABSIO``); ``en`` and ``zh`` say
    in a few words what the name stands for."""

    name: str
    first: int
    last: int
    en: str
    zh: str

    @property
    def indexed(self) -> bool:
        """True when the name needs a subscript ``[n]``."""
        return self.last > self.first

    @property
    def count(self) -> int:
        return self.last - self.first + 1


@dataclass(frozen=True, slots=True)
class CodeDoc:
    """A G or M code: ``code`` as written (``G01``, ``M98``), its modal group (empty for a
    one-shot code) and what it does."""

    code: str
    group: str
    en: str
    zh: str


# What a word of the functions table is (``FunctionDoc.kind``): the editor colours and completes
# it by this (``lsp/semantic_tokens.py``, ``lsp/completion.py``).
FUNCTION = "function"  # written with its arguments in brackets (SIN[a]) or alone (POPEN)
OPERATOR = "operator"  # written between two operands (a AND b, [a EQ b])
STATEMENT = "statement"  # a word of a macro statement (IF, GOTO, THEN, WHILE, DO, END; G65 Hm)
FUNCTION_KINDS = (FUNCTION, OPERATOR, STATEMENT)


@dataclass(frozen=True, slots=True)
class FunctionDoc:
    """A function, operator or statement word: its ``kind`` (one of ``FUNCTION_KINDS``), its
    ``signature`` as a programmer writes it and what it does."""

    name: str
    kind: str
    signature: str
    en: str
    zh: str
    # the alarm the text names where it writes ``{alarm}``, filled as the profile shows it
    # (``Dialect.functions``: "alarm 119", or "alarm" where the profile documents no number)
    alarm: int | None = None


@dataclass(frozen=True, slots=True)
class AlarmDoc:
    """An alarm number and its text."""

    number: int
    en: str
    zh: str


@dataclass(frozen=True, slots=True)
class ProgramDoc:
    """A program the control keeps in its own memory (a probing macro, say) as its maker documents
    it: ``number`` (9811 for O9811), a short ``title`` and a paragraph ``en``/``zh`` on what it
    does; ``arguments`` are the G65 letters it reads, each ``(letter, en, zh)``; ``results`` the
    variables it writes for the caller, each ``(number, en, zh)``."""

    number: int
    title: str
    title_zh: str
    en: str
    zh: str
    arguments: tuple[tuple[str, str, str], ...] = ()
    results: tuple[tuple[int, str, str], ...] = ()
