// `cncmacro dap` launched in a folder that anybody may have filled (docs/design.md "Untrusted
// folders and files"): a hostile machine file, or a program or machine file that is a FIFO, fails
// the launch with a message that names the file and what is wrong with it (never an "internal
// error", never a hang), and the adapter goes on: a good launch after it runs.
'use strict';

const assert = require('node:assert/strict');
const cp = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { afterEach, beforeEach, test } = require('node:test');
const { CncMacroClient } = require('./client.js');

let dc;
let folder;

beforeEach(async () => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-untrusted-'));
  fs.writeFileSync(path.join(folder, 'O0001.nc'), 'O0001\n#100=1\nM30\n');
  dc = new CncMacroClient();
  await dc.start();
});

afterEach(async () => {
  // an adapter stuck in a launch answers nothing, disconnect neither: it is stopped all the same
  let timer;
  await Promise.race([dc.stop(), new Promise((resolve) => { timer = setTimeout(resolve, 5000); })]);
  clearTimeout(timer);
  dc.stopAdapter();
  fs.rmSync(folder, { recursive: true, force: true });
});

const LIMIT = { timeout: 30000 }; // a launch that waits this long is stuck
const FIFOS = { ...LIMIT, skip: process.platform === 'win32' };

const HOSTILE = {
  'a superscript digit in [calls]': ['[calls]\n"G²" = 9000\n', /'calls\.G²' must be a G or M code/],
  'tables nested 10,000 deep': [`a = ${'{a = '.repeat(10000)}1${'}'.repeat(10000)}\n`, /nested too deeply/],
  'a table header 10,000 levels deep': [`[base${'.a'.repeat(10000)}]\n`, /'base' must be/],
  'text that is not UTF-8': [Buffer.from('base = "\xb3\xcc"\n', 'latin1'), /not UTF-8 text \(byte 0xb3 on line 1\)/],
};

async function launchFails(args, said) {
  const initialized = dc.waitForEvent('initialized');
  await dc.initializeRequest({ adapterID: 'cnc-macro', linesStartAt1: true, columnsStartAt1: true, pathFormat: 'path' });
  await initialized;
  await dc.configurationDoneRequest();
  const error = await dc.launchRequest({ noSave: true, ...args }).then(() => null, (e) => e);
  assert.ok(error, 'the launch was accepted');
  assert.match(error.message, said);
  assert.doesNotMatch(error.message, /internal error/);
}

async function goodLaunchRuns() {
  const ended = dc.waitForEvent('terminated');
  await dc.launchRequest({ program: path.join(folder, 'O0001.nc'), noSave: true, stopAtEnd: false });
  await ended;
}

for (const [name, [content, said]] of Object.entries(HOSTILE)) {
  test(`a machine file with ${name} fails the launch with a message that names it`, LIMIT, async () => {
    const machine = path.join(folder, '.cncmacro.toml');
    fs.writeFileSync(machine, content);
    await launchFails({ program: path.join(folder, 'O0001.nc') }, new RegExp(`${escape(machine)}: .*${said.source}`));
    fs.unlinkSync(machine);
    await goodLaunchRuns();
  });
}

test('a machine file that is a FIFO fails the launch at once', FIFOS, async () => {
  const fifo = path.join(folder, 'machine.toml');
  cp.execFileSync('mkfifo', [fifo]);
  await launchFails(
    { program: path.join(folder, 'O0001.nc'), machine: fifo },
    new RegExp(`${escape(fifo)}: a FIFO \\(named pipe\\), not a file: not read \\(the machine file\\)`),
  );
  await goodLaunchRuns();
});

test('a program that is a FIFO fails the launch at once', FIFOS, async () => {
  const fifo = path.join(folder, 'O1234.nc');
  cp.execFileSync('mkfifo', [fifo]);
  await launchFails({ program: fifo }, /a FIFO \(named pipe\), not a file: not read/);
  await goodLaunchRuns();
});

function escape(text) {
  return text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
}
