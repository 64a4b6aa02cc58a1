"""The ``--locale`` option of ``check`` and ``run``: the language of the messages.

cncmacro writes English and simplified Chinese. ``--locale`` takes a locale the way the
places that hand one over spell it: ``en``, ``zh-CN`` and VS Code's ``zh-cn``, the POSIX form
``zh_CN.UTF-8`` (with an ``@modifier`` or not), ``zh``, and the Chinese of Taiwan or Hong Kong
(``zh-tw``, ``zh_TW.UTF-8``, ``zh-HK``), which reads the simplified texts. Without
``--locale`` the environment decides as POSIX orders it: the first of ``LC_ALL``,
``LC_MESSAGES`` and ``LANG`` that is set and not empty; a Chinese one gives Chinese, anything
else (``C``, ``POSIX``, ``de_DE.UTF-8``) English. A ``--locale`` in neither language is a usage
mistake whose message lists the accepted forms.
"""

from __future__ import annotations

import argparse
import os
from collections.abc import Mapping

from ..bilingual import is_chinese

ENGLISH = "en"
CHINESE = "zh-CN"
ENVIRONMENT = ("LC_ALL", "LC_MESSAGES", "LANG")  # POSIX precedence for the language of messages


def _language(text: str) -> str | None:
    """``en`` or ``zh-CN`` for a locale in either language, else None."""
    name = text.strip().split(".")[0].split("@")[0].replace("_", "-").lower()
    if is_chinese(name) and (len(name) == 2 or name[2] == "-"):  # zh, zh-cn, zh-tw; not zha
        return CHINESE
    if name in ("en", "c", "posix") or name.startswith("en-"):
        return ENGLISH
    return None


def locale_argument(text: str) -> str:
    """argparse ``type`` for ``--locale``: ``en`` or ``zh-CN`` from any spelling of either."""
    language = _language(text)
    if language is None:
        raise argparse.ArgumentTypeError(
            f"unknown locale {text!r}: the messages are in English (en) or Chinese "
            "(zh-CN; also written zh-cn, zh, zh_CN.UTF-8, zh-TW)"
        )
    return language


def environment_locale(environ: Mapping[str, str] | None = None) -> str:
    """The language the environment asks for: the first of ``LC_ALL``, ``LC_MESSAGES`` and
    ``LANG`` that is set decides; English when none is, or when it names another language."""
    env = os.environ if environ is None else environ
    for name in ENVIRONMENT:
        value = env.get(name, "")
        if value:
            return _language(value) or ENGLISH
    return ENGLISH


def add_locale_option(parser: argparse.ArgumentParser, what: str) -> None:
    """``--locale`` on ``parser``; its default is the environment's language, read now."""
    parser.add_argument(
        "--locale", type=locale_argument, default=environment_locale(), metavar="LOCALE",
        help=f"language of {what}: en or zh-CN (also zh-cn, zh_CN.UTF-8, zh-TW); "
             "default: from LC_ALL, LC_MESSAGES or LANG, else en",
    )  # fmt: skip
