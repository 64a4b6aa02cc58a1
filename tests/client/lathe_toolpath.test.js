// A lathe's toolpath is drawn as a lathe because the run says it is one (`lathe`, `lathe_axes`,
// from the profile; ARCHITECTURE.md C2): the spindle axis Z across with its centre line X0, X up,
// to scale (X, a diameter, drawn as the radius), the X scale reading diameters or radii as the
// user picks, the other half mirrored when asked, and every pass of a cycle drawn from the moves
// the run sends. client/src/toolpathGeometry.ts and toolpathView.ts, bundled as the extension
// bundles them, read real `cncmacro run --json` output; the expected numbers are worked out by hand.
'use strict';

const { test, before, after } = require('node:test');
const assert = require('node:assert/strict');
const cp = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');

const ROOT = path.resolve(__dirname, '..', '..');
const PYTHON = process.env.CNCMACRO_TEST_PYTHON || path.join(ROOT, '.venv', 'bin', 'python');
let geometry;
let view;
let scratch;

before(() => {
  scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-lathe-plot-'));
  const bundle = (name) => {
    const out = path.join(scratch, `${name}.js`);
    require(path.join(ROOT, 'node_modules', 'esbuild')).buildSync({
      entryPoints: [path.join(ROOT, 'client', 'src', `${name}.ts`)],
      bundle: true, platform: 'node', format: 'cjs', outfile: out, logLevel: 'error',
    });
    return require(out);
  };
  geometry = bundle('toolpathGeometry');
  view = bundle('toolpathView');
});

after(() => fs.rmSync(scratch, { recursive: true, force: true }));  // the bundle and the runs' programs

function runJson(file, text) {
  let target = file;
  if (text !== undefined) {
    target = path.join(fs.mkdtempSync(path.join(scratch, 'run-')), file);
    fs.writeFileSync(target, text);
  }
  const r = cp.spawnSync(PYTHON, ['-m', 'cncmacro', 'run', '--json', '--no-save', target], { cwd: ROOT, encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  const parsed = geometry.parseRunResult(r.stdout);
  assert.notEqual(typeof parsed, 'string', String(parsed));
  return parsed;
}

// one cut along Z at X40 (a diameter: radius 20) from Z2 to Z-30 (32 long)
const CUT = '(cncmacro: dialect=gsk980tdi)\nO0007\nG00 X40. Z2.\nG01 Z-30. F0.2\nM30\n';

/** The numbers of SVG path data. */
const numbers = (d) => d.match(/-?[\d.]+/g).map(Number);

test('a lathe is drawn with the spindle axis Z across, X up, and X a diameter drawn as the radius', () => {
  const run = runJson('CUT.nc', CUT);
  const axes = geometry.latheAxesOf(run);
  assert.deepEqual(axes, { spindle: 'Z', radial: 'X', diameter: true });
  const plot = geometry.plot(run.moves, geometry.viewFor(axes), false);
  const [x0, y0, x1, y1] = numbers(plot.moves[1].legs[0].d);
  assert.equal(y0, y1); // the cut keeps X: one screen height
  assert.ok(x1 < x0); // toward Z-30: to the left
  // to scale: 20 (the radius of X40) above the centre line against 32 along Z
  assert.ok(Math.abs((plot.spindle - y0) / (x0 - x1) - 20 / 32) < 1e-3);
});

test('the spindle axis (the centre line X0) is drawn on a lathe, and not on a mill', () => {
  const lathe = runJson('CUT.nc', CUT);
  const plot = geometry.plot(lathe.moves, geometry.viewFor(geometry.latheAxesOf(lathe)), false);
  assert.equal(plot.spindle, plot.origin[1]); // at X0, where the origin is
  const page = view.toolpathHtml(pageOf(plot, lathe, geometry.viewFor(geometry.latheAxesOf(lathe))), 'n0nce');
  assert.match(page, /<line class="spindle" x1="0" y1="[\d.]+" x2="[\d.]+"/);
  const mill = runJson('MILL.nc', 'O0008\nG00 X40. Y2.\nG01 Y-30. F100\nM30\n');
  assert.equal(geometry.latheAxesOf(mill), undefined);
  const millPlot = geometry.plot(mill.moves, geometry.viewFor(undefined, 'ZX'), false);
  assert.equal(millPlot.spindle, undefined);
  assert.doesNotMatch(view.toolpathHtml(pageOf(millPlot, mill, geometry.viewFor(undefined, 'ZX')), 'n0nce'), /class="spindle"/);
});

test('the radius/diameter toggle halves the X scale: the cut at X40 sits on the line labelled 40, or 20 reading radii', () => {
  const run = runJson('CUT.nc', CUT);
  const axes = geometry.latheAxesOf(run);
  const diameters = geometry.plot(run.moves, geometry.viewFor(axes, 'XY', { scale: 'diameter' }), false);
  const radii = geometry.plot(run.moves, geometry.viewFor(axes, 'XY', { scale: 'radius' }), false);
  const y = numbers(diameters.moves[1].legs[0].d)[1];
  assert.equal(numbers(radii.moves[1].legs[0].d)[1], y); // the drawing itself does not change
  const labelAt = (ticks) => ticks.find((t) => Math.abs(t.at - y) < 0.01)?.value;
  assert.equal(labelAt(diameters.yTicks), 40);
  assert.equal(labelAt(radii.yTicks), 20);
  // every grid line: the same places, labelled at twice the radius when reading diameters
  assert.deepEqual(diameters.yTicks.map((t) => [t.at, t.value / 2]), radii.yTicks.map((t) => [t.at, t.value]));
  assert.deepEqual(diameters.xTicks, radii.xTicks); // Z is Z
});

test('both halves: the other half mirrored about the centre line, the picture as far below it as above', () => {
  const run = runJson('CUT.nc', CUT);
  const axes = geometry.latheAxesOf(run);
  const one = geometry.plot(run.moves, geometry.viewFor(axes, 'XY', { scale: 'radius' }), false);
  const both = geometry.plot(run.moves, geometry.viewFor(axes, 'XY', { scale: 'radius', bothHalves: true }), false);
  assert.equal(one.mirror, undefined);
  assert.equal(both.mirror, both.spindle);
  const values = both.yTicks.map((t) => t.value);
  assert.ok(values.includes(20) && values.includes(-20), values.join(' ')); // X40 above, its mirror below
  assert.ok(!one.yTicks.some((t) => t.value < 0));
  const page = view.toolpathHtml(pageOf(both, run, geometry.viewFor(axes, 'XY', { bothHalves: true })), 'n0nce');
  assert.match(page, new RegExp(`<g class="mirror" transform="matrix\\(1 0 0 -1 0 ${Math.round(2 * both.mirror * 100) / 100}\\)">`));
});

test('a lathe view comes from the run alone: lathe without its axes, or axes on no lathe, draw no lathe', () => {
  const axes = { spindle: 'Z', radial: 'X', diameter: true };
  assert.equal(geometry.latheAxesOf({ lathe: true }), undefined);
  assert.equal(geometry.latheAxesOf({ lathe: false, latheAxes: axes }), undefined);
  assert.deepEqual(geometry.latheAxesOf({ lathe: true, latheAxes: axes }), axes);
  assert.equal(geometry.parseLatheAxes({ spindle: 'Z', radial: 'Z', diameter: true }), undefined);
});

test('every pass of G71 is drawn from the moves sent, each naming its cycle; a G92 thread by its four legs', () => {
  const run = runJson(path.join(ROOT, 'examples', 'gsk980tdi', 'shaft_g71.nc'));
  const plot = geometry.plot(run.moves, geometry.viewFor(geometry.latheAxesOf(run)), false);
  assert.equal(plot.moves.length, run.moves.length); // one drawn move per move sent
  const passes = run.moves.filter((m) => m.passOf === 'G71');
  assert.ok(passes.length > 10 && passes.every((m) => m.line === 11)); // the G71 P10 Q20 block
  // GSK980TDi §3.23.1: first at rapid from the start X44 Z2 to A', moved by the allowances U0.4 W0.1
  // (X44.4 Z2.1); the first pass in to X41.4 (44.4 less 2 x 1.5) at rapid, dashed; the cut along Z solid
  const dashed = (m) => plot.moves[run.moves.indexOf(m)].legs[0].dashed;
  assert.deepEqual([passes[0].to.X, passes[0].to.Z, dashed(passes[0])], [44.4, 2.1, true]);
  assert.deepEqual([passes[1].to.X, dashed(passes[1])], [41.4, true]);
  assert.deepEqual([passes[2].kind, dashed(passes[2])], ['feed', false]);
  const title = view.toolpathHtml(pageOf(plot, run, geometry.viewFor(geometry.latheAxesOf(run))), 'n0nce');
  assert.match(title, /shaft_g71\.nc:11  G01  Z2\.1 → Z-59\.9  F0\.25  \(pass of G71\)/);
  const thread = run.moves.find((m) => m.kind === 'cycle');
  const drawn = plot.moves[run.moves.indexOf(thread)];
  assert.deepEqual(drawn.legs.map((l) => l.dashed), [true, false, true, true]); // in, the thread, out, back
});

/** The webview's page of `plot`, in English. */
function pageOf(plot, run, v) {
  const legend = { rapid: 'rapid', feed: 'feed', arc: 'arc', cycle: 'cycle', hole: 'hole', origin: 'origin', alarm: 'alarm',
    probe: 'probe', contact: 'contact', spindle: 'spindle axis', mirror: 'the other half' };
  const texts = { refresh: 'Refresh', fit: 'Fit', source: '', status: '', statusKind: 'completed', hint: '', legend,
    passOf: 'pass of {0}', plane: '', planeButton: '', verticalAxis: 'X',
    lathe: { radius: 'Radius', diameter: 'Diameter', scaleTip: '', bothHalves: 'Both halves', bothHalvesTip: '' } };
  return { cspSource: 'x', language: 'en', texts, plot, moves: run.moves, view: v, planes: false };
}
