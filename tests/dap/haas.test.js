// A Haas NGC mill program (the `haas` profile, chosen by the file's dialect comment) through
// `cncmacro dap` and a real DAP client: stepping into `M97 P100` shows a stack frame of its own
// for the local subprogram at N100 and step out comes back after the M97; the Variables pane
// shows the Haas variables (six axes, every common kept at power-off, by hundreds, G54-G59 with six axes,
// the tool of `T5 M06`); the console reads G154 P1's offset by both its numbers; a call to a
// probing macro kept on the control (O9000-O9999) returns at once. Read as fanuc-0i, none of
// this holds (M97 is a plain M code, #14001 and #3026 do not exist, O9810 is not found).
// Run from the repository root: `node --test tests/dap/`.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

// tests/dap/programs/haas_m97.nc, line by line:
//  1 (cncmacro: dialect=haas)         8 M97 P100         13 N100 #100=#100+1
//  2 O01000 (HAAS POCKET)             9 #101=#100        14 G01 X10. Y5. F200
//  3 G90 G17 G40 G80 G54 G00 X0 Y0   10 G65 P9810 Z-5.   15 M99
//  4 #100=0                          11 G00 Z50.
//  5 T5 M06                          12 M30
//  6 G154 P1
//  7 #14001=12.5
const HAAS = 'haas_m97.nc';

const dc = clientPerTest();

async function frames() {
  const trace = (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames;
  return trace.map((f) => [f.name, f.line]);
}

async function names(scope) {
  return (await dc.scopeVariables(1, scope)).variables.map((v) => [v.name, v.value]);
}

describe('a Haas program in the debugger', () => {
  test('step into M97 P100 shows the local subprogram at N100 as a frame; step out returns after the M97', async () => {
    const { event } = await dc.begin({ program: program(HAAS) }, { breakpoints: { [HAAS]: [{ line: 8 }] } });
    assert.equal(event.body.reason, 'breakpoint');
    assert.deepEqual(await frames(), [['O1000 (main)', 8]]);
    await dc.step('stepInRequest');
    assert.deepEqual(await frames(), [["O1000 (M97, main's locals)", 13], ['O1000 (main)', 8]]);
    await dc.step('nextRequest'); // N100 #100=#100+1
    assert.deepEqual(await frames(), [["O1000 (M97, main's locals)", 14], ['O1000 (main)', 8]]);
    assert.equal(await dc.value('#100'), '1');
    await dc.step('stepOutRequest'); // runs the cut and the M99
    assert.deepEqual(await frames(), [['O1000 (main)', 9]]);
    assert.deepEqual([await dc.value('#5001'), await dc.value('#5002')], ['10', '5']); // the subprogram's cut
  });

  test('the Variables pane shows six axes, the kept commons, G59 with C, and T5 in the modal scope', async () => {
    await dc.begin({ program: program(HAAS) }, { breakpoints: { [HAAS]: [{ line: 9 }] } });
    const scopes = (await dc.scopesRequest({ frameId: 1 })).body.scopes.map((s) => s.name);
    // every Haas common is kept at power-off: one scope for them, no empty "Common" scope
    assert.deepEqual(scopes, ['Locals', 'Persistent #100–#199, #500–#999, #10000–#10999', 'Position', 'Modal', 'Offsets']);
    // 1,600 kept commons open by hundreds: #100–#199, #500–#599 … #900–#999, #10000–#10099 …
    // #10900–#10999 is 1 + 5 + 10 = 16 rows; #100 = 1 after the M97 (N100 #100=#100+1 from 0)
    const kept = (await dc.scopeVariables(1, 'Persistent')).variables;
    assert.deepEqual([kept.length, [kept[0].name, kept[0].value], kept[6].name, kept.at(-1).name],
      [16, ['#100–#199', '#100 = 1'], '#10000–#10099', '#10900–#10999']);
    const tenThousands = (await dc.variablesRequest({ variablesReference: kept[6].variablesReference })).body.variables;
    assert.deepEqual([tenThousands.length, tenThousands[1].name, tenThousands[1].value], [100, '#10001', '<vacant>']);

    const position = await names('Position');
    const machine = position.filter(([name]) => /^#502[1-6] /.test(name));
    assert.deepEqual(machine.map(([name]) => name.split(' ')[1]), ['(X', '(Y', '(Z', '(A', '(B', '(C']);
    // X10. in G154 P1, whose X offset #14001 is 12.5: the machine is at X22.5
    assert.deepEqual(machine[0], ['#5021 (X axis present position, machine coordinates)', '22.5']);

    const modal = await names('Modal');
    assert.ok(modal.some(([name, value]) => name.startsWith('#4120 (Address T') && value === '5'), modal.join('\n'));
    assert.ok(modal.some(([name, value]) => name.startsWith('#4012 (Modal G code of group 12') && value === '154'));

    const offsets = (await names('Offsets')).map(([name]) => name);
    assert.ok(offsets.includes('#5226 (C axis G54 work offset)'), offsets.join('\n'));
    assert.ok(offsets.includes('#5326 (C axis G59 work offset)'), offsets.join('\n'));
    assert.equal(offsets.filter((name) => / G59 /.test(name)).length, 6);
  });

  test('in a Chinese locale the kept commons are one scope, named in Chinese', async () => {
    await dc.begin({ program: program(HAAS) }, { breakpoints: { [HAAS]: [{ line: 9 }] }, locale: 'zh-CN' });
    const scopes = (await dc.scopesRequest({ frameId: 1 })).body.scopes.map((s) => s.name);
    assert.deepEqual(scopes, ['局部变量', '保持型变量 #100–#199, #500–#999, #10000–#10999', '位置', '模态', '偏置']);
  });

  test('the console reads G154 P1 by #14001 and #7001, the tool in the spindle #3026, and writes #10500', async () => {
    await dc.begin({ program: program(HAAS) }, { breakpoints: { [HAAS]: [{ line: 9 }] } });
    const repl = async (expression) => (await dc.evaluateRequest({ expression, context: 'repl', frameId: 1 })).body.result;
    assert.equal(await repl('#14001'), '12.5');
    assert.equal(await repl('#7001'), '12.5'); // G110, another number for G154 P1
    assert.equal(await repl('#3026'), '5'); // T5 M06
    await repl('#10500=#3026+1');
    assert.equal(await repl('#10500'), '6');
  });

  test('G65 P9810, a probing macro kept on the control, steps over at once without an error', async () => {
    await dc.begin({ program: program(HAAS), stopAtEnd: false }, { breakpoints: { [HAAS]: [{ line: 10 }] } });
    assert.deepEqual(await frames(), [['O1000 (main)', 10]]);
    const stop = await dc.step('stepInRequest');
    assert.equal(stop.body.reason, 'step');
    assert.deepEqual(await frames(), [['O1000 (main)', 11]]);
    assert.doesNotMatch(dc.output, /alarm|not found|error/i);
    const terminated = dc.waitForEvent('terminated');
    await dc.continueRequest({ threadId: 1 });
    await terminated;
    assert.match(dc.output, /status: completed/);
  });
});
