// A data breakpoint on a local (#1–#33) watches the local of one macro level, the one of the
// frame it was set from (docs/debugging.md): a G65 call or an M99 return that only switches
// levels is no change, and a block of another level that writes its own #1 does not stop.
// `cncmacro dap` driven through a real DAP client.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const dc = clientPerTest();
// tests/dap/programs/local_watch.nc: #1=111 (line 3), G65 P8001 A1. (line 4), #1=#1+1 (line 5), M30.
// O8001 (level 1): #10=#1+1 (2), G65 P8002 A30. (3), #1=5 (4), M99 (5).
// O8002 (level 2): #1=#1+1 (2), M98 P8003 (3: shares level 2's locals, #1=#1*2), M99 (4).

async function stops(request) {
  const seen = [];
  for (;;) {
    const event = await dc.step(request);
    if (event.body.reason === 'entry' || event.body.description === 'program end (M30)') return seen;
    const top = await dc.top();
    seen.push(`${event.body.description} at ${top.name}:${top.line}`);
  }
}

async function watch(frameId) {
  const { scope } = await dc.scopeVariables(frameId, 'Local');
  const info = await dc.dataBreakpointInfoRequest({ variablesReference: scope.variablesReference, name: '#1' });
  const set = await dc.setDataBreakpointsRequest({ breakpoints: [{ dataId: info.body.dataId }] });
  assert.equal(set.body.breakpoints[0].verified, true);
  return info.body;
}

describe('a data breakpoint on a local', () => {
  test("main's #1 stops only where main writes it, not at the calls and returns", async () => {
    await dc.begin({ program: program('local_watch.nc'), stopOnEntry: true });
    const info = await watch((await dc.top()).id);
    assert.equal(info.description, 'when #1 of the main program changes');
    // #1=111 (vacant -> 111, stop before line 4), #1=#1+1 (111 -> 112, stop before line 6); the
    // levels below write their own #1 (1, 30, 31, 62, 5): none of them stops
    const forward = await stops('continueRequest');
    assert.deepEqual(forward, [
      '#1 changed: vacant -> 111 at O8000 (main):4',
      '#1 changed: 111 -> 112 at O8000 (main):6',
    ]);
    assert.deepEqual(await stops('reverseContinueRequest'), [...forward].reverse());
  });

  test("level 1's #1, set from its frame, stops where level 1 writes it, and its M98 callee's writes count at level 2 only", async () => {
    await dc.begin(
      { program: program('local_watch.nc') },
      { breakpoints: { 'O8001.nc': [{ line: 2 }] } },
    );
    const top = await dc.top();
    assert.equal(top.name, 'O8001 (G65, level 1)');
    const info = await watch(top.id);
    assert.equal(info.description, 'when #1 of macro level 1 changes');
    await dc.setBreakpointsRequest({ source: { path: program('O8001.nc') }, breakpoints: [] });
    // level 2 writes its #1 (30 -> 31, then 62 in O8003 through M98): not level 1's; #1=5 at
    // line 4 is (1 -> 5, stop before line 5); main's #1=#1+1 is not
    const forward = await stops('continueRequest');
    assert.deepEqual(forward, ['#1 changed: 1 -> 5 at O8001 (G65, level 1):5']);
    // going back, the G65 P8001 A1. that began this level wrote its #1 (its locals start vacant)
    assert.deepEqual(await stops('reverseContinueRequest'), [...forward, '#1 changed: vacant -> 1 at O8001 (G65, level 1):2']);
  });
});
