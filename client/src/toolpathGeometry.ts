/**
 * The geometry of a toolpath plot: the result of `cncmacro run --json` read and checked, the
 * plane it is drawn in, each move turned into SVG path data in that plane, the extents, and
 * grid lines at round numbers. What each move is comes from the run: its `kind` (rapid, feed,
 * arc, probe, cycle), an arc's `plane`, `centre` and direction, a cycle's `legs`, a drilled
 * `hole`, the cycle a lathe pass belongs to (`pass_of`) and, under cutter radius compensation,
 * where the tool's centre goes (`tool_path`: drawn beside the programmed path, as the run gives
 * it: its pieces straight or arcs about their centres). Nothing here knows a G code, and
 * nothing here knows VS Code; the webview's page is built from what it returns.
 *
 * A mill is drawn in XY, ZX or YZ. A lathe (the run says so: `lathe` and `lathe_axes`, from
 * its profile) is drawn to scale with its spindle axis across and its radial axis up, the
 * spindle's centre line (radial 0) marked; a radial axis programmed as a diameter is drawn at
 * half its value, the radius, so that arcs stay round, and its scale reads radii or diameters
 * as the user picks. The other half of the part, mirrored about the centre line, can be drawn
 * too.
 */

export type Axes = Record<string, number>;

export type MoveKind = 'rapid' | 'feed' | 'arc' | 'cycle' | 'probe';
const MOVE_KINDS: readonly string[] = ['rapid', 'feed', 'arc', 'cycle', 'probe'];

/** One leg of a cycle, as the run gives it: at rapid or at the feed, to a point. */
export interface RunLeg {
  rapid: boolean;
  to: Axes;
}

/** One piece of a move's tool-centre path (`tool_path`): straight to `to`, or an arc about `centre`. */
export interface RunCentrePiece {
  to: Axes;
  centre?: Axes;
  clockwise?: boolean;
}

/** Where the tool's centre goes during a move under cutter radius compensation: from `from`, piece by piece. */
export interface RunToolPath {
  from: Axes;
  pieces: RunCentrePiece[];
}

export interface RunMove {
  file: string;
  line: number;
  mode: string;
  kind: MoveKind;
  from: Axes;
  to: Axes;
  feed: number;
  centre?: Axes;
  /** an arc's: the two axes it turns in, G03 turning from the first toward the second */
  plane?: [string, string];
  clockwise?: boolean;
  /** a cycle's path, leg by leg from `from` */
  legs?: RunLeg[];
  /** a drilling cycle's hole (its bottom) */
  hole?: Axes;
  /** a G31's: whether the skip signal came on where it stopped (its `to`: the contact point) */
  skip?: boolean;
  /** which end is at a place the run does not know (`start`, `end`, `both`): the move is not drawn,
   * nor counted in the extents (docs/semantics.md §8) */
  unknown?: string;
  /** a lathe cycle's pass: the cycle it belongs to, as the run names it */
  passOf?: string;
  /** under cutter radius compensation: where the tool's centre goes */
  toolPath?: RunToolPath;
}

/** A lathe's axes as the run names them: the spindle's (drawn across), the radial one (drawn
 * up, its 0 the spindle's centre line) and whether the radial axis is programmed as a diameter. */
export interface LatheAxes {
  spindle: string;
  radial: string;
  diameter: boolean;
}

export interface RunAlarm {
  number: number;
  message: string;
  file: string;
  line: number;
}

export interface RunResult {
  status: string;
  alarm: RunAlarm | null;
  blocks: number;
  moves: RunMove[];
  dialect?: string;
  /** whether the run's profile is a lathe, as `cncmacro run --json` says */
  lathe?: boolean;
  /** a lathe's axes, as `cncmacro run --json` says (`lathe_axes`) */
  latheAxes?: LatheAxes;
  /** the cycle time and path of the run, as `cncmacro run --json` writes them (`cycle.text`) */
  cycleText?: string;
}

export type Plane = 'XY' | 'ZX' | 'YZ';
export const PLANES: readonly Plane[] = ['XY', 'ZX', 'YZ'];

/** What the radial scale of a lathe reads: the radius (the drawing's own units) or the diameter. */
export type RadialScale = 'radius' | 'diameter';
export const RADIAL_SCALES: readonly RadialScale[] = ['radius', 'diameter'];

/** How a lathe is drawn: its axes, what the radial scale reads, and whether the mirrored half is drawn. */
export interface LatheView extends LatheAxes {
  scale: RadialScale;
  bothHalves: boolean;
}

/** How the run is drawn: the horizontal and vertical axes, and a lathe's view when it is one. */
export interface View {
  plane: Plane | 'lathe';
  h: string;
  v: string;
  lathe?: LatheView;
}

/** One leg of a move: SVG path data in screen units, dashed for the rapid part of a cycle. */
export interface Leg {
  d: string;
  dashed: boolean;
}

export interface DrawnMove {
  index: number;
  kind: MoveKind;
  legs: Leg[];
  /** a hole of a drilling cycle: where the marker goes, in screen units */
  hole?: [number, number];
  /** where a G31 stopped with the skip signal on (the contact point), in screen units */
  contact?: [number, number];
  /** the tool centre's path under cutter radius compensation: SVG path data in screen units */
  centre?: string;
}

export interface Tick {
  value: number;
  at: number; // screen units
}

export interface Plot {
  width: number; // screen units of the drawing, margins excluded
  height: number;
  moves: DrawnMove[];
  origin: [number, number];
  end?: [number, number]; // where the tool stopped (marked when the run ended in an alarm)
  xTicks: Tick[];
  yTicks: Tick[];
  holeRadius: number;
  /** the extents of the moves in program units, per axis X, Y, Z (X as written: a diameter on a lathe) */
  extents: { axis: string; min: number; max: number }[];
  /** a lathe's spindle centre line (radial 0): its screen y, drawn across the whole width */
  spindle?: number;
  /** a lathe drawn with both halves: the screen y about which the moves are mirrored (the centre line) */
  mirror?: number;
}

const isNumber = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);

function axesOf(v: unknown): Axes | undefined {
  if (v === null || typeof v !== 'object' || Array.isArray(v)) return undefined;
  const out: Axes = {};
  for (const [k, x] of Object.entries(v as Record<string, unknown>)) {
    if (!isNumber(x)) return undefined;
    out[k] = x;
  }
  return out;
}

/** The run's JSON, checked field by field; a string says what is wrong with it. */
export function parseRunResult(text: string): RunResult | string {
  let raw: unknown;
  try {
    raw = JSON.parse(text);
  } catch (e) {
    return `the run did not print JSON: ${(e as Error).message}`;
  }
  if (raw === null || typeof raw !== 'object') return 'the run printed no result object';
  const r = raw as Record<string, unknown>;
  if (typeof r.status !== 'string' || !Array.isArray(r.moves)) return 'the run result has no status or moves';
  const moves: RunMove[] = [];
  for (const m of r.moves as unknown[]) {
    const o = (m ?? {}) as Record<string, unknown>;
    const from = axesOf(o.from);
    const to = axesOf(o.to);
    if (typeof o.file !== 'string' || !isNumber(o.line) || typeof o.mode !== 'string' || !from || !to) {
      return `a move of the run is malformed: ${JSON.stringify(m).slice(0, 200)}`;
    }
    if (typeof o.kind !== 'string' || !MOVE_KINDS.includes(o.kind)) {
      return `a move of the run has no kind: ${JSON.stringify(m).slice(0, 200)}`;
    }
    const kind = o.kind as MoveKind;
    const move: RunMove = { file: o.file, line: o.line, mode: o.mode, kind, from, to, feed: isNumber(o.feed) ? o.feed : 0 };
    const centre = axesOf(o.centre);
    if (centre) move.centre = centre;
    if (Array.isArray(o.plane) && o.plane.length === 2) {
      const [a, b] = o.plane as unknown[];
      if (typeof a === 'string' && typeof b === 'string') move.plane = [a, b];
    }
    if (typeof o.clockwise === 'boolean') move.clockwise = o.clockwise;
    if (Array.isArray(o.legs)) {
      const legs: RunLeg[] = [];
      for (const l of o.legs as unknown[]) {
        const leg = (l ?? {}) as Record<string, unknown>;
        const at = axesOf(leg.to);
        if (typeof leg.rapid !== 'boolean' || !at) return `a leg of a cycle is malformed: ${JSON.stringify(l).slice(0, 200)}`;
        legs.push({ rapid: leg.rapid, to: at });
      }
      move.legs = legs;
    }
    const hole = axesOf(o.hole);
    if (hole) move.hole = hole;
    if (typeof o.skip === 'boolean') move.skip = o.skip;
    if (typeof o.pass_of === 'string') move.passOf = o.pass_of;
    if (typeof o.unknown === 'string') move.unknown = o.unknown;
    if (o.tool_path !== undefined) {
      const toolPath = parseToolPath(o.tool_path);
      if (!toolPath) return `the tool centre path of a move is malformed: ${JSON.stringify(o.tool_path).slice(0, 200)}`;
      move.toolPath = toolPath;
    }
    moves.push(move);
  }
  let alarm: RunAlarm | null = null;
  if (r.alarm !== null && typeof r.alarm === 'object') {
    const a = r.alarm as Record<string, unknown>;
    alarm = {
      number: isNumber(a.number) ? a.number : 0,
      message: typeof a.message === 'string' ? a.message : '',
      file: typeof a.file === 'string' ? a.file : '',
      line: isNumber(a.line) ? a.line : 0,
    };
  }
  const result: RunResult = { status: r.status, alarm, blocks: isNumber(r.blocks) ? r.blocks : 0, moves };
  if (typeof r.dialect === 'string') result.dialect = r.dialect;
  if (typeof r.lathe === 'boolean') result.lathe = r.lathe;
  const axes = parseLatheAxes(r.lathe_axes);
  if (axes) result.latheAxes = axes;
  const cycle = r.cycle as Record<string, unknown> | null | undefined;
  if (cycle && typeof cycle === 'object' && typeof cycle.text === 'string') result.cycleText = cycle.text;
  return result;
}

/** A lathe's axes as the run sends them (`lathe_axes`); undefined when absent or malformed. */
/** A move's `tool_path`, checked; undefined when it is malformed. */
function parseToolPath(raw: unknown): RunToolPath | undefined {
  if (raw === null || typeof raw !== 'object') return undefined;
  const t = raw as Record<string, unknown>;
  const from = axesOf(t.from);
  if (!from || !Array.isArray(t.pieces)) return undefined;
  const pieces: RunCentrePiece[] = [];
  for (const p of t.pieces as unknown[]) {
    const piece = (p ?? {}) as Record<string, unknown>;
    const to = axesOf(piece.to);
    if (!to) return undefined;
    const drawn: RunCentrePiece = { to };
    const centre = axesOf(piece.centre);
    if (centre) drawn.centre = centre;
    if (typeof piece.clockwise === 'boolean') drawn.clockwise = piece.clockwise;
    pieces.push(drawn);
  }
  return { from, pieces };
}

export function parseLatheAxes(raw: unknown): LatheAxes | undefined {
  if (raw === null || typeof raw !== 'object') return undefined;
  const a = raw as Record<string, unknown>;
  if (typeof a.spindle !== 'string' || typeof a.radial !== 'string' || typeof a.diameter !== 'boolean') return undefined;
  if (a.spindle === a.radial) return undefined;
  return { spindle: a.spindle, radial: a.radial, diameter: a.diameter };
}

/** The lathe's axes when the machine that ran is a lathe, as the run says (`lathe` and `lathe_axes`, from its profile). */
export function latheAxesOf(result: { lathe?: boolean; latheAxes?: LatheAxes }): LatheAxes | undefined {
  return result.lathe === true ? result.latheAxes : undefined;
}

/** The view of a run: a lathe's (its spindle axis across, its radial axis up) or a mill's in `plane`. */
export function viewFor(
  lathe: LatheAxes | undefined,
  plane: Plane = 'XY',
  options: { scale?: RadialScale; bothHalves?: boolean } = {},
): View {
  if (lathe) {
    const view: LatheView = { ...lathe, scale: options.scale ?? 'diameter', bothHalves: options.bothHalves ?? false };
    return { plane: 'lathe', h: lathe.spindle, v: lathe.radial, lathe: view };
  }
  const [h, v] = plane === 'XY' ? ['X', 'Y'] : plane === 'ZX' ? ['Z', 'X'] : ['Y', 'Z'];
  return { plane, h, v };
}

/** What one unit drawn up reads on a lathe's radial scale: 2 when it reads diameters, else 1. */
export function radialFactor(view: View): number {
  return view.lathe?.scale === 'diameter' ? 2 : 1;
}

type P3 = Axes;

/** A point as drawn: on a lathe whose radial axis is a diameter, that axis halved (the radius). */
function display(p: Axes, view: View): P3 {
  const lathe = view.lathe;
  if (!lathe?.diameter || !(lathe.radial in p)) return p;
  return { ...p, [lathe.radial]: (p[lathe.radial] ?? 0) / 2 };
}

interface Arc {
  a: string; // the arc plane's axes
  b: string;
  ca: number; // centre
  cb: number;
  r: number;
  start: number; // angle of the start point, radians
  sweep: number; // signed: positive counter-clockwise (G03)
}

const get = (p: Axes, k: string): number => p[k] ?? 0;

/**
 * The arc a move makes, from its `centre` and the `plane` the run gives (on a lathe X is a
 * diameter, like the end points; the axes off the plane keep the start's values). None without
 * a centre or a plane, or when the start lies on the centre: drawn as a chord.
 */
function arcOf(move: RunMove, view: View): Arc | undefined {
  if (!move.centre || !move.plane) return undefined;
  const [a, b] = move.plane;
  const c = display(move.centre, view);
  const s = display(move.from, view);
  const e = display(move.to, view);
  const ca = get(c, a);
  const cb = get(c, b);
  const rs = Math.hypot(get(s, a) - ca, get(s, b) - cb);
  const re = Math.hypot(get(e, a) - ca, get(e, b) - cb);
  // a centre the end is not as far from as the start (beyond rounding) draws no arc: a chord
  if (rs < 1e-9 || Math.abs(rs - re) > Math.max(0.005, rs * 0.005)) return undefined;
  const t0 = Math.atan2(get(s, b) - cb, get(s, a) - ca);
  const t1 = Math.atan2(get(e, b) - cb, get(e, a) - ca);
  const ccw = move.clockwise !== true;
  const twoPi = 2 * Math.PI;
  let sweep = ccw ? (t1 - t0 + twoPi) % twoPi : (t0 - t1 + twoPi) % twoPi;
  if (sweep < 1e-9) sweep = twoPi; // the end is the start: a full circle
  return { a, b, ca, cb, r: (rs + re) / 2, start: t0, sweep: ccw ? sweep : -sweep };
}

/** Points along an arc (in display units, every axis: the others move linearly, as in a helix). */
function arcPoints(move: RunMove, arc: Arc, view: View, steps: number): P3[] {
  const s = display(move.from, view);
  const e = display(move.to, view);
  const out: P3[] = [];
  for (let i = 0; i <= steps; i++) {
    const f = i / steps;
    const p: P3 = {};
    for (const k of new Set([...Object.keys(s), ...Object.keys(e)])) p[k] = get(s, k) + (get(e, k) - get(s, k)) * f;
    const t = arc.start + arc.sweep * f;
    p[arc.a] = arc.ca + arc.r * Math.cos(t);
    p[arc.b] = arc.cb + arc.r * Math.sin(t);
    out.push(p);
  }
  out[0] = s;
  out[steps] = e;
  return out;
}

/** The 3-D legs of a move (before projection), each with whether it is a rapid leg. */
function legsOf(move: RunMove, view: View): { points: P3[]; dashed: boolean }[] {
  const s = display(move.from, view);
  const e = display(move.to, view);
  if (move.kind === 'arc') {
    const arc = arcOf(move, view);
    if (arc) {
      const steps = Math.max(8, Math.ceil((Math.abs(arc.sweep) / (2 * Math.PI)) * 96));
      return [{ points: arcPoints(move, arc, view, steps), dashed: false }];
    }
    return [{ points: [s, e], dashed: false }];
  }
  if (move.legs && move.legs.length > 0) {
    let at = s;
    return move.legs.map((leg) => {
      const to = display(leg.to, view);
      const drawn = { points: [at, to], dashed: leg.rapid };
      at = to;
      return drawn;
    });
  }
  return [{ points: [s, e], dashed: move.kind === 'rapid' }];
}

/** The points of a move's tool-centre path (before projection), an arc piece sampled as the
 * move's own arc is, in the move's plane; none without compensation. */
function centreOf(move: RunMove, view: View): P3[] | undefined {
  const tp = move.toolPath;
  if (!tp) return undefined;
  const points: P3[] = [display(tp.from, view)];
  let from = tp.from;
  for (const piece of tp.pieces) {
    const arc = piece.centre
      ? legsOf({ ...move, kind: 'arc', from, to: piece.to, centre: piece.centre, clockwise: piece.clockwise === true,
                 legs: undefined }, view)[0]
      : undefined;
    if (arc) points.push(...arc.points.slice(1));
    else points.push(display(piece.to, view));
    from = piece.to;
  }
  return points;
}

/** A round step (1, 2 or 5 times a power of ten) that cuts `span` into about `count` parts. */
export function niceStep(span: number, count: number): number {
  const raw = span / count;
  if (!(raw > 0)) return 1;
  const power = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw * (1 - 1e-9)) ?? 10 * power;
}

/** The multiples of `step` in [lo, hi]. */
export function ticksBetween(lo: number, hi: number, step: number): number[] {
  const out: number[] = [];
  for (let i = Math.ceil(lo / step - 1e-9); i * step <= hi + step * 1e-9; i++) {
    out.push(Number((i * step).toPrecision(12)) || 0);
  }
  return out;
}

/** A number as a machinist writes it: up to three decimals, no trailing zeros. */
export function formatNumber(n: number): string {
  const s = n.toFixed(3).replace(/\.?0+$/, '');
  return s === '-0' ? '0' : s;
}

/** The plot of `moves` in `view`, `size` screen units across the longer side. */
export function plot(moves: RunMove[], view: View, ended: boolean, size = 1000): Plot {
  // a move from or to a place the run does not know is drawn not (the line would cross the part)
  const legs = moves.map((m) => (m.unknown ? [] : legsOf(m, view)));
  const centres = moves.map((m) => (m.unknown ? undefined : centreOf(m, view)));
  const mirrored = view.lathe?.bothHalves === true; // the other half: every point at minus its radial value
  const project = (p: P3): [number, number] => [get(p, view.h), get(p, view.v)];
  let x0 = 0;
  let x1 = 0;
  let y0 = 0;
  let y1 = 0; // the origin is always in the picture
  const everyPoint = [...legs.map((move) => move.map((leg) => leg.points)), centres.map((c) => c ?? [])];
  for (const move of everyPoint) {
    for (const points of move) {
      for (const p of points) {
        const [x, y] = project(p);
        x0 = Math.min(x0, x);
        x1 = Math.max(x1, x);
        y0 = Math.min(y0, y, mirrored ? -y : y);
        y1 = Math.max(y1, y, mirrored ? -y : y);
      }
    }
  }
  if (x1 - x0 === 0 && y1 - y0 === 0) {
    // no move left the origin (an alarm before the first one): a 10 x 10 picture around it
    x0 = y0 = -5;
    x1 = y1 = 5;
  }
  let w = x1 - x0;
  let h = y1 - y0;
  const span = Math.max(w, h, 1e-3);
  // a flat picture (all moves on one line) still gets some room across
  if (w < span * 0.05) {
    x0 -= (span * 0.05 - w) / 2;
    w = span * 0.05;
  }
  if (h < span * 0.05) {
    y0 -= (span * 0.05 - h) / 2;
    h = span * 0.05;
  }
  const pad = span * 0.04;
  x0 -= pad;
  y0 -= pad;
  w += 2 * pad;
  h += 2 * pad;
  const k = size / Math.max(w, h);
  const sx = (x: number): number => (x - x0) * k;
  const sy = (y: number): number => (y0 + h - y) * k; // screen y grows downward
  const r2 = (n: number): string => (Math.round(n * 100) / 100).toString();
  const pt = (p: P3): string => {
    const [x, y] = project(p);
    return `${r2(sx(x))} ${r2(sy(y))}`;
  };
  const drawn: DrawnMove[] = moves.map((move, index) => {
    const kind = move.kind;
    const arc = kind === 'arc' ? arcOf(move, view) : undefined;
    let out: Leg[];
    if (arc && arc.a === planeAxes(view)[0] && arc.b === planeAxes(view)[1]) {
      out = [{ d: svgArc(move, arc, view, pt, k), dashed: false }];
    } else {
      out = (legs[index] ?? []).map((leg) => ({
        d: leg.points.map((p, i) => `${i === 0 ? 'M' : 'L'}${pt(p)}`).join(' '),
        dashed: leg.dashed,
      }));
    }
    const d: DrawnMove = { index, kind, legs: out };
    if (move.hole) {
      const [x, y] = project(display(move.hole, view));
      d.hole = [sx(x), sy(y)];
    }
    if (kind === 'probe' && move.skip === true) {
      const [x, y] = project(display(move.to, view));
      d.contact = [sx(x), sy(y)];
    }
    const centre = centres[index];
    if (centre) d.centre = centre.map((p, i) => `${i === 0 ? 'M' : 'L'}${pt(p)}`).join(' ');
    return d;
  });
  const step = niceStep(Math.max(w, h), 8); // one step on both axes: the scales are equal
  // a lathe's radial scale reading diameters labels each line at twice its radius (square cells still)
  const f = radialFactor(view);
  const ticks = (lo: number, hi: number, at: (v: number) => number, factor = 1): Tick[] =>
    ticksBetween(lo * factor, hi * factor, step * factor).map((value) => ({ value, at: at(value / factor) }));
  const last = moves[moves.length - 1];
  const extents = ['X', 'Y', 'Z'].flatMap((axis) => {
    let min = Infinity;
    let max = -Infinity;
    for (const m of moves) {
      if (m.unknown) continue;
      for (const p of [m.from, m.to]) {
        if (!(axis in p)) continue;
        min = Math.min(min, get(p, axis));
        max = Math.max(max, get(p, axis));
      }
    }
    // an axis the program never used (a lathe's Y) is left out
    return min <= max && (min !== 0 || max !== 0) ? [{ axis, min, max }] : [];
  });
  const result: Plot = {
    width: w * k,
    height: h * k,
    moves: drawn,
    origin: [sx(0), sy(0)],
    xTicks: ticks(x0, x0 + w, sx),
    yTicks: ticks(y0, y0 + h, sy, f),
    holeRadius: Math.max(3, Math.min(10, size * 0.006)),
    extents,
  };
  if (view.lathe) result.spindle = sy(0);
  if (mirrored) result.mirror = sy(0);
  if (ended && last) {
    const [x, y] = project(display(last.to, view));
    result.end = [sx(x), sy(y)];
  }
  return result;
}

/** The arc plane's axes in the order that makes G03 counter-clockwise on the screen. */
function planeAxes(view: View): [string, string] {
  return [view.h, view.v];
}

/**
 * An arc drawn in its own plane, as SVG arc commands. With screen y downward, sweep-flag 1
 * turns clockwise on the screen: G02 seen from the plane's third axis (G17 XY, G18 ZX with X
 * up, G19 YZ). A full circle is drawn as two halves.
 */
function svgArc(move: RunMove, arc: Arc, view: View, pt: (p: P3) => string, k: number): string {
  const s = display(move.from, view);
  const r = Math.round(arc.r * k * 100) / 100;
  const clockwise = arc.sweep < 0 ? 1 : 0;
  const parts = [`M${pt(s)}`];
  const sweeps = Math.abs(arc.sweep) > Math.PI * 1.999 ? [arc.sweep / 2, arc.sweep] : [arc.sweep];
  let done = 0;
  for (const until of sweeps) {
    const t = arc.start + until;
    const p: P3 = { [arc.a]: arc.ca + arc.r * Math.cos(t), [arc.b]: arc.cb + arc.r * Math.sin(t) };
    const large = Math.abs(until - done) > Math.PI ? 1 : 0;
    parts.push(`A${r} ${r} 0 ${large} ${clockwise} ${until === arc.sweep ? pt(display(move.to, view)) : pt(p)}`);
    done = until;
  }
  return parts.join(' ');
}
