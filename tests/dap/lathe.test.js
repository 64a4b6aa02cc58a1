// A lathe's roughing and finishing cycles through `cncmacro dap` and a real DAP client
// (docs/semantics.md §10.2): step over a G71 runs the whole roughing and lands after its shape;
// a breakpoint in the shape stops only when G70 runs it, in a stack frame of the shape; the
// roughing passes are in the toolpath by then. Run from the repository root: `node --test tests/dap/`.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const dc = clientPerTest();
// tests/dap/programs/lathe_g71.nc: G71 U2. R1. (line 4), G71 P10 Q20 … (line 5), the shape N10
// (line 6) to N20 (line 8), G70 P10 Q20 (line 9).

describe('a lathe roughing cycle in the debugger', () => {
  test('step over a G71 runs its roughing and lands on the G70 after the shape', async () => {
    await dc.begin({ program: program('lathe_g71.nc') }, { breakpoints: { 'lathe_g71.nc': [{ line: 5 }] } });
    assert.equal((await dc.top()).line, 5);
    const stop = await dc.step('nextRequest');
    assert.equal(stop.body.reason, 'step');
    const frame = await dc.top();
    assert.deepEqual([frame.name, frame.line], ['O0301 (main)', 9]);
  });

  test('a breakpoint in the shape stops only when G70 runs it, in the shape frame', async () => {
    const { event } = await dc.begin(
      { program: program('lathe_g71.nc'), stopAtEnd: false },
      { breakpoints: { 'lathe_g71.nc': [{ line: 7 }] } },
    );
    assert.equal(event.body.reason, 'breakpoint');
    const trace = (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames;
    assert.deepEqual(trace.map((f) => [f.name, f.line]), [['O0301 (G70 shape N10–N20)', 7], ['O0301 (main)', 9]]);
    const toolpath = (await dc.customRequest('toolpath')).body;
    const roughing = toolpath.moves.filter((mv) => mv.pass_of === 'G71');
    assert.ok(roughing.length > 20, `the roughing passes are drawn by now: ${roughing.length}`);
    const exited = dc.waitForEvent('exited');
    await dc.continueRequest({ threadId: 1 });
    assert.equal((await exited).body.exitCode, 0);
  });
});
