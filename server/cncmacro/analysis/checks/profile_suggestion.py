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

The block form of IF (``IF [cond] THEN`` / ``ELSE`` / ``ENDIF``) under a profile without it is such
a feature: the suggestion names the first profile that reads it (``mitsubishi-m70``) and the other
profiles that read it too (``mazak-eia``). Profiles are tried in ``SUGGESTION_ORDER``: by their
``Dialect.suggestion_rank``, then by name, so that of two profiles that read a file alike the one
that reads less beyond it is named; ``&&`` and ``||`` (or block IFs with them) are read only by
``mazak-eia``, which such a file gets.

A third sign is a program number written with more digits than ``M98 P`` names a program with
under the profile in force: ``O00012345`` is the 8-digit program numbering of a 30i (or of a
0i-F with that option), where ``M98 P00012346`` calls O12346 and only ``L`` counts, while a 0i
reading it splits P into a count and a 4-digit program. Such a header names the first other
profile whose ``M98 P`` takes that many digits.

A lathe program read under a mill profile has no finding at all, and runs wrongly: a ``G92``
thread shifts coordinates, U and W move nothing. When its lathe signs are strong enough
(``lathe_signs.py``) it gets the suggestion first, naming the control's own lathe form
(``Dialect.lathe_variant``: ``fanuc-30i``'s, which the machine file's ``lathe = true`` chooses),
else its lathe profile (``registry.lathe_forms``: ``fanuc-0i-lathe``), or the first lathe profile that
reads the file without a feature finding where that one does not (a GSK980TDi's ``G65 H``
arithmetic).
"""

from __future__ import annotations

from collections.abc import Mapping

from ...bilingual import Detail, detail, pick
from ...dialects import BY_NAME, DIALECTS, Dialect
from ...dialects.registry import lathe_forms
from ...library.machine_file import MachineSettings
from ...library.profiles import machine_profile
from ...syntax.program import Program
from ..diagnostics import Diagnostic, diagnostic
from .lathe_signs import LatheEvidence, lathe_evidence
from .line_facts import LineFacts

CODE = "profile-suggestion"
# the order in which other profiles are tried: rank first, the registry's order (by name) within a rank
SUGGESTION_ORDER: tuple[str, ...] = tuple(sorted(DIALECTS, key=lambda name: BY_NAME[name].suggestion_rank))
# the findings that say "this control lacks it": syntax or G codes another control has
FEATURE_CODES = ("dialect-feature", "unknown-g-code")


def suggested_profile(
    program: Program,
    dialect: Dialect,
    settings: MachineSettings,
    lines: list[int] | None = None,
    among: tuple[str, ...] = SUGGESTION_ORDER,
) -> Dialect | None:
    """The first other profile (of ``among``) under which ``program`` has no
    ``dialect-feature`` or ``unknown-g-code`` finding, or None when no profile reads it all.
    Both findings belong to one block, so only ``lines`` (the blocks that have them under
    ``dialect``) are checked again; without ``lines`` every block is."""
    from .static_checks import line_context, line_facts  # the per-block checks, once per profile tried

    blocks = program.blocks
    wanted = range(len(blocks)) if lines is None else lines
    for name in among:
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
    facts: Mapping[int, LineFacts], program: Program, dialect: Dialect, settings: MachineSettings
) -> tuple[Dialect, list[tuple[int, int, int]]] | None:
    """The first other profile that reads some block of ``program`` as a local subprogram call
    (``Dialect.local_subprogram_code``, Haas ``M97``) to a label the program has, where
    ``dialect`` reads no such call, with those calls (line, and the span of their label); None
    when there is none. ``facts`` are the program's per-line facts under ``dialect``
    (``LineFacts.foreign_calls``), so that only the lines that have facts are looked at."""
    found: dict[float, list[tuple[int, int, int]]] = {}
    for k, f in facts.items():
        for code, label, start, end in f.foreign_calls:
            if k < program.read_end and label in program.labels:
                found.setdefault(code, []).append((k, start, end))
    for name in DIALECTS:
        other = machine_profile(name, settings)
        if name != dialect.name and other.local_subprogram_code in found:
            return other, sorted(found[other.local_subprogram_code])
    return None


# fewer written digits are no sign: 5-digit numbers are Haas's and many 0i machines' own
LONG_HEADER_DIGITS = 6


def long_header(program: Program, dialect: Dialect, settings: MachineSettings) -> tuple[Dialect, int, int, int] | None:
    """The first other profile whose ``M98 P`` names a program of as many digits as an O header
    of ``program`` is written with (at least ``LONG_HEADER_DIGITS``), where ``dialect``'s names
    fewer, with that header (line and the span of its O word); None when there is none."""
    for unit in program.units:
        if unit.number is None or unit.duplicate:
            continue
        span = program.blocks[unit.start].program_span
        digits = 0 if span is None else span[1] - span[0] - 1
        if digits < LONG_HEADER_DIGITS or digits <= dialect.m98_program_digits:
            continue
        for name in DIALECTS:
            other = machine_profile(name, settings)
            if name != dialect.name and other.m98_program_digits >= digits:
                assert span is not None
                return other, unit.start, span[0], span[1]
        return None
    return None


def lathe_program(
    facts: Mapping[int, LineFacts], program: Program, dialect: Dialect, settings: MachineSettings, features: list[int]
) -> tuple[Dialect, LatheEvidence] | None:
    """The lathe profile to offer for ``program`` read under the mill profile ``dialect`` when
    its signs make it a lathe program (``lathe_signs.lathe_evidence``), with the evidence; None
    under a lathe profile or when the evidence is short. ``features`` are the lines with
    feature findings under ``dialect``: the first lathe that reads them cleanly is offered,
    else the mill's own lathe."""
    if dialect.lathe:
        return None
    evidence = lathe_evidence({k: f.lathe_signs for k, f in facts.items() if f.lathe_signs}, program)
    if evidence is None:
        return None
    if dialect.lathe_variant is not None:  # the control's own lathe form: fanuc-30i with lathe = true
        return machine_profile(dialect.lathe_variant, settings), evidence
    forms = lathe_forms(dialect.name)
    if not forms:
        return None
    names = tuple(d.name for d in forms)
    other = suggested_profile(program, dialect, settings, features, names) if features else None
    return other or machine_profile(names[0], settings), evidence


def suggestion_target(program: Program, dialect: Dialect, settings: MachineSettings) -> Dialect | None:
    """The profile that ``suggestion`` names for ``program`` (for its quick fixes, which are
    asked without the findings): the same choice, with the feature findings found again."""
    from .static_checks import line_context, line_facts

    ctx = line_context(dialect, settings)
    facts = {k: f for k, b in enumerate(program.blocks) if (f := line_facts(b, ctx)) is not None}
    features = [k for k, f in facts.items() if any(x.code in FEATURE_CODES for x in f.findings)]
    lathe = lathe_program(facts, program, dialect, settings, features)
    if lathe is not None:
        return lathe[0]
    if features:
        return suggested_profile(program, dialect, settings, features)
    found = local_call_lines(facts, program, dialect, settings)
    if found is not None:
        return found[0]
    header = long_header(program, dialect, settings)
    return None if header is None else header[0]


def suggestion(
    own: list[Diagnostic],
    facts: Mapping[int, LineFacts],
    program: Program,
    file: str,
    dialect: Dialect,
    settings: MachineSettings,
    locale: str,
) -> Diagnostic | None:
    """The ``profile-suggestion`` for a file whose findings are ``own``, placed on its first
    strong lathe sign or ``dialect-feature`` finding; None when there is nothing to suggest."""
    features = [d for d in own if d.code in FEATURE_CODES]
    lathe = lathe_program(facts, program, dialect, settings, sorted({d.line for d in features}))
    if lathe is not None:
        return _lathe_hint(*lathe, file, dialect, locale)
    if features:
        other = suggested_profile(program, dialect, settings, sorted({d.line for d in features}))
        if other is None:
            return None
        at = (features[0].line, features[0].column, features[0].end_line, features[0].end_column)
        lines = sorted({d.line + 1 for d in features})
    else:
        found = local_call_lines(facts, program, dialect, settings)
        if found is None:
            header = long_header(program, dialect, settings)
            return None if header is None else _header_hint(header, file, dialect, locale)
        other, calls = found
        at = (calls[0][0], calls[0][1], calls[0][0], calls[0][2])
        lines = sorted({k + 1 for k, _, _ in calls})
    where = ", ".join(str(n) for n in lines[:5]) + (" …" if len(lines) > 5 else "")
    where_zh = "、".join(str(n) for n in lines[:5]) + ("……" if len(lines) > 5 else "")
    word = "line" if len(lines) == 1 else "lines"
    also = _block_if_elsewhere(other, dialect) if any(program.blocks[n - 1].branch_marker() for n in lines) else None
    message = pick(
        locale,
        f"This file uses what {other.title} has and {dialect.title} lacks ({word} {where}). If it was written for "
        f'that control, add (cncmacro: dialect={other.name}) to its first lines, or set base = "{other.name}" '
        "in .cncmacro.toml" + (f"; {also}" if also else ""),
        f"此文件用到了 {other.title} 才有而 {dialect.title} 没有的功能（第 {where_zh} 行）。若程序是为该系统编写的，"
        f'请在文件开头加上 (cncmacro: dialect={other.name})，或在 .cncmacro.toml 中设定 base = "{other.name}"'
        + (f"；{also.zh}" if also else ""),
    )
    return diagnostic(file, *at, CODE, message)


def _block_if_elsewhere(other: Dialect, dialect: Dialect) -> Detail | None:
    """What a suggestion of ``other`` for a file with block IFs adds: the other profiles that read
    them too (English, Chinese), or None where ``other`` lacks them or no other profile has them."""
    if not other.block_if:
        return None
    also = [BY_NAME[n] for n in SUGGESTION_ORDER if BY_NAME[n].block_if and n not in (other.name, dialect.name)]
    if not also:
        return None
    names = " and ".join(f"{d.name} ({d.title})" for d in also)
    names_zh = "和".join(f"{d.name}（{d.title}）" for d in also)
    if len(also) == 1:
        return detail(f"the profile {names} reads IF..THEN / ELSE / ENDIF blocks too",
                      f"配置 {names_zh}也能执行 IF..THEN / ELSE / ENDIF 块")  # fmt: skip
    return detail(f"the profiles {names} read IF..THEN / ELSE / ENDIF blocks too",
                  f"配置 {names_zh}也能执行 IF..THEN / ELSE / ENDIF 块")  # fmt: skip


def _header_hint(header: tuple[Dialect, int, int, int], file: str, dialect: Dialect, locale: str) -> Diagnostic:
    """The ``profile-suggestion`` on an O header written with more digits than ``dialect``'s
    ``M98 P`` names a program with."""
    other, line, start, end = header
    digits = end - start - 1
    message = pick(
        locale,
        f"This program number is written with {digits} digits, as on {other.title}, where M98 P names the whole "
        f"program and only L counts; {dialect.title} reads the digits of M98 P before the last "
        f"{dialect.m98_program_digits} as a repeat count. If it was written for that control, add "
        f'(cncmacro: dialect={other.name}) to its first lines, or set base = "{other.name}" (or program_digits = '
        f"{digits} for a machine with {digits}-digit program numbers) in .cncmacro.toml",
        f"此程序号写成 {digits} 位，与 {other.title} 相同：在该系统上 M98 P 整个是程序号，重复次数只由 L 指定；"
        f"而 {dialect.title} 把 M98 P 最后 {dialect.m98_program_digits} 位之前的数字读作重复次数。"
        "若程序是为该系统编写的，"
        f'请在文件开头加上 (cncmacro: dialect={other.name})，或在 .cncmacro.toml 中设定 base = "{other.name}"'
        f"（机床程序号为 {digits} 位时也可设定 program_digits = {digits}）",
    )
    return diagnostic(file, line, start, line, end, CODE, message)


def _lathe_hint(other: Dialect, evidence: LatheEvidence, file: str, dialect: Dialect, locale: str) -> Diagnostic:
    """The ``profile-suggestion`` for a lathe program read under the mill profile ``dialect``,
    on its first strong sign, naming the signs found (the first of each kind, at most four)."""
    shown = evidence.signs[:4]
    more = " …" if len(evidence.signs) > 4 else ""
    en = ", ".join(f"{s.shown} on line {k + 1}" for k, s in shown) + more
    zh = "，".join(f"第 {k + 1} 行 {s.shown}" for k, s in shown) + more
    line, sign = evidence.signs[0]
    if other.name == dialect.name:  # its own lathe form, which the machine file's lathe = true chooses
        message = pick(
            locale,
            f"This looks like a lathe program ({en}); it is read under the mill profile {dialect.name} "
            f"({dialect.title}). Choose its lathe form, {other.title}? Set lathe = true in .cncmacro.toml "
            f'(with base = "{dialect.name}")',
            f"这看起来是车床程序（{zh}），现在按铣床系统 {dialect.name}（{dialect.title}）读取。"
            f"是否选择其车床形式 {other.title}？请在 .cncmacro.toml 中设定 lathe = true"
            f'（以及 base = "{dialect.name}"）',
        )
        return diagnostic(file, line, sign.start, line, sign.end, CODE, message)
    message = pick(
        locale,
        f"This looks like a lathe program ({en}); it is read under the mill profile {dialect.name} ({dialect.title}). "
        f"Choose the lathe profile {other.name} ({other.title})? Add (cncmacro: dialect={other.name}) to its first "
        f'lines, or set base = "{other.name}" in .cncmacro.toml',
        f"这看起来是车床程序（{zh}），现在按铣床系统 {dialect.name}（{dialect.title}）读取。"
        f"是否选择车床系统 {other.name}（{other.title}）？请在文件开头加上 (cncmacro: dialect={other.name})，"
        f'或在 .cncmacro.toml 中设定 base = "{other.name}"',
    )
    return diagnostic(file, line, sign.start, line, sign.end, CODE, message)
