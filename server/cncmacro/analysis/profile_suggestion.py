"""Which profile a file seems written for, when the one in force lacks what it uses.

A file read as ``fanuc-0i`` that writes ``[#_ABSIO[1]]`` or ``POW[..]``, or a FANUC file with
``G65 H01`` arithmetic, gets ``dialect-feature`` errors. When another built-in profile would read
the same file without any (nor a G code it does not know), that is a strong sign the file was
written for that control: the file gets one ``profile-suggestion`` (information) that names it,
with quick fixes that write the ``(cncmacro: dialect=...)`` comment or the machine file's
``base``. Nothing switches by itself.

A file can also be plainly another control's without an error under the profile in force: a
Haas ``M97 P100`` that calls the program's own ``N100`` is an M code without a meaning to a
FANUC control, which then runs on into N100 (``local_call_lines``). Such a call, to a label that
the program has, is the other profile's signature and gets the same suggestion. The NGC's
``#10000`` commons are no signature: on a FANUC control the same numbers are tool offsets, which
FANUC tool-wear programs write (docs/profiles.md).
"""

from __future__ import annotations

import re

from ..bilingual import pick
from ..dialects import DIALECTS, Dialect
from ..library.machine_file import MachineSettings
from ..library.profiles import machine_profile
from ..syntax.program import Program
from .diagnostics import Diagnostic, diagnostic

CODE = "profile-suggestion"
# the findings that say "this control lacks it": syntax or G codes another control has
FEATURE_CODES = ("dialect-feature", "unknown-g-code")


def suggested_profile(
    program: Program, dialect: Dialect, settings: MachineSettings, lines: list[int] | None = None
) -> Dialect | None:
    """The first other profile under which ``program`` has no ``dialect-feature`` or
    ``unknown-g-code`` finding, or None when no profile reads it all. Both findings belong to
    one block, so only ``lines`` (the blocks that have them under ``dialect``) are checked again;
    without ``lines`` every block is."""
    from .static_checks import line_context, line_facts  # the per-block checks, once per profile tried

    blocks = program.blocks
    wanted = range(len(blocks)) if lines is None else lines
    for name in DIALECTS:
        if name == dialect.name:
            continue
        other = machine_profile(name, settings)
        ctx = line_context(other, settings)
        if not any(
            f.code in FEATURE_CODES
            for k in wanted
            if (facts := line_facts(blocks[k], ctx)) is not None
            for f in facts.findings
        ):
            return other
    return None


def local_call_lines(
    program: Program, dialect: Dialect, settings: MachineSettings
) -> tuple[Dialect, list[tuple[int, int, int]]] | None:
    """The first other profile that reads some block of ``program`` as a local subprogram call
    (``Dialect.local_subprogram_code``, Haas ``M97``) to a label the program has, where
    ``dialect`` reads no such call, with those calls (line, and the span of their P word); None
    when there is none."""
    from .static_checks import line_context, line_facts

    for name in DIALECTS:
        other = machine_profile(name, settings)
        code = other.local_subprogram_code
        if name == dialect.name or code is None or code == dialect.local_subprogram_code:
            continue
        mention = re.compile(rf"[Mm][+]?0*{code:g}(?![0-9.])").search
        how = f"M{code:g}"
        ctx = line_context(other, settings)
        lines: list[tuple[int, int, int]] = []
        for k, b in enumerate(program.blocks[: program.read_end]):
            if not (mention(b.plain) if b.plain is not None else any(w.letter == "M" for w in b.words)):
                continue
            facts = line_facts(b, ctx)
            lines += [(k, *c.q_span) for c in facts.calls if c.how == how and c.q in program.labels] if facts else []
        if lines:
            return other, lines
    return None


def suggestion_target(program: Program, dialect: Dialect, settings: MachineSettings) -> Dialect | None:
    """The profile that ``suggestion`` names for ``program`` (for its quick fixes, which are
    asked without the findings): the same choice, with the feature findings found again."""
    from .static_checks import line_context, line_facts

    ctx = line_context(dialect, settings)
    features = [
        k
        for k, b in enumerate(program.blocks)
        if (facts := line_facts(b, ctx)) is not None and any(f.code in FEATURE_CODES for f in facts.findings)
    ]
    if features:
        return suggested_profile(program, dialect, settings, features)
    found = local_call_lines(program, dialect, settings)
    return None if found is None else found[0]


def suggestion(
    own: list[Diagnostic], program: Program, file: str, dialect: Dialect, settings: MachineSettings, locale: str
) -> Diagnostic | None:
    """The ``profile-suggestion`` for a file whose findings are ``own``, placed on its first
    ``dialect-feature`` finding; None when there is nothing to suggest."""
    features = [d for d in own if d.code in FEATURE_CODES]
    if features:
        other = suggested_profile(program, dialect, settings, sorted({d.line for d in features}))
        if other is None:
            return None
        at = (features[0].line, features[0].column, features[0].end_line, features[0].end_column)
        lines = sorted({d.line + 1 for d in features})
    else:
        found = local_call_lines(program, dialect, settings)
        if found is None:
            return None
        other, calls = found
        at = (calls[0][0], calls[0][1], calls[0][0], calls[0][2])
        lines = sorted({k + 1 for k, _, _ in calls})
    where = ", ".join(str(n) for n in lines[:5]) + (" …" if len(lines) > 5 else "")
    word = "line" if len(lines) == 1 else "lines"
    message = pick(
        locale,
        f"This file uses what {other.title} has and {dialect.title} lacks ({word} {where}). If it was written for "
        f'that control, add (cncmacro: dialect={other.name}) to its first lines, or set base = "{other.name}" '
        "in .cncmacro.toml",
        f"此文件用到了 {other.title} 才有而 {dialect.title} 没有的功能（第 {where} 行）。若程序是为该系统编写的，"
        f'请在文件开头加上 (cncmacro: dialect={other.name})，或在 .cncmacro.toml 中设定 base = "{other.name}"',
    )
    return diagnostic(file, *at, CODE, message)
