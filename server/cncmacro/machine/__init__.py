"""The machine layer: the interpreter of the macro language (docs/design.md "machine").

``Machine`` runs a program block by block on a simulated control; ``run_program`` is the
one-call form that the command line uses.
"""

from .alarms import Alarm, CallSite, MacroAlarm
from .machine import COMPLETED, Machine, RunResult, Snapshot

__all__ = ["COMPLETED", "Alarm", "CallSite", "Machine", "MacroAlarm", "RunResult", "Snapshot"]
