// `cncmacro dap` at the edges, through a real DAP client: a second launch while a program runs
// is refused and the first stays in reach; a message nested too deeply to read is refused and
// the adapter goes on; a run without debugging that prints without end keeps its memory.
'use strict';

const assert = require('node:assert/strict');
const fs = require('node:fs');
const { afterEach, beforeEach, describe, test } = require('node:test');
const { CncMacroClient, program } = require('./client.js');

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
});
