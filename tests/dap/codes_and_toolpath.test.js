// Function breakpoints on codes (M06, T, M00, M01, G01, G81), the toolpath the paused run shows (the moves
// run so far and the move of the block it stands on) and "run to here" on a move, forward and
// back: `cncmacro dap` driven through a real DAP client.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const dc = clientPerTest();

const PROGRAM = program('tool_changes.nc');
const STOP_AND_DRILL = program('stop_and_drill.nc');
const LATHE_ROUGH = program('lathe_rough.nc');
const CUTTER_SQUARE = program('cutter_square.nc');

async function continueTo() {
  const stopped = dc.waitForEvent('stopped');
  await dc.continueRequest({ threadId: 1 });
  return stopped;
}

async function toolpath() {
  return (await dc.customRequest('toolpath', {})).body;
}

async function runToMove(index) {
  const stopped = dc.waitForEvent('stopped');
  await dc.customRequest('runToMove', { index });
  return stopped;
}

describe('breaking on codes', () => {
  test('M06 stops before each tool change, also one whose T is an expression', async () => {
    const { event } = await dc.begin({ program: PROGRAM }, { functionBreakpoints: ['M06'] });
    assert.equal(event.body.reason, 'function breakpoint');
    assert.equal((await dc.top()).line, 4);
    assert.equal((await continueTo()).body.reason, 'function breakpoint');
    assert.equal((await dc.top()).line, 9);
  });

  test('T alone is "run to the next tool change"; the T argument of a G65 call is no tool call', async () => {
    await dc.begin({ program: PROGRAM }, { functionBreakpoints: ['T'] });
    assert.equal((await dc.top()).line, 4);
    await continueTo();
    assert.equal((await dc.top()).line, 9);
    const ended = dc.waitForEvent('stopped');
    await dc.continueRequest({ threadId: 1 });
    assert.match((await ended).body.description, /program end \(M30\)/); // not at line 12's G65 ... T5
  });

  test('T2 matches T#1 by its value, M1 matches M01, G1 matches G01', async () => {
    await dc.begin({ program: PROGRAM }, { functionBreakpoints: ['T2'] });
    assert.equal((await dc.top()).line, 9);
    await dc.setFunctionBreakpointsRequest({ breakpoints: [{ name: 'M1' }, { name: 'G1' }] });
    await continueTo();
    assert.equal((await dc.top()).line, 11);
    await dc.restart();
    await dc.begin({ program: PROGRAM }, { functionBreakpoints: ['G1'] });
    assert.equal((await dc.top()).line, 6);
  });

  test('M00 stops before the program stop, which then pauses as it runs', async () => {
    const { event } = await dc.begin({ program: STOP_AND_DRILL }, { functionBreakpoints: ['M00'] });
    assert.equal(event.body.reason, 'function breakpoint');
    assert.equal((await dc.top()).line, 7);
    const paused = await continueTo();
    assert.equal(paused.body.reason, 'pause');
    assert.match(paused.body.description, /M00 program stop/);
    assert.equal((await dc.top()).line, 8);
    assert.match((await continueTo()).body.description, /program end \(M30\)/);
  });

  test("the console names the M00's own line when it pauses", async () => {
    await dc.begin({ program: STOP_AND_DRILL, stopOnEntry: true });
    const paused = await continueTo(); // the M00 at line 7; the run goes on at line 8
    assert.equal(paused.body.reason, 'pause');
    assert.equal((await dc.top()).line, 8);
    assert.match(dc.output, /stop at stop_and_drill\.nc:7: M00 program stop/);
  });

  test('G81 stops before each block that holds it, not at a hole the modal cycle repeats', async () => {
    const { event } = await dc.begin({ program: STOP_AND_DRILL }, { functionBreakpoints: ['G81'] });
    assert.equal(event.body.reason, 'function breakpoint');
    assert.equal((await dc.top()).line, 4);
    assert.equal((await continueTo()).body.reason, 'pause'); // the M00 of line 7, not the X20. of line 5
    assert.equal((await continueTo()).body.reason, 'function breakpoint');
    assert.equal((await dc.top()).line, 9);
    assert.equal(await dc.value('#1'), '1');
    assert.match((await continueTo()).body.description, /program end \(M30\)/);
  });

  test('a name that is no code, or an M code with a decimal point, is unverified with the reason', async () => {
    await dc.begin({ program: PROGRAM, stopOnEntry: true });
    const made = (await dc.setFunctionBreakpointsRequest({
      breakpoints: [{ name: 'X5' }, { name: 'M6.5' }, { name: 'G999' }, { name: 'M06' }, { name: 'N100' }],
    })).body.breakpoints;
    assert.deepEqual(made.map((b) => b.verified), [false, false, false, true, true]);
    assert.match(made[0].message, /name a sequence number \(N100\), a program \(O9100\) or a G, M or T code/);
    assert.match(made[1].message, /M6\.5: an M code takes no decimal point/);
    assert.match(made[2].message, /G999: FANUC 0i.*has no such G code/);
  });

  test('a G code set before the launch is checked against the launch\'s dialect', async () => {
    const changed = dc.waitForEvent('breakpoint');
    await dc.begin({ program: PROGRAM, stopOnEntry: true }, { functionBreakpoints: ['G999'] });
    const event = await changed;
    assert.equal(event.body.breakpoint.verified, false);
    assert.match(event.body.breakpoint.message, /G999/);
  });

  test('reverse continue goes back to the earlier tool change', async () => {
    await dc.begin({ program: PROGRAM }, { functionBreakpoints: ['M06'] });
    await continueTo();
    assert.equal((await dc.top()).line, 9);
    await dc.step('reverseContinueRequest');
    assert.equal((await dc.top()).line, 4);
  });
});

describe('the toolpath of a paused run', () => {
  test('the moves run so far and the move of the current block, which step back takes back', async () => {
    await dc.begin({ program: PROGRAM }, { breakpoints: { 'tool_changes.nc': [{ line: 7 }] } });
    let path = await toolpath();
    assert.equal(path.line, 7);
    assert.deepEqual(path.moves.map((m) => m.line), [3, 5, 6]);
    assert.deepEqual(path.current.map((m) => [m.line, m.mode, m.to.X]), [[7, 'G01', 10]]);
    await dc.step('nextRequest');
    path = await toolpath();
    assert.deepEqual([path.line, path.moves.length, path.current[0].to.Y], [8, 4, 10]);
    await dc.step('stepBackRequest');
    path = await toolpath();
    assert.deepEqual([path.line, path.moves.length, path.current[0].line], [7, 3, 7]);
    assert.equal(await dc.value('#1'), '2'); // looking ahead ran nothing for good
  });

  test('under cutter radius compensation the moves carry the tool centre path', async () => {
    // cutter_square.nc: radius 5, the tool left of a clockwise square, outside. Paused at line 7
    // (Y0): the side of line 5 (Y50.) has both its corners, on x = -5 from y = 2.071 to 55; the
    // side of line 6 (X50.), the last run, ends for now on the perpendicular of its end, left of +X
    // at (50,50): (50,55), the block after it not run yet
    await dc.begin({ program: CUTTER_SQUARE }, { breakpoints: { 'cutter_square.nc': [{ line: 7 }] } });
    const path = await toolpath();
    assert.deepEqual(path.moves.map((m) => m.line), [3, 4, 5, 6]);
    assert.equal(path.moves[0].tool_path, undefined);
    const round = (p) => [Math.round(p.X * 1000) / 1000, Math.round(p.Y * 1000) / 1000];
    const points = (m) => [round(m.tool_path.from), ...m.tool_path.pieces.map((p) => round(p.to))];
    assert.deepEqual(points(path.moves[2]), [[-5, 2.071], [-5, 55]]);
    assert.deepEqual(points(path.moves[3]), [[-5, 55], [50, 55]]);
    assert.deepEqual(path.current.map((m) => m.line), [7]);
    assert.ok(path.current[0].tool_path, 'the current block is looked at under compensation too');
  });

  test('a limit sends only the first moves run, and counts them all', async () => {
    await dc.begin({ program: PROGRAM }, { breakpoints: { 'tool_changes.nc': [{ line: 10 }] } });
    const path = (await dc.customRequest('toolpath', { limit: 2 })).body;
    assert.deepEqual([path.moves.length, path.made, path.current.length], [2, 5, 1]);
  });

  test('the toolpath is answered a page at a time, however many moves the run made', async () => {
    // 11 blocks of 9,999 holes and the rapid before them: 109,990 moves, one answer used to hold them all
    await dc.begin({ program: program('many_holes.nc'), maxBlocks: 1000000 }, { until: 'stopped' });
    const first = (await dc.customRequest('toolpath', {})).body;
    assert.deepEqual([first.start, first.moves.length, first.made], [0, 100000, 109990]);
    const rest = (await dc.customRequest('toolpath', { start: 100000 })).body;
    assert.deepEqual([rest.start, rest.moves.length], [100000, 9990]);
    assert.equal(rest.moves[rest.moves.length - 1].line, 14); // the last hole, of the last cycle block
  });

  test('a name that is no code is unverified with the reason in Chinese in a Chinese locale', async () => {
    await dc.begin({ program: PROGRAM, stopOnEntry: true }, { locale: 'zh-CN' });
    const made = (await dc.setFunctionBreakpointsRequest({ breakpoints: [{ name: 'X5' }, { name: 'M6.5' }] })).body
      .breakpoints;
    assert.match(made[0].message, /请写顺序号（N100）、程序号（O9100）或 G、M、T 代码/);
    assert.match(made[1].message, /M代码只能写整数/);
  });

  test('a lathe is sent as one: lathe true and its axes, Z the spindle axis, X radial and a diameter', async () => {
    await dc.begin({ program: LATHE_ROUGH, stopOnEntry: true });
    const path = await toolpath();
    assert.equal(path.lathe, true);
    assert.deepEqual(path.lathe_axes, { spindle: 'Z', radial: 'X', diameter: true });
  });

  test('a mill is sent as no lathe, without lathe axes', async () => {
    await dc.begin({ program: PROGRAM, stopOnEntry: true });
    const path = await toolpath();
    assert.equal(path.lathe, false);
    assert.equal(path.lathe_axes, undefined);
  });

  test('paused at a G71 P Q block, every pass is a move of the current block; at the G70 block, the finishing cut', async () => {
    await dc.begin({ program: LATHE_ROUGH }, { breakpoints: { 'lathe_rough.nc': [{ line: 5 }, { line: 8 }] } });
    let path = await toolpath();
    assert.equal(path.line, 5);
    assert.equal(path.moves.length, 1); // G00 X40. Z2. of line 3
    // From X40 with U2. (radius) per pass: cuts at X36, X32, then the shape's X30 (GSK980TDi §3.23.1):
    // each roughing pass is in at rapid, the cut, pulled back R1. at 45 degrees AT THE FEED (step 4:
    // X+2 on the diameter, Z+1) and back to Z2 at rapid: 2 x 4 moves; the last is in to X30, the
    // shape at the feed and one rapid from its end straight to the start X40 Z2 (step 8): 3 moves
    assert.equal(path.current.length, 11);
    assert.ok(path.current.every((m) => m.line === 5 && m.pass_of === 'G71'));
    assert.deepEqual(path.current.filter((m) => m.kind === 'feed').map((m) => m.to.X), [36, 38, 32, 34, 30]);
    assert.deepEqual(path.current.filter((m) => m.kind === 'rapid').map((m) => m.to.X), [36, 38, 32, 34, 30, 40]);
    assert.equal((await dc.top()).line, 5); // looking ahead ran nothing for good: still before the G71 block
    await continueTo();
    path = await toolpath();
    assert.equal(path.line, 8);
    assert.equal(path.moves.length, 12);
    // G70 runs the shape as written (N10 G00 X30., N20 G01 Z-20.) and goes back to the start X40 Z2
    assert.deepEqual(path.current.map((m) => [m.line, m.kind, m.to.X, m.to.Z]), [
      [6, 'rapid', 30, 2], [7, 'feed', 30, -20], [8, 'rapid', 40, 2],
    ]);
  });

  test('a block without a move has no current move', async () => {
    await dc.begin({ program: PROGRAM }, { functionBreakpoints: ['M06'] });
    const path = await toolpath();
    assert.deepEqual([path.line, path.moves.length, path.current.length], [4, 1, 0]);
  });

  test('run to a move ahead stops before the block that makes it; to a move behind goes back', async () => {
    await dc.begin({ program: PROGRAM, stopOnEntry: true });
    let event = await runToMove(6);
    assert.equal(event.body.reason, 'goto');
    assert.equal((await dc.top()).line, 13);
    let path = await toolpath();
    assert.deepEqual([path.moves.length, path.current[0].line], [6, 13]);
    event = await runToMove(1);
    assert.equal(event.body.reason, 'goto');
    assert.equal((await dc.top()).line, 5);
    path = await toolpath();
    assert.deepEqual([path.moves.length, path.current[0].to.Z], [1, 5]);
    assert.equal(await dc.value('#1'), '2');
  });

  test('run to a move stops at a breakpoint on the way', async () => {
    await dc.begin({ program: PROGRAM, stopOnEntry: true });
    await dc.setBreakpointsRequest({ source: { path: PROGRAM }, breakpoints: [{ line: 8 }] });
    const event = await runToMove(5);
    assert.equal(event.body.reason, 'breakpoint');
    assert.equal((await dc.top()).line, 8);
  });

  test('the expressions of inline values evaluate in the paused frame, an indirect one too', async () => {
    await dc.begin({ program: PROGRAM }, { functionBreakpoints: ['M06'] });
    assert.equal(await dc.value('#1'), '2');
    assert.equal(await dc.value('#[#1-1]'), '2');
    assert.equal(await dc.value('#[#1+2]'), '<vacant>');
    await assert.rejects(dc.value('#[#1+'), /.+/);
  });

  test('runToMove without a move number is refused', async () => {
    await dc.begin({ program: PROGRAM, stopOnEntry: true });
    await assert.rejects(dc.customRequest('runToMove', {}), /needs the 'index' of a move/);
  });
});
