"""Which profile a file seems written for, when the one in force lacks what it uses.

A file read as ``fanuc-0i`` that writes ``[#_ABSIO[1]]`` or ``POW[..]``, or a FANUC file with
``G65 H01`` arithmetic, gets ``dialect-feature`` errors. When another built-in profile would read
the same file without any (nor a G code it does not know), that is a strong sign the file was
written for that control: the file gets one ``profile-suggestion`` (information) that names it,
with quick fixes that write the ``(cncmacro: dialect=...)`` comment or the machine file's
``base``. Nothing switches by itself.
"""

from __future__ import annotations

from ..dialects import DIALECTS, Dialect
from ..library.machine_file import MachineSettings
from ..library.profiles import machine_profile
from ..syntax.program import Program
from .diagnostics import Diagnostic
from .locale import pick

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


def suggestion(
    own: list[Diagnostic], program: Program, file: str, dialect: Dialect, settings: MachineSettings, locale: str
) -> Diagnostic | None:
    """The ``profile-suggestion`` for a file whose findings are ``own``, placed on its first
    ``dialect-feature`` finding; None when there is nothing to suggest."""
    features = [d for d in own if d.code in FEATURE_CODES]
    if not features:
        return None
    other = suggested_profile(program, dialect, settings, sorted({d.line for d in features}))
    if other is None:
        return None
    first = features[0]
    lines = sorted({d.line + 1 for d in features})
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
    return Diagnostic(file, first.line, first.column, first.end_line, first.end_column, "information", CODE, message)
