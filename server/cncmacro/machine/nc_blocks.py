"""NC blocks compiled into closures: motion, calls, returns and ends (docs/semantics.md §5, §8).

A block of words is one of: a macro call (``G65``/``G66``, or on gsk980tdi ``G65 Hm`` arithmetic),
``G67``, or an NC block whose M codes may call (``M98``, and Haas ``M97`` where the dialect has
a local subprogram call), return (``M99``), end (``M30``, ``M02``) or pause (``M00``), and whose
G, M or T code may be configured to call a program. Which call the block makes, as far as its
literal words say, is ``recognise_call``'s (``machine/calls.py``); what it may not contain is
``validate_block``'s (``machine/block_rules.py``), whose first problem becomes the block's alarm.
M codes from variables are known only when the block runs, and are dispatched then.
Literal values are rounded once here; only variable values are computed when the block runs.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from typing import TYPE_CHECKING, Any

from ..bilingual import detail
from ..dialects.alarms import ARGUMENT_RANGE, IMPROPER_G_CODE, PROGRAM_NOT_FOUND
from ..planner.alarms import UnknownValue, is_unknown
from ..planner.numbers import INCREMENT_LETTERS, in_least_increments, increment_places
from ..syntax.nodes import Block, Bracket, Number, Var, Word
from .alarms import MacroAlarm, raiser
from .block_rules import CALL_WITHOUT_P, BlockProblem, first_alarm, validate_block
from .calls import (
    BlockCall,
    argument_targets,
    codes_before_call,
    macro_program_number,
    map_arguments,
    program_and_count,
    recognise_call,
    repeat_count,
)
from .hcodes import compile_h_code
from .program_end import END_CODES, RETURN_CODE
from .words import g_code_known, unknown_g_code

if TYPE_CHECKING:
    from ..planner.lathe_cycles import ShapeCall
    from ..planner.plain_words import PlainPlan, PlainRun
    from .blocks import CompiledFile, Runner
    from .machine import Machine

CONTROL_M = {98.0, RETURN_CODE, *END_CODES, 0.0, 198.0}  # calls, return, end, M00
DATA_SETTING = 10.0  # G10: its words are values written to the offset tables (planner/one_shot.py)
_DATA_SELECTORS = frozenset("GLP")  # a G10 block's words that say what is written, not the value


def _literal_g(w: Word) -> float | None:
    return w.value.value if w.letter == "G" and isinstance(w.value, Number) else None


# a compiled NC block waiting for its next line: the same words compile alike on any line
Compiled = Callable[[int], "Runner"]


def compile_nc_block(cf: CompiledFile, block: Block, pc: int, nxt: int) -> Runner:
    return nc_block_of(cf, block)(nxt)


def nc_block_of(cf: CompiledFile, block: Block) -> Compiled:
    """``block`` compiled, given the line it goes on to (``Compiled``): everything decided from
    its words is decided here, once, so that a line of the same literal words elsewhere in the
    file can take it (``CompiledFile.plain_words``)."""
    words = list(block.words)
    # each word's value, read once for all below
    read = _WordValues(cf, _dwell_block(cf, words), any(_literal_g(w) == DATA_SETTING for w in words))
    plan = _plain_plan(cf, words, read)
    if plan is not None:
        return partial(_plan_runner, cf, plan)
    dialect = cf.machine.dialect
    calls = cf.machine.settings.calls
    value = _known_value(read)
    call = recognise_call(words, dialect, calls, value)
    problems = validate_block(block, dialect, calls, value, call)
    if call is not None and call.kind in ("G65", "G66"):
        return _macro_call(cf, block, words, call, problems)
    if any(_literal_g(w) == 67.0 for w in words):
        rest = [w for w in words if _literal_g(w) != 67.0]
        compiled = _nc(cf, block, rest, read, problems, call) if rest else None

        def cancelling(nxt: int) -> Runner:
            inner = compiled(nxt) if compiled is not None else None

            def cancel(m: Machine, pc: int) -> int:
                m.cancel_modal_call()
                return inner(m, pc) if inner is not None else nxt

            return cancel

        return cancelling
    return _nc(cf, block, words, read, problems, call)


class _WordValues:
    """``CompiledFile.word_value`` of the words of one block being compiled, each read once
    however many of the steps below ask for it; a dwell block's P by ``dwell_p_value``. In a
    ``G10`` block (``data``) the values it writes may be unknown (machine/unknown_values.py): an
    offset written from an unknown becomes unknown, as ``#13005=#570`` makes it, and the run goes
    on; its G, L and P, which say what is written, still stop the run when unknown."""

    def __init__(self, cf: CompiledFile, dwell: bool = False, data: bool = False) -> None:
        self._cf = cf
        self._dwell = dwell
        self._data = data
        self._read: dict[int, tuple[bool, Any]] = {}

    def __call__(self, w: Word) -> tuple[bool, Any]:
        got = self._read.get(id(w))
        if got is None:
            cf = self._cf
            if self._dwell and w.letter == "P":
                got = cf.dwell_p_value(w)
            else:
                got = cf.word_value(w, data=self._data and w.letter not in _DATA_SELECTORS)
            self._read[id(w)] = got
        return got


def _dwell_block(cf: CompiledFile, words: list[Word]) -> bool:
    """Whether the block's P is a dwell whose unit its decimal point decides
    (``Timing.dwell_p_point_seconds``): the block names G04 or a drilling cycle (a code of the
    canned group but G80, or a lathe's drilling cycle). A P given in a later block of the
    cycle, without its code, is read in P's unit as written."""
    dialect = cf.machine.dialect
    if not dialect.timing.dwell_p_point_seconds or not any(w.letter == "P" for w in words):
        return False
    groups = cf.machine.planner.g_groups
    lathe_drills = dialect.lathe_drilling.cycles if dialect.lathe_drilling is not None else {}
    for w in words:
        g = _literal_g(w)
        if g is not None and (g == 4.0 or (groups.get(g) == "canned" and g != 80.0) or g in lathe_drills):
            return True
    return False


def _known_value(read: _WordValues) -> Callable[[Word], float | None]:
    """A word's value rounded for its address when it is known before the block runs (a literal
    or a constant expression), else None: what ``validate_block`` and ``recognise_call`` see."""

    def value(w: Word) -> float | None:
        is_const, v = read(w)
        return v if is_const else None

    return value


def compile_plain_line(cf: CompiledFile, text: str, nxt: int) -> Runner | None:
    """``_plain_motion`` for a line kept as text (``Block.plain``), read without building
    syntax nodes; None when the line needs the general path."""
    plan = cf.machine.planner.plain.text_plan(text)
    return None if plan is None else _plan_runner(cf, plan, nxt)


def _plain_plan(cf: CompiledFile, words: list[Word], read: _WordValues) -> PlainPlan | None:
    """The plan of the commonest block of all, literal modal G codes, F, S and axis words
    (``G01 X10.5 Y-3 F200``), or None for anything else; ``read`` holds the words' values."""
    calls = cf.machine.settings.calls
    plain: list[tuple[str, float]] = []
    for w in words:
        value = w.value
        if value.__class__ is not Number:
            return None
        letter = w.letter
        if letter == "G" and calls and f"G{value.value:g}" in calls:
            return None
        v = read(w)[1]
        if v is None:
            continue
        plain.append((letter, v))
    return cf.machine.planner.plain.plan(plain)


def _plan_runner(cf: CompiledFile, plan: PlainPlan, nxt: int) -> Runner:
    """The runner of a plain-motion line: the plan (with its file and next line appended)
    bound to one shared function, which costs far less memory than a closure per line."""
    return partial(_run_plain_line, (*plan, cf.file.path, nxt))


def _run_plain_line(plan: PlainRun, m: Machine, pc: int) -> int:
    if m.planner.run_plain(plan, pc) and m.modal_calls:
        return m.modal_call(pc, plan[6])
    return plan[6]


# ---------------------------------------------------------------- G65 / G66


def _macro_call(
    cf: CompiledFile, block: Block, words: list[Word], call: BlockCall, problems: list[BlockProblem]
) -> Compiled:
    name = call.kind
    dialect = cf.machine.dialect
    first = first_alarm(problems)
    if first is not None and first.rule != CALL_WITHOUT_P:  # raised when the call is made (below)
        return _always(raiser(first.alarm, first.message))
    before: list[tuple[str, float]] = []
    if call.at > 0:  # modal G codes the control sets before it calls (block_rules.py: else alarm 127)
        codes = codes_before_call([(w.letter, _literal_g(w)) for w in words[: call.at]], dialect) or []
        before = [("G", c) for c in codes]
    after = words[call.at + 1 :]
    if call.arithmetic:
        return partial(_h_code, cf, after, block)
    p_word = call.target
    l_word = call.count
    args = list(call.arguments)
    resolve = _program_resolver(cf, p_word, first)
    count = _getter(cf, l_word)
    arg_values = [(w.letter, _getter(cf, w)) for w in args]
    in_increments = _in_increments(cf, args)
    if in_increments:
        arg_values = [(w.letter, _argument_in_increments(w) if i in in_increments else get)
                      for i, (w, (_, get)) in enumerate(zip(args, arg_values, strict=True))]  # fmt: skip
    scaled = _locals_in_increments(args, in_increments)

    path = cf.file.path

    def evaluate(m: Machine, pc: int) -> tuple[Any, Any, int]:
        if before:
            m.planner.execute_nc(before, path, pc)
        found = resolve(m)
        arguments = map_arguments([(letter, get(m)) for letter, get in arg_values], dialect)
        if scaled:
            inch = m.planner.modal.get("units") == 20.0
            arguments.increments = {
                n: 10.0 ** increment_places(letter, inch) for n, letter in scaled.items() if n in arguments.values
            }
        notes: list[str] = []
        repeats = repeat_count(count(m), dialect, notes)
        for text in notes:
            m.note("call", text, pc, "repeat-count")
        for text in arguments.remarks:
            m.note("call", text, pc, "argument-order")
        return found, arguments, repeats

    if name == "G65":
        cancels = dialect.g65_cancels_modal_call  # GSK: a G65 call ends the G66 in force, as G67 does

        def g65_to(nxt: int) -> Runner:
            def g65(m: Machine, pc: int) -> int:
                found, arguments, repeats = evaluate(m, pc)
                if cancels and m.modal_calls:
                    m.cancel_modal_call()
                return m.macro_call(found, arguments, repeats, pc, nxt, "G65")

            return g65

        return g65_to

    def g66_to(nxt: int) -> Runner:
        def g66(m: Machine, pc: int) -> int:
            found, arguments, repeats = evaluate(m, pc)
            m.set_modal_call(found, arguments, repeats)
            return nxt

        return g66

    return g66_to


def _h_code(cf: CompiledFile, words: list[Word], block: Block, nxt: int) -> Runner:
    return compile_h_code(cf, words, nxt, block)


def _always(run: Runner) -> Compiled:
    """A runner that does not depend on the line it goes on to (an alarm)."""
    return lambda nxt: run


def _getter(cf: CompiledFile, w: Word | None) -> Any:
    """A closure giving a word's value as written (no address rounding), or None."""
    if w is None or w.value is None:
        return lambda m: None
    return cf.values.value(w.value)


def _in_increments(cf: CompiledFile, args: list[Word]) -> frozenset[int]:
    """The argument words (their indexes) that pass least input increments: literal numbers
    without a decimal point in a length or angle address, where the machine reads numbers so
    (``decimal_point = "increment"``; FANUC 16i/18i B-63684EN §16 "Position of the decimal
    point": "The units used for argument data passed without a decimal point correspond to the
    least input increment of each address"). The same rule as an NC word's (``round_for``)."""
    if cf.machine.settings.decimal_point != "increment":
        return frozenset()
    return frozenset(
        i for i, w in enumerate(args)
        if isinstance(w.value, Number) and not w.value.has_point and w.letter.upper() in INCREMENT_LETTERS
    )  # fmt: skip


def _argument_in_increments(w: Word) -> Any:
    """The getter of argument word ``w`` read in least input increments of the unit in force."""
    assert isinstance(w.value, Number)
    letter, written = w.letter.upper(), w.value.value
    return lambda m: in_least_increments(letter, written, m.planner.modal.get("units") == 20.0)


def _locals_in_increments(args: list[Word], in_increments: frozenset[int]) -> dict[int, str]:
    """The locals that end up holding an argument passed in least input increments (a later
    word on the same local wins, as in ``map_arguments``), with its letter."""
    out: dict[int, str] = {}
    for i, n in enumerate(argument_targets([w.letter for w in args])):
        if n is None:
            continue
        if i in in_increments:
            out[n] = args[i].letter.upper()
        else:
            out.pop(n, None)
    return out


def _program_resolver(cf: CompiledFile, p_word: Word | None, missing: BlockProblem | None) -> Any:
    """A closure finding the program that ``P`` names (``missing``: the alarm when there is none)."""
    dialect = cf.machine.dialect
    if p_word is None:
        assert missing is not None  # block_rules.py's CALL_WITHOUT_P
        return raiser(missing.alarm, missing.message)
    if p_word.name is not None:
        text = p_word.name
        return lambda m: m.find_program_named(text)
    value = p_word.value
    assert value is not None  # a word without a value has a name
    if isinstance(value, Bracket) and dialect.bracket_names and isinstance(value.inner, Var):
        get_bracket = cf.values.value(value.inner)
        return lambda m: m.find_program(macro_program_number(get_bracket(m), dialect))
    get = cf.values.value(value)
    return lambda m: m.find_program(macro_program_number(get(m), dialect))


# ---------------------------------------------------------------- NC blocks


def _nc(
    cf: CompiledFile,
    block: Block,
    words: list[Word],
    read: _WordValues,
    problems: list[BlockProblem],
    call: BlockCall | None,
) -> Compiled:
    """An NC block: words evaluated, NC executed, then M98 / M99 / M30 / M00 and call codes
    (``read``: the words' values)."""
    items: list[tuple[str, float | None, Any]] = []  # (letter, rounded literal, or a getter)
    dialect = cf.machine.dialect
    calls = cf.machine.settings.calls
    for w in words:
        is_const, v = read(w)
        items.append((w.letter, v, None) if is_const else (w.letter, None, v))
    refused = first_alarm(problems)  # a G code the control lacks, an M code with a point
    if refused is not None:
        return _always(raiser(refused.alarm, refused.message))
    # a configured code's other words are its arguments, not NC words
    strict = dialect.word_format_alarms and not (call is not None and call.configured)
    all_constant = all(get is None for _, _, get in items)
    constant = [(letter, v) for letter, v, get in items if get is None]
    # the program words (P, L, Q) of a call are not NC words
    # Haas's M97 local call and M96 input jump (``_input_jump``), where the dialect has them
    local, input_jump = dialect.local_subprogram_code, dialect.input_jump_code
    control_m = CONTROL_M | {code for code in (local, input_jump) if code is not None}
    local_kind = f"M{local:g}" if local is not None else ""
    m_values = [v for letter, v in constant if letter == "M"]
    dynamic_m = any(letter == "M" and get is not None for letter, _, get in items)
    control = [v for v in m_values if v in control_m]
    calls = cf.machine.settings.calls
    call_codes = bool(calls)
    file_path = cf.file.path

    if all_constant and not control and not dynamic_m and not call_codes:
        plain = [(letter, v) for letter, v in constant if v is not None]
        return partial(_motion_runner, plain, file_path)

    p_text = None
    for w in words:
        if w.letter == "P" and isinstance(w.value, Number):
            p_text = w.value.text
    p_name = next((w.name for w in words if w.letter == "P" and w.name is not None), None)
    p_bracket_var = next(
        (
            w.value.inner
            for w in words
            if w.letter == "P" and isinstance(w.value, Bracket) and isinstance(w.value.inner, Var)
        ),
        None,
    )
    # P[#100] names a program on a dialect with bracketed names; elsewhere it is P#100
    get_bracket = cf.values.value(p_bracket_var) if p_bracket_var is not None and dialect.bracket_names else None
    check_g = strict and any(letter == "G" and get is not None for letter, _, get in items)

    def general_to(nxt: int) -> Runner:
        return partial(general, nxt)

    def general(nxt: int, m: Machine, pc: int) -> int:
        values: list[tuple[str, float]] = []
        for letter, const, get in items:
            v = get(m) if get is not None else const
            if v is not None:
                values.append((letter, v))
        if check_g:  # a G code from a variable: known only now
            for letter, v in values:
                if letter == "G" and not g_code_known(v, dialect, calls):
                    raise MacroAlarm(IMPROPER_G_CODE, unknown_g_code(f"{v:g}", dialect))
        ms = [v for letter, v in values if letter == "M"]
        mcontrol = [v for v in ms if v in control_m]
        found_call = m.call_code_for(values) if call_codes else None
        if found_call is not None and found_call[1].call == "macro":
            return m.code_macro_call(*found_call, values, pc, nxt)
        nc_words = values
        if mcontrol and (98.0 in mcontrol or RETURN_CODE in mcontrol or 198.0 in mcontrol or local in mcontrol
                         or input_jump in mcontrol):  # fmt: skip
            nc_words = [(letter, v) for letter, v in values if letter not in ("P", "L", "Q")]
        moved, skip_to = m.planner.execute_nc(nc_words, file_path, pc)
        if found_call is not None:
            return m.code_subprogram_call(*found_call, values, pc, nxt)
        if 98.0 in mcontrol or 198.0 in mcontrol:
            found, repeats, q = _subprogram_target(m, values, p_text, p_name, get_bracket, dialect, pc)
            return m.subprogram_call(found, repeats, q, pc, nxt, "M98")
        if local in mcontrol:
            words = dict(values)
            notes: list[str] = []
            repeats = repeat_count(words.get("L"), dialect, notes)
            for text in notes:
                m.note("call", text, pc, "repeat-count")
            return m.local_subprogram_call(words.get("P"), repeats, pc, nxt, local_kind)
        if input_jump in mcontrol:
            return _input_jump(cf, m, dict(values), pc, nxt)
        if RETURN_CODE in mcontrol:
            p = next((v for letter, v in values if letter == "P"), None)
            return m.return_from_call(pc, p)
        if not END_CODES.isdisjoint(mcontrol):
            return m.end_program(pc, next(v for v in mcontrol if v in END_CODES))
        if 0.0 in mcontrol:
            return m.pause(detail("M00 program stop", "M00 程序停止"), pc, nxt)
        return _after_nc(m, moved, skip_to, pc, nxt)

    return general_to


def _input_jump(cf: CompiledFile, m: Machine, words: dict[str, float], pc: int, nxt: int) -> int:
    """Haas's ``M96 P n Q i`` (``Dialect.input_jump_code``): on to N n of the program, by the jump
    rules of GOTO, when discrete input i (#1000 + i) is 0, else the next block (docs/semantics.md
    §4). An input whose value the analysis does not know leaves the branch undecided, as
    ``IF [#1027 EQ 0] GOTO n`` (machine/unknown_values.py)."""
    q = words.get("Q")
    if q is None or not 0 <= q <= 63:
        raise MacroAlarm(
            ARGUMENT_RANGE,
            detail("M96 needs Q, the discrete input to test (0 to 63)", "M96 需要 Q，即要检测的离散输入（0～63）"),
        )
    value = m.read(1000 + q)
    if is_unknown(value):
        raise UnknownValue
    if value:  # the input is on: no jump
        return nxt
    return cf.jump(m.frames[-1], pc, words.get("P"), "M96 P")


def _motion_runner(plain: list[tuple[str, float]], file_path: str, nxt: int) -> Runner:
    """The runner of an NC block of literal words only, none of which calls or ends."""

    def motion(m: Machine, pc: int) -> int:
        moved, skip_to = m.planner.execute_nc(plain, file_path, pc)
        return _after_nc(m, moved, skip_to, pc, nxt)

    return motion


def _after_nc(m: Machine, moved: bool, shape: ShapeCall | None, pc: int, nxt: int) -> int:
    """Where a block goes after its NC words ran: into a lathe cycle's finishing shape, a
    G66 call after a move, or on to the next line."""
    if shape is not None:
        return m.enter_shape(shape, pc, nxt)
    if moved and m.modal_calls:
        return m.modal_call(pc, nxt)
    return nxt


def _subprogram_target(
    m: Any,
    values: list[tuple[str, float]],
    p_text: str | None,
    p_name: str | None,
    get_bracket: Any,
    dialect: Any,
    pc: int,
) -> tuple[Any, int, float | None]:
    """(program, count, Q label) of an M98 block."""
    words = dict(values)
    notes: list[str] = []
    q = words.get("Q")
    if p_name is not None:
        found = m.find_program_named(p_name)
        repeats = repeat_count(words.get("L"), dialect, notes)
    elif get_bracket is not None:  # P[#100]: the variable holds a program name only, never a count (seed 002)
        number = macro_program_number(get_bracket(m), dialect)
        repeats = repeat_count(words.get("L"), dialect, notes)
        found = m.find_program(number)
    elif "P" not in words:
        if q is None:
            raise MacroAlarm(
                PROGRAM_NOT_FOUND,
                detail(
                    "M98 needs P (the program), or Q to call the current program",
                    "M98 需要用 P 指定子程序，或用 Q 调用当前程序",
                ),
            )
        found = m.frame.found
        repeats = repeat_count(words.get("L"), dialect, notes)
    else:
        number, repeats = program_and_count(p_text, words["P"], words.get("L"), dialect, notes)
        found = m.find_program(number)
    for text in notes:
        m.note("call", text, pc, "repeat-count")
    return found, repeats, q
