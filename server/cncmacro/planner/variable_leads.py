"""A variable-lead thread's lead as the control checks it (docs/semantics.md §10.3): G34 (and
any code of ``LatheCycles.variable_lead``) whose lead would go below zero before the thread's
end, or that starts from a negative lead, stops with the control's alarm, PS0313 "illegal lead
command" on the FANUC 0i-TF (its alarm list: "a negative lead value was specified"); the
GSK980TDi's manual (§3.24.4) says "因R的增加/减小使螺距…出现负值时产生报警" and gives no number
(the profile shows it unnumbered).

After N turns the tool has gone F·N + K·N²/2 along the long axis, the lead being F + K·N: with
K < 0 it falls to zero after F / |K| turns, F² / (2·|K|) along, so a thread longer than that
(F² + 2·K·L < 0) asks the lead to go negative.
"""

from __future__ import annotations

from ..bilingual import detail
from ..dialects.alarms import ILLEGAL_LEAD
from .alarms import MacroAlarm


def lead_alarm(code: float, lead: float, change: float, length: float) -> MacroAlarm | None:
    """The alarm of a variable-lead thread ``code`` that starts at ``lead`` (F), changes by
    ``change`` per revolution and runs ``length`` along its long axis (module docstring); None
    where the lead stays at zero or above to the end."""
    g = f"G{code:g}"
    if lead < 0.0:
        return MacroAlarm(ILLEGAL_LEAD, detail(
            f"{g}: the lead F{lead:g} is negative",
            f"{g}：导程 F{lead:g} 为负值"))  # fmt: skip
    if change >= 0.0 or lead * lead + 2.0 * change * length >= 0.0:
        return None
    reach = lead * lead / (-2.0 * change)
    return MacroAlarm(ILLEGAL_LEAD, detail(
        f"{g}: the lead F{lead:g} changing by {change:g} a revolution falls to zero after {reach:g} of the "
        f"{length:g} to cut, and would go negative",
        f"{g}：导程 F{lead:g} 每转变化 {change:g}，切削 {length:g} 中的 {reach:g} 后即降为零，"
        "其后将为负值"))  # fmt: skip
