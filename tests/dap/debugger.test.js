// `cncmacro dap` driven through a real DAP client (@vscode/debugadapter-testsupport).
// Run from the repository root: `node --test tests/dap/` (part of `make test`).
'use strict';

const assert = require('node:assert/strict');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const dc = clientPerTest();

describe('starting and breakpoints', () => {
  test('stop on entry stops at the first block after the O header', async () => {
    const { event } = await dc.begin({ program: program('main.nc'), stopOnEntry: true });
    assert.equal(event.body.reason, 'entry');
    const frame = await dc.top();
    assert.equal(frame.line, 2);
    assert.equal(frame.name, 'O0001 (main)');
    assert.equal(frame.source.path, program('main.nc'));
  });

  test('a line breakpoint in the main file (the testsupport scenario)', async () => {
    await dc.hitBreakpoint({ program: program('main.nc'), noSave: true }, { path: program('main.nc'), line: 5 });
    assert.equal(await dc.value('#100'), '6.5');
  });

  test('a breakpoint on the first block stops before it runs', async () => {
    const { event } = await dc.begin({ program: program('main.nc') }, { breakpoints: { 'main.nc': [{ line: 1 }] } });
    assert.equal(event.body.reason, 'breakpoint');
    assert.equal((await dc.top()).line, 2); // the O header alone: the breakpoint moved to the first block
    assert.equal(await dc.value('#100'), '<vacant>');
  });

  test('a breakpoint on a comment line in a subprogram file moves to the next block and stops there', async () => {
    const { event, verified } = await dc.begin(
      { program: program('main.nc') }, { breakpoints: { 'O9100.nc': [{ line: 2 }] } },
    );
    assert.deepEqual([verified['O9100.nc'][0].verified, verified['O9100.nc'][0].line], [true, 3]);
    assert.equal(event.body.reason, 'breakpoint');
    const trace = (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames;
    assert.deepEqual(trace.map((f) => [f.name, path.basename(f.source.path), f.line]), [
      ['O9100 (G65, level 1)', 'O9100.nc', 3],
      ['O0001 (main)', 'main.nc', 4],
    ]);
  });

  test('a breakpoint on a blank line of an M98 subprogram stops at the next block', async () => {
    const { verified } = await dc.begin(
      { program: program('main.nc') }, { breakpoints: { 'O0200.nc': [{ line: 3 }] } },
    );
    assert.equal(verified['O0200.nc'][0].line, 4);
    const frame = await dc.top();
    assert.deepEqual([frame.name, frame.line], ["O0200 (M98, main's locals)", 4]);
    assert.equal(await dc.value('#103'), '7');
  });

  test('a conditional breakpoint in macro syntax stops only when it holds', async () => {
    await dc.begin({ program: program('loop.nc') }, { breakpoints: { 'loop.nc': [{ line: 5, condition: '#1 GT 5' }] } });
    assert.equal(await dc.value('#1'), '6');
    assert.equal((await dc.top()).line, 5);
  });

  test('a hit-count breakpoint stops on the third pass', async () => {
    await dc.begin({ program: program('loop.nc') }, { breakpoints: { 'loop.nc': [{ line: 6, hitCondition: '3' }] } });
    assert.equal(await dc.value('#1'), '3');
    assert.equal(await dc.value('#100'), '3');
  });

  test('a log point writes its message and does not stop', async () => {
    const { event } = await dc.begin(
      { program: program('loop.nc') }, { breakpoints: { 'loop.nc': [{ line: 8, logMessage: 'sum is {#100}' }] } },
    );
    assert.deepEqual([event.body.reason, event.body.description], ['step', 'program end (M30)']); // the first stop
    assert.match(dc.output, /sum is 55\n/);
  });

  test('function breakpoints on a program and on a sequence number', async () => {
    await dc.begin({ program: program('main.nc') }, { functionBreakpoints: ['O0200'] });
    const frame = await dc.top();
    assert.deepEqual([frame.name, frame.line], ["O0200 (M98, main's locals)", 2]);
    await dc.restart();
    const { event } = await dc.begin({ program: program('alarm.nc'), set: { 100: 4 } }, { functionBreakpoints: ['N10'] });
    assert.equal(event.body.reason, 'function breakpoint');
    // the hole count #100 is given, so the IF jumps over the alarm to N10
    assert.equal((await dc.top()).line, 5);
  });
});

describe('stepping', () => {
  async function atTheCall() {
    await dc.begin({ program: program('main.nc') }, { breakpoints: { 'main.nc': [{ line: 4 }] } });
    assert.equal((await dc.top()).line, 4);
  }

  test('step over a G65 runs the macro and lands on the next line', async () => {
    await atTheCall();
    const stop = await dc.step('nextRequest');
    assert.equal(stop.body.reason, 'step');
    const frame = await dc.top();
    assert.deepEqual([frame.name, frame.line], ['O0001 (main)', 5]);
    assert.equal(await dc.value('#100'), '6.5');
    assert.equal(await dc.value('#1'), '3'); // the caller's locals again
  });

  test('step in enters the macro with #1 holding the A argument', async () => {
    await atTheCall();
    await dc.step('stepInRequest');
    const frame = await dc.top();
    assert.deepEqual([frame.name, path.basename(frame.source.path), frame.line], ['O9100 (G65, level 1)', 'O9100.nc', 3]);
    assert.equal(await dc.value('#1'), '2.5');
    assert.equal(await dc.value('#1', 1), '3'); // the main program's #1, evaluated in its frame
  });

  test('step out runs past the M99 to the line after the call', async () => {
    await atTheCall();
    await dc.step('stepInRequest');
    await dc.step('stepOutRequest');
    const frame = await dc.top();
    assert.deepEqual([frame.name, frame.line], ['O0001 (main)', 5]);
    assert.equal(await dc.value('#100'), '6.5');
  });

  test('step back and reverse continue restore the earlier state', async () => {
    await dc.begin(
      { program: program('main.nc'), stopOnEntry: true }, { breakpoints: { 'main.nc': [{ line: 3 }] } },
    );
    await dc.step('stepInRequest');
    await dc.step('stepInRequest');
    assert.deepEqual([(await dc.top()).line, await dc.value('#1')], [4, '3']);
    const back = await dc.step('stepBackRequest');
    assert.equal(back.body.reason, 'step');
    assert.deepEqual([(await dc.top()).line, await dc.value('#1')], [3, '<vacant>']);
    await dc.step('nextRequest');
    await dc.step('nextRequest');
    assert.deepEqual([(await dc.top()).line, await dc.value('#100')], [5, '6.5']);
    const reverse = await dc.step('reverseContinueRequest');
    assert.equal(reverse.body.reason, 'breakpoint');
    assert.deepEqual([(await dc.top()).line, await dc.value('#100')], [3, '0']);
  });

  test('pause stops a run inside an endless loop, and it can go on', async () => {
    await dc.begin({ program: program('endless.nc'), maxBlocks: 1000000000, stopOnEntry: true });
    await dc.step('nextRequest'); // #1=0: the loop comes next
    for (let round = 0; round < 2; round += 1) {
      const before = Number(await dc.value('#1'));
      await dc.continueRequest({ threadId: 1 });
      const stop = await dc.step('pauseRequest');
      assert.equal(stop.body.reason, 'pause');
      assert.ok([3, 4, 5].includes((await dc.top()).line));
      assert.ok(Number(await dc.value('#1')) >= before);
    }
  });
});

describe('variables, evaluate and data breakpoints', () => {
  test('each scope shows its variables; vacant is <vacant>', async () => {
    await dc.begin({ program: program('main.nc') }, { breakpoints: { 'O9100.nc': [{ line: 4 }] } });
    const scopes = (await dc.scopesRequest({ frameId: 2 })).body.scopes.map((s) => s.name);
    assert.deepEqual(scopes, ['Locals', 'Common #100–#499', 'Persistent #500–#999', 'Position', 'Modal', 'Offsets']);
    const locals = (await dc.scopeVariables(2, 'Locals')).variables;
    assert.equal(locals.length, 33);
    assert.deepEqual(locals.slice(0, 3).map((v) => [v.name, v.value]), [['#1 (A)', '2.5'], ['#2 (B)', '4'], ['#3', '<vacant>']]);
    const mainLocals = (await dc.scopeVariables(1, 'Locals')).variables;
    assert.deepEqual([mainLocals[0].name, mainLocals[0].value], ['#1', '3']);
    // 400 commons open by hundreds (#100–#199 … #400–#499), each on its 100 variables
    const { variables: hundreds } = await dc.scopeVariables(2, 'Common');
    assert.deepEqual([hundreds.length, hundreds[0].name, hundreds[3].name], [4, '#100–#199', '#400–#499']);
    const common = (await dc.variablesRequest({ variablesReference: hundreds[0].variablesReference })).body.variables;
    assert.deepEqual([common.length, common[0].name, common[0].value, common[1].value], [100, '#100', '6.5', '<vacant>']);
    const persistent = (await dc.scopeVariables(2, 'Persistent')).variables;
    assert.deepEqual(persistent.map((v) => v.name), ['#500–#599', '#600–#699', '#700–#799', '#800–#899', '#900–#999']);
    const position = (await dc.scopeVariables(2, 'Position')).variables;
    assert.ok(position.some((v) => v.name.startsWith('#5001 (X axis block end position') && v.value === '0'));
    const modal = (await dc.scopeVariables(2, 'Modal')).variables;
    assert.ok(modal.some((v) => v.name.startsWith('#4115 ') && v.value === '9100'));
    const offsets = (await dc.scopeVariables(2, 'Offsets')).variables;
    assert.ok(offsets.some((v) => v.name.startsWith('#5221 (X axis G54 work zero offset')));
  });

  test('vacant shows as <空> in a Chinese locale', async () => {
    await dc.begin({ program: program('main.nc'), stopOnEntry: true }, { locale: 'zh-CN' });
    const locals = (await dc.scopeVariables(1, '局部变量')).variables;
    assert.equal(locals[0].value, '<空>');
    assert.equal(await dc.value('#1'), '<空>');
  });

  test('setVariable changes the rest of the run', async () => {
    await dc.begin(
      { program: program('loop.nc') }, { breakpoints: { 'loop.nc': [{ line: 5, hitCondition: '1' }, { line: 9 }] } },
    );
    const { scope } = await dc.scopeVariables(1, 'Locals');
    const set = await dc.setVariableRequest({ variablesReference: scope.variablesReference, name: '#1 ', value: '8' });
    assert.equal(set.body.value, '8');
    await dc.step('continueRequest');
    assert.equal((await dc.top()).line, 9);
    assert.equal(await dc.value('#101'), '19'); // 9 + 10: the loop ran twice more, not ten times
    await assert.rejects(
      dc.setVariableRequest({ variablesReference: scope.variablesReference, name: '#1', value: '1/0' }), /alarm 112/,
    );
  });

  test('evaluate: expressions in the frame, assignments in the console, clear errors', async () => {
    await dc.begin({ program: program('main.nc') }, { breakpoints: { 'O9100.nc': [{ line: 4 }] } });
    assert.equal(await dc.value('#1+#2*2'), '10.5');
    assert.equal(await dc.value('SQRT[16]+ROUND[2.5]'), '7');
    assert.equal(await dc.value('#[99+1]'), '6.5');
    const hover = await dc.evaluateRequest({ expression: '#2', context: 'hover', frameId: 2 });
    assert.equal(hover.body.result, '4');
    const assigned = await dc.evaluateRequest({ expression: '#100=5', context: 'repl', frameId: 2 });
    assert.equal(assigned.body.result, '#100 = 5');
    assert.equal(await dc.value('#100'), '5');
    await assert.rejects(dc.evaluateRequest({ expression: '#1+', context: 'watch', frameId: 2 }), /expected/);
    await assert.rejects(dc.evaluateRequest({ expression: '#1/#0', context: 'watch', frameId: 2 }), /alarm 112/);
  });

  test('a data breakpoint on #100 stops after each block that changes it', async () => {
    await dc.begin({ program: program('loop.nc'), stopOnEntry: true });
    const { scope } = await dc.scopeVariables(1, 'Common');
    const info = await dc.dataBreakpointInfoRequest({ variablesReference: scope.variablesReference, name: '#100' });
    assert.equal(info.body.dataId, '#100');
    const set = await dc.setDataBreakpointsRequest({ breakpoints: [{ dataId: info.body.dataId }] });
    assert.equal(set.body.breakpoints[0].verified, true);
    const first = await dc.step('continueRequest');
    assert.equal(first.body.reason, 'data breakpoint');
    assert.deepEqual([(await dc.top()).line, await dc.value('#100')], [4, '0']);
    await dc.step('continueRequest');
    assert.deepEqual([(await dc.top()).line, await dc.value('#100'), await dc.value('#1')], [7, '1', '1']);
  });
});

describe('alarms, messages and the end of a session', () => {
  test('an alarm stops as an exception with its number and text', async () => {
    const { event } = await dc.begin({ program: program('alarm.nc') });
    // no hole count in #100: the IF does not jump and #3000 raises alarm 3001
    assert.equal(event.body.reason, 'exception');
    assert.match(event.body.text, /3001/);
    const info = await dc.exceptionInfoRequest({ threadId: 1 });
    assert.equal(info.body.exceptionId, 'alarm 3001');
    assert.match(info.body.description, /HOLE COUNT MISSING/);
    assert.equal((await dc.top()).line, 4);
  });

  test('#3006 stops as a pause with its message; motion is echoed; terminate saves #500', async () => {
    const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-dap-'));
    const copy = path.join(folder, 'message.nc');
    fs.copyFileSync(program('message.nc'), copy);
    try {
      const { event } = await dc.begin({ program: copy, echoMotion: true, noSave: false });
      assert.equal(event.body.reason, 'pause');
      assert.match(event.body.text, /CHECK THE PART/);
      assert.equal((await dc.top()).line, 5);
      assert.match(dc.output, /message\.nc:3 G01\s+X0\.000 Y0\.000 -> X10\.000 Y0\.000\s+F100/);
      await dc.step('nextRequest');
      await dc.step('nextRequest');
      assert.equal(await dc.value('#500'), '1');
      const terminated = dc.waitForEvent('terminated');
      await dc.terminateRequest({});
      await terminated;
      const saved = JSON.parse(fs.readFileSync(path.join(folder, '.cncmacro-vars.json'), 'utf8'));
      assert.deepEqual(saved.variables, { 500: 1 });
    } finally {
      fs.rmSync(folder, { recursive: true, force: true });
    }
  });

  test('echoed motion shows the axes the program commands, never an axis it does not mention', async () => {
    await dc.begin({ program: program('three_axes.nc'), echoMotion: true, stopAtEnd: false }, { until: 'terminated' });
    const moves = dc.output.split('\n').filter((line) => line.startsWith('three_axes.nc:'));
    assert.equal(moves.length, 5);
    assert.ok(moves.every((line) => !/A-?\d/.test(line)), moves.join('\n'));
    // X and Y, commanded at 0 where the tool already is, are shown; Z only once commanded
    assert.match(moves[0], /^three_axes\.nc:2 G00\s+X0\.000 Y0\.000 -> X0\.000 Y0\.000$/);
    assert.match(moves[1], /^three_axes\.nc:3 G00\s+X0\.000 Y0\.000 Z0\.000 -> X0\.000 Y0\.000 Z50\.000$/);
    // once commanded, an axis stays shown while it stands still
    assert.match(moves[3], /^three_axes\.nc:5 G01\s+X0\.000 Y0\.000 Z-2\.000 -> X40\.000 Y0\.000 Z-2\.000\s+F100$/);
  });

  test('echoed motion shows the A axis from the block that commands it on', async () => {
    await dc.begin({ program: program('rotary.nc'), echoMotion: true, stopAtEnd: false }, { until: 'terminated' });
    const moves = dc.output.split('\n').filter((line) => line.startsWith('rotary.nc:'));
    assert.deepEqual(moves.map((line) => /A-?\d/.test(line)), [false, true, true]);
    assert.match(moves[1], /^rotary\.nc:3 G00\s+X0\.000 Y0\.000 Z50\.000 A0\.000 -> X0\.000 Y0\.000 Z50\.000 A90\.000$/);
    assert.match(moves[2], /^rotary\.nc:4 G01\s+X0\.000 Y0\.000 Z50\.000 A90\.000 -> X10\.000 Y0\.000 Z50\.000 A90\.000\s+F200$/);
  });

  test('with stopAtEnd false a program that runs to its end terminates the session', async () => {
    const { event } = await dc.begin({ program: program('main.nc'), stopAtEnd: false }, { until: 'terminated' });
    assert.equal(event.event, 'terminated');
    assert.match(dc.output, /status: completed after 13 blocks/);
  });

  test('an unknown or bad request fails with a message and the adapter keeps running', async () => {
    await dc.begin({ program: program('main.nc'), stopOnEntry: true });
    await assert.rejects(dc.customRequest('flyToTheMoon', {}), /unknown request 'flyToTheMoon'/);
    await assert.rejects(dc.stackTraceRequest({ threadId: 1, levels: 'many' }), /levels/);
    await assert.rejects(dc.scopesRequest({ frameId: 7 }), /no stack frame 7/);
    await assert.rejects(dc.launchRequest({}), /needs 'program'/);
    const threads = await dc.threadsRequest();
    assert.equal(threads.body.threads.length, 1);
    assert.equal((await dc.top()).line, 2);
  });
});
