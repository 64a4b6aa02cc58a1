"""The static checks: every diagnostic that can be decided without running the program.

``static_diagnostics`` checks a whole parsed file: each line on its own (``line_facts``: the
statements, the words, the variables; see ``statement_checks``, ``call_checks`` and
``variable_checks``), then what connects the lines (``unit_checks`` for repeated O numbers,
``loop_checks``, and ``label_checks`` with the program lookups of ``call_targets``). The per-line
part is a pure function of the block, the dialect, the machine settings and the locale, so an
incremental analysis may cache it per block and call ``block_diagnostics`` for changed lines only
(``static_lines`` does), then ``cross_line_diagnostics`` (with ``lathe_cycle_checks`` on a lathe).
A plain CAM line (``Block.plain``) is
looked at only when its text holds a word ``check_words`` looks at (``words_looked_at``, made into
one search by ``machine/word_sets.plain_search``); its words are never built otherwise.
Syntax errors are ``syntax_check``'s: a block that does not parse is not checked here.
"""

from __future__ import annotations

from ...dialects.dialect import Dialect
from ...library.machine_file import MachineSettings
from ...library.programs import ProgramLibrary
from ...machine.word_sets import plain_search
from ...syntax.nodes import Block
from ...syntax.program import Program
from ..diagnostics import Diagnostic
from ..faults import FILE, internal_error, line_fault
from .call_checks import check_words, words_looked_at
from .call_targets import ProgramFinder
from .corner_checks import check_corners
from .label_checks import LabelChecker
from .lathe_cycle_checks import lathe_cycle_diagnostics
from .line_facts import LineContext, LineFacts
from .loop_checks import if_diagnostics, loop_diagnostics
from .statement_checks import check_abbreviations, check_statements
from .tape_checks import tape_diagnostics
from .unit_checks import duplicate_program_diagnostics

_contexts: dict[tuple[str, int, str], LineContext] = {}


def line_context(dialect: Dialect, settings: MachineSettings, locale: str = "en") -> LineContext:
    """The ``LineContext`` for these settings (made once and reused)."""
    key = (dialect.name, id(settings), locale)
    ctx = _contexts.get(key)
    if ctx is None or ctx.settings is not settings or ctx.dialect is not dialect:
        if len(_contexts) > 64:
            _contexts.clear()
        ctx = _contexts[key] = LineContext(dialect, settings, locale)
        ctx.plain_hint = plain_search(words_looked_at(ctx))  # the checks say which words they look at
    return ctx


def line_facts(block: Block, ctx: LineContext) -> LineFacts | None:
    """What ``block`` says by itself: findings, jumps, calls, returns (None for nothing). A
    fault of the checker on the block is an ``internal-error`` finding of its own (faults.py)."""
    try:
        return _line_facts(block, ctx)
    except Exception as e:  # a bug must cost one line, not the file
        return line_fault(e, ctx.locale)


def _line_facts(block: Block, ctx: LineContext) -> LineFacts | None:
    plain = block.plain_text  # after a label too (N10 G01 X5.): looked at as a plain line's
    if plain is not None:
        if not ctx.plain_hint(plain):
            return None
    elif block.problems and block.has_error:
        return None
    facts = LineFacts()
    if block.statements:
        check_statements(block, ctx, facts)
    elif block.words or block.corners:
        check_words(block, ctx, facts)
        if block.corners:
            check_corners(block, ctx, facts)
    if block.abbreviations:
        check_abbreviations(block, ctx, facts)
    return facts if facts else None


def block_diagnostics(
    block: Block, line: int, file: str, dialect: Dialect, settings: MachineSettings, locale: str = "en"
) -> list[Diagnostic]:
    """The diagnostics that ``block`` on ``line`` earns by itself (no cross-line checks)."""
    facts = line_facts(block, line_context(dialect, settings, locale))
    return findings_of(facts, line, file) if facts is not None else []


def findings_of(facts: LineFacts, line: int, file: str) -> list[Diagnostic]:
    return [
        Diagnostic(file, line, f.start, line, max(f.end, f.start + 1), f.severity, f.code, f.message)
        for f in facts.findings
    ]


def static_diagnostics(
    program: Program,
    file: str,
    dialect: Dialect,
    settings: MachineSettings,
    library: ProgramLibrary | None = None,
    locale: str = "en",
) -> list[Diagnostic]:
    """Every static finding in ``program`` (the parsed text of ``file``), in line order.
    Called programs are looked up in ``library`` near ``file``; without a library only the
    file's own O programs are known and other targets are not reported."""
    ctx = line_context(dialect, settings, locale)
    hint = ctx.plain_hint
    out: list[Diagnostic] = []
    collected: list[tuple[int, LineFacts]] = []
    for line in range(program.read_end):  # nothing after the closing '%' is read
        block = program.blocks[line]
        plain = block.plain
        if plain is not None and not hint(plain):
            continue
        facts = line_facts(block, ctx)
        if facts is None:
            continue
        if facts.findings:
            out.extend(findings_of(facts, line, file))
        if facts.jumps or facts.calls or facts.returns:
            collected.append((line, facts))
    out.extend(cross_line_diagnostics(program, file, ctx.dialect, library, locale, collected, ctx))
    out.sort(key=Diagnostic.sort_key)
    return out


def cross_line_diagnostics(
    program: Program,
    file: str,
    dialect: Dialect,
    library: ProgramLibrary | None,
    locale: str,
    collected: list[tuple[int, LineFacts]],
    ctx: LineContext | None = None,
) -> list[Diagnostic]:
    """What connects the lines: repeated O numbers, loops, the labels and call targets of
    ``collected`` (the lines with jumps, calls or returns, in line order, with their facts) and,
    with the line context ``ctx``, a lathe's cycles and their shapes (``lathe_cycle_checks``). A
    fault of the checker here is one ``internal-error`` on the file's first line (faults.py)."""
    try:
        out = duplicate_program_diagnostics(program, file, locale, dialect)
        out.extend(loop_diagnostics(program, file, locale, dialect))
        out.extend(if_diagnostics(program, file, locale, dialect))
        out.extend(tape_diagnostics(program, file, locale))
        finder = ProgramFinder(program, file, dialect, library)
        out.extend(LabelChecker(program, file, finder, locale, dialect).run(collected))
        if ctx is not None:
            out.extend(lathe_cycle_diagnostics(program, file, ctx))
    except Exception as e:  # a bug must not cost the per-line findings
        return [internal_error(file, 0, FILE, e, locale)]
    return out
