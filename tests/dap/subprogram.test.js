// A subprogram launched on its own, through `cncmacro dap` and a real DAP client: as with
// `cncmacro run`, it ends at its M99 after one pass and the Debug Console says it is a
// subprogram and names the programs in its folder that call it (in Chinese under a Chinese
// locale); `"repeat": true` keeps the control's loop; a `repeat` that is not true or false is
// refused with the reason. Run from the repository root: `node --test tests/dap/`.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const dc = clientPerTest();

// tests/dap/programs/O0200.nc is `#103=7`, `#104=#103+1`, `M99`; main.nc calls it with M98 P0200.
const SENTENCE =
  'O0200.nc ends in M99: it is a subprogram, which returns to the program that calls it. ' +
  'Run on its own it stopped at the M99 after one pass ("repeat": true runs it again from its start, ' +
  'as a control runs a main program that ends in M99).\n' +
  'called by: main.nc (O0001)\n';

describe('a subprogram launched on its own', () => {
  test('ends at its M99 after one pass and the console says it is a subprogram called by main.nc', async () => {
    const { event } = await dc.begin({ program: program('O0200.nc') });
    assert.deepEqual([event.body.reason, event.body.description], ['step', 'program end (M99)']);
    assert.equal((await dc.top()).line, 5); // the M99, with the final values to look at
    assert.deepEqual([await dc.value('#103'), await dc.value('#104')], ['7', '8']);
    assert.ok(dc.output.includes(SENTENCE), dc.output);

    const exited = dc.waitForEvent('exited');
    const terminated = dc.waitForEvent('terminated');
    await dc.continueRequest({ threadId: 1 });
    assert.equal((await exited).body.exitCode, 0);
    await terminated;
    assert.match(dc.output, /status: completed after 3 blocks\n/);
    assert.equal(dc.output.split('called by:').length, 2, 'the sentence is said once');
  });

  test('the sentence and the callers are in Chinese under a Chinese locale', async () => {
    await dc.begin({ program: program('O0200.nc'), stopAtEnd: false }, { locale: 'zh-CN', until: 'terminated' });
    assert.ok(dc.output.includes(
      'O0200.nc 以 M99 结束：这是子程序，执行完返回调用它的程序。单独运行时执行一遍后在 M99 处停止' +
      '（"repeat": true 则像数控系统执行以 M99 结束的主程序那样从头再次运行）。\n' +
      '调用它的程序：main.nc（O0001）\n',
    ), dc.output);
    assert.match(dc.output, /status: completed after 3 blocks/);
  });

  test('"repeat": true runs it again from its start until the block budget; restarted without it, one pass', async () => {
    const { event } = await dc.begin({ program: program('O0200.nc'), repeat: true, maxBlocks: 50 });
    assert.equal(event.body.reason, 'exception');
    assert.match(event.body.description, /stopped after 50 blocks: the block budget ran out/);
    assert.ok(!dc.output.includes('ends in M99'), dc.output);

    const stopped = dc.waitForEvent('stopped');
    await dc.restartRequest({ arguments: { program: program('O0200.nc'), maxBlocks: 50, noSave: true } });
    const again = await stopped;
    assert.deepEqual([again.body.reason, again.body.description], ['step', 'program end (M99)']);
    assert.ok(dc.output.includes(SENTENCE), dc.output);
  });

  test('a repeat that is not true or false is refused with the reason', async () => {
    await dc.initializeRequest({ adapterID: 'cnc-macro', pathFormat: 'path' });
    await assert.rejects(
      dc.launchRequest({ program: program('O0200.nc'), repeat: 'yes', noSave: true }),
      { message: '\'repeat\' must be true or false, not "yes"' },
    );
    await assert.rejects(
      dc.launchRequest({ program: program('O0200.nc'), repeat: 1, noSave: true }),
      { message: '\'repeat\' must be true or false, not 1' },
    );
  });

  test('the refusal is in Chinese under a Chinese locale', async () => {
    await dc.initializeRequest({ adapterID: 'cnc-macro', pathFormat: 'path', locale: 'zh-CN' });
    await assert.rejects(
      dc.launchRequest({ program: program('O0200.nc'), repeat: 'yes', noSave: true }),
      { message: '\'repeat\' 必须是 true 或 false，而不是 "yes"' },
    );
  });
});
