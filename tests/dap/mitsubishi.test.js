// A Mitsubishi M70/M80 program (the launch's dialect `mitsubishi-m70`) through `cncmacro dap` and a
// real DAP client: stepping over a block IF [cond] THEN whose condition
// fails lands on the first block after its ELSE; stepping to the end of that branch stops on its
// ENDIF; where the condition holds, the step from the last block of the THEN branch stops on the
// ELSE, whose next step goes on after the ENDIF. Read as fanuc-0i the same text stops at the first IF
// with alarm 114.
// Run from the repository root: `node --test tests/dap/`.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

// tests/dap/programs/mitsubishi_block_if.nc, line by line:
//  1 O1000 (BLOCK IF)                        9 ENDIF
//  2 #1=3                                   10 #3=#2+1
//  3 IF [#1 GT 5] THEN                      11 IF [#3 EQ 21] THEN
//  4   #2=10                                12   #4=1
//  5   G01 X10. F100                        13 ELSE
//  6 ELSE                                   14   #4=2
//  7   #2=20                                15 ENDIF
//  8   G01 X20. F100                        16 M30
const M70 = 'mitsubishi_block_if.nc';

const dc = clientPerTest();

async function line() {
  return (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames[0].line;
}

describe('a Mitsubishi block IF in the debugger', () => {
  test('stepping through IF..ELSE..ENDIF visits only the branch that runs', async () => {
    const { event } = await dc.begin({ program: program(M70), dialect: 'mitsubishi-m70' },
      { breakpoints: { [M70]: [{ line: 3 }] } });
    assert.equal(event.body.reason, 'breakpoint');
    // 3 GT 5 fails: the step from the IF lands after the ELSE, passing over lines 4 and 5
    await dc.step('nextRequest');
    assert.equal(await line(), 7);
    await dc.step('nextRequest'); // #2=20
    await dc.step('nextRequest'); // G01 X20.
    assert.equal(await line(), 9); // the ENDIF ends the ELSE branch
    assert.deepEqual([await dc.value('#2'), await dc.value('#5001')], ['20', '20']);
    await dc.step('nextRequest');
    assert.equal(await line(), 10);
    await dc.step('nextRequest'); // #3 = 20 + 1 = 21
    await dc.step('nextRequest'); // 21 EQ 21 holds: into the THEN branch
    assert.equal(await line(), 12);
    await dc.step('nextRequest'); // #4=1, then the ELSE that ends the THEN branch
    assert.equal(await line(), 13);
    await dc.step('nextRequest'); // the ELSE goes on after the ENDIF, passing over line 14
    assert.equal(await line(), 16);
    assert.deepEqual([await dc.value('#3'), await dc.value('#4')], ['21', '1']);
  });

  test('read as fanuc-0i the first IF [..] THEN stops with alarm 114', async () => {
    const { event } = await dc.begin({ program: program(M70), dialect: 'fanuc-0i' });
    assert.equal(event.body.reason, 'exception');
    assert.match(event.body.text, /114/);
    assert.equal(await line(), 3);
  });
});
