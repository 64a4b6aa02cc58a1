"""The language of messages: English, or simplified Chinese for any ``zh`` locale.

Each check writes its message in both languages side by side and ``pick`` chooses one, so a
message and its translation are always read and changed together.
"""

from __future__ import annotations


def is_chinese(locale: str | None) -> bool:
    return bool(locale) and locale.lower().startswith("zh")  # type: ignore[union-attr]


def pick(locale: str | None, en: str, zh: str) -> str:
    """``zh`` for a Chinese locale (``zh``, ``zh-cn``, ``zh-CN``, ``zh_TW``), else ``en``."""
    return zh if is_chinese(locale) else en
