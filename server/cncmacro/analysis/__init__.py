"""The analysis layer: static checks over parsed programs (and, later, bounded runs of the
machine) turned into ``Diagnostic`` objects with stable codes."""

from .checks.syntax_check import syntax_diagnostics
from .diagnostics import Diagnostic

__all__ = ["Diagnostic", "syntax_diagnostics"]
