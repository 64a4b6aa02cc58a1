// The server as the .vsix ships it, started by the oldest and the newest Python on this machine
// (tests/pythons.py finds them): the built cncmacro.vsix is unpacked, each interpreter gets a
// bare venv (no pip, no site-packages, as a shop PC's Python), and the server runs from the
// package's bundled/tool and bundled/libs on PYTHONPATH, as the extension starts it
// (client/src/serverProcess.ts). One LSP session each: initialize names the server and its
// version, and an open program gets its diagnostics, read with the folder's machine file.
import assert from 'node:assert/strict';
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { ROOT } from './codeServer.mjs';

const VSIX = path.join(ROOT, 'cncmacro.vsix');
const VENV_PYTHON = path.join(ROOT, '.venv', 'bin', 'python');
const VERSION = JSON.parse(fs.readFileSync(path.join(ROOT, 'package.json'), 'utf8')).version;
const MAIN = `O1000 (CALLS A PROBING MACRO KEPT ON THE CONTROL)
G65 P8810 Z-5.
GOTO 99
M30
`;
// Without this machine file O8810 would be program-not-found: the finding proves it was read
// (with tomllib, or tomli on Python 3.10).
const MACHINE = 'programs_on_control = ["O8000-O8999"]\n';

let unpacked;
const found = JSON.parse(spawnSync(VENV_PYTHON, [path.join(ROOT, 'tests', 'pythons.py')], { encoding: 'utf8' }).stdout || '[]');

before(() => {
  unpacked = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-vsix-'));
  const unzip = spawnSync('unzip', ['-q', VSIX, '-d', unpacked], { encoding: 'utf8' });
  assert.equal(unzip.status, 0, `unzip ${VSIX}: ${unzip.stderr}`);
});

after(() => {
  if (unpacked) fs.rmSync(unpacked, { recursive: true, force: true });
});

/** A minimal LSP client over a child's stdio: requests, notifications, and the messages it got. */
class LspPipe {
  constructor(child) {
    this.child = child;
    this.buffer = Buffer.alloc(0);
    this.messages = [];
    this.waiters = [];
    this.nextId = 1;
    child.stdout.on('data', (chunk) => this.receive(chunk));
  }

  receive(chunk) {
    this.buffer = Buffer.concat([this.buffer, chunk]);
    for (;;) {
      const end = this.buffer.indexOf('\r\n\r\n');
      if (end < 0) return;
      const length = Number(/Content-Length: (\d+)/i.exec(this.buffer.subarray(0, end).toString('ascii'))[1]);
      if (this.buffer.length < end + 4 + length) return;
      const message = JSON.parse(this.buffer.subarray(end + 4, end + 4 + length).toString('utf8'));
      this.buffer = this.buffer.subarray(end + 4 + length);
      if (message.method && message.id !== undefined) this.send({ jsonrpc: '2.0', id: message.id, result: null });
      this.messages.push(message);
      for (const w of [...this.waiters]) w();
    }
  }

  send(message) {
    const body = Buffer.from(JSON.stringify(message), 'utf8');
    this.child.stdin.write(`Content-Length: ${body.length}\r\n\r\n`);
    this.child.stdin.write(body);
  }

  waitFor(predicate, what, timeoutMs = 60000) {
    return new Promise((resolve, reject) => {
      const check = () => {
        const hit = this.messages.find(predicate);
        if (!hit) return false;
        this.waiters = this.waiters.filter((w) => w !== check);
        clearTimeout(timer);
        resolve(hit);
        return true;
      };
      const timer = setTimeout(() => {
        this.waiters = this.waiters.filter((w) => w !== check);
        reject(new Error(`no ${what} within ${timeoutMs / 1000} s`));
      }, timeoutMs);
      this.waiters.push(check);
      check();
    });
  }

  request(method, params) {
    const id = this.nextId++;
    this.send({ jsonrpc: '2.0', id, method, params });
    return this.waitFor((m) => m.id === id && m.method === undefined, `answer to ${method}`);
  }

  notify(method, params) {
    this.send({ jsonrpc: '2.0', method, params });
  }
}

for (const python of found) {
  test(`the server in the .vsix runs under Python ${python.version} with nothing installed`, { timeout: 180000 }, async () => {
    const base = fs.mkdtempSync(path.join(os.tmpdir(), `cncmacro-py${python.version}-`));
    try {
      const venv = path.join(base, 'venv');
      const made = spawnSync(python.executable, ['-m', 'venv', '--without-pip', venv], { encoding: 'utf8' });
      assert.equal(made.status, 0, made.stderr);
      const bare = path.join(venv, 'bin', 'python');
      assert.notEqual(spawnSync(bare, ['-c', 'import pygls']).status, 0, 'the bare venv must not have pygls of its own');
      const folder = path.join(base, 'shop');
      fs.mkdirSync(folder);
      fs.writeFileSync(path.join(folder, 'O1000.nc'), MAIN);
      fs.writeFileSync(path.join(folder, '.cncmacro.toml'), MACHINE);
      const extension = path.join(unpacked, 'extension');
      const child = spawn(bare, ['-m', 'cncmacro', 'lsp'], {
        cwd: folder,
        env: {
          PATH: process.env.PATH,
          HOME: base,
          PYTHONPATH: [path.join(extension, 'bundled', 'tool'), path.join(extension, 'bundled', 'libs')].join(path.delimiter),
          PYTHONUTF8: '1',
        },
      });
      let stderr = '';
      child.stderr.on('data', (d) => { stderr += d; });
      const exited = new Promise((resolve) => child.on('exit', (code) => resolve(code)));
      const lsp = new LspPipe(child);
      const uri = `file://${path.join(folder, 'O1000.nc')}`;

      const init = await lsp.request('initialize', {
        processId: process.pid, rootUri: `file://${folder}`, capabilities: {},
        workspaceFolders: [{ uri: `file://${folder}`, name: 'shop' }],
      });
      assert.equal(init.error, undefined, `${JSON.stringify(init.error)}\n${stderr}`);
      assert.deepEqual(init.result.serverInfo, { name: 'cncmacro', version: VERSION });
      lsp.notify('initialized', {});
      lsp.notify('textDocument/didOpen', { textDocument: { uri, languageId: 'cnc-macro', version: 1, text: MAIN } });
      const published = await lsp.waitFor(
        (m) => m.method === 'textDocument/publishDiagnostics' && m.params.uri === uri && m.params.diagnostics.length > 0,
        'diagnostics for O1000.nc',
      );
      const codes = published.params.diagnostics.map((d) => d.code);
      assert.ok(codes.includes('undefined-label'), `GOTO 99 is found: ${JSON.stringify(codes)}`);
      assert.ok(!codes.includes('program-not-found'), `O8810 is on the control: ${JSON.stringify(codes)}`);

      await lsp.request('shutdown', null);
      lsp.notify('exit', null);
      assert.equal(await exited, 0, stderr);
    } finally {
      fs.rmSync(base, { recursive: true, force: true });
    }
  });
}

test('the oldest and the newest Python were found, or the run says which is missing', () => {
  if (found.length < 2) {
    console.log(`  only ${found.map((p) => p.version).join(', ') || 'no'} supported Python found: the other run was skipped`);
  }
  assert.ok(found.length >= 1, 'at least the Python that runs the tests is supported');
});
