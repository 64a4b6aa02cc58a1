// `cncmacro dap` at the edges, through a real DAP client: a second launch while a program runs
// is refused and the first stays in reach; a message nested too deeply to read is refused and
// the adapter goes on; a run without debugging that prints without end keeps its memory; a
// session that saves #500-#999 has them until it ends, and a `cncmacro run` meanwhile waits.
'use strict';

const assert = require('node:assert/strict');
const cp = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { afterEach, beforeEach, describe, test } = require('node:test');
const { CncMacroClient, program, PYTHON, ROOT } = require('./client.js');

let dc;

beforeEach(async () => {
  dc = new CncMacroClient();
  await dc.start();
});

afterEach(async () => {
  await dc.stop();
});

function residentMb(pid, field) {
  const status = fs.readFileSync(`/proc/${pid}/status`, 'utf8');
  const line = status.split('\n').find((l) => l.startsWith(field));
  return Number(line.split(/\s+/)[1]) / 1024;
}

describe('the edges of the adapter', () => {
  test('a second launch while a program runs is refused, and the first stays in reach', async () => {
    await dc.begin({ program: program('main.nc'), stopOnEntry: true });
    await assert.rejects(dc.launchRequest({ program: program('loop.nc'), noSave: true }), /already running/);
    assert.equal((await dc.top()).line, 2);
    const next = await dc.step('nextRequest');
    assert.equal(next.body.reason, 'step');
    assert.equal((await dc.top()).line, 3);
    const answered = await Promise.race([
      dc.disconnectRequest({ terminateDebuggee: true }).then(() => 'answered'),
      new Promise((resolve) => setTimeout(() => resolve('no answer within 5 s'), 5000)),
    ]);
    assert.equal(answered, 'answered', 'disconnect after a refused second launch');
    dc = new CncMacroClient(); // the adapter has ended: afterEach stops a fresh one
    await dc.start();
  });

  test('a preset beyond what a variable holds is refused at launch, naming the variable', async () => {
    // 1e50 is a finite number, but beyond the control's ±1e47: it used to stop the run with an internal error
    await assert.rejects(dc.launchRequest({ program: program('main.nc'), noSave: true, set: { 500: 1e50 } }),
      /#500 = 1e\+50 is beyond what a variable holds/);
  });

  test('a header line of 30 MB is read past without being held, and the adapter goes on', async () => {
    // it used to be read whole: 300 MB took the adapter to 928 MB, 600 MB under a 1 GB limit killed it
    await dc.begin({ program: program('main.nc'), stopOnEntry: true });
    const pid = dc._adapterProcess.pid;
    const measured = fs.existsSync('/proc/self/status');
    const before = measured ? residentMb(pid, 'VmHWM') : 0;
    dc._adapterProcess.stdin.write('X'.repeat(30 * 1024 * 1024) + '\r\n');
    const threads = await dc.threadsRequest();
    assert.equal(threads.body.threads.length, 1);
    assert.equal((await dc.top()).line, 2);
    if (measured) {
      const grown = residentMb(pid, 'VmHWM') - before;
      assert.ok(grown < 15, `the adapter's peak grew by ${grown.toFixed(0)} MB for a 30 MB line`);
    }
  });

  test('a program path with a NUL character is refused with a message, not an internal error', async () => {
    await dc.initializeRequest({ adapterID: 'cnc-macro', linesStartAt1: true, columnsStartAt1: true, pathFormat: 'path' });
    await assert.rejects(dc.launchRequest({ program: `${program('main.nc')}\u0000.nc`, noSave: true }),
      /'program' holds a NUL character, which no file name has/);
  });

  test('#1e400 names no variable: not set as #1, and no data breakpoint is offered for it', async () => {
    await dc.begin({ program: program('main.nc'), stopOnEntry: true });
    const { scope } = await dc.scopeVariables((await dc.top()).id, 'Local');
    await assert.rejects(dc.setVariableRequest({ variablesReference: scope.variablesReference, name: '#1e400',
      value: '7' }), /is not a # variable/);
    assert.equal(await dc.value('#1'), '<vacant>');
    for (const name of ['#1e400', '#123456']) { // what setDataBreakpoints would refuse is never offered
      const info = await dc.dataBreakpointInfoRequest({ variablesReference: scope.variablesReference, name });
      assert.equal(info.body.dataId, null, name);
    }
  });

  test('a run halted by disconnect sends no stopped event after it', async () => {
    await dc.begin({ program: program('endless.nc'), stopOnEntry: true, maxBlocks: 1000000000 });
    const after = [];
    let disconnected = false;
    dc.on('stopped', () => { if (disconnected) after.push('stopped'); });
    await dc.continueRequest({ threadId: 1 });
    await new Promise((resolve) => setTimeout(resolve, 300)); // it runs
    disconnected = true; // from the request on: the halted run is heard of no more
    await dc.disconnectRequest({ terminateDebuggee: true });
    await new Promise((resolve) => setTimeout(resolve, 500));
    assert.deepEqual(after, []);
    dc = new CncMacroClient(); // the adapter has ended: afterEach stops a fresh one
    await dc.start();
  });

  test('a message nested too deeply to read is refused and the adapter goes on', async () => {
    await dc.begin({ program: program('main.nc'), stopOnEntry: true });
    const body = '['.repeat(100000) + ']'.repeat(100000);
    dc._adapterProcess.stdin.write(`Content-Length: ${body.length}\r\n\r\n${body}`);
    const threads = await dc.threadsRequest();
    assert.equal(threads.body.threads.length, 1);
    assert.equal((await dc.top()).line, 2);
  });

  test('running without debugging a program that prints without end keeps the memory of the adapter', async () => {
    if (!fs.existsSync('/proc/self/status')) return;
    const pid = dc._adapterProcess.pid;
    const ended = dc.waitForEvent('terminated', 60000);
    await dc.begin({ program: program('printing.nc'), noDebug: true, maxBlocks: 600000 }, { until: 'initialized' });
    const start = residentMb(pid, 'VmRSS');
    await ended;
    assert.ok(dc.output.includes('LINE'), 'the printed lines reach the console');
    const peak = residentMb(pid, 'VmHWM');
    assert.ok(peak - start < 40, `the adapter grew from ${start.toFixed(0)} to ${peak.toFixed(0)} MB`);
  });

  test('a session that saves #500 has them until it ends: a cncmacro run meanwhile waits and says so', async () => {
    const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-dap-'));
    const main = path.join(folder, 'O0001.nc');
    fs.writeFileSync(main, 'O0001\n#500=#500+1\nM30\n');
    const run = () => cp.spawnSync(PYTHON,
      ['-m', 'cncmacro', 'run', '--wait', '0.2', main], { encoding: 'utf8', timeout: 30000 });
    try {
      await dc.begin({ program: main, stopOnEntry: true, noSave: false });
      await dc.step('nextRequest');
      const waited = run();
      assert.equal(waited.status, 2, waited.stdout);
      assert.match(waited.stderr, /in use by another run or debug session \(process \d+\)/);
      const terminated = dc.waitForEvent('terminated');
      await dc.terminateRequest({});
      await terminated;
      const after = run();
      assert.equal(after.status, 0, after.stderr);
      const saved = JSON.parse(fs.readFileSync(path.join(folder, '.cncmacro-vars.json'), 'utf8'));
      assert.deepEqual(saved.variables, { 500: 2 });
    } finally {
      fs.rmSync(folder, { recursive: true, force: true });
    }
  });
});
