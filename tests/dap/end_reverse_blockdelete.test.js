// The end of a program as a stop, reverse continue that honours hit counts and data
// breakpoints, and breakpoints on block-delete lines, through `cncmacro dap` and a real DAP client.
// Run from the repository root: `node --test tests/dap/`.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const dc = clientPerTest();

async function where() {
  const frame = await dc.top();
  return [frame.line, await dc.value('#1'), await dc.value('#100')];
}

async function commonValue(name) {
  return (await dc.scopeRow(1, 'Common', name)).value;
}

describe('the end of the program is a stop', () => {
  test('stop at M30 with the final state, step back from it, continue ends the session', async () => {
    const { event } = await dc.begin({ program: program('main.nc') });
    assert.deepEqual([event.body.reason, event.body.description], ['step', 'program end (M30)']);
    const trace = (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames;
    assert.deepEqual(trace.map((f) => [f.name, f.line]), [['O0001 (main)', 8]]); // the M30 line, the last one run
    assert.equal(await commonValue('#102'), '15'); // the final variables in the Variables pane
    assert.equal(await commonValue('#104'), '8');

    const back = await dc.step('stepBackRequest');
    assert.equal(back.body.reason, 'step');
    assert.deepEqual([(await dc.top()).line, await dc.value('#102')], [8, '15']); // before M30 ran
    await dc.step('stepBackRequest');
    assert.deepEqual([(await dc.top()).line, await dc.value('#102')], [7, '<vacant>']); // before #102=#101*2

    const again = await dc.step('continueRequest');
    assert.equal(again.body.description, 'program end (M30)');
    const exited = dc.waitForEvent('exited');
    const terminated = dc.waitForEvent('terminated');
    await dc.continueRequest({ threadId: 1 });
    assert.equal((await exited).body.exitCode, 0);
    await terminated;
    assert.match(dc.output, /status: completed after 13 blocks/);
  });

  test('next at the end ends the session too; the end is described in Chinese under a Chinese locale', async () => {
    const { event } = await dc.begin({ program: program('loop.nc') }, { locale: 'zh-CN' });
    assert.equal(event.body.description, '程序结束 (M30)');
    assert.equal(await dc.value('#101'), '55');
    const terminated = dc.waitForEvent('terminated');
    await dc.nextRequest({ threadId: 1 });
    await terminated;
  });

  test('a program without M30 stops after its last block', async () => {
    const { event } = await dc.begin({ program: program('noend.nc') });
    assert.deepEqual([event.body.reason, event.body.description], ['step', 'program end']);
    assert.equal((await dc.top()).line, 3); // its last block, not the end of the file
    assert.equal(await dc.value('#101'), '2');
  });

  test('Run Without Debugging never stops: not on entry, at breakpoints, at the end or at an alarm', async () => {
    let stops = 0;
    dc.on('stopped', () => { stops += 1; });
    const exited = dc.waitForEvent('exited');
    const { event } = await dc.begin(
      { program: program('main.nc'), noDebug: true, stopOnEntry: true },
      { breakpoints: { 'main.nc': [{ line: 5 }] }, until: 'terminated' },
    );
    assert.equal(event.event, 'terminated');
    assert.equal((await exited).body.exitCode, 0);
    assert.equal(stops, 0);
    await dc.restart();
    dc.on('stopped', () => { stops += 1; });
    const alarmExit = dc.waitForEvent('exited');
    await dc.begin({ program: program('alarm.nc'), noDebug: true }, { until: 'terminated' });
    assert.equal((await alarmExit).body.exitCode, 1);
    assert.match(dc.output, /ALARM 3001/);
    assert.equal(stops, 0);
  });

  test('an alarm still stops as an exception, and continue from it ends the session with exit code 1', async () => {
    const { event } = await dc.begin({ program: program('alarm.nc') });
    assert.equal(event.body.reason, 'exception');
    const exited = dc.waitForEvent('exited');
    await dc.continueRequest({ threadId: 1 });
    assert.equal((await exited).body.exitCode, 1);
  });
});

describe('reverse continue honours hit counts and data breakpoints', () => {
  test('a hit count %3: forward stops at passes 3, 6, 9; backwards at 9, 6, 3 and no other pass', async () => {
    const { event } = await dc.begin(
      { program: program('loop.nc') }, { breakpoints: { 'loop.nc': [{ line: 6, hitCondition: '%3' }] } },
    );
    assert.equal(event.body.reason, 'breakpoint');
    assert.deepEqual(await where(), [6, '3', '3']);
    await dc.step('continueRequest');
    assert.deepEqual(await where(), [6, '6', '15']);
    await dc.step('continueRequest');
    assert.deepEqual(await where(), [6, '9', '36']);
    const end = await dc.step('continueRequest');
    assert.equal(end.body.description, 'program end (M30)');

    const back = await dc.step('reverseContinueRequest');
    assert.equal(back.body.reason, 'breakpoint');
    assert.deepEqual(await where(), [6, '9', '36']);
    await dc.step('reverseContinueRequest');
    assert.deepEqual(await where(), [6, '6', '15']);
    await dc.step('continueRequest'); // the counts went back too: forward again, the next stop is pass 9
    assert.deepEqual(await where(), [6, '9', '36']);
    await dc.step('reverseContinueRequest');
    await dc.step('reverseContinueRequest');
    assert.deepEqual(await where(), [6, '3', '3']);
    const start = await dc.step('reverseContinueRequest'); // no earlier stop: the start of the run
    assert.equal(start.body.reason, 'entry');
    assert.deepEqual(await where(), [2, '<vacant>', '<vacant>']);
  });

  test('a hit count ==3 stops backwards only at the third pass, also with a condition', async () => {
    await dc.begin(
      { program: program('loop.nc') },
      { breakpoints: { 'loop.nc': [{ line: 6, hitCondition: '3', condition: '#1 GT 4' }] } },
    );
    assert.deepEqual(await where(), [6, '7', '21']); // the third pass with #1 > 4 is #1 = 7
    await dc.step('continueRequest');
    await dc.step('reverseContinueRequest');
    assert.deepEqual(await where(), [6, '7', '21']);
    assert.equal((await dc.step('reverseContinueRequest')).body.reason, 'entry');
  });

  test('a data breakpoint: backwards it stops right after each block that changed the variable', async () => {
    await dc.begin({ program: program('loop.nc'), stopOnEntry: true });
    await dc.setDataBreakpointsRequest({ breakpoints: [{ dataId: '#101' }, { dataId: '#100', hitCondition: '3' }] });
    const third = await dc.step('continueRequest');
    assert.equal(third.body.reason, 'data breakpoint');
    assert.deepEqual(await where(), [7, '2', '3']); // the third change of #100: 1 -> 3
    const sum = await dc.step('continueRequest');
    assert.match(sum.body.description, /#101 changed: vacant -> 55/);
    assert.equal((await dc.top()).line, 9);
    await dc.step('continueRequest'); // the end

    const back = await dc.step('reverseContinueRequest');
    assert.deepEqual([back.body.reason, back.body.description], ['data breakpoint', '#101 changed: vacant -> 55']);
    assert.deepEqual([(await dc.top()).line, await dc.value('#101')], [9, '55']);
    const earlier = await dc.step('reverseContinueRequest');
    assert.deepEqual([earlier.body.reason, earlier.body.description], ['data breakpoint', '#100 changed: 1 -> 3']);
    assert.deepEqual(await where(), [7, '2', '3']);
    assert.equal((await dc.step('reverseContinueRequest')).body.reason, 'entry');
  });

  test('a data breakpoint set at the end without a hit count finds the last change going back', async () => {
    await dc.begin({ program: program('loop.nc') });
    await dc.setDataBreakpointsRequest({ breakpoints: [{ dataId: '#100' }] });
    await dc.step('reverseContinueRequest');
    assert.deepEqual(await where(), [7, '10', '55']);
    await dc.step('reverseContinueRequest');
    assert.deepEqual(await where(), [7, '9', '45']);
  });
});

describe('breakpoints on block delete lines', () => {
  const specs = [{ line: 3 }, { line: 4 }, { line: 5 }];

  test('block delete off: the / block is verified and stops; comment and blank lines move on', async () => {
    const { event, verified } = await dc.begin(
      { program: program('optional.nc'), blockDelete: false }, { breakpoints: { 'optional.nc': specs } },
    );
    assert.deepEqual(verified['optional.nc'].map((b) => [b.verified, b.line]), [[true, 4], [true, 4], [true, 6]]);
    assert.equal(event.body.reason, 'breakpoint');
    assert.deepEqual([(await dc.top()).line, await dc.value('#100')], [4, '1']);
    await dc.step('continueRequest');
    assert.deepEqual([(await dc.top()).line, await dc.value('#100')], [6, '2']);
  });

  test('block delete on: the / block is not verified, with the reason; the comment moves past it', async () => {
    const changed = [];
    dc.on('breakpoint', (e) => changed.push(e.body));
    const { event, verified } = await dc.begin(
      { program: program('optional.nc'), blockDelete: true }, { breakpoints: { 'optional.nc': specs } },
    );
    // set before the launch said which switch: the launch sends the corrections
    const ids = verified['optional.nc'].map((b) => b.id);
    assert.deepEqual(changed.map((c) => [c.reason, c.breakpoint.id, c.breakpoint.verified]).sort(),
      [['changed', ids[0], true], ['changed', ids[1], false]].sort());
    assert.equal(changed.find((c) => c.breakpoint.id === ids[0]).breakpoint.line, 6);
    assert.equal(event.body.reason, 'breakpoint');
    assert.deepEqual([(await dc.top()).line, await dc.value('#100')], [6, '1']); // the / block never ran

    const again = await dc.setBreakpointsRequest({ source: { path: program('optional.nc') }, breakpoints: specs });
    assert.deepEqual(again.body.breakpoints.map((b) => [b.verified, b.line]), [[true, 6], [false, undefined], [true, 6]]);
    assert.equal(again.body.breakpoints[1].message, 'this block is skipped: block delete is on');
  });

  test('the reason is in Chinese under a Chinese locale', async () => {
    await dc.begin({ program: program('optional.nc'), blockDelete: true, stopOnEntry: true }, { locale: 'zh-CN' });
    const set = await dc.setBreakpointsRequest({ source: { path: program('optional.nc') }, breakpoints: [{ line: 4 }] });
    assert.deepEqual([set.body.breakpoints[0].verified, set.body.breakpoints[0].message],
      [false, '此程序段会被跳过：跳段开关已打开']);
  });
});
