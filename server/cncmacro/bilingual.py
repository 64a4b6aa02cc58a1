"""Texts in two languages: English, with simplified Chinese beside it.

A message that the parser or the interpreter writes (a syntax problem, an alarm's detail, a
note) is a ``Detail``: a ``str`` whose value is the English text (so everything that stores,
compares or prints the message sees English) and whose ``zh`` attribute holds the Chinese.
``detail(en, zh)`` makes one, written at the place that reports the problem so that both texts
are read and changed together; the front ends choose with ``in_language``, which gives back a
text the program wrote itself (a ``#3000`` message) unchanged. A ``Detail`` survives copying
and pickling; string operations on it (an f-string, ``+``) give a plain English ``str``.

Where both texts are at hand (a check's message, a table row's ``en``/``zh``, a word of the
editor), ``pick(locale, en, zh)`` chooses, and ``listed`` writes a list as each language does.
``is_chinese`` is the one place that says which
locales read Chinese: any ``zh`` locale (``zh``, ``zh-cn``, ``zh-CN``, ``zh_TW``), in any case.
This module imports nothing of the package, so that every layer may use it.
"""

from __future__ import annotations

from collections.abc import Iterable


class Detail(str):
    """English text (the ``str`` value) that also knows its Chinese (``zh``)."""

    zh: str

    def __new__(cls, en: str, zh: str) -> Detail:
        text = super().__new__(cls, en)
        text.zh = zh
        return text

    def __getnewargs__(self) -> tuple[str, str]:  # type: ignore[override]
        return str(self), self.zh

    def __repr__(self) -> str:
        return f"detail({str(self)!r}, {self.zh!r})"


def detail(en: str, zh: str) -> Detail:
    """The same text in English and in Chinese (numbers, codes and ``#`` variables as in ``en``)."""
    return Detail(en, zh)


def is_chinese(locale: str | None) -> bool:
    """Whether ``locale`` reads Chinese: it starts with ``zh`` in any case; None or ``""`` is English."""
    return bool(locale) and str(locale).lower().startswith("zh")


def pick(locale: str | None, en: str, zh: str) -> str:
    """``zh`` for a Chinese locale (``is_chinese``), else ``en``."""
    return zh if is_chinese(locale) else en


def listed(locale: str | None, items: Iterable[object]) -> str:
    """The items written as a list in the language of ``locale``: ``19, 20`` in English,
    ``19、20`` in Chinese (its enumeration comma; an ASCII comma between Chinese words is wrong)."""
    return ("、" if is_chinese(locale) else ", ").join(str(item) for item in items)


def in_language(text: str, chinese: bool) -> str:
    """``text`` in Chinese when ``chinese`` and it has a translation, else as it is (a plain ``str``)."""
    if chinese and isinstance(text, Detail):
        return text.zh
    return str(text)
