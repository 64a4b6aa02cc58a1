// The toolpath's plot draws what the run sends (ARCHITECTURE.md, C2): client/src/toolpathGeometry.ts,
// bundled as the extension bundles it, reads real `cncmacro run --json` output and draws each move by
// its kind, an arc by its plane and direction, a cycle by its legs and a drilled hole where the run
// says. Nothing here is a copy of the server's geometry: the expected legs are worked out by hand.
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
let scratch;

before(() => {
  scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-plot-'));
  const out = path.join(scratch, 'toolpathGeometry.js');
  require(path.join(ROOT, 'node_modules', 'esbuild')).buildSync({
    entryPoints: [path.join(ROOT, 'client', 'src', 'toolpathGeometry.ts')],
    bundle: true, platform: 'node', format: 'cjs', outfile: out, logLevel: 'error',
  });
  geometry = require(out);
});

after(() => fs.rmSync(scratch, { recursive: true, force: true }));  // the bundle and the runs' programs

function runJson(name, text, machineFile) {
  const dir = fs.mkdtempSync(path.join(scratch, 'run-'));
  if (machineFile) fs.writeFileSync(path.join(dir, '.cncmacro.toml'), machineFile);
  const file = path.join(dir, name);
  fs.writeFileSync(file, text);
  const r = cp.spawnSync(PYTHON, ['-m', 'cncmacro', 'run', '--json', '--no-save', file], { cwd: ROOT, encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  const parsed = geometry.parseRunResult(r.stdout);
  assert.notEqual(typeof parsed, 'string', String(parsed));
  return parsed;
}

test('a drilled hole is drawn by its four legs: position and rapid to R dashed, the cut solid, the way out dashed', () => {
  const run = runJson('MAIN.nc', 'O0001\nG90 G00 X0 Y0 Z50.\nG98 G81 X10. Y10. Z-10. R2. F100\nG80\nM30\n');
  const view = geometry.viewFor(geometry.latheAxesOf(run), 'ZX');
  const drawn = geometry.plot(run.moves, view, false).moves[1];
  assert.equal(drawn.kind, 'cycle');
  assert.deepEqual(drawn.legs.map((leg) => leg.dashed), [true, true, false, true]);
  assert.ok(drawn.hole, 'the hole gets its marker');
  // in the ZX view (Z across, X up) the cut runs along Z from R2 to Z-10 at X10: its path keeps one
  // screen y (the same X) and goes left; the way out comes back to where the rapid to R began
  const points = drawn.legs.map((leg) => leg.d.match(/-?[\d.]+/g).map(Number));
  assert.equal(points[2][1], points[2][3]);
  assert.ok(points[2][2] < points[2][0]);
  assert.deepEqual(points[3].slice(2), points[1].slice(0, 2));
});

test('an arc is drawn in the plane the run names: a G18 arc is an SVG arc in the ZX view and a line in XY', () => {
  const run = runJson('ARC.nc', 'O0002\nG90 G00 X0 Y0 Z0\nG18 G02 X10. Z10. R10. F100\nM30\n');
  const arc = run.moves[1];
  assert.deepEqual([arc.kind, arc.plane, arc.clockwise], ['arc', ['Z', 'X'], true]);
  const zx = geometry.plot(run.moves, geometry.viewFor(undefined, 'ZX'), false).moves[1];
  assert.match(zx.legs[0].d, / A/);
  // G02 seen from +Y in the Z-across, X-up view turns clockwise on the screen: sweep flag 1
  assert.match(zx.legs[0].d, /A[\d.]+ [\d.]+ 0 [01] 1 /);
  const xy = geometry.plot(run.moves, geometry.viewFor(undefined, 'XY'), false).moves[1];
  assert.doesNotMatch(xy.legs[0].d, / A/);
});

test('a lathe G90 cycle is drawn by the legs the run gives, X halved as a radius', () => {
  const run = runJson('O0003.CNC', 'O0003\nG00 X50. Z2.\nG90 X40. Z-30. F0.2\nM30\n', 'base = "gsk980tdi"\n');
  assert.equal(run.lathe, true);
  const drawn = geometry.plot(run.moves, geometry.viewFor(geometry.latheAxesOf(run)), false).moves[1];
  assert.deepEqual(drawn.legs.map((leg) => leg.dashed), [true, false, false, true]);
  assert.equal(drawn.hole, undefined);
});

test('a move without a kind is refused with a message, not guessed from its G code', () => {
  const text = JSON.stringify({ status: 'completed', moves: [{ file: 'a.nc', line: 1, mode: 'G01', from: { X: 0 }, to: { X: 1 } }] });
  const parsed = geometry.parseRunResult(text);
  assert.equal(typeof parsed, 'string');
  assert.match(parsed, /has no kind/);
});
