"""What each drilling canned cycle of a mill does between its R point and its hole bottom: the
control's data for the cycle time (docs/semantics.md §9 "Canned cycles").

Every drilling cycle positions the hole at rapid at the level it is at, rapids down to the R
point, cuts to Z and returns (G98 to the initial level, G99 to R); a ``DrillCycle`` says how it
cuts, what it does at the bottom and how it comes out. ``planner/drill_cycles.py`` turns one
into the moves of a hole and ``planner/cycle_time.py`` times them.

FANUC's table (Series 0i-MF / 30i-B operator's manuals, "Canned cycle for drilling", the table of
drilling, operation at the bottom and retraction of each code, and each cycle's page):

* G73 high-speed peck: intermittent feed, pecks of Q, each followed by a rapid retract of d
  (parameter 5114); rapid out.
* G74 left-hand tapping, G84 tapping: feed in, dwell P, spindle reverses, feed out to R, dwell P
  again at R, where the spindle turns back (``DrillCycle.dwell_at_r``; FANUC's tapping format:
  "P_ : Dwell time at the bottom of the hole and at point R when a return is made").
* G76 fine boring: feed in, dwell P, oriented spindle stop, shift by Q away from the wall,
  rapid out, shift back.
* G81 drilling, G86 boring (spindle stop): feed in, rapid out.
* G82 counter boring: feed in, dwell P, rapid out.
* G83 peck drilling: pecks of Q, back to R at rapid after each and rapid down to d above the
  last depth (parameter 5115); rapid out.
* G85 boring: feed in, feed out to R. G89 boring: the same with a dwell P at the bottom.
* G87 back boring: orient and shift, rapid down to the R point below the work, shift back, bore
  upwards to Z, dwell P, orient and shift, rapid out to the initial level (G99 is not used),
  shift back.
* G88 boring: feed in, dwell P, spindle stop, then the operator retracts by hand; the manual
  retract is counted as a rapid.

Haas (Mill Operator's Manual 96-8000, G codes) runs G73, G74, G76, G81–G86, G88 and G89 the same
way; its G87 is "bore in and manual retract" (G88 without the dwell) and its G77 the back bore.
Its taps dwell at the bottom only: no Haas source at hand has the dwell at R (to confirm).
"""

from __future__ import annotations

from dataclasses import dataclass

FEED = "feed"  # one cutting feed from R to Z
PECK = "peck"  # G83: pecks of Q, back to R after each
SHORT_PECK = "short-peck"  # G73: pecks of Q, a retract of d after each


@dataclass(frozen=True)
class DrillCycle:
    """How one drilling cycle cuts (``FEED``, ``PECK``, ``SHORT_PECK``), whether it dwells P at
    the bottom, comes out at F to R (tapping and feed-out boring), shifts by Q at the bottom
    before a rapid out (fine boring) or bores upwards from an R point below the work (back
    boring, which always returns to the initial level). ``dwell_at_r``: a tap dwells P again at
    the R point on the way out, where the spindle turns back (FANUC)."""

    cut: str = FEED
    dwell: bool = False
    feed_out: bool = False
    shift: bool = False
    back: bool = False
    dwell_at_r: bool = False

    @property
    def dwells(self) -> int:
        """How many times a hole dwells P: at the bottom, and again at R where ``dwell_at_r``."""
        return int(self.dwell) + int(self.dwell_at_r)


# a canned code the table does not list drills as G81 does
PLAIN_DRILLING = DrillCycle()

FANUC_DRILL_CYCLES: dict[float, DrillCycle] = {
    73.0: DrillCycle(cut=SHORT_PECK),
    74.0: DrillCycle(dwell=True, feed_out=True, dwell_at_r=True),
    76.0: DrillCycle(dwell=True, shift=True),
    81.0: PLAIN_DRILLING,
    82.0: DrillCycle(dwell=True),
    83.0: DrillCycle(cut=PECK),
    84.0: DrillCycle(dwell=True, feed_out=True, dwell_at_r=True),
    85.0: DrillCycle(feed_out=True),
    86.0: PLAIN_DRILLING,
    87.0: DrillCycle(dwell=True, back=True),
    88.0: DrillCycle(dwell=True),
    89.0: DrillCycle(dwell=True, feed_out=True),
}

# FANUC's table with the taps dwelling at the bottom only, where no source at hand has the dwell at
# R (Haas, Mitsubishi, Mazak)
TAPS_DWELL_AT_BOTTOM: dict[float, DrillCycle] = {
    **FANUC_DRILL_CYCLES,
    74.0: DrillCycle(dwell=True, feed_out=True),
    84.0: DrillCycle(dwell=True, feed_out=True),
}

HAAS_DRILL_CYCLES: dict[float, DrillCycle] = {
    **TAPS_DWELL_AT_BOTTOM,
    73.0: DrillCycle(cut=SHORT_PECK, dwell=True),  # P: a pause at the bottom after the last peck
    83.0: DrillCycle(cut=PECK, dwell=True),
    77.0: DrillCycle(back=True),
    87.0: PLAIN_DRILLING,  # bore in, manual retract
}


@dataclass(frozen=True)
class LatheDrill:
    """A lathe's drilling cycle: the axis it drills along (Z on the face, X on the side), how it
    cuts there (``DrillCycle``), and whether its F is the tap's lead (per revolution, whatever
    G98/G99 says, I threads per inch: GSK980TDi §3.24.6, "F（I）：螺纹的导程")."""

    axis: str
    cycle: DrillCycle
    lead: bool = False


@dataclass(frozen=True)
class LatheDrilling:
    """A lathe control's drilling cycles (docs/semantics.md §10.3, ``planner/lathe_drilling.py``):
    ``cycles`` by G code; ``r_point``: whether R is the distance from the initial level to the R
    point the cut starts from (FANUC), or the retract after each peck, the cut starting where the
    tool stands (GSK, whose J1 retracts to the start after each peck instead, and whose R is 1 mm
    when left out: ``default_retract``)."""

    cycles: dict[float, LatheDrill]
    r_point: bool = True
    default_retract: float = 0.0


# FANUC 0i-TF (G-code system A), "canned cycle for drilling": G83/G87 drilling, in pecks of Q where
# Q is given (high-speed pecks, parameter 5101#2 RTR = 0, retract d: parameter 5114), G84/G88
# tapping, G85/G89 boring; face cycles along Z, side cycles along X; P dwells at the bottom, and a
# tap's again at the R point on its way out (FANUC 16i/18i/21i-TA/TB, G84/G88: "P_ : Dwell time at
# the bottom of the hole and at point R when a return is made")
FANUC_LATHE_DRILLING = LatheDrilling(
    {
        83.0: LatheDrill("Z", DrillCycle(cut=SHORT_PECK, dwell=True)),
        84.0: LatheDrill("Z", DrillCycle(dwell=True, feed_out=True, dwell_at_r=True)),
        85.0: LatheDrill("Z", DrillCycle(feed_out=True)),
        87.0: LatheDrill("X", DrillCycle(cut=SHORT_PECK, dwell=True)),
        88.0: LatheDrill("X", DrillCycle(dwell=True, feed_out=True, dwell_at_r=True)),
        89.0: LatheDrill("X", DrillCycle(dwell=True, feed_out=True)),
    }
)
# GSK980TDi §3.23.9 (G83, G87) and §3.24.6 (G84, G88): pecks of Q with a retract of R (J0) or back
# to the start after each (J1), from where the tool stands and back there; the rigid taps' F is the
# lead (their Q, R, J pecking forms are not read: the tap goes in and out at once)
GSK_LATHE_DRILLING = LatheDrilling(
    {
        83.0: LatheDrill("Z", DrillCycle(cut=SHORT_PECK, dwell=True)),
        84.0: LatheDrill("Z", DrillCycle(dwell=True, feed_out=True), lead=True),
        87.0: LatheDrill("X", DrillCycle(cut=SHORT_PECK, dwell=True)),
        88.0: LatheDrill("X", DrillCycle(dwell=True, feed_out=True), lead=True),
    },
    r_point=False,
    default_retract=1.0,
)
