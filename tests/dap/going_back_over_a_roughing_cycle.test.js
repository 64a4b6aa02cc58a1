// Going backwards over a lathe roughing cycle (docs/debugging.md, docs/semantics.md §10.2): a
// G71 is one step, its shape only read, so reverse continue (line, function and data
// breakpoints) and "run to here" stop where a forward run stops, never inside the shape while
// it is read. `cncmacro dap` driven through a real DAP client.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const dc = clientPerTest();
// tests/dap/programs/lathe_shaft.nc (fanuc-0i-lathe): G00 X62. Z2. (line 6), G71 P10 Q20 (line 8),
// the shape N10 (line 9) to N20 (line 14), G70 P10 Q20 (line 18), M30 (line 20).
const SHAFT = program('lathe_shaft.nc');

async function where() {
  const frames = (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames;
  return frames.map((f) => `${f.name}:${f.line}`).join(' < ');
}

// every stop of `request` until the run's end (forward) or the start of the history (back)
async function stops(request) {
  const seen = [];
  for (;;) {
    const event = await dc.step(request);
    if (event.body.reason === 'entry' || event.body.description === 'program end (M30)') return seen;
    seen.push(`${event.body.reason} ${event.body.description || ''} at ${await where()}`);
  }
}

describe('going back over a roughing cycle stops only where a forward run stops', () => {
  test('a line breakpoint in the shape: reverse continue stops in G70 only, then at the start', async () => {
    await dc.begin({ program: SHAFT }, { breakpoints: { 'lathe_shaft.nc': [{ line: 11 }] } });
    // the forward run stopped at line 11 as G70 ran it (the begin's stop); on to the end
    assert.equal(await where(), 'O7000 (G70 shape N10–N20):11 < O7000 (main):18');
    assert.equal((await dc.step('continueRequest')).body.description, 'program end (M30)');
    const back = await stops('reverseContinueRequest');
    assert.deepEqual(back, ['breakpoint  at O7000 (G70 shape N10–N20):11 < O7000 (main):18']);
  });

  test('a function breakpoint N20 and a data breakpoint on #5001 stop backwards where they stopped forwards', async () => {
    await dc.begin({ program: SHAFT, stopOnEntry: true }, { functionBreakpoints: ['N20'] });
    await dc.setDataBreakpointsRequest({ breakpoints: [{ dataId: '#5001' }] });
    const forward = await stops('continueRequest');
    // #5001 (X) changes after G00 X62. (0 -> 62); not after the whole G71 (its passes end where the
    // cycle began, X62); after G00 X100. (line 15) and G00 X62. (line 17); in G70's shape after X20.,
    // X30. and X45. (62 -> 20 -> 30 -> 45: the last stop is N20's own, which also stops before its
    // block); after G70, which returns to where it began (45 -> 62), and after G00 X100. (line 19).
    // N20 never stops while G71 only reads the shape.
    assert.deepEqual(forward, [
      'data breakpoint #5001 changed: 0 -> 62 at O7000 (main):7',
      'data breakpoint #5001 changed: 62 -> 100 at O7000 (main):16',
      'data breakpoint #5001 changed: 100 -> 62 at O7000 (main):18',
      'data breakpoint #5001 changed: 62 -> 20 at O7000 (G70 shape N10–N20):10 < O7000 (main):18',
      'data breakpoint #5001 changed: 20 -> 30 at O7000 (G70 shape N10–N20):12 < O7000 (main):18',
      'function breakpoint  at O7000 (G70 shape N10–N20):14 < O7000 (main):18',
      'data breakpoint #5001 changed: 45 -> 62 at O7000 (main):19',
      'data breakpoint #5001 changed: 62 -> 100 at O7000 (main):20',
    ]);
    const back = await stops('reverseContinueRequest');
    assert.deepEqual(back, [...forward].reverse());
  });

  test('run to here on a roughing pass stops at the G71 block in the main program, forward and back', async () => {
    await dc.begin({ program: SHAFT, stopOnEntry: true });
    const forward = dc.waitForEvent('stopped');
    await dc.customRequest('runToMove', { index: 10 }); // move 11: a G71 pass (move 1 is G00 X62. Z2.)
    assert.equal((await forward).body.reason, 'goto');
    assert.equal(await where(), 'O7000 (main):8');
    assert.equal(await dc.value('#5001'), '62');
    assert.equal((await dc.step('continueRequest')).body.description, 'program end (M30)');
    const back = dc.waitForEvent('stopped');
    await dc.customRequest('runToMove', { index: 10 });
    assert.equal((await back).body.reason, 'goto');
    assert.equal(await where(), 'O7000 (main):8');
    assert.equal(await dc.value('#5001'), '62');
  });

  test('run to here on a GSK980TDi roughing pass stops at its G71 block too', async () => {
    await dc.begin({ program: program('lathe_g71.nc'), stopOnEntry: true });
    const stopped = dc.waitForEvent('stopped');
    await dc.customRequest('runToMove', { index: 5 }); // moves 1 and 2: G00 X52. Z2.; then the passes
    assert.equal((await stopped).body.reason, 'goto');
    assert.equal(await where(), 'O0301 (main):5');
  });
});
