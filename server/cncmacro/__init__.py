"""cncmacro: a faithful, steppable interpreter of CNC custom-macro programs (FANUC 0i Custom
Macro B and GSK980TDi) and the tools built on it: ``cncmacro check``, the language server and
the debug adapter."""

__version__ = "0.2.0"
