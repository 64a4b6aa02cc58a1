"""The analysis layer: static checks over parsed programs (and, later, bounded runs of the
machine) turned into ``Diagnostic`` objects with stable codes."""

from .diagnostics import Diagnostic
from .syntax_check import syntax_diagnostics

__all__ = ["Diagnostic", "syntax_diagnostics"]
