// Finding Python, the part that needs no editor (client/src/pythonProbe.ts, bundled as the
// extension bundles it): a Python answers with its version and executable; a command that is not
// there is "missing"; on Windows, the Microsoft Store's placeholder `python3` (exit status 9009,
// no Python installed) is named as such, and `py -3` is tried after `python3`. Runs here and on
// the CI workflow's Windows and macOS runners.
'use strict';

const { test, before, after } = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');

const ROOT = path.resolve(__dirname, '..', '..');
const PYTHON = process.env.CNCMACRO_TEST_PYTHON
  || path.join(ROOT, '.venv', process.platform === 'win32' ? 'Scripts' : 'bin', process.platform === 'win32' ? 'python.exe' : 'python');
let probe;
let built; // the folder the bundle is built in, removed after the tests

before(() => {
  built = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-probe-'));
  const out = path.join(built, 'pythonProbe.js');
  require(path.join(ROOT, 'node_modules', 'esbuild')).buildSync({
    entryPoints: [path.join(ROOT, 'client', 'src', 'pythonProbe.ts')],
    bundle: true, platform: 'node', format: 'cjs', outfile: out, logLevel: 'error',
  });
  probe = require(out);
});

after(() => {
  if (built) fs.rmSync(built, { recursive: true, force: true });
});

test('a Python answers with its version and its executable', async () => {
  const found = await probe.probeCommand({ command: PYTHON, args: [], source: 'setting' });
  assert.ok(!('why' in found), JSON.stringify(found));
  assert.ok(probe.versionOk(found.version), `version ${found.version.join('.')}`);
  assert.ok(fs.existsSync(found.executable), found.executable);
});

test('a command that is not there is missing', async () => {
  const found = await probe.probeCommand({ command: 'cncmacro-no-such-python-3', args: [], source: 'PATH' });
  assert.deepEqual(found, { why: 'missing' });
});

test("on Windows a command that exits with 9009 is the Microsoft Store's placeholder", () => {
  assert.deepEqual(probe.notPython(9009, 'Command failed: python3', 'win32'), { why: 'store-placeholder' });
  // elsewhere an exit status like any other (a POSIX status is below 256 anyway)
  assert.deepEqual(probe.notPython(9009, 'Command failed: python3\nmore', 'linux'), { why: 'failed', text: 'Command failed: python3' });
});

test('the placeholder is named when it runs', { skip: process.platform !== 'win32' && 'Windows only: an exit status of 9009 (runs on the Windows runner)' }, async () => {
  // a stand-in for the placeholder: Node itself, told to exit as the placeholder does
  const placeholder = { command: process.execPath, args: ['-e', 'process.exit(9009)', '--'], source: 'PATH' };
  assert.deepEqual(await probe.probeCommand(placeholder), { why: 'store-placeholder' });
});

test('py -3 is tried after python3 on Windows only', () => {
  const names = (platform) => probe.pathCandidates(platform).map((c) => [c.command, ...c.args].join(' '));
  assert.deepEqual(names('win32'), ['python3', 'py -3', 'python']);
  assert.deepEqual(names('linux'), ['python3', 'python']);
});

test('py -3 on Windows is a Python 3.10 or newer', { skip: process.platform !== 'win32' && 'Windows only: the py launcher (runs on the Windows runner)' }, async () => {
  const found = await probe.probeCommand({ command: 'py', args: ['-3'], source: 'PATH' });
  assert.ok(!('why' in found) && probe.versionOk(found.version), JSON.stringify(found));
});
