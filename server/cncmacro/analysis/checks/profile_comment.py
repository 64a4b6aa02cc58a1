"""A ``(cncmacro: dialect=...)`` comment that names no profile (docs/design.md, "Which profile").

The comment is the first link of the chain that decides a file's profile
(``library/dialect_choice.py``). A name that is no profile's (``hass`` for ``haas``) is passed
over, so the file is read in the next link's profile, silently, and a ``profile-suggestion``
would ask for the comment that is already there. The comment gets an ``unknown-profile``
warning instead, naming the profile the file is read in and the nearest valid name.
"""

from __future__ import annotations

from ...bilingual import pick
from ...dialects import DIALECTS, nearest_dialect, normalise_dialect
from ...library.dialect_choice import dialect_comment
from ..diagnostics import Diagnostic, diagnostic

UNKNOWN_PROFILE = "unknown-profile"


def profile_comment_diagnostics(lines: list[str], file: str, read_as: str, locale: str) -> list[Diagnostic]:
    """The ``unknown-profile`` warning on a dialect comment of ``lines`` (the file's first lines)
    whose name is no profile's; ``read_as`` is the profile the file is read in instead."""
    found = dialect_comment(lines)
    if found is None or normalise_dialect(found[3]) is not None:
        return []
    line, start, end, name = found
    near = nearest_dialect(name)
    names = ", ".join(DIALECTS)
    if near is not None:
        en = f"'{name}' is not a profile, so this comment is passed over and the file is read as {read_as}: " \
             f"did you mean '{near}'? (profiles: {names})"  # fmt: skip
        zh = f"'{name}' 不是系统类型，此注释被忽略，文件按 {read_as} 读取：是否应为 '{near}'？（可用：{names}）"
    else:
        en = f"'{name}' is not a profile, so this comment is passed over and the file is read as {read_as} " \
             f"(profiles: {names})"  # fmt: skip
        zh = f"'{name}' 不是系统类型，此注释被忽略，文件按 {read_as} 读取（可用：{names}）"
    return [diagnostic(file, line, start, line, end, UNKNOWN_PROFILE, pick(locale, en, zh))]
