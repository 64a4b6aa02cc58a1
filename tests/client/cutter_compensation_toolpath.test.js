// Under cutter radius compensation the toolpath draws the tool centre's path the run sends
// (`tool_path`, docs/semantics.md §12) beside the programmed one, and a button hides and shows it.
// client/src/toolpathGeometry.ts and toolpathView.ts, bundled as the extension bundles them, read real
// `cncmacro run --json` output; the expected numbers are worked out by hand.
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
  scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-centre-plot-'));
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

function runJson(text) {
  const file = path.join(fs.mkdtempSync(path.join(scratch, 'run-')), 'MAIN.nc');
  fs.writeFileSync(file, text);
  const r = cp.spawnSync(PYTHON, ['-m', 'cncmacro', 'run', '--json', '--no-save', file], { cwd: ROOT, encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  const parsed = geometry.parseRunResult(r.stdout);
  assert.notEqual(typeof parsed, 'string', String(parsed));
  return parsed;
}

// a 50 x 50 square cut clockwise, the tool (radius 5) on the left: outside
const SQUARE = 'O0001\nG10 L12 P1 R5.\nG90 G17 G00 X-20. Y-20.\nG41 D1 G01 X0 Y0 F100\nY50.\nX50.\nY0\nX0\nG40 X-20. Y-20.\nM30\n';

test('each compensated move carries its centre path, drawn beside the programmed one', () => {
  const run = runJson(SQUARE);
  assert.equal(run.moves[0].toolPath, undefined); // the G00 before G41
  // the side X50. (line 6) is programmed from (0,50) to (50,50); its centre runs on y = 55 from x = -5 to 55
  const side = run.moves.find((m) => m.line === 6);
  assert.deepEqual([side.toolPath.from.X, side.toolPath.from.Y], [-5, 55]);
  assert.deepEqual(side.toolPath.pieces.map((p) => [p.to.X, p.to.Y]), [[55, 55]]);
  const plot = geometry.plot(run.moves, geometry.viewFor(undefined, 'XY'), true);
  const drawn = plot.moves[run.moves.indexOf(side)];
  assert.ok(drawn.centre, 'the centre path is drawn');
  assert.notEqual(drawn.centre, drawn.legs[0].d);
  // the centre reaches x = 55 and y = -5, outside the programmed square: the picture takes it in
  assert.ok(plot.width > 0 && plot.moves[0].centre === undefined);
  const page = view.toolpathHtml({
    cspSource: 'x', language: 'en', planes: true, plot, moves: run.moves, view: geometry.viewFor(undefined, 'XY'),
    texts: {
      refresh: 'Refresh', fit: 'Fit', source: '', status: 'ok', statusKind: 'completed', hint: '', passOf: 'pass of {0}',
      legend: { rapid: 'r', feed: 'f', arc: 'a', cycle: 'c', hole: 'h', origin: 'o', alarm: 'x', probe: 'p', contact: 'k',
                spindle: 's', mirror: 'm', centre: 'tool centre' },
      centre: { button: 'Tool centre', tip: 'show or hide' }, plane: 'XY', planeButton: '', verticalAxis: 'Y',
    },
  }, 'n0nce');
  assert.match(page, /<button id="centre-path" class="on"/);
  assert.match(page, /<path class="centre" d="M/);
  assert.match(page, /tool centre<\/li>/);
});

test('a compensated arc is drawn as an arc about its programmed centre at the offset radius', () => {
  // radius 2, tool left; G03 from (10,0) about (10,10): the centre's arc at radius 8 from (10,2) to (18,10)
  const run = runJson('O0002\nG10 L12 P1 R2.\nG90 G17 G00 X-10. Y0\nG41 D1 G01 X0 F100\nX10.\nG03 X20. Y10. R10.\n' +
                      'G01 Y30.\nG40 X0\nM30\n');
  const arc = run.moves.find((m) => m.line === 6);
  assert.deepEqual(arc.toolPath.pieces.map((p) => [p.to.X, p.to.Y, p.centre.X, p.centre.Y, p.clockwise]), [[18, 10, 10, 10, false]]);
  const drawn = geometry.plot(run.moves, geometry.viewFor(undefined, 'XY'), true).moves[run.moves.indexOf(arc)];
  assert.ok(drawn.centre.split('L').length > 8, 'sampled along the arc');
});

test('a malformed centre path is refused with a message', () => {
  const text = JSON.stringify({ status: 'completed', moves: [
    { file: 'a.nc', line: 1, mode: 'G01', kind: 'feed', from: { X: 0 }, to: { X: 1 }, tool_path: { from: { X: 0 } } }] });
  assert.match(String(geometry.parseRunResult(text)), /tool centre path/);
});
