"""The language-server session fixtures (one server per module, workspace and locale)."""

from .lsp_session import fanuc_en, fanuc_zh, gsk_en, gsk_zh

__all__ = ["fanuc_en", "fanuc_zh", "gsk_en", "gsk_zh"]
