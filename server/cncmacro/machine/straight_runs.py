"""Consecutive plain motion lines run in one pass, read and carried out together.

A CAM program is mostly lines like ``G01 X12.5 Y-3.`` one after another (``Block.plain``), one
in ten after a sequence number (``N10 G01 X5.``, ``Block.plain_tail``: the run sets the last
sequence number read, as the labelled block's runner does).
Compiling each into a runner and then calling it costs more than reading it: most run once.
``run_straight`` reads such a line's words and applies them in one loop over the lines, with
the machine's modal state, position and clock held in locals, until a line that is not
plain motion, a line the general path must decide (a canned cycle in force, G93 inverse time
feed, a G code of a group with side effects, an address with its own rounding), or the block budget. It does
exactly what ``PlainWords.text_plan`` and ``Planner.run_plain`` (planner/) do for one line (docs/semantics.md
§8), an arc's centre from its R, I, J, K words included, and a line it declines is left
untouched for the compiled path: so is an arc the control finds fault with (planner/arc_checks.py).
Both run loops use it for a line not compiled yet, when no modal call (G66) is in force; such a
line stays uncompiled, which also spares an analysis the memory of a runner per line.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ..planner.alarms import MacroAlarm
from ..planner.angled_moves import PENDING_ANGLE
from ..planner.arcs import ARC_MODES
from ..planner.cutter_stage import StraightCuts
from ..planner.cycle_time import INCH, INVERSE_TIME, SPEED_CLAMP
from ..planner.machine_limits import Bounds, leaves_travel, outside, program_bounds
from ..planner.missing_feed import missing_feed
from ..planner.moves import Move
from ..planner.plain_words import NOT_PLAIN, PLAIN_ARC_LETTERS, PLAIN_F, PLAIN_G, PLAIN_INCREMENTAL, PLAIN_S
from ..planner.planner import FEED_HINT_GIVEN
from ..planner.turning_cycles import forget_single_cycle
from ..planner.virtual_planes import CYLINDER, VIRTUAL_PLANE
from ..planner.whereabouts import astray

if TYPE_CHECKING:
    from collections.abc import Sequence

    from ..planner.planner import Planner
    from ..syntax.nodes import Block
    from .blocks import CompiledFile
    from .machine import Machine
    from .observer import RunObserver

_new_move = tuple.__new__


def run_straight(
    m: Machine,
    cf: CompiledFile,
    pc: int,
    budget: int,
    tracked: tuple[RunObserver, list[int]] | None = None,
    step: int = 0,
) -> tuple[int, int]:
    """Run at most ``budget`` plain motion lines of ``cf`` from line ``pc``; returns how many
    ran and the line to run next (``pc`` itself when the first line is declined). With
    ``tracked`` (a run with an observer, see tracking.py: the observer and the per-line stamps
    of ``cf``'s file), each line run is stamped there as ``run_tracked`` stamps it, ``step``
    being the number of blocks run before ``pc``."""
    program = cf.file.program
    blocks = program.blocks
    if pc >= len(blocks) or blocks[pc].plain_text is None:  # not a plain line: nothing to set up
        return 0, pc
    n_blocks = program.read_end  # nothing from the closing '%' on
    p = m.planner
    kinds = p.plain.kinds()
    if pc >= n_blocks or not kinds or p.shape is not None:  # a lathe cycle's shape: the compiled path reads it
        return 0, pc
    if PENDING_ANGLE in p.codes:  # after ",A1" alone: the general path ends FANUC's two-block form
        return 0, pc
    if p.corner is not None:  # a chamfer or rounding waits for this move: the general path cuts it
        return 0, pc  # (planner/corner_stage.py)
    if CYLINDER in p.modal:  # a cut on a cylinder: the general path takes C on its surface (virtual_planes.py)
        return 0, pc
    if p.vector_before is not None:  # the tool vector changed: the general path times the machine's travel
        return 0, pc  # (planner/offset_travel.py)
    if p.whereabouts.lost:  # a G30 left an axis unknown: the general path finds its next absolute move
        return 0, pc  # (planner/whereabouts.py)
    # the drawn axes astray (never named since the start, or at a point whose offsets are not
    # given): a line that moves one is the general path's, which marks its move as from an unknown
    # place; and the axes whose program position a G28/G53 gave: a line that names one absolutely
    # is the general path's too, which says the axis is where the program says (planner/whereabouts.py).
    # A line that moves only other axes runs here: its move is drawn as the general path draws it.
    wander = astray(p)
    homed = p.whereabouts.homed | wander if wander else p.whereabouts.homed
    if p.modal.get("feed") == INVERSE_TIME:  # G93: each cut's time is its block's F (missing_feed.py)
        return 0, pc
    g_words = p.plain.g_words()
    lathe = p.lathe
    drills = p.drills  # a canned drilling cycle in force: the compiled path drills its holes
    cycles = p.cycle_codes
    own_modes = p.own_path_modes  # a variable-lead thread, a three-point arc…: the compiled path
    feed_hint = p.feed_hint
    modal = p.modal
    codes = p.codes
    clock = p.clock
    cut = p.cut_length
    rapid = p.rapid_length
    times = p.times  # the cycle time's rules (cycle_time.py)
    dist = math.dist if times.scale is None else times.distance
    rapid_seconds = times.rapid_seconds
    append = p.moves.append if p.record_moves else None
    path = cf.file.path
    skipped = cf.skipped
    # The modal state every line reads, kept in locals and written back as lines change it.
    mode = modal["motion"]
    canned = modal["canned"]
    absolute = lathe or modal["distance"] == 90.0
    if tracked is not None:
        observer, trk = tracked
        serial, floor, first = observer.track_serial, observer.track_floor, observer.first_run
    else:
        trk = None
    per_rev = modal.get("feed") == 95.0 or (lathe and modal.get("feed") == 99.0)
    unit = INCH if modal.get("units") == 20.0 else 1.0
    css = modal.get("spindle") == 96.0
    plane = modal.get("plane", 17.0)
    f = codes.get("F") or 0.0
    # a straight cut's rate (``MoveTimes.straight_rate``: None under G96 on a lathe), worked
    # out again only when a line changes F, S or the modes it reads; a thread is timed by its lead
    threads = times.thread_modes
    rate = times.straight_rate(f, per_rev, codes.get("S") or 0.0, css, unit)
    # where the tool is (after the last line run) and where the line being read sends it: one
    # list, changed in place, that each line starts as ``start`` (a line declined is dropped)
    start = tuple(p.pos)
    target = list(start)
    # the machine file's [limits] (planner/machine_limits.py): the travel in program coordinates
    # under the offsets in force, which no plain line changes, and the spindle's top speed
    bounds = program_bounds(p) if p.travel is not None else None
    spindle_top = p.spindle_top
    arc_centre, arc_fault = p.arc_centre, p.arc_fault
    centre_alarm = p.dialect.arc_centre_alarm  # FANUC's PS0022 (planner/arc_checks.py)
    # cutter radius compensation under way (planner/cutter_stage.py): a straight cut after a
    # straight cut is joined by ``cuts``, which holds the last one until the next comes; any
    # other move goes through ``Planner.record`` (the held one handed back first)
    cutter = p.cutter
    cuts = StraightCuts(p, path, p.record_moves) if cutter is not None else None
    # the lines run are the lines passed but the blank and comment ones (``blanks``): the
    # budget counts the lines run, so each of those moves ``stop`` on by one
    first_pc = pc
    blanks = 0
    stop = min(n_blocks, pc + budget)
    while pc < stop:
        block = blocks[pc]
        text = block.plain
        label = None
        if text is None:
            text = block.plain_tail  # a plain line after a sequence number (``N10 G01 X5.``)
            if text is None:
                if pc > first_pc and skipped(block):  # a blank or comment line between two plain ones
                    pc += 1
                    blanks += 1
                    stop = min(n_blocks, stop + 1)
                    continue
                break
            label = block.label  # (a lathe cycle's shape, which ends after its N(Q), is not run here)
        moved = False
        inc: list[tuple[int, float]] | None = None
        others: list[tuple[str, float]] | None = None
        new_mode: float | None = None
        feed: float | None = None
        speed: float | None = None
        arc: dict[str, float] | None = None  # R, I, J, K
        for word in text.split():
            kind = kinds[word[0]]
            if kind < PLAIN_INCREMENTAL:  # an axis
                moved = True
                if absolute:
                    if homed and kind in homed:
                        break
                    target[kind] = float(word[1:])
                else:
                    if wander and kind in wander:
                        break
                    target[kind] += float(word[1:])
            elif kind == PLAIN_G:
                group, v = g_words.get(word) or p.plain.g_word(word)
                if group == "motion":
                    new_mode = v
                    continue
                if not group:
                    break
                if group == "distance":
                    if moved:  # G90/G91 after an axis word still governs it: the general path
                        break
                    absolute = lathe or v == 90.0  # for the axis words after it (set again below)
                if others is None:
                    others = [(group, v)]
                else:
                    others.append((group, v))
            elif kind < PLAIN_G:  # an incremental letter (U, V, W): added after the absolute ones
                if wander and kind - PLAIN_INCREMENTAL in wander:
                    break
                moved = True
                if inc is None:
                    inc = [(kind - PLAIN_INCREMENTAL, float(word[1:]))]
                else:
                    inc.append((kind - PLAIN_INCREMENTAL, float(word[1:])))
            elif kind == PLAIN_F:
                feed = float(word[1:])
            elif kind == PLAIN_S:
                speed = float(word[1:])
                if speed % 1:
                    break
            elif kind == NOT_PLAIN:
                break
            elif arc is None:
                arc = {PLAIN_ARC_LETTERS[kind]: float(word[1:])}
            else:
                arc[PLAIN_ARC_LETTERS[kind]] = float(word[1:])
        else:
            if wander and moved and (inc is not None or tuple(target) == start):
                break  # a move that goes nowhere, at a place not known: the general path marks it (whereabouts.py)
            if others is not None and ("feed", INVERSE_TIME) in others:
                break  # G93 from here on: the compiled path times each cut by its block's F
            if cutter is not None and others is not None:
                break  # a modal code under compensation (a plane change is an alarm): the compiled path
            if arc is not None and not moved and (mode if new_mode is None else new_mode) in ARC_MODES:
                break  # I, J, K alone are a full circle, R alone no move: the compiled path decides
            line_mode = mode if new_mode is None else new_mode
            if moved and line_mode in own_modes:
                break
            line_f = f if feed is None else feed
            if (feed_hint and moved and line_mode != 0.0 and (others is not None or not per_rev)
                    and 0.0 < line_f < 1.0 and FEED_HINT_GIVEN not in codes):  # fmt: skip
                break  # a per-minute feed below 1: the compiled path looks at it (``feed_per_minute_hint``)
            # (a line that changes nothing the rate reads, at a rate above 0, has a feed: not asked)
            if moved and line_mode != 0.0 and (line_f <= 0.0 or not rate or others is not None or speed is not None
                                                or line_mode in threads) and missing_feed(
                p, line_f, others is not None or per_rev or line_mode in threads,
                (codes.get("S") or 0.0) if speed is None else speed,
            ):  # fmt: skip
                break  # no feed, or per revolution at S0: the compiled path says so (planner/missing_feed.py)
            if bounds is not None and moved:
                if others is None and inc is None and arc is None:  # the common line, checked here
                    out = False
                    for i, low, high, _ in bounds:
                        e = target[i]
                        if (e > high and e > start[i]) or (e < low and e < start[i]):
                            out = True
                            break
                else:
                    out = _leaves(p, bounds, others, line_mode, plane, start, target, inc, arc)
                if out:
                    break  # the move leaves the machine's travel: the compiled path stops it there with the alarm
            if speed is not None and spindle_top is not None and speed > spindle_top:
                break  # an S above the spindle's top speed: the compiled path says so
            centre = None
            if arc is None and moved and line_mode in ARC_MODES and centre_alarm:
                break  # an arc with no R, I, J, K: the general path's to judge (planner/arc_checks.py)
            if arc is not None and moved and line_mode in ARC_MODES:
                if VIRTUAL_PLANE in modal:
                    break  # an arc in polar or cylindrical interpolation: the general path's (virtual_planes.py)
                # the arc's centre in the plane this line leaves in force; an arc the control finds
                # fault with (``Planner.arc_fault``) is the general path's to report,
                # the line left untouched
                line_plane = plane
                if others is not None:
                    for group, g in others:
                        if group == "plane":
                            line_plane = g
                arc_end = target
                if inc is not None:
                    arc_end = list(target)
                    for i, v in inc:
                        arc_end[i] += v
                centre = arc_centre(line_mode, start, arc_end, arc, line_plane)
                if centre is not None and arc_fault(start, arc_end, centre, arc, line_plane) is not None:
                    break
            if new_mode is not None:
                if moved and new_mode in cycles:
                    break  # a cycle decides this line: the compiled path runs it
                if new_mode != mode:
                    mode = modal["motion"] = new_mode
                    if lathe and new_mode not in p.dialect.single_cycles:
                        forget_single_cycle(p)  # a single cycle's modal words (planner/turning_cycles.py)
                if canned != 80.0 and drills:
                    canned = modal["canned"] = 80.0
            elif moved and (mode in cycles or (canned != 80.0 and drills)):
                break
            if label is not None:
                codes["N"] = float(label)  # the last sequence number read, as a labelled block sets it
            if trk is not None:
                if trk[pc] < floor:
                    p.clock, p.cut_length, p.rapid_length = clock, cut, rapid  # what the observer reads
                    first(path, pc, step + pc - first_pc - blanks)
                trk[pc] = serial
            if others is not None:
                for group, g in others:
                    modal[group] = g
                absolute = lathe or modal["distance"] == 90.0
                per_rev = modal.get("feed") == 95.0 or (lathe and modal.get("feed") == 99.0)
                unit = INCH if modal.get("units") == 20.0 else 1.0
                css = modal.get("spindle") == 96.0
                plane = modal.get("plane", 17.0)
            if feed is not None:
                codes["F"] = feed
                f = feed or 0.0
            if speed is not None:
                codes["S"] = speed
            if others is not None or feed is not None or speed is not None:
                rate = times.straight_rate(f, per_rev, codes.get("S") or 0.0, css, unit)
            if moved:
                if inc is not None:
                    for i, v in inc:
                        target[i] += v
                end = tuple(target)
                if cutter is not None and cuts is not None:  # its record and centre path (planner/cutter_stage.py)
                    try:
                        if centre is not None or mode == 0.0:
                            joined = None
                        else:
                            send = cuts.send
                            joined = (
                                send((pc, mode, f, start, end))
                                if send is not None
                                else cuts.begin((pc, mode, f, start, end))
                            )
                        if joined is not None:  # joined to the cut before, whose time is put right
                            correction, seconds, change = joined
                            clock += correction
                            clock += seconds
                            cut += change
                        else:
                            p.clock, p.cut_length, p.rapid_length = clock, cut, rapid
                            cuts.flush()
                            p.record(path, pc, mode, start, end, centre)
                            clock, cut, rapid, cutter = p.clock, p.cut_length, p.rapid_length, p.cutter
                    except MacroAlarm:
                        break  # found before anything changed: the compiled path runs the line and stops on it
                    except BaseException:
                        cuts.flush()
                        raise
                    start = end
                    pc += 1
                    continue
                # the time and length of the move: ``Planner.record``'s rules, inline
                if mode == 0.0:
                    seconds = rapid_seconds(start, end, unit)
                    rapid += dist(start, end) * unit
                else:
                    if centre is None:
                        length = dist(start, end)
                    else:
                        length = times.arc_length(mode, plane, start, end, centre)
                    if rate is not None and mode not in threads:
                        seconds = length / rate * 60.0 if rate > 0.0 and length > 0.0 else 0.0
                    else:
                        seconds = times.feed_seconds(mode, length, f, per_rev, codes.get("S") or 0.0, css,
                                                     codes.get(SPEED_CLAMP), start, end, unit)  # fmt: skip
                    cut += length * unit
                clock += seconds
                if append is not None:
                    append(_new_move(Move, (path, pc, mode, start, end, f, centre, seconds, plane, None, None, None,
                                            None, None)))  # fmt: skip
                start = end
            pc += 1
            continue
        break  # a word the general path must read
    if cuts is not None:
        cuts.flush()
    done = pc - first_pc - blanks
    if done and p.plain.last_keys:
        _keep_last_words(p.plain.last_keys, codes, blocks, first_pc, pc)
    if done:  # stop on a line that does something, as ``CompiledFile.next_line`` does
        while pc < n_blocks and blocks[pc].plain is None and skipped(blocks[pc]):
            pc += 1
    if done:
        p.pos = list(start)
        p.whereabouts = p.whereabouts.leave_reference()  # a line run may have left a reference point
    p.clock = clock
    p.cut_length = cut
    p.rapid_length = rapid
    if append is not None and len(p.moves) >= p.move_budget:  # at most a budget of lines past the toolpath's
        p.moves_full(pc - 1)
    return done, pc


def _leaves(
    p: Planner,
    bounds: Bounds,
    others: list[tuple[str, float]] | None,
    mode: float,
    plane: float,
    start: tuple[float, ...],
    target: list[float],
    inc: list[tuple[int, float]] | None,
    arc: dict[str, float] | None,
) -> bool:
    """Whether a plain line's move from ``start`` to ``target`` (with its incremental words
    ``inc``, an arc's words ``arc``) leaves ``bounds``; a line that also sets modal codes (a unit
    or plane among them) is left to the compiled path, which checks it under those codes."""
    if others is not None:
        return True
    end = list(target)
    if inc is not None:
        for i, v in inc:
            end[i] += v
    if arc is not None and mode in ARC_MODES:
        centre = p.arc_centre(mode, start, end, arc)
        return leaves_travel(p, bounds, mode, plane, start, tuple(end), centre, None) is not None
    return outside(bounds, start, end)


def _keep_last_words(
    last_keys: dict[str, str], codes: dict[str, float | None], blocks: Sequence[Block], first: int, end: int
) -> None:
    """The last value of each letter the profile's address variables read, from the plain lines
    ``first``..``end`` just run (``Dialect.last_address_letters``): no macro statement runs
    between them, so only the last line to write a letter counts, as one pass after the run."""
    for pc in range(first, end):
        text = blocks[pc].plain_text
        if text is not None:
            for word in text.split():
                key = last_keys.get(word[0].upper())
                if key is not None:
                    codes[key] = float(word[1:])
