/**
 * The toolpath webview's page: one SVG drawing of a run's moves (a `<g class="move">` per move,
 * with a `<title>` naming its file, line and block, over grid lines with their coordinates, the
 * origin marked), a legend and a status line, under a strict Content-Security-Policy where the
 * one style sheet and the one script carry a nonce and nothing is loaded from anywhere. The
 * script posts `reveal` (a move was clicked), `refresh`, `plane` and, on a lathe, `radialScale`
 * (radius or diameter) and `bothHalves` to the extension, and zooms (mouse wheel) and pans (drag)
 * by changing the SVG's viewBox. The texts arrive translated.
 *
 * Under cutter radius compensation each move also has the tool centre's path (`DrawnMove.centre`),
 * drawn thin in a colour of its own beside the programmed path; the "Tool centre" button hides
 * and shows it, in the page alone (nothing is posted), and the page keeps that choice.
 *
 * A lathe's drawing has its spindle's centre line across it, dash-dotted, and, with both halves
 * on, every move again mirrored about that line, faint and not clickable.
 *
 * The grid labels and axis names keep their size and their distance from the drawing in screen
 * pixels, whatever the zoom: the script fits the drawing into the view with margins of so many
 * pixels around it, where they go, so that a short or narrow view does not cut them off or lay
 * them over one another. The status line wraps only between its items, never inside a number.
 *
 * While a debug session is paused (`Page.debug`), each move is `done` (run so far), `current`
 * (the block the run stands on makes it: drawn thick in a colour of its own, a ring where the
 * tool is; less thick when the block makes many, as a lathe cycle its passes, so that each
 * shows) or `ahead` (faint), and a click on a move opens a small menu: "Run to here" posts
 * `runTo`, "Go to its line" posts `reveal`.
 */
import * as path from 'node:path';
import { type Axes, formatNumber, type Plot, PLANES, RADIAL_SCALES, type RunMove, type View } from './toolpathGeometry';

export interface Texts {
  refresh: string;
  fit: string;
  source: string; // "drawn from the editor's text of ..."
  /**
   * The run's outcome, blocks and moves, extents: groups shown with " · " between them, each a
   * list of items shown with ", " between them; the line wraps only between items. A message
   * (running, an error) is one text that wraps as prose.
   */
  status: string | string[][];
  statusKind: 'completed' | 'alarm' | 'limit' | 'error' | 'running' | 'paused';
  note?: string; // e.g. only the first N moves are drawn
  hint: string;
  legend: {
    rapid: string;
    feed: string;
    arc: string;
    cycle: string;
    hole: string;
    origin: string;
    alarm: string;
    probe: string;
    contact: string;
    spindle: string; // a lathe's centre line
    mirror: string; // a lathe's other half, mirrored
    centre?: string; // the tool centre's path under cutter radius compensation
  };
  /** the button that hides and shows the tool centre's path, and its tooltip */
  centre?: { button: string; tip: string };
  /** a lathe cycle's pass in a move's tooltip: "pass of {0}", {0} the cycle as the run names it */
  passOf: string;
  /** a lathe's buttons: the radial scale in radii or diameters, and the mirrored half */
  lathe?: { radius: string; diameter: string; scaleTip: string; bothHalves: string; bothHalvesTip: string };
  /** the run's cycle time and path (`≈ 3 min 12 s · 1,842 mm cut · 6,300 mm rapid`), shown in the legend */
  totals?: string;
  plane: string; // what the drawing shows: the plane, or the lathe's Z/X with X halved
  planeButton: string; // tooltip of the plane buttons
  verticalAxis: string; // the name on the vertical axis ("Y", "X/2")
}

/** Where the labels sit, in screen pixels from the drawing's edge (their font is 11 px, the axis names' 13 px). */
const LABEL = { xBelow: 16, yLeft: 6, yDown: 4, hNameBelow: 34, vNameAbove: 14 };
const CHAR_PX = 7; // the width of one digit of an 11 px label, a little more than most fonts draw
export const MAX_DRAWN_MOVES = 50000;

export function escapeHtml(s: string): string {
  return s.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

export function nonce(): string {
  const chars = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789';
  let out = '';
  for (let i = 0; i < 32; i++) out += chars.charAt(Math.floor(Math.random() * chars.length));
  return out;
}

/** `G01  X0 Y0 -> X10 Y5  F200`: the axes that moved (all of them when none did); a lathe
 * cycle's pass ends with `passOf` filled with its cycle. */
export function moveText(move: RunMove, passOf = '{0}'): string {
  const names = [...new Set([...Object.keys(move.from), ...Object.keys(move.to)])];
  let shown = names.filter((k) => (move.from[k] ?? 0) !== (move.to[k] ?? 0));
  if (shown.length === 0) shown = names.filter((k) => ['X', 'Y', 'Z'].includes(k));
  const at = (p: Axes): string => shown.map((k) => `${k}${formatNumber(p[k] ?? 0)}`).join(' ');
  const feed = move.kind !== 'rapid' && move.feed ? `  F${formatNumber(move.feed)}` : '';
  const centre = move.centre
    ? `  (${Object.entries(move.centre)
        .map(([k, v]) => `${k}${formatNumber(v)}`)
        .join(' ')})`
    : '';
  const pass = move.passOf ? `  (${passOf.replace('{0}', move.passOf)})` : '';
  return `${move.mode}  ${at(move.from)} → ${at(move.to)}${feed}${centre}${pass}`;
}

const STYLE = `
:root { --rapid: #ffa94d; --feed: #74c0fc; --arc: #63e6be; --cycle: #e599f7; --alarm: #ff6b6b; --current: #ffe066;
  --probe: #b197fc; --centre: #f783ac; --grid: rgba(128,128,128,0.16); --axis: rgba(160,160,160,0.75); }
body.vscode-light { --rapid: #d9480f; --feed: #1864ab; --arc: #087f5b; --cycle: #ae3ec9; --alarm: #c92a2a; --current: #e8590c;
  --probe: #7048e8; --centre: #c2255c;
  --grid: rgba(0,0,0,0.09); --axis: rgba(0,0,0,0.5); }
body { margin: 0; padding: 0; color: var(--vscode-foreground); background: var(--vscode-editor-background);
  font-family: var(--vscode-font-family); font-size: var(--vscode-font-size); height: 100vh;
  display: flex; flex-direction: column; overflow: hidden; }
header { display: flex; gap: 6px; align-items: center; padding: 6px 10px; flex-wrap: wrap;
  border-bottom: 1px solid var(--vscode-panel-border, rgba(128,128,128,0.3)); }
button { color: var(--vscode-button-secondaryForeground); background: var(--vscode-button-secondaryBackground);
  border: none; padding: 3px 10px; cursor: pointer; font: inherit; }
button:hover { background: var(--vscode-button-secondaryHoverBackground); }
button.on { color: var(--vscode-button-foreground); background: var(--vscode-button-background); }
.source { opacity: 0.8; margin-left: 8px; }
#status { padding: 4px 10px; font-family: var(--vscode-editor-font-family); }
#status .item { white-space: nowrap; }
#status.alarm, #status.error { color: var(--alarm); font-weight: bold; }
#status.limit { color: var(--rapid); font-weight: bold; }
.note { padding: 0 10px 4px; opacity: 0.8; }
main { position: relative; flex: 1; min-height: 0; }
svg#plot { width: 100%; height: 100%; display: block; user-select: none; cursor: grab; --u: 1; }
svg#plot.dragging { cursor: grabbing; }
.grid line { stroke: var(--grid); stroke-width: 1; vector-effect: non-scaling-stroke; }
.axes line { stroke: var(--axis); stroke-width: 1; vector-effect: non-scaling-stroke; }
text { fill: var(--vscode-foreground); font-family: var(--vscode-editor-font-family); opacity: 0.85;
  font-size: calc(var(--u) * 11px); }
text.axis-name { font-weight: bold; font-size: calc(var(--u) * 13px); opacity: 1; }
text.x-label { transform: translateY(calc(var(--u) * ${LABEL.xBelow}px)); }
text.y-label { transform: translate(calc(var(--u) * -${LABEL.yLeft}px), calc(var(--u) * ${LABEL.yDown}px)); }
text.axis-name.h { transform: translateY(calc(var(--u) * ${LABEL.hNameBelow}px)); }
text.axis-name.v { transform: translateY(calc(var(--u) * -${LABEL.vNameAbove}px)); }
.move { cursor: pointer; }
.move .leg { fill: none; stroke-width: 1.6; vector-effect: non-scaling-stroke; stroke-linecap: round; }
.move .leg.dashed { stroke-dasharray: 5 4; stroke-width: 1.2; }
.move .hit { fill: none; stroke: transparent; stroke-width: 10; vector-effect: non-scaling-stroke; pointer-events: stroke; }
.move.rapid .leg { stroke: var(--rapid); }
.move.feed .leg { stroke: var(--feed); }
.move.arc .leg { stroke: var(--arc); }
.move.cycle .leg, .move .hole { stroke: var(--cycle); }
.move .hole { fill: none; stroke-width: 1.4; vector-effect: non-scaling-stroke; }
.move.probe .leg { stroke: var(--probe); stroke-width: 2.2; stroke-dasharray: 2 3; }
.move .contact { fill: var(--probe); stroke: var(--vscode-editor-background); stroke-width: 1; vector-effect: non-scaling-stroke; }
.move:hover .leg, .move.selected .leg { stroke-width: 3.5; }
.move.selected .leg { stroke: var(--vscode-editor-foreground); }
.move .centre, #legend .centre { fill: none; stroke: var(--centre); stroke-width: 1.2; stroke-dasharray: 6 2 1 2;
  vector-effect: non-scaling-stroke; pointer-events: none; }
body.hide-centre .move .centre { display: none; }
.spindle { stroke: var(--axis); stroke-width: 1.2; stroke-dasharray: 14 3 2 3; vector-effect: non-scaling-stroke; }
.mirror { opacity: 0.3; pointer-events: none; }
.origin { fill: var(--vscode-foreground); stroke: var(--vscode-foreground); stroke-width: 1.2; vector-effect: non-scaling-stroke; }
.origin circle { fill: none; }
.end { stroke: var(--alarm); stroke-width: 3; vector-effect: non-scaling-stroke; }
#legend { display: flex; flex-wrap: wrap; gap: 2px 16px; list-style: none; margin: 0; padding: 2px 10px 6px; }
#legend li { display: flex; align-items: center; gap: 6px; }
#legend svg { width: 36px; height: 12px; flex: none; }
#legend .plane { opacity: 0.85; }
#status.paused { color: var(--current); font-weight: bold; }
.move.ahead { opacity: 0.25; }
.move.current .leg, #legend .move.current .leg { stroke: var(--current); stroke-width: 5; }
.moves.many-current .move.current .leg { stroke-width: 2.5; } /* a lathe cycle's passes: each still seen */
.moves.many-current .move.current .leg.dashed { stroke-width: 1.6; }
.tool { fill: none; stroke: var(--current); stroke-width: 2.5; vector-effect: non-scaling-stroke; pointer-events: none; }
#menu { position: absolute; display: none; flex-direction: column; gap: 2px; padding: 4px; z-index: 2;
  background: var(--vscode-menu-background, var(--vscode-editor-background)); color: var(--vscode-menu-foreground);
  border: 1px solid var(--vscode-menu-border, rgba(128,128,128,0.5)); box-shadow: 0 2px 8px rgba(0,0,0,0.35); }
#menu.open { display: flex; }
#menu button { text-align: left; white-space: nowrap; }
#legend .totals { font-weight: bold; display: block; flex-basis: 100%; } /* a line of its own: not read as an entry's */
#legend .totals .item { white-space: nowrap; }
.hint { opacity: 0.7; margin-left: auto; }
`;

/** The page's script: clicks to the extension, wheel zoom and drag pan on the SVG's viewBox. */
const SCRIPT = `
const vscode = acquireVsCodeApi();
const svg = document.getElementById('plot');
for (const b of document.querySelectorAll('button[data-post]')) {
  b.addEventListener('click', () => vscode.postMessage({ type: b.dataset.post, plane: b.dataset.plane, value: b.dataset.value }));
}
// the tool centre's path: shown or hidden in the page, the choice kept with the page's state
const centreButton = document.getElementById('centre-path');
if (centreButton) {
  const show = (on) => {
    document.body.classList.toggle('hide-centre', !on);
    centreButton.classList.toggle('on', on);
    vscode.setState({ ...(vscode.getState() || {}), hideCentre: !on });
  };
  show(!(vscode.getState() || {}).hideCentre);
  centreButton.addEventListener('click', () => show(document.body.classList.contains('hide-centre')));
}
if (svg) {
  const base = svg.getAttribute('viewBox');
  const parse = (s) => s.split(/\\s+/).map(Number);
  const [w, h] = [Number(svg.dataset.width), Number(svg.dataset.height)];
  const [ml, mr, mt, mb] = parse(svg.dataset.margin);
  // The drawing as large as the view allows with the margins (pixels) around it, centred.
  const fit = () => {
    const r = svg.getBoundingClientRect();
    if (!(r.width > ml + mr && r.height > mt + mb)) return parse(base);
    const u = Math.max(w / (r.width - ml - mr), h / (r.height - mt - mb));
    const spareX = (r.width - ml - mr) * u - w;
    const spareY = (r.height - mt - mb) * u - h;
    return [-ml * u - spareX / 2, -mt * u - spareY / 2, r.width * u, r.height * u];
  };
  const saved = vscode.getState();
  let zoomed = Boolean(saved && saved.base === base && saved.zoomed);
  let vb = zoomed ? saved.vb : fit();
  const apply = () => {
    svg.setAttribute('viewBox', vb.join(' '));
    const r = svg.getBoundingClientRect();
    if (r.width > 0 && r.height > 0) svg.style.setProperty('--u', String(Math.max(vb[2] / r.width, vb[3] / r.height)));
    vscode.setState({ ...(vscode.getState() || {}), base, vb, zoomed });
  };
  const toSvg = (e) => {
    const m = svg.getScreenCTM();
    const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(m.inverse());
    return [p.x, p.y];
  };
  svg.addEventListener('wheel', (e) => {
    e.preventDefault();
    const [px, py] = toSvg(e);
    const f = e.deltaY > 0 ? 1.2 : 1 / 1.2;
    vb = [px - (px - vb[0]) * f, py - (py - vb[1]) * f, vb[2] * f, vb[3] * f];
    zoomed = true;
    apply();
  }, { passive: false });
  let drag = null;
  let dragged = false;
  svg.addEventListener('pointerdown', (e) => {
    if (e.button !== 0) return;
    drag = { x: e.clientX, y: e.clientY, vb: vb.slice() };
    dragged = false;
  });
  svg.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x;
    const dy = e.clientY - drag.y;
    if (!dragged && Math.hypot(dx, dy) < 4) return;
    if (!dragged) { dragged = true; svg.setPointerCapture(e.pointerId); svg.classList.add('dragging'); }
    const r = svg.getBoundingClientRect();
    const u = Math.max(drag.vb[2] / r.width, drag.vb[3] / r.height);
    vb = [drag.vb[0] - dx * u, drag.vb[1] - dy * u, drag.vb[2], drag.vb[3]];
    zoomed = true;
    apply();
  });
  const end = () => { drag = null; svg.classList.remove('dragging'); };
  svg.addEventListener('pointerup', end);
  svg.addEventListener('pointercancel', end);
  const menu = document.getElementById('menu');
  const closeMenu = () => { if (menu) menu.classList.remove('open'); };
  if (menu) {
    for (const b of menu.querySelectorAll('button')) {
      b.addEventListener('click', () => {
        vscode.postMessage({ type: b.dataset.action, index: Number(menu.dataset.index) });
        closeMenu();
      });
    }
  }
  svg.addEventListener('click', (e) => {
    if (dragged) { dragged = false; return; }
    const g = e.target.closest('.move');
    closeMenu();
    if (!g) return;
    for (const s of svg.querySelectorAll('.move.selected')) s.classList.remove('selected');
    g.classList.add('selected');
    if (menu) { // paused in the debugger: run to the move, or go to its line
      const box = svg.parentElement.getBoundingClientRect();
      menu.dataset.index = g.dataset.index;
      menu.classList.add('open'); // then measured, and kept inside the view
      const x = Math.min(e.clientX - box.left + 4, box.width - menu.offsetWidth - 4);
      const y = Math.min(e.clientY - box.top + 4, box.height - menu.offsetHeight - 4);
      menu.style.left = Math.max(0, x) + 'px';
      menu.style.top = Math.max(0, y) + 'px';
      return;
    }
    vscode.postMessage({ type: 'reveal', index: Number(g.dataset.index) });
  });
  document.addEventListener('keydown', (e) => { if (e.key === 'Escape') closeMenu(); });
  document.getElementById('fit').addEventListener('click', () => { zoomed = false; vb = fit(); apply(); });
  window.addEventListener('resize', () => { if (!zoomed) vb = fit(); apply(); });
  apply();
}
`;

export interface Page {
  cspSource: string;
  language: string;
  texts: Texts;
  plot?: Plot;
  moves?: RunMove[];
  view?: View;
  planes: boolean; // offer the XY / ZX / YZ buttons (a mill)
  /** a paused debug session: the first `done` moves ran, the next `current` are the current block's */
  debug?: PausedPage;
}

export interface PausedPage {
  done: number;
  current: number;
  runTo: string;
  goTo: string;
  legend: { done: string; current: string; ahead: string };
}

/** A move's part in a paused run: run so far, the current block's, or still to run. */
export function pausedClass(index: number, debug: PausedPage | undefined): string {
  if (!debug) return '';
  if (index < debug.done) return ' done';
  return index < debug.done + debug.current ? ' current' : ' ahead';
}

const NUMBER = /-?\d+(\.\d+)?(e-?\d+)?/g;

/** The first (`last` false) or last point of SVG path data: its first or last two numbers. */
function endPoint(d: string, last: boolean): [number, number] | undefined {
  const numbers = d.match(NUMBER);
  if (!numbers || numbers.length < 2) return undefined;
  const k = last ? numbers.length - 2 : 0;
  return [Number(numbers[k]), Number(numbers[k + 1])];
}

function legendLine(cls: string, dashed: boolean): string {
  const dash = dashed ? ' dashed' : '';
  return `<svg viewBox="0 0 36 12"><g class="move ${cls}"><path class="leg${dash}" d="M2 6 L34 6"/></g></svg>`;
}

/** The room, in screen pixels, that the labels and axis names need around the drawing. */
export function margins(plot: Plot): { left: number; right: number; top: number; bottom: number } {
  const longest = (ticks: Plot['xTicks']): number => Math.max(0, ...ticks.map((t) => formatNumber(t.value).length));
  return {
    left: Math.max(40, LABEL.yLeft + 8 + CHAR_PX * longest(plot.yTicks)),
    right: Math.max(16, 6 + (CHAR_PX / 2) * longest(plot.xTicks)),
    top: LABEL.vNameAbove + 16,
    bottom: LABEL.hNameBelow + 10,
  };
}

function drawing(plot: Plot, moves: RunMove[], view: View, texts: Texts, debug?: PausedPage): string {
  const w = plot.width;
  const h = plot.height;
  const n = (v: number): string => (Math.round(v * 100) / 100).toString();
  const out: string[] = [];
  const m = margins(plot);
  const vb = [-m.left, -m.top, w + m.left + m.right, h + m.top + m.bottom];
  out.push(
    `<svg id="plot" xmlns="http://www.w3.org/2000/svg" viewBox="${vb.map(n).join(' ')}" preserveAspectRatio="xMidYMid meet"` +
      ` data-width="${n(w)}" data-height="${n(h)}" data-margin="${[m.left, m.right, m.top, m.bottom].map(n).join(' ')}">`,
  );
  out.push('<g class="grid">');
  for (const t of plot.xTicks) out.push(`<line x1="${n(t.at)}" y1="0" x2="${n(t.at)}" y2="${n(h)}"/>`);
  for (const t of plot.yTicks) out.push(`<line x1="0" y1="${n(t.at)}" x2="${n(w)}" y2="${n(t.at)}"/>`);
  out.push('</g><g class="labels">');
  for (const t of plot.xTicks) {
    out.push(`<text class="x-label" x="${n(t.at)}" y="${n(h)}" text-anchor="middle">${formatNumber(t.value)}</text>`);
  }
  for (const t of plot.yTicks) {
    out.push(`<text class="y-label" x="0" y="${n(t.at)}" text-anchor="end">${formatNumber(t.value)}</text>`);
  }
  // the axis names: below the x labels at the right end, above the drawing at the left end
  out.push(`<text class="axis-name h" x="${n(w)}" y="${n(h)}" text-anchor="end">${escapeHtml(view.h)} →</text>`);
  out.push(`<text class="axis-name v" x="0" y="0" text-anchor="start">↑ ${escapeHtml(texts.verticalAxis)}</text>`);
  const [ox, oy] = plot.origin;
  out.push('</g><g class="axes">');
  // a lathe: the spindle's centre line across the whole drawing instead of the horizontal axis
  if (plot.spindle === undefined) out.push(`<line x1="0" y1="${n(oy)}" x2="${n(w)}" y2="${n(oy)}"/>`);
  out.push(`<line x1="${n(ox)}" y1="0" x2="${n(ox)}" y2="${n(h)}"/>`);
  if (plot.spindle !== undefined) {
    const y = n(plot.spindle);
    out.push(
      `<line class="spindle" x1="0" y1="${y}" x2="${n(w)}" y2="${y}"><title>${escapeHtml(texts.legend.spindle)}</title></line>`,
    );
  }
  out.push('</g>');
  if (plot.mirror !== undefined) {
    // the other half: the same legs mirrored about the centre line (y' = 2m - y), faint
    out.push(`<g class="mirror" transform="matrix(1 0 0 -1 0 ${n(2 * plot.mirror)})">`);
    for (const drawn of plot.moves) {
      out.push(`<g class="move ${drawn.kind}">`);
      for (const leg of drawn.legs) out.push(`<path class="leg${leg.dashed ? ' dashed' : ''}" d="${leg.d}"/>`);
      out.push('</g>');
    }
    out.push('</g>');
  }
  out.push(`<g class="moves${debug && debug.current > 1 ? ' many-current' : ''}">`);
  const hr = n(plot.holeRadius);
  // probe moves (G31) last, on top: a retract along the same line must not hide them or their contact points
  const ordered = [...plot.moves.filter((d) => d.kind !== 'probe'), ...plot.moves.filter((d) => d.kind === 'probe')];
  for (const drawn of ordered) {
    const move = moves[drawn.index];
    if (!move) continue;
    const title = `${path.basename(move.file)}:${move.line}  ${moveText(move, texts.passOf)}`;
    const d = drawn.legs.map((l) => l.d).join(' ');
    out.push(`<g class="move ${drawn.kind}${pausedClass(drawn.index, debug)}" data-index="${drawn.index}" data-line="${move.line}"><title>${escapeHtml(title)}</title>`);
    for (const leg of drawn.legs) out.push(`<path class="leg${leg.dashed ? ' dashed' : ''}" d="${leg.d}"/>`);
    if (drawn.centre) out.push(`<path class="centre" d="${drawn.centre}"/>`);
    if (drawn.hole) {
      const [x, y] = drawn.hole;
      out.push(`<circle class="hole" cx="${n(x)}" cy="${n(y)}" r="${hr}"/>`);
    }
    if (drawn.contact) {
      const [x, y] = drawn.contact;
      out.push(`<circle class="contact" cx="${n(x)}" cy="${n(y)}" r="${hr}"/>`);
    }
    out.push(`<path class="hit" d="${d}${drawn.hole ? ` M${n(drawn.hole[0])} ${n(drawn.hole[1])} h0.01` : ''}"/></g>`);
  }
  out.push('</g>');
  if (debug) {
    // where the tool is: the start of the current block's move, else the end of the last move run
    const current = debug.current > 0 ? plot.moves[debug.done]?.legs[0] : undefined;
    const last = plot.moves[debug.done - 1]?.legs.at(-1);
    const at = current ? endPoint(current.d, false) : last ? endPoint(last.d, true) : plot.origin;
    if (at) out.push(`<circle class="tool" cx="${n(at[0])}" cy="${n(at[1])}" r="9"/>`);
  }
  // the origin: a datum symbol, two quarters filled
  const r = 8;
  out.push(
    `<g class="origin"><title>${escapeHtml(texts.legend.origin)}</title><circle cx="${n(ox)}" cy="${n(oy)}" r="${r}"/>` +
      `<path d="M${n(ox)} ${n(oy)} L${n(ox + r)} ${n(oy)} A${r} ${r} 0 0 0 ${n(ox)} ${n(oy - r)} Z` +
      ` M${n(ox)} ${n(oy)} L${n(ox - r)} ${n(oy)} A${r} ${r} 0 0 0 ${n(ox)} ${n(oy + r)} Z"/></g>`,
  );
  if (plot.end) {
    const [x, y] = plot.end;
    const s = 7;
    out.push(
      `<g class="end"><title>${escapeHtml(texts.legend.alarm)}</title>` +
        `<path d="M${n(x - s)} ${n(y - s)} L${n(x + s)} ${n(y + s)} M${n(x - s)} ${n(y + s)} L${n(x + s)} ${n(y - s)}"/></g>`,
    );
  }
  out.push('</svg>');
  return out.join('\n');
}

function legend(texts: Texts, plot: Plot, debug?: PausedPage): string {
  const l = texts.legend;
  const drawn = new Set(plot.moves.map((m) => m.kind));
  const items = [
    `<li>${legendLine('rapid', true)}${escapeHtml(l.rapid)}</li>`,
    `<li>${legendLine('feed', false)}${escapeHtml(l.feed)}</li>`,
  ];
  if (drawn.has('arc')) items.push(`<li>${legendLine('arc', false)}${escapeHtml(l.arc)}</li>`);
  if (drawn.has('cycle')) items.push(`<li>${legendLine('cycle', false)}${escapeHtml(l.cycle)}</li>`);
  if (drawn.has('probe')) items.push(`<li>${legendLine('probe', false)}${escapeHtml(l.probe)}</li>`);
  if (plot.moves.some((m) => m.contact)) {
    items.push(
      `<li><svg viewBox="0 0 36 12"><g class="move probe"><circle class="contact" cx="18" cy="6" r="4"/></g></svg>${escapeHtml(l.contact)}</li>`,
    );
  }
  if (plot.moves.some((m) => m.hole)) {
    items.push(
      `<li><svg viewBox="0 0 36 12"><g class="move cycle"><circle class="hole" cx="18" cy="6" r="4.5"/></g></svg>${escapeHtml(l.hole)}</li>`,
    );
  }
  if (l.centre && plot.moves.some((m) => m.centre)) {
    items.push(`<li><svg viewBox="0 0 36 12"><path class="centre" d="M2 6 L34 6"/></svg>${escapeHtml(l.centre)}</li>`);
  }
  if (plot.spindle !== undefined) {
    items.push(`<li><svg viewBox="0 0 36 12"><line class="spindle" x1="0" y1="6" x2="36" y2="6"/></svg>${escapeHtml(l.spindle)}</li>`);
  }
  if (plot.mirror !== undefined) {
    items.push(`<li><svg viewBox="0 0 36 12"><g class="mirror move feed"><path class="leg" d="M2 6 L34 6"/></g></svg>${escapeHtml(l.mirror)}</li>`);
  }
  items.push(
    `<li><svg viewBox="0 0 36 12"><g class="origin"><circle cx="18" cy="6" r="5"/><path d="M18 6 L23 6 A5 5 0 0 0 18 1 Z M18 6 L13 6 A5 5 0 0 0 18 11 Z"/></g></svg>${escapeHtml(l.origin)}</li>`,
  );
  if (plot.end) {
    items.push(`<li><svg viewBox="0 0 36 12"><g class="end"><path d="M14 2 L22 10 M14 10 L22 2"/></g></svg>${escapeHtml(l.alarm)}</li>`);
  }
  if (debug) {
    items.push(`<li>${legendLine('feed done', false)}${escapeHtml(debug.legend.done)}</li>`);
    items.push(`<li>${legendLine('feed current', false)}${escapeHtml(debug.legend.current)}</li>`);
    items.push(`<li>${legendLine('feed ahead', false)}${escapeHtml(debug.legend.ahead)}</li>`);
  }
  // the run's totals (`≈ 1 min 48 s · 596 mm cut · 766 mm rapid`) wrap only between their parts, as the status line
  if (texts.totals) items.push(`<li class="totals">${statusHtml(texts.totals.split(' · ').map((part) => [part]))}</li>`);
  items.push(`<li class="plane">${escapeHtml(texts.plane)}</li>`);
  return `<ul id="legend">${items.join('')}</ul>`;
}

/** The status line: a message as it is, or its groups and items with the breaks only between items. */
export function statusHtml(status: Texts['status']): string {
  if (typeof status === 'string') return escapeHtml(status);
  return status
    .map((group) => group.map((item) => `<span class="item">${escapeHtml(item)}</span>`).join(', '))
    .join(' · ');
}

export function toolpathHtml(page: Page, nonceValue: string): string {
  const t = page.texts;
  const csp = [
    "default-src 'none'",
    `style-src 'nonce-${nonceValue}'`,
    `script-src 'nonce-${nonceValue}'`,
    `img-src ${page.cspSource} data:`,
    `font-src ${page.cspSource}`,
  ].join('; ');
  const planeButtons =
    page.planes && page.view
      ? PLANES.map(
          (p) =>
            `<button data-post="plane" data-plane="${p}" title="${escapeHtml(t.planeButton)}"${p === page.view?.plane ? ' class="on"' : ''}>${p}</button>`,
        ).join('')
      : '';
  const lathe = page.view?.lathe;
  const latheButtons =
    lathe && t.lathe
      ? RADIAL_SCALES.map(
          (scale) =>
            `<button data-post="radialScale" data-value="${scale}" title="${escapeHtml(t.lathe?.scaleTip ?? '')}"` +
            `${scale === lathe.scale ? ' class="on"' : ''}>${escapeHtml(t.lathe?.[scale] ?? scale)}</button>`,
        ).join('') +
        `<button id="both-halves" data-post="bothHalves" title="${escapeHtml(t.lathe.bothHalvesTip)}"` +
        `${lathe.bothHalves ? ' class="on"' : ''}>${escapeHtml(t.lathe.bothHalves)}</button>`
      : '';
  const centreButton =
    t.centre && page.plot?.moves.some((m) => m.centre)
      ? `<button id="centre-path" class="on" title="${escapeHtml(t.centre.tip)}">${escapeHtml(t.centre.button)}</button>`
      : '';
  const body: string[] = [
    `<header><button id="refresh" data-post="refresh">${escapeHtml(t.refresh)}</button>`,
    page.plot ? `<button id="fit">${escapeHtml(t.fit)}</button>${planeButtons}${latheButtons}${centreButton}` : '',
    `<span class="source">${escapeHtml(t.source)}</span>`,
    page.plot ? `<span class="hint">${escapeHtml(t.hint)}</span>` : '',
    '</header>',
    `<div id="status" class="${t.statusKind}">${statusHtml(t.status)}</div>`,
    t.note ? `<div class="note">${escapeHtml(t.note)}</div>` : '',
    page.plot ? legend(t, page.plot, page.debug) : '',
    '<main>',
    page.plot && page.moves && page.view ? drawing(page.plot, page.moves, page.view, t, page.debug) : '',
    page.debug
      ? `<div id="menu"><button data-action="runTo">${escapeHtml(page.debug.runTo)}</button>` +
        `<button data-action="reveal">${escapeHtml(page.debug.goTo)}</button></div>`
      : '',
    '</main>',
  ];
  return `<!DOCTYPE html>
<html lang="${escapeHtml(page.language)}">
<head>
<meta charset="UTF-8">
<meta http-equiv="Content-Security-Policy" content="${csp}">
<meta name="viewport" content="width=device-width, initial-scale=1.0">
<style nonce="${nonceValue}">${STYLE}</style>
</head>
<body>
${body.join('\n')}
<script nonce="${nonceValue}">${SCRIPT}</script>
</body>
</html>`;
}
