// What the adapter reads, through a real DAP client: `source` and `setBreakpoints` read program
// files under the launch's folders only (a link leading out of them is not followed), regular
// files only, opened without blocking, up to a size; a launch of a pipe or a device is a clear
// error. Nothing here may hang: each test has a timeout.
'use strict';

const assert = require('node:assert/strict');
const cp = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { after, afterEach, before, beforeEach, describe, test } = require('node:test');
const { CncMacroClient } = require('./client.js');

const PROMPT = { timeout: 8000 };
const SECRET = 'root:SECRET-TOKEN:19000:0:99999:7:::\n';

let dc;
let top; // a temporary folder: `shop` (the launch's folder) and `outside` beside it
let shop;
let outside;

before(() => {
  top = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-dap-'));
  shop = path.join(top, 'shop');
  outside = path.join(top, 'outside');
  fs.mkdirSync(shop);
  fs.mkdirSync(outside);
  fs.writeFileSync(path.join(shop, '.cncmacro.toml'), ''); // the nearest machine file: the shop folder
  fs.writeFileSync(path.join(shop, 'main.nc'), 'O0001 (MAIN)\n#100=1\nG65 P9100 A2.\n#101=#100\nM30\n');
  fs.writeFileSync(path.join(shop, 'O9100.nc'), 'O9100 (CALLED)\n(A IS #1)\n#100=#1*2\nM99\n');
  fs.writeFileSync(path.join(outside, 'shadow'), SECRET);
  fs.writeFileSync(path.join(outside, 'O9200.nc'), 'O9200\n#100=9\nM99\n');
  fs.symlinkSync(path.join(outside, 'shadow'), path.join(shop, 'leak.nc'));
  fs.symlinkSync('/dev/zero', path.join(shop, 'zero.nc'));
  cp.execFileSync('mkfifo', [path.join(shop, 'pipe.nc')]);
  fs.closeSync(fs.openSync(path.join(shop, 'huge.nc'), 'w'));
  fs.truncateSync(path.join(shop, 'huge.nc'), 100_000_000); // sparse: 100 MB on paper, nothing on disk
});

after(() => {
  fs.rmSync(top, { recursive: true, force: true });
});

beforeEach(async () => {
  dc = new CncMacroClient();
  await dc.start();
});

afterEach(() => {
  dc.stopAdapter(); // no disconnect: an adapter stuck on a pipe would never answer it
});

function inShop(name) {
  return path.join(shop, name);
}

async function stoppedInMain() {
  return dc.begin({ program: inShop('main.nc'), stopOnEntry: true });
}

async function initialized() {
  const ready = dc.waitForEvent('initialized');
  await dc.initializeRequest({ adapterID: 'cnc-macro', linesStartAt1: true, columnsStartAt1: true, pathFormat: 'path' });
  await ready;
}

describe('source', () => {
  test('a link in the launch folder that leads out of it is refused, its target unread', PROMPT, async () => {
    await stoppedInMain();
    const refused = await dc.sourceRequest({ source: { path: inShop('leak.nc') } }).then(
      () => null, (e) => e.message);
    assert.ok(refused !== null, 'the link was served');
    assert.match(refused, /not under .*shop/);
    assert.ok(!refused.includes('SECRET'), refused);
  });

  test('a link to /dev/zero is refused at once, and so is /dev/zero itself', PROMPT, async () => {
    await stoppedInMain();
    await assert.rejects(dc.sourceRequest({ source: { path: inShop('zero.nc') } }), /not under/);
    await assert.rejects(dc.sourceRequest({ source: { path: '/dev/zero' } }), /not a program file/);
    assert.equal((await dc.top()).line, 2); // the session goes on
  });

  test('a pipe named like a program is refused at once, never waited on', PROMPT, async () => {
    await stoppedInMain();
    await assert.rejects(dc.sourceRequest({ source: { path: inShop('pipe.nc') } }), /a FIFO \(named pipe\), not a file/);
    assert.equal((await dc.top()).line, 2);
  });

  test('a program file over the size limit is refused at once, unread', PROMPT, async () => {
    await stoppedInMain();
    await assert.rejects(dc.sourceRequest({ source: { path: inShop('huge.nc') } }),
      /huge\.nc: 100,000,000 bytes, over the limit of 64,000,000: not read/);
    assert.equal((await dc.top()).line, 2);
  });

  test('the launched program and the macro it calls are shown', PROMPT, async () => {
    await stoppedInMain();
    const main = await dc.sourceRequest({ source: { path: inShop('main.nc') } });
    assert.match(main.body.content, /^O0001 \(MAIN\)/);
    const called = await dc.sourceRequest({ source: { path: inShop('O9100.nc') } });
    assert.match(called.body.content, /#100=#1\*2/);
  });
});

describe('setBreakpoints', () => {
  test('on a pipe: answered at once, unverified, saying why', PROMPT, async () => {
    await initialized();
    const set = await dc.setBreakpointsRequest({ source: { path: inShop('pipe.nc') }, breakpoints: [{ line: 2 }] });
    const [bp] = set.body.breakpoints;
    assert.equal(bp.verified, false);
    assert.match(bp.message, /pipe\.nc: a FIFO \(named pipe\), not a file/);
  });

  test('on /dev/zero: answered at once, unverified, saying why', PROMPT, async () => {
    await stoppedInMain();
    const set = await dc.setBreakpointsRequest({ source: { path: '/dev/zero' }, breakpoints: [{ line: 1 }] });
    assert.deepEqual([set.body.breakpoints[0].verified, set.body.breakpoints[0].message],
      [false, '/dev/zero: not a program file']);
    assert.equal((await dc.top()).line, 2);
  });

  test('on a file over the size limit: answered at once, unverified, saying why', PROMPT, async () => {
    await stoppedInMain();
    const set = await dc.setBreakpointsRequest({ source: { path: inShop('huge.nc') }, breakpoints: [{ line: 1 }] });
    assert.equal(set.body.breakpoints[0].verified, false);
    assert.match(set.body.breakpoints[0].message, /100,000,000 bytes, over the limit of 64,000,000/);
  });

  test('on a link leading out of the launch folder: unverified', PROMPT, async () => {
    await stoppedInMain();
    const set = await dc.setBreakpointsRequest({ source: { path: inShop('leak.nc') }, breakpoints: [{ line: 1 }] });
    assert.equal(set.body.breakpoints[0].verified, false);
    assert.match(set.body.breakpoints[0].message, /not under/);
  });

  test('set before the launch in a file outside its folders: unverified when the launch comes', PROMPT, async () => {
    const changed = [];
    dc.on('breakpoint', (e) => changed.push(e.body.breakpoint));
    await initialized();
    const outsider = path.join(outside, 'O9200.nc');
    const set = await dc.setBreakpointsRequest({ source: { path: outsider }, breakpoints: [{ line: 2 }] });
    const { id } = set.body.breakpoints[0];
    await dc.configurationDoneRequest();
    const stopped = dc.waitForEvent('stopped');
    await dc.launchRequest({ program: inShop('main.nc'), stopOnEntry: true, noSave: true });
    await stopped;
    const mine = changed.filter((b) => b.id === id);
    assert.equal(mine.length, 1, JSON.stringify(changed));
    assert.equal(mine[0].verified, false);
    assert.match(mine[0].message, /not under .*shop/);
  });

  test('in the launched program and in the macro it calls: verified, and the run stops there', PROMPT, async () => {
    await stoppedInMain();
    const inMain = await dc.setBreakpointsRequest({ source: { path: inShop('main.nc') }, breakpoints: [{ line: 4 }] });
    const inMacro = await dc.setBreakpointsRequest({ source: { path: inShop('O9100.nc') }, breakpoints: [{ line: 2 }] });
    assert.deepEqual([inMain.body.breakpoints[0].verified, inMacro.body.breakpoints[0].verified], [true, true]);
    assert.equal(inMacro.body.breakpoints[0].line, 3);
    await dc.step('continueRequest');
    const frame = await dc.top();
    assert.deepEqual([path.basename(frame.source.path), frame.line], ['O9100.nc', 3]);
    await dc.step('continueRequest');
    assert.deepEqual([path.basename((await dc.top()).source.path), (await dc.top()).line], ['main.nc', 4]);
  });
});

describe('launch', () => {
  for (const [what, program, why] of [
    ['a pipe', () => inShop('pipe.nc'), /pipe\.nc: a FIFO \(named pipe\), not a file/],
    ['/dev/zero', () => '/dev/zero', /\/dev\/zero: a device, not a file/],
  ]) {
    test(`of ${what} is a clear error, at once`, PROMPT, async () => {
      await initialized();
      await dc.configurationDoneRequest();
      await assert.rejects(dc.launchRequest({ program: program(), noSave: true }), why);
      assert.equal((await dc.threadsRequest()).body.threads.length, 1); // the adapter goes on
    });
  }
});
