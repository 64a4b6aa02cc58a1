"""Expressions compiled once into Python closures (docs/semantics.md §2 and §3).

A block's syntax tree is turned into nested closures the first time the block runs; after
that, executing it never looks at the tree again. Each closure takes the machine and returns
a float, or None for vacant. The common shapes (a local variable, a constant, a local and a
constant joined by ``+ - * /``) get closures of their own, because they are most of what
loops execute. Errors that the text alone decides (a relation outside a condition, ``==`` on
fanuc, brackets nested too deep) compile to a closure that raises the alarm when the block
runs, since a program may well never reach the block. ``call_problem`` judges a function call
(its arguments, and whether the dialect has the function) for the interpreter and the checks alike.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, Literal, overload

from ..bilingual import detail
from ..dialects import BY_NAME
from ..dialects.alarms import (
    ARGUMENT_RANGE,
    BRACKET_NESTING,
    DIVISION_BY_ZERO,
    FORMAT,
    MAX_VALUE,
    OVERFLOW,
    VARIABLE_NUMBER,
)
from ..planner.alarms import UnknownValue
from ..planner.numbers import bcd, bin_, fix, fup, increment_places, round_half_away, to_increment
from ..syntax.nodes import (
    CONDITION_JOINS,
    LOGICAL_SYMBOLS,
    Binary,
    Bracket,
    Expr,
    FunctionCall,
    IndirectVar,
    NamedVar,
    Number,
    Relation,
    Unary,
    Var,
)
from .alarms import MacroAlarm, raiser
from .unknown_values import UNKNOWN, kept_extended
from .variables import named_number
from .words import logical_symbol_refused

if TYPE_CHECKING:
    from ..dialects import Dialect
    from ..dialects.tables import CommonRange
    from .machine import Machine

Value = float | None
Getter = Callable[["Machine"], Value]
Test = Callable[["Machine"], bool]

MAX_BRACKETS = 5
# A chain of more binary operators than this (``1+1+1+...``) is compiled as a loop over its
# operands instead of one closure per operator, so that neither compiling nor running it nests
# Python calls as deep as the chain is long. Shorter chains keep the nested closures, which
# run faster; both evaluate left to right, except that a short chain's division evaluates its
# divisor first.
LONG_CHAIN = 16


def bracket_depth(node: Expr) -> int:
    """The deepest nesting of ``[ ]`` in ``node``: every pair counts once, whether it is a plain
    bracket, a function's, an IF/WHILE condition's or the one of an indirection ``#[..]`` (whose
    index is a ``Bracket`` node: the ``#`` adds no level of its own). The leaves, most of the
    nodes, are passed over first."""
    best = 0
    stack: list[tuple[Expr, int]] = [(node, 0)]
    pop = stack.pop
    push = stack.append
    while stack:
        n, d = pop()
        c = n.__class__
        if c is Number or c is Var:
            continue
        if isinstance(n, (Binary, Relation)):
            push((n.left, d))
            push((n.right, d))
        elif isinstance(n, Bracket):
            d += 1
            if d > best:
                best = d
            push((n.inner, d))
        elif isinstance(n, FunctionCall):
            d += 1
            if d > best:
                best = d
            for a in n.args:
                push((a, d))
        elif isinstance(n, Unary):
            push((n.operand, d))
        elif isinstance(n, IndirectVar):
            push((n.index, d))
        elif isinstance(n, NamedVar) and n.index is not None:
            push((n.index, d))  # the subscript's brackets count once
    return best


def _too_deep(node: Expr) -> Callable[..., Any] | None:
    """A runner that raises alarm 118 when brackets nest deeper than ``MAX_BRACKETS`` in
    ``node`` (the same for a value and a condition), else None."""
    depth = bracket_depth(node)
    if depth <= MAX_BRACKETS:
        return None
    return raiser(
        BRACKET_NESTING,
        detail(
            f"brackets nested {depth} deep (at most {MAX_BRACKETS})", f"括号嵌套 {depth} 层（最多 {MAX_BRACKETS} 层）"
        ),
    )


class VariableKinds:
    """Sorts variable numbers into local, common, system or nonexistent, for one profile as a
    machine has it (its common ranges come from the profile or the machine file)."""

    def __init__(self, dialect: Dialect) -> None:
        self.dialect = dialect
        self.ranges = dialect.common_ranges

    @property
    def volatile(self) -> tuple[CommonRange, ...]:
        """The common ranges cleared at power-off (the debugger's "Common" scope)."""
        return tuple(r for r in self.ranges if not r.persistent)

    @property
    def persistent(self) -> tuple[CommonRange, ...]:
        """The common ranges kept at power-off (#500–#999 and the like)."""
        return tuple(r for r in self.ranges if r.persistent)

    def kind(self, n: int) -> str:
        """``vacant`` (#0), ``local``, ``common``, ``persistent`` (both below #1000, kept in
        ``Machine.C``), ``extended`` (a common variable from #1000 up, such as the 30i's
        #98000–#98499, kept with the stored system values), ``indirect9`` (gsk #9xxx),
        ``system`` or ``none``."""
        if n == 0:
            return "vacant"
        if 1 <= n <= 33:
            return "local"
        for r in self.ranges:
            if r.first <= n <= r.last:
                if n >= 1000:
                    return "extended"
                return "persistent" if r.persistent else "common"
        if self.dialect.nine_indirection and 9000 <= n <= 9999 and self.kind(n - 9000) in ("common", "persistent"):
            return "indirect9"
        if n >= 1000 and self.dialect.system_variable(n) is not None:
            return "system"
        return "none"

    def persistent_numbers(self) -> list[int]:
        return [n for r in self.persistent for n in range(r.first, r.last + 1)]


class ExpressionCompiler:
    """Compiles expression and condition nodes into closures for one dialect and machine."""

    def __init__(self, kinds: VariableKinds, in_address: bool = False, watch: bool = False,
                 unknowns: bool = False) -> None:  # fmt: skip
        self.kinds = kinds
        self.dialect = kinds.dialect
        self.in_address = in_address
        self.letter = "X"  # the address being compiled (``value``), for ROUND in an address
        # For the analysis only: local reads that find a vacant local call
        # ``Machine.vacant_local(n, line)``; ``line`` is set by the block compiler.
        self.watch = watch
        self.line = -1
        # For the analysis only: values may be unknown (NaN, unknown_values.py); a function
        # gives unknown for unknown, a condition on one stops the path (``UnknownValue``)
        self.unknowns = unknowns
        # the first alarm the text alone decides (compiled to a closure raising it): a
        # debugger's condition is refused when it is set rather than when it is first tested
        self.refusal: MacroAlarm | None = None

    def _refuse(self, number: int, message: str) -> Callable[..., Any]:
        """What a text compiles to when it alone decides that it alarms (it may never be
        reached): a closure raising the alarm, the first such alarm kept in ``refusal``."""
        if self.refusal is None:
            self.refusal = MacroAlarm(number, message)
        return raiser(number, message)

    # ---------------------------------------------------------------- values
    def value(self, node: Expr, letter: str = "X") -> Getter:
        """A closure computing ``node``; brackets nested too deep raise alarm 118. ``letter``
        is the address the value is for (an ``in_address`` compiler's ROUND rounds to its
        least increment)."""
        too_deep = _too_deep(node)
        if too_deep is not None:
            return too_deep
        self.letter = letter
        return self._value(node)

    def constant(self, node: Expr) -> tuple[bool, Value]:
        """(True, value) when ``node`` is a literal number (possibly negated)."""
        while isinstance(node, Bracket):  # a loop, not recursion: brackets may nest 1,000 deep
            node = node.inner
        if isinstance(node, Number):
            return True, node.value
        if isinstance(node, Unary) and isinstance(node.operand, Number):
            return True, -node.operand.value if node.op == "-" else node.operand.value
        return False, None

    def _value(self, node: Expr) -> Getter:
        if isinstance(node, Number):
            c = node.value
            return lambda m: c
        if isinstance(node, Var):
            return self.reader(node.number)
        if isinstance(node, IndirectVar):
            index = self._value(node.index)

            def indirect(m: Machine) -> Value:
                return m.read(index(m))

            return indirect
        if isinstance(node, NamedVar):
            return self.named(node, write=False)
        if isinstance(node, Bracket):
            while isinstance(node, Bracket):  # nested brackets need no closure each
                node = node.inner
            return self._value(node)
        if isinstance(node, Unary):
            if isinstance(node.operand, Unary):
                return self._signs(node)
            inner = self._value(node.operand)
            if node.op == "-":
                return lambda m: -(inner(m) or 0.0)
            return lambda m: inner(m) or 0.0
        if isinstance(node, Binary):
            if isinstance(node.left, Binary) and _spine_length(node) > LONG_CHAIN:
                return self._chain(node)
            return self._binary(node)
        if isinstance(node, FunctionCall):
            return self._call(node)
        if isinstance(node, Relation):
            return self._refuse(
                FORMAT,
                detail(
                    "a relation (EQ, LT, ...) is only allowed in an IF or WHILE condition",
                    "关系运算（EQ、LT 等）只能用在 IF 或 WHILE 的条件中",
                ),
            )
        return self._refuse(FORMAT, detail("illegal expression", "非法的表达式"))

    def reader(self, n: int) -> Getter:
        """A closure reading ``#n`` (a literal number)."""
        kind = self.kinds.kind(n)
        if kind == "local":
            if self.watch:
                return self._watched_local(n, self.line)
            return lambda m: m.L[n]
        if kind in ("common", "persistent"):
            return lambda m: m.C[n]
        if kind == "vacant":
            return lambda m: None
        if kind == "indirect9":
            k = n - 9000
            return lambda m: m.read(m.C[k])
        if kind == "system":
            return lambda m: m.read_system(n)
        if kind == "extended":
            if self.unknowns and kept_extended(self.kinds, n):
                return lambda m: m.S.get(n, UNKNOWN)
            return lambda m: m.S.get(n)
        return self._refuse(
            VARIABLE_NUMBER,
            self.dialect.missing_variable(n),
        )

    @overload
    def named(self, node: NamedVar, write: Literal[False]) -> Getter: ...
    @overload
    def named(self, node: NamedVar, write: Literal[True]) -> Callable[[Machine], int]: ...

    def named(self, node: NamedVar, write: bool) -> Getter | Callable[[Machine], int]:
        """For a read (``write`` False): a closure giving the value of ``[#_NAME[n]]``. For a
        write: a closure giving the variable number it stands for. A dialect without names
        compiles it to alarm 114; the number itself is decided by ``named_number``."""
        dialect = self.dialect
        if not dialect.variable_names:
            return self._refuse(
                FORMAT,
                detail(
                    f"{node.text}: system variable names are not a feature of {dialect.title}; write the number",
                    f"{node.text}：{dialect.title} 不支持系统变量名，请写变量号",
                ),
            )
        name = node.name
        if node.index is None:
            try:
                number = named_number(dialect, name, None, False)
            except MacroAlarm as alarm:
                return self._refuse(alarm.number, alarm.message)
            return (lambda m: number) if write else self.reader(number)
        index = self._value(node.index)
        if write:
            return lambda m: named_number(dialect, name, index(m), True)
        return lambda m: m.read(named_number(dialect, name, index(m), True))

    @staticmethod
    def _watched_local(n: int, line: int) -> Getter:
        def watched(m: Machine) -> Value:
            v = m.L[n]
            if v is None:
                m.vacant_local(n, line)
            return v

        return watched

    def _signs(self, node: Unary) -> Getter:
        """A run of signs (``--#1``, a thousand of them in a generated line): one closure that
        applies them in a loop, innermost first, each exactly as a single sign does."""
        negate: list[bool] = []
        x: Expr = node
        while isinstance(x, Unary):
            negate.append(x.op == "-")
            x = x.operand
        inner = self._value(x)
        order = tuple(reversed(negate))

        def signs(m: Machine) -> Value:
            v = inner(m)
            for neg in order:
                v = -(v or 0.0) if neg else (v or 0.0)
            return v

        return signs

    def _chain(self, node: Binary) -> Getter:
        """A long left-to-right chain of binary operators (``1+1+1+...``, ``a*b-c/d...``): the
        tree leans left, so its spine is walked in a loop and the operators applied one after
        another, each as ``_binary`` would; no closure nests deeper than one step."""
        steps: list[tuple[str, Getter]] = []
        x: Expr = node
        while isinstance(x, Binary):
            steps.append((x.op, self._value(x.right)))
            x = x.left
        first = self._value(x)
        apply: list[tuple[Callable[[Value, Value], Value], Getter]] = []
        for op, b in reversed(steps):
            if op in LOGICAL_SYMBOLS and not self.dialect.logical_symbols:
                return self._refuse(FORMAT, logical_symbol_refused(self.dialect, op))
            fn = _STEP.get(LOGICAL_SYMBOLS.get(op, op))
            if fn is None:
                return self._refuse(FORMAT, detail(f"unknown operator {op}", f"未知的运算符 {op}"))
            apply.append((fn, b))

        def chain(m: Machine) -> Value:
            v = first(m)
            for fn, b in apply:
                v = fn(v, b(m))
            return v

        return chain

    def _binary(self, node: Binary) -> Getter:
        op = node.op
        if op in LOGICAL_SYMBOLS:  # && and || are AND and OR where the control reads them
            if not self.dialect.logical_symbols:
                return self._refuse(FORMAT, logical_symbol_refused(self.dialect, op))
            op = LOGICAL_SYMBOLS[op]
        rc, rv = self.constant(node.right)
        left_local = isinstance(node.left, Var) and self.kinds.kind(node.left.number) == "local" and not self.watch
        if op in ("+", "-", "*") and left_local and rc:
            assert isinstance(node.left, Var)
            n = node.left.number
            c = rv or 0.0
            if op == "+":
                return lambda m: (m.L[n] or 0.0) + c
            if op == "-":
                return lambda m: (m.L[n] or 0.0) - c
            return lambda m: (m.L[n] or 0.0) * c
        a = self._value(node.left)
        b = self._value(node.right)
        if op == "+":
            if rc:
                c = rv or 0.0
                return lambda m: (a(m) or 0.0) + c
            return lambda m: (a(m) or 0.0) + (b(m) or 0.0)
        if op == "-":
            return lambda m: (a(m) or 0.0) - (b(m) or 0.0)
        if op == "*":
            if rc:
                c = rv or 0.0
                return lambda m: (a(m) or 0.0) * c
            return lambda m: (a(m) or 0.0) * (b(m) or 0.0)
        if op == "/":

            def divide(m: Machine) -> Value:
                d = b(m)
                if not d:
                    raise _division_by_zero(d)
                return (a(m) or 0.0) / d

            return divide
        if op == "MOD":

            def modulo(m: Machine) -> Value:
                d = b(m)
                if not d:
                    raise MacroAlarm(DIVISION_BY_ZERO, detail("MOD by zero", "MOD 的除数为零"))
                return math.fmod(a(m) or 0.0, d)

            return modulo
        if op in ("AND", "OR", "XOR"):
            bitop = _BITWISE[op]

            def bitwise(m: Machine) -> Value:
                u, v = a(m) or 0.0, b(m) or 0.0
                if u != u or v != v:  # unknown (machine/unknown_values.py)
                    return math.nan
                return float(bitop(_whole(u), _whole(v)))

            return bitwise
        return self._refuse(FORMAT, detail(f"unknown operator {op}", f"未知的运算符 {op}"))

    def _call(self, node: FunctionCall) -> Getter:
        name = node.name
        problem = call_problem(node, self.dialect)
        if problem is not None:
            return self._refuse(FORMAT, problem[1])
        args = [self._value(a) for a in node.args]
        if name in RANDOM_FUNCTIONS:
            return _random(args, self.unknowns)
        if name == "ADP":
            return _adp(args[0], node.args[0])
        if name in _EXTRA:
            return _EXTRA[name](args, node.comma)
        if name == "ATAN" and len(args) == 2:
            y, x = args

            def atan2(m: Machine) -> Value:
                a = y(m) or 0.0
                b = x(m) or 0.0
                if a == 0 and b == 0:
                    raise MacroAlarm(ARGUMENT_RANGE, detail("ATAN[0]/[0] has no angle", "ATAN[0]/[0] 无法求出角度"))
                r = math.degrees(math.atan2(a, b))
                return r + 360.0 if r < 0 else r

            return atan2
        f = _FUNCTIONS[name]
        arg = args[0]
        if name == "ROUND" and self.in_address:
            return _round_in_address(arg, self.letter, self.unknowns)
        if self.unknowns:  # an unknown argument gives an unknown result

            def call_unknown(m: Machine) -> Value:
                x = arg(m) or 0.0
                return x if x != x else f(x)

            return call_unknown

        def call(m: Machine) -> Value:
            return f(arg(m) or 0.0)

        return call

    # ---------------------------------------------------------------- conditions
    def condition(self, node: Expr) -> Test:
        """A closure deciding an IF/WHILE condition (which must hold a relation)."""
        too_deep = _too_deep(node)
        if too_deep is not None:
            return too_deep
        return self._condition(node)

    def _condition(self, node: Expr) -> Test:
        while isinstance(node, Bracket):
            node = node.inner
        if isinstance(node, Relation):
            return self._relation(node)
        if isinstance(node, Binary) and node.op in CONDITION_JOINS and _has_relation(node):
            op = node.op
            if op in LOGICAL_SYMBOLS:
                if not self.dialect.logical_symbols:
                    return self._refuse(FORMAT, logical_symbol_refused(self.dialect, op))
                op = LOGICAL_SYMBOLS[op]
            a = self._condition(node.left)
            b = self._condition(node.right)
            if op == "AND":
                return lambda m: a(m) and b(m)
            if op == "OR":
                return lambda m: a(m) or b(m)
            return lambda m: a(m) != b(m)
        return self._refuse(
            FORMAT,
            detail("a condition needs a relation such as [#1 GT 0]", "条件中需要关系运算，例如 [#1 GT 0]"),
        )

    def _relation(self, node: Relation) -> Test:
        if not node.spelling.isalpha() and not self.dialect.c_relations:
            return self._refuse(
                FORMAT,
                detail(
                    f"'{node.spelling}' is not a relation on {self.dialect.title}; write {node.op}",
                    f"'{node.spelling}' 在 {self.dialect.title} 上不是关系运算符，请写作 {node.op}",
                ),
            )
        op = node.op
        if self.watch and op in ("EQ", "NE") and _is_vacant_test(node):
            self.watch = False  # ``#24 EQ #0`` tests for a missing argument: not a use of it
            try:
                return self._relation(node)
            finally:
                self.watch = True
        rc, rv = self.constant(node.right)
        left_local = isinstance(node.left, Var) and self.kinds.kind(node.left.number) == "local" and not self.watch
        exact = op in ("EQ", "NE") and self.dialect.vacant_differs_in_eq
        if self.unknowns:
            return _decided(op, self._value(node.left), self._value(node.right), exact, _is_vacant_test(node))
        if left_local and rc and not exact:
            assert isinstance(node.left, Var)
            n = node.left.number
            c = rv or 0.0
            if op == "LT":
                return lambda m: (m.L[n] or 0.0) < c
            if op == "LE":
                return lambda m: (m.L[n] or 0.0) <= c
            if op == "GT":
                return lambda m: (m.L[n] or 0.0) > c
            if op == "GE":
                return lambda m: (m.L[n] or 0.0) >= c
        a = self._value(node.left)
        b = self._value(node.right)
        if exact:  # fanuc: vacant EQ vacant holds, 0 EQ vacant does not
            if op == "EQ":
                return lambda m: _same(a(m), b(m))
            return lambda m: not _same(a(m), b(m))
        if op == "EQ":
            return lambda m: (a(m) or 0.0) == (b(m) or 0.0)
        if op == "NE":
            return lambda m: (a(m) or 0.0) != (b(m) or 0.0)
        if op == "LT":
            return lambda m: (a(m) or 0.0) < (b(m) or 0.0)
        if op == "LE":
            return lambda m: (a(m) or 0.0) <= (b(m) or 0.0)
        if op == "GT":
            return lambda m: (a(m) or 0.0) > (b(m) or 0.0)
        return lambda m: (a(m) or 0.0) >= (b(m) or 0.0)


# The forms of each function: (number of arguments, comma between the first two). ``None`` for
# the forms every dialect has; else the key a dialect's ``extra_functions`` must hold.
_FORMS: dict[str, dict[tuple[int, bool], str | None]] = {
    **{name: {(1, False): None} for name in ("SIN", "COS", "TAN", "ASIN", "ACOS", "SQRT", "ABS", "LN", "EXP",
                                               "ROUND", "FIX", "FUP", "BIN", "BCD")},
    "ATAN": {(1, False): None, (2, False): None, (2, True): "ATAN[a,b]"},
    "POW": {(2, True): "POW"},
    "ADP": {(1, False): "ADP"},
    "PRM": {(1, False): "PRM", (2, True): "PRM", (2, False): "PRM", (3, True): "PRM"},
    "RAND": {(1, False): "RAND"},
    "SRAND": {(2, True): "SRAND"},
}  # fmt: skip
# the functions whose value no run can foresee (GSK980TDi's random numbers)
RANDOM_FUNCTIONS = frozenset(("RAND", "SRAND"))
_SHAPES = {
    (1, False): "[a]",
    (2, True): "[a,b]",
    (2, False): "[a]/[b]",
    (3, True): "[a,b]/[c]",
}


def call_problem(node: FunctionCall, dialect: Dialect) -> tuple[str, str] | None:
    """Why a call cannot run on ``dialect`` (docs/semantics.md §3), or None: (``dialect-feature``
    when the function or form is another dialect's, ``syntax`` when no dialect has it, with a
    bilingual message). Either is alarm 114 when the block runs."""
    forms = _FORMS.get(node.name, {})
    shape = (len(node.args), node.comma)
    if node.bare:  # SIN30: the argument, a number, written without brackets (§3)
        number = node.args[0]
        text = number.text if isinstance(number, Number) else "a"
        if not dialect.bare_function_argument or (1, False) not in forms:
            return "syntax", detail(
                f"{node.name}{text}: a function's argument is written in brackets, {node.name}[{text}]",
                f"{node.name}{text}：函数的参数须写在方括号中，{node.name}[{text}]",
            )
        shape = (1, False)
    written = f"{node.name}{_SHAPES.get(shape, '[...]')}"
    if shape not in forms:
        allowed = ", ".join(f"{node.name}{_SHAPES[s]}" for s in forms)
        return "syntax", detail(
            f"{written} is not a form of {node.name}; write {allowed}",
            f"{written} 不是 {node.name} 的写法，应写作 {allowed}",
        )
    key = forms[shape]
    if key is not None and key not in dialect.extra_functions:
        has = " / ".join(d.title for d in BY_NAME.values() if key in d.extra_functions)
        return "dialect-feature", detail(
            f"{written} is not a function on {dialect.title} ({has} has it)",
            f"{dialect.title} 没有 {written} 这个函数（{has} 才有）",
        )
    return None


def _pow(args: list[Getter], comma: bool) -> Getter:
    base, exponent = args

    def power(m: Machine) -> Value:
        a = base(m) or 0.0
        b = exponent(m) or 0.0
        if a != a or b != b:  # unknown (machine/unknown_values.py)
            return math.nan
        if (a < 0 and b != int(b)) or (a == 0 and b < 0):
            raise MacroAlarm(
                ARGUMENT_RANGE,
                detail(f"POW[{a:g},{b:g}] has no real value", f"POW[{a:g},{b:g}] 没有实数值"),
            )
        try:
            r = math.pow(a, b)
        except OverflowError:
            r = math.inf
        if not -MAX_VALUE <= r <= MAX_VALUE:
            raise MacroAlarm(OVERFLOW, detail(f"POW[{a:g},{b:g}] is too large", f"POW[{a:g},{b:g}] 的结果太大"))
        return r

    return power


def _round_in_address(arg: Getter, letter: str, unknowns: bool) -> Getter:
    """ROUND inside address ``letter``: rounded to the address's least increment in the unit in
    force (0.001 mm, 0.0001 inch under G20, 0.001° for an angle: Haas 96-8000, "Notes on
    Functions", docs/semantics.md §3), not to a whole number; an unknown stays unknown."""

    def round_address(m: Machine) -> Value:
        x = arg(m) or 0.0
        if unknowns and x != x:
            return x
        return to_increment(x, increment_places(letter, m.planner.modal.get("units") == 20.0))

    return round_address


def _adp(arg: Getter, node: Expr) -> Getter:
    """``ADP[#n]`` (fanuc-30i): undoes the least-increment reading of an argument written
    without a decimal point (``G65 … X10`` passes 0.010 under ``decimal_point = "increment"``,
    ADP[#24] gives 10 again), while the local still holds the value the call passed
    (``Machine.passed_in_increments``). Anything else keeps its value."""
    while isinstance(node, Bracket):
        node = node.inner
    if not isinstance(node, Var) or not 1 <= node.number <= 33:
        return lambda m: arg(m) or 0.0
    n = node.number

    def adp(m: Machine) -> Value:
        x = arg(m) or 0.0
        return x * m.passed_in_increments(n, x)

    return adp


def _prm(args: list[Getter], comma: bool) -> Getter:
    # the simulated machine has no parameters: every parameter (and bit) reads 0
    return lambda m: 0.0


def _random(args: list[Getter], unknowns: bool) -> Getter:
    """``RAND[a]`` (a random number above 0 up to a) and ``SRAND[a,b]`` (one between a and b): the
    GSK980TDi's random numbers (§3.29.1, docs/semantics.md §3). What the control draws cannot be
    foreseen, so the value is unknown in an analysis run (``unknowns``: a condition on it stops
    the path there, machine/unknown_values.py) and vacant in a run of one simulated machine, as
    that run reads the other values the folder lacks; the arguments are still worked out."""
    result = UNKNOWN if unknowns else None

    def draw(m: Machine) -> Value:
        for arg in args:
            arg(m)
        return result

    return draw


_EXTRA: dict[str, Callable[[list[Getter], bool], Getter]] = {"POW": _pow, "PRM": _prm}


_RELATIONS: dict[str, Callable[[float, float], bool]] = {
    "EQ": operator.eq, "NE": operator.ne, "LT": operator.lt, "LE": operator.le, "GT": operator.gt, "GE": operator.ge,
}  # fmt: skip


def _decided(op: str, a: Getter, b: Getter, exact: bool, vacant_test: bool) -> Test:
    """Relation ``op`` of ``a`` and ``b`` where values may be unknown (an analysis run): as
    ``_relation`` decides it, but a side that is unknown stops the path (``UnknownValue``). An
    unknown is a value, not vacant: where the profile tells vacant from 0 (``exact``),
    ``[x EQ #0]`` (``vacant_test``) is false and ``[x NE #0]`` true for an unknown ``x``."""
    relation = _RELATIONS[op]

    def decided(m: Machine) -> bool:
        x, y = a(m), b(m)
        if x != x or y != y:  # NaN; vacant (None) equals itself
            if exact and vacant_test:
                return op == "NE"
            raise UnknownValue
        if exact:
            return _same(x, y) == (op == "EQ")
        return relation(x or 0.0, y or 0.0)

    return decided


def _is_vacant_test(node: Relation) -> bool:
    """``a EQ #0`` or ``#0 NE a``: a comparison with the always-vacant ``#0``."""
    return any(isinstance(side, Var) and side.number == 0 for side in (node.left, node.right))


def _same(x: Value, y: Value) -> bool:
    if x is None or y is None:
        return x is None and y is None
    return x == y


def _has_relation(node: Expr) -> bool:
    """Whether a comparison hides in ``node`` outside functions and indirections (walked
    without recursion: a condition may join hundreds of comparisons). Not the readers'
    ``has_relation`` (``syntax/conditions.py``), which looks inside them too: here it decides whether AND/OR join
    conditions or numbers."""
    stack: list[Expr] = [node]
    while stack:
        n = stack.pop()
        if isinstance(n, Relation):
            return True
        if isinstance(n, Bracket):
            stack.append(n.inner)
        elif isinstance(n, Binary):
            stack.append(n.right)
            stack.append(n.left)
    return False


def _spine_length(node: Binary) -> int:
    """How many binary operators a left-leaning chain ``a op b op c ...`` starting at ``node``
    holds (counted up to ``LONG_CHAIN + 1``)."""
    n = 0
    x: Expr = node
    while isinstance(x, Binary) and n <= LONG_CHAIN:
        n += 1
        x = x.left
    return n


def _add(a: Value, b: Value) -> Value:
    return (a or 0.0) + (b or 0.0)


def _sub(a: Value, b: Value) -> Value:
    return (a or 0.0) - (b or 0.0)


def _mul(a: Value, b: Value) -> Value:
    return (a or 0.0) * (b or 0.0)


def _div(a: Value, d: Value) -> Value:
    if not d:
        raise _division_by_zero(d)
    return (a or 0.0) / d


def _division_by_zero(d: Value) -> MacroAlarm:
    """Alarm 112 for a divisor ``d`` that is 0 or vacant (both division paths raise it)."""
    return MacroAlarm(
        DIVISION_BY_ZERO,
        detail("division by zero (the divisor is vacant)", "除数为零（除数为空变量）")
        if d is None
        else detail("division by zero", "除数为零"),
    )


def _mod(a: Value, d: Value) -> Value:
    if not d:
        raise MacroAlarm(DIVISION_BY_ZERO, detail("MOD by zero", "MOD 的除数为零"))
    return math.fmod(a or 0.0, d)


def _bitwise(op: str) -> Callable[[Value, Value], Value]:
    bitop = _BITWISE[op]
    return lambda a, b: math.nan if a != a or b != b else float(bitop(_whole(a or 0.0), _whole(b or 0.0)))


def _whole(x: float) -> int:
    if not -MAX_VALUE <= x <= MAX_VALUE:
        raise MacroAlarm(OVERFLOW, detail("value out of range for a bitwise operation", "位运算的数值超出范围"))
    return int(round_half_away(x))


_BITWISE: dict[str, Callable[[int, int], int]] = {
    "AND": lambda x, y: x & y,
    "OR": lambda x, y: x | y,
    "XOR": lambda x, y: x ^ y,
}


# one step of a long chain of binary operators (``_chain``): the left value so far and the right one
_STEP: dict[str, Callable[[Value, Value], Value]] = {
    "+": _add,
    "-": _sub,
    "*": _mul,
    "/": _div,
    "MOD": _mod,
    **{op: _bitwise(op) for op in _BITWISE},
}


def _sqrt(x: float) -> float:
    if x < 0:
        raise MacroAlarm(ARGUMENT_RANGE, detail(f"SQRT of a negative number ({x:g})", f"SQRT 的自变量为负数（{x:g}）"))
    return math.sqrt(x)


def _asin(x: float) -> float:
    if not -1.0 <= x <= 1.0:
        raise MacroAlarm(ARGUMENT_RANGE, detail(f"ASIN[{x:g}] is outside -1..1", f"ASIN[{x:g}] 超出 -1～1 的范围"))
    return math.degrees(math.asin(x))


def _acos(x: float) -> float:
    if not -1.0 <= x <= 1.0:
        raise MacroAlarm(ARGUMENT_RANGE, detail(f"ACOS[{x:g}] is outside -1..1", f"ACOS[{x:g}] 超出 -1～1 的范围"))
    return math.degrees(math.acos(x))


def _ln(x: float) -> float:
    if x <= 0:
        raise MacroAlarm(
            ARGUMENT_RANGE,
            detail(f"LN of {x:g} (it must be above 0)", f"LN 的自变量为 {x:g}（必须大于 0）"),
        )
    return math.log(x)


def _exp(x: float) -> float:
    try:
        return math.exp(x)
    except OverflowError:
        raise MacroAlarm(OVERFLOW, detail(f"EXP[{x:g}] is too large", f"EXP[{x:g}] 的结果太大")) from None


def _tan(x: float) -> float:
    r = math.fmod(x, 180.0)
    if abs(abs(r) - 90.0) < 1e-12:
        raise MacroAlarm(ARGUMENT_RANGE, detail(f"TAN[{x:g}] is infinite", f"TAN[{x:g}] 为无穷大"))
    return math.tan(math.radians(x))


_FUNCTIONS: dict[str, Callable[[float], float]] = {
    "SIN": lambda x: math.sin(math.radians(x)),
    "COS": lambda x: math.cos(math.radians(x)),
    "TAN": _tan,
    "ASIN": _asin,
    "ACOS": _acos,
    "ATAN": lambda x: math.degrees(math.atan(x)),
    "SQRT": _sqrt,
    "ABS": abs,
    "LN": _ln,
    "EXP": _exp,
    "ROUND": round_half_away,
    "FIX": fix,
    "FUP": fup,
    "BIN": bin_,
    "BCD": bcd,
}
