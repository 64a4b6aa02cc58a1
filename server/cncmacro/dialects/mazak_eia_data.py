"""Mazak Mazatrol Matrix and Smooth controls in EIA/ISO: the tables of the ``mazak-eia`` profile
(``dialects/profiles/mazak_eia.py``).

Mazak's EIA/ISO mode reads the FANUC Macro B language, so where it reads a number the way a
FANUC 0i does the row is ``fanuc_data``'s own: the tool offsets (#10001…, #11001…, #12001…,
#13001… and the short numbers #2001…), the timers and clock (#3001, #3002, #3011, #3012), the
parts counters, the modal information (#4001…, #4101…), the positions (#5001…, the skip
positions #5061…, the tool length offset #5081…) and the work offsets (#5201…, G54.1 P1–P48 at
#7001…). What is its own:

* #3000 raises the control's own macro alarm with the program's message, whose number the
  profile does not list yet;
* ``M98 P`` names a program of up to 8 digits, and only ``L`` counts.

Which of the FANUC numbers Mazak reads otherwise, and Mazak's own tool data (the MAZATROL tool
file: length, diameter, life), are to be confirmed against its programming manual
(docs/profiles.md "mazak-eia"); none of them is listed until then.
"""

from __future__ import annotations

from . import fanuc_data as fanuc
from .shared_data import with_m98_count_in_l, with_macro_alarm_shown
from .tables import CodeDoc, SystemVariable

# ---------------------------------------------------------------------------------------------
# macro alarm: FANUC's row, said as this control shows it

_CONTROL: tuple[SystemVariable, ...] = with_macro_alarm_shown(fanuc._CONTROL)

SYSTEM_VARIABLES: tuple[SystemVariable, ...] = (
    *fanuc._SIGNALS,
    *fanuc._TOOL_OFFSETS,
    *_CONTROL,
    *fanuc._MODAL,
    *fanuc._POSITIONS,
    *fanuc._WORK_OFFSETS,
)

# ---------------------------------------------------------------------------------------------
# G and M codes: the FANUC mill's, M98 reading P as the whole program number


G_CODES: tuple[CodeDoc, ...] = fanuc.G_CODES
# not FANUC's M29 row (its parameter 5210): no source at hand gives this control's tapping M code
M_CODES: tuple[CodeDoc, ...] = with_m98_count_in_l(tuple(c for c in fanuc.M_CODES if c.code != "M29"))
