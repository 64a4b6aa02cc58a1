// `make package` on a machine without the test stack: a copy of the repository (its files as git
// knows them, no node_modules, no .venv) is packaged with a PATH from which Chromium, code-server,
// Neovim and apt are missing. It must fill a fresh node_modules with only the build's packages
// (package-lock.json), never run the editor tests' setup, and leave a working cncmacro.vsix.
// It asks no registry: npm installs from its cache, which set-up's `npm ci` filled
// (--offline), and pip takes the wheels set-up kept in .cache/wheels (make setup).
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';
import { ROOT } from './codeServer.mjs';

const HIDDEN = /^(chromium.*|google-chrome.*|code-server|nvim|apt|apt-get|dpkg|sudo)$/;
const PYTHON = path.join(ROOT, '.venv', 'bin', 'python');
const WHEELS = path.join(ROOT, '.cache', 'wheels');
let work;

after(() => {
  if (work) fs.rmSync(work, { recursive: true, force: true });
});

/** The repository's files as git lists them (committed and new, not ignored) copied to `to`. */
function copyRepository(to) {
  const listed = spawnSync('git', ['ls-files', '-z', '--cached', '--others', '--exclude-standard'], {
    cwd: ROOT, encoding: 'utf8', maxBuffer: 64 * 1024 * 1024,
  });
  assert.equal(listed.status, 0, listed.stderr);
  for (const name of listed.stdout.split('\0').filter(Boolean)) {
    const from = path.join(ROOT, name);
    if (!fs.existsSync(from)) continue; // deleted in the work tree
    fs.mkdirSync(path.dirname(path.join(to, name)), { recursive: true });
    fs.copyFileSync(from, path.join(to, name));
  }
}

/** One folder of links to every program on PATH but the hidden ones: a machine without them. */
function pathWithout(bin) {
  fs.mkdirSync(bin);
  for (const dir of (process.env.PATH || '').split(path.delimiter)) {
    let names = [];
    try {
      names = fs.readdirSync(dir);
    } catch {
      continue;
    }
    for (const name of names) {
      if (HIDDEN.test(name) || fs.existsSync(path.join(bin, name))) continue;
      fs.symlinkSync(path.join(dir, name), path.join(bin, name));
    }
  }
  return bin;
}

test('make package works with only Python and npm ci: no Chromium, code-server or test stack', { timeout: 600000 }, () => {
  work = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-package-'));
  const repo = path.join(work, 'repo');
  copyRepository(repo);
  const bin = pathWithout(path.join(work, 'bin'));
  assert.ok(fs.existsSync(path.join(WHEELS, '.downloaded')), `no wheels in ${WHEELS}: run make setup`);
  const env = {
    ...process.env, PATH: bin, npm_config_offline: 'true', PIP_NO_INDEX: '1', PIP_FIND_LINKS: WHEELS,
  };
  for (const tool of ['chromium', 'code-server', 'apt-get']) {
    assert.notEqual(spawnSync('sh', ['-c', `command -v ${tool}`], { env }).status, 0, `${tool} must be hidden`);
  }

  const dry = spawnSync('make', ['-n', 'package', `PYTHON=${PYTHON}`], { cwd: repo, env, encoding: 'utf8' });
  assert.equal(dry.status, 0, dry.stderr);
  assert.doesNotMatch(dry.stdout, /setup-editor|apt-get|chromium|tests\/node_modules|pip install .*\[test\]/);

  const made = spawnSync('make', ['package', `PYTHON=${PYTHON}`], {
    cwd: repo, env, encoding: 'utf8', timeout: 540000, maxBuffer: 64 * 1024 * 1024,
  });
  assert.equal(made.status, 0, `make package failed:\n${made.stdout}\n${made.stderr}`);

  const installed = fs.readdirSync(path.join(repo, 'node_modules'));
  for (const name of ['code-server', 'playwright-core', 'vscode-tmgrammar-test']) {
    assert.ok(!installed.includes(name), `${name} is a test package, not one the build needs`);
  }
  assert.ok(!fs.existsSync(path.join(repo, 'node_modules', '@vscode', 'debugadapter-testsupport')));
  assert.ok(!fs.existsSync(path.join(repo, 'tests', 'node_modules')), 'the test stack was not installed');
  assert.ok(!fs.existsSync(path.join(repo, '.venv')), 'no virtual environment with the test tools was made');

  const listing = spawnSync('unzip', ['-l', path.join(repo, 'cncmacro.vsix')], { encoding: 'utf8' });
  assert.equal(listing.status, 0, listing.stderr);
  for (const file of ['extension/client/out/extension.js', 'extension/bundled/tool/cncmacro/__main__.py',
    'extension/bundled/libs/pygls/__init__.py', 'extension/package.json']) {
    assert.match(listing.stdout, new RegExp(file.replace(/[.]/g, '\\.')), `${file} is in the .vsix`);
  }
});
