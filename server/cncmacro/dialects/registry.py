"""The list of control profiles, found once by listing ``dialects/profiles/``.

Everything that offers a choice of control (the command line, the machine file, the language
server's setting, the client's status bar and picker) asks here, so a new profile module shows up
everywhere without a second list to keep in step.
"""

from __future__ import annotations

import importlib
import pkgutil
from functools import cache
from typing import Any

from . import profiles
from .dialect import Dialect

DEFAULT_PROFILE = "fanuc-0i"
LATHE_SUFFIX = "-lathe"  # a control's lathe profile is named after its mill's: fanuc-0i-lathe


@cache
def all_profiles() -> tuple[Dialect, ...]:
    """Every built-in profile, the default first, then by name."""
    found: list[Dialect] = []
    for info in pkgutil.iter_modules(profiles.__path__):
        module = importlib.import_module(f"{profiles.__name__}.{info.name}")
        profile = getattr(module, "PROFILE", None)
        if isinstance(profile, Dialect):
            found.append(profile)
    found.sort(key=lambda d: (d.name != DEFAULT_PROFILE, d.name))
    names = [d.name for d in found]
    if len(set(names)) != len(names):
        raise RuntimeError(f"two profile modules share a name: {names}")
    return tuple(found)


def lathe_forms(mill: str) -> tuple[Dialect, ...]:
    """The lathe profiles to offer for a lathe program read as the profile ``mill``: its own
    control's lathe (``mill`` + ``LATHE_SUFFIX``) where there is one, else the default
    profile's, then every other lathe profile in the registry's order."""
    lathes = [d for d in all_profiles() if d.lathe]
    first = [d for d in lathes if d.name == mill + LATHE_SUFFIX] or [
        d for d in lathes if d.name == DEFAULT_PROFILE + LATHE_SUFFIX
    ]
    return (*first, *(d for d in lathes if d not in first))


@cache
def names_and_aliases() -> dict[str, str]:
    """Every accepted spelling (name or alias, lower case, no spaces) -> the profile's name."""
    table: dict[str, str] = {}
    for d in all_profiles():
        for spelling in (d.name, d.name.replace("-", ""), *d.aliases):
            key = spelling.lower().replace(" ", "")
            if table.setdefault(key, d.name) != d.name:
                raise RuntimeError(f"{spelling!r} names both {table[key]} and {d.name}")
    return table


def profile_facts() -> list[dict[str, Any]]:
    """Each profile as a client shows it (the language server's ``cncmacro/profiles`` answer and
    ``cncmacro profiles --json``): name, titles and summaries (English and Chinese), aliases,
    lathe or mill, axes, commons."""
    return [
        {
            "name": d.name,
            "title": d.title,
            "titleZh": d.title_zh or d.title,
            "summary": d.summary,
            "summaryZh": d.summary_zh,
            "aliases": list(d.aliases),
            "lathe": d.lathe,
            "axes": list(d.axes),
            "common": [[r.first, r.last] for r in d.common_ranges],
            "default": d.name == DEFAULT_PROFILE,
        }
        for d in all_profiles()
    ]
