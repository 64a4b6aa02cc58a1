"""The machine layer: the interpreter of the macro language (docs/design.md "machine").

``Machine`` runs a program block by block on a simulated control; ``run_program`` is the
one-call form that the command line uses.
"""

from .alarms import Alarm, CallLevel, MacroAlarm
from .machine import Machine
from .observer import RunObserver
from .run_records import RunResult, Snapshot
from .status import RunStatus

__all__ = ["Alarm", "CallLevel", "Machine", "MacroAlarm", "RunObserver", "RunResult", "RunStatus", "Snapshot"]
