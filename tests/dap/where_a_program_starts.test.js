// docs/semantics.md §1 "Where a program starts": an O line that holds a sequence number
// (`O0300 N5`) is the program's first block, so the run begins on it and a breakpoint on it
// stops there, both at the start and where `GOTO 5` lands, through `cncmacro dap` and a real
// DAP client. Run from the repository root: `node --test tests/dap/`.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const dc = clientPerTest();

describe('where a program starts', () => {
  test('stop on entry stands on an O line that holds a sequence number', async () => {
    const { event } = await dc.begin({ program: program('labelled_header.nc'), stopOnEntry: true });
    assert.equal(event.body.reason, 'entry');
    assert.deepEqual([(await dc.top()).line, await dc.value('#4114')], [1, '0']); // before its N5 ran
    await dc.step('nextRequest');
    assert.deepEqual([(await dc.top()).line, await dc.value('#4114')], [2, '5']);
  });

  test('a breakpoint on that O line stops at the start and again where GOTO 5 lands', async () => {
    const { event, verified } = await dc.begin(
      { program: program('labelled_header.nc') },
      { breakpoints: { 'labelled_header.nc': [{ line: 1 }] } },
    );
    assert.deepEqual([verified['labelled_header.nc'][0].verified, verified['labelled_header.nc'][0].line], [true, 1]);
    assert.equal(event.body.reason, 'breakpoint');
    assert.deepEqual([(await dc.top()).line, await dc.value('#1')], [1, '<vacant>']); // the first block of the run
    const landed = await dc.step('continueRequest');
    assert.equal(landed.body.reason, 'breakpoint');
    assert.deepEqual([(await dc.top()).line, await dc.value('#1')], [1, '1']); // GOTO 5 landed here
    const end = await dc.step('continueRequest');
    assert.equal(end.body.description, 'program end (M30)');
  });
});
