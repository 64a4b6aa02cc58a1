"""The machine file's ``[skip]`` table: the part a probe touches, for G31 (docs/machine-file.md
"Probing: the [skip] table").

Two ways to say where a G31 move stops, which may be combined:

- a **sequence of contact points**, one per G31 in the order the run makes them
  (``contacts = [{ X = 24.98 }, { X = -25.02 }, "miss"]``): the n-th G31 stops at the n-th point
  (``"miss"``: the skip signal never comes on); once they are used up the model below decides;
- a **model** of the part's surfaces: planes (``Z = -12.5``, ``X = [-40, 40]``), bores and bosses
  (``bore = { X = 0, Y = 0, diameter = 50 }``, or ``[[skip.bore]]`` tables for several), which the
  straight G31 move hits by geometry (``planner/probing.py``).

This module only reads and checks the table; what a G31 does with it is the interpreter's.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal

from ..bilingual import Detail, detail
from ..dialects.registry import all_profiles
from .toml_numbers import finite_number

CircleKind = Literal["bore", "boss"]
SHAPES: tuple[CircleKind, ...] = ("bore", "boss")
# the letters any profile names an axis with: a plane or a contact point may use these
AXIS_LETTERS: tuple[str, ...] = tuple(sorted({a for p in all_profiles() for a in p.axes}))
_Fail = Callable[[str, Detail], Exception]
# each G31 looks at every surface: a part to probe has a few, and a hostile file must not make a
# run of many G31 blocks crawl (docs/robustness.md)
MAX_SURFACES = 200


@dataclass(frozen=True, slots=True)
class Plane:
    """The surface ``axis = at``: a G31 move that reaches it, from either side, stops there."""

    axis: str
    at: float


@dataclass(frozen=True, slots=True)
class Circle:
    """A bore or a boss: a circle of ``diameter`` centred at ``centre`` in the plane of its two
    axes (``(("X", 0.0), ("Y", 0.0))``), its wall running along every other axis. A bore's wall
    is hit where a move leaves the circle, a boss's where a move comes into it."""

    kind: CircleKind
    centre: tuple[tuple[str, float], tuple[str, float]]
    diameter: float


@dataclass(frozen=True, slots=True)
class Contact:
    """Where one G31 stops: the axes named take these values, the others end where the block
    commands them; ``hit`` False (written ``"miss"``) is a G31 whose skip signal never comes on."""

    point: tuple[tuple[str, float], ...] = ()
    hit: bool = True


@dataclass(frozen=True, slots=True)
class SkipModel:
    """The whole ``[skip]`` table. Empty: every G31 runs to its end point, the signal never on."""

    planes: tuple[Plane, ...] = ()
    circles: tuple[Circle, ...] = ()
    contacts: tuple[Contact, ...] = ()

    def __bool__(self) -> bool:
        return bool(self.planes or self.circles or self.contacts)


def planes_model(positions: dict[str, float]) -> SkipModel:
    """A model of one plane per axis (``{"Z": -12.5}``)."""
    return SkipModel(planes=tuple(Plane(a.upper(), float(v)) for a, v in positions.items()))


def read_skip(value: object, fail: _Fail) -> SkipModel:
    """``[skip]`` as the machine file gives it (parsed TOML); ``fail(key, what)`` makes the error
    for a key (``skip.bore``), whose line the machine file's reader finds."""
    if not isinstance(value, dict):
        raise fail("skip", detail("must be a table ([skip])", "必须是表（[skip]）"))
    planes: list[Plane] = []
    circles: list[Circle] = []
    contacts: tuple[Contact, ...] = ()
    for key, item in value.items():
        name = str(key)
        if name.upper() in AXIS_LETTERS and len(name) == 1:
            planes += [Plane(name.upper(), v) for v in _positions(item, f"skip.{name}", fail)]
        elif name == "bore" or name == "boss":
            tables = item if isinstance(item, list) else [item]
            kind: CircleKind = "bore" if name == "bore" else "boss"
            circles += [_circle(kind, t, f"skip.{name}", k, len(tables) > 1, fail) for k, t in enumerate(tables, 1)]
        elif name == "contacts":
            contacts = _contacts(item, fail)
        else:
            known = ", ".join((*AXIS_LETTERS, *SHAPES, "contacts"))
            raise fail(f"skip.{name}", detail(f"is not an axis letter or a shape of the part (known: {known})",
                                              f"不是轴地址或工件形状（可用的有：{known}）"))  # fmt: skip
    if len(planes) + len(circles) > MAX_SURFACES:
        raise fail("skip", detail(f"describes more than {MAX_SURFACES} surfaces (planes, bores and bosses)",
                                  f"描述的面（平面、孔和凸台）超过 {MAX_SURFACES} 个"))  # fmt: skip
    return SkipModel(tuple(planes), tuple(circles), contacts)


def _positions(value: object, key: str, fail: _Fail) -> list[float]:
    """A plane's position or a list of them (``-12.5``, ``[-40, 40]``)."""
    items = value if isinstance(value, list) else [value]
    out = [finite_number(v) for v in items]
    if not items or any(v is None for v in out):
        raise fail(key, detail("must be a position or a list of positions (finite numbers), e.g. -12.5 or [-40, 40]",
                               "必须是位置或位置的列表（有限的数值），如 -12.5 或 [-40, 40]"))  # fmt: skip
    return [v for v in out if v is not None]


def _circle(kind: CircleKind, table: object, key: str, k: int, several: bool, fail: _Fail) -> Circle:
    """One bore or boss: two axis letters for its centre and ``diameter``."""
    which, which_zh = (f"(table {k}) ", f"（第 {k} 个表）") if several else ("", "")
    bad = detail(f"{which}must be a table of two axes for its centre and its diameter, e.g. "
                 f"{{ X = 0, Y = 0, diameter = 50 }}",
                 f"{which_zh}必须是由圆心的两个轴坐标和直径组成的表，如 {{ X = 0, Y = 0, diameter = 50 }}")  # fmt: skip
    if not isinstance(table, dict):
        raise fail(key, bad)
    centre: list[tuple[str, float]] = []
    diameter: float | None = None
    for name, v in table.items():
        number = finite_number(v)
        if name == "diameter":
            diameter = number
            if number is None or number <= 0:
                raise fail(key, detail(f"{which}has a 'diameter' that is not a number above 0",
                                       f"{which_zh}的 'diameter' 不是大于 0 的数值"))  # fmt: skip
        elif str(name).upper() in AXIS_LETTERS and len(str(name)) == 1 and number is not None:
            centre.append((str(name).upper(), number))
        else:
            raise fail(key, bad)
    if diameter is None or len(centre) != 2 or centre[0][0] == centre[1][0]:
        raise fail(key, bad)
    return Circle(kind, (centre[0], centre[1]), diameter)


def _contacts(value: object, fail: _Fail) -> tuple[Contact, ...]:
    """``contacts``: a list of points (tables of axis = position) and ``"miss"``."""
    if not isinstance(value, list):
        raise fail("skip.contacts", detail('must be a list of contact points, e.g. [{ X = 24.98 }, "miss"]',
                                           '必须是接触点的列表，如 [{ X = 24.98 }, "miss"]'))  # fmt: skip
    out: list[Contact] = []
    for k, item in enumerate(value, 1):
        if item == "miss":
            out.append(Contact(hit=False))
            continue
        point: list[tuple[str, float]] = []
        if isinstance(item, dict) and item:
            for name, v in item.items():
                number = finite_number(v)
                if str(name).upper() not in AXIS_LETTERS or len(str(name)) != 1 or number is None:
                    point = []
                    break
                point.append((str(name).upper(), number))
        if not point:
            raise fail("skip.contacts", detail(
                f'contact {k} must be a table of axis = position ({{ X = 24.98, Y = 0 }}) or "miss"',
                f'第 {k} 个接触点必须是“轴地址 = 位置”形式的表（{{ X = 24.98, Y = 0 }}）或 "miss"'))  # fmt: skip
        out.append(Contact(tuple(point)))
    return tuple(out)
