// A Mazak EIA/ISO program (the launch's dialect `mazak-eia`) through `cncmacro dap` and a real DAP
// client: `&&` and `||` are AND and OR there, so the IF whose two conditions hold jumps over line
// 5, the loop written `WH` runs twice, and the `||` condition holds on its first pass only. Read
// as fanuc-0i the same text stops at the first `&&` with alarm 114 (FANUC writes AND).
// Run from the repository root: `node --test tests/dap/`.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

// tests/dap/programs/mazak_logical.nc, line by line:
//  1 O2000 (MAZAK AND OR)                          6 N10 WH [#2 LT 2] DO1
//  2 #1=3                                          7 IF [[#2 EQ 0] || [#2 EQ 5]] THEN #3=7
//  3 #2=0                                          8 #2=#2+1
//  4 IF [[#1 GT 0] && [#1 LT 5]] GOTO 10           9 END1
//  5 #2=9                                         10 M30
const MAZAK = 'mazak_logical.nc';

const dc = clientPerTest();

async function line() {
  return (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames[0].line;
}

describe('a Mazak program with && and || in the debugger', () => {
  test('&& and || are AND and OR: the IF jumps, the loop runs twice, the THEN runs once', async () => {
    const { event } = await dc.begin({ program: program(MAZAK), dialect: 'mazak-eia' },
      { breakpoints: { [MAZAK]: [{ line: 4 }] } });
    assert.equal(event.body.reason, 'breakpoint');
    // 3 GT 0 and 3 LT 5 both hold: the GOTO 10 passes over line 5
    await dc.step('nextRequest');
    assert.equal(await line(), 6);
    await dc.step('nextRequest'); // 0 LT 2: into the loop
    assert.equal(await line(), 7);
    await dc.step('nextRequest'); // 0 EQ 0 holds: #3 = 7
    assert.equal(await dc.value('#3'), '7');
    await dc.step('nextRequest'); // #2 = 1
    await dc.step('nextRequest'); // END1: back to the WH
    assert.equal(await line(), 6);
    await dc.step('nextRequest'); // 1 LT 2: a second pass
    await dc.step('nextRequest'); // 1 EQ 0 or 1 EQ 5: neither holds, #3 stays
    await dc.step('nextRequest'); // #2 = 2
    await dc.step('nextRequest'); // END1
    await dc.step('nextRequest'); // 2 LT 2 fails: on to M30
    assert.equal(await line(), 10);
    assert.deepEqual([await dc.value('#2'), await dc.value('#3')], ['2', '7']);
  });

  test('read as fanuc-0i the first && stops with alarm 114', async () => {
    const { event } = await dc.begin({ program: program(MAZAK), dialect: 'fanuc-0i' });
    assert.equal(event.body.reason, 'exception');
    assert.match(event.body.text, /114/);
    assert.equal(await line(), 4);
  });
});
