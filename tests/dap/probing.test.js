// Probing offline through the debugger (docs/machine-file.md "Probing: the [skip] table"): the
// machine file beside tests/dap/programs/probing/probe_bore.nc gives its first G31 a contact
// point and the others a bore D50 at X0 Y0. The Debug Console says where each G31 stopped and
// why, the Position scope and the watch show #5061, and stepping back gives a contact back.
'use strict';

const assert = require('node:assert/strict');
const { test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const BORE = program('probing/probe_bore.nc');
const dc = clientPerTest();

test('the console says where each G31 stopped, and #5061 holds it', async () => {
  const breakpoints = { 'probing/probe_bore.nc': [{ line: 4 }, { line: 7 }, { line: 10 }] };
  await dc.begin({ program: BORE }, { breakpoints });
  assert.equal((await dc.top()).line, 4);
  assert.match(dc.output, /note at probe_bore\.nc:3: G31 stopped at X24\.99: the skip signal came on \(contact point 1 of the machine file\)/);
  assert.equal(await dc.value('#5061'), '24.99');
  const position = (await dc.scopeVariables(1, 'Position')).variables;
  assert.ok(position.some((v) => v.name.startsWith('#5061 (X axis skip position') && v.value === '24.99'));

  await dc.step('continueRequest');
  assert.equal((await dc.top()).line, 7);
  assert.match(dc.output, /note at probe_bore\.nc:6: G31 stopped at X-25: the skip signal came on \(the bore D50 at X0 Y0\)/);
  assert.equal(await dc.value('#5061'), '-25');

  await dc.step('continueRequest');
  assert.equal((await dc.top()).line, 10);
  assert.match(dc.output, /note at probe_bore\.nc:9: G31 reached its end point X10: the skip signal did not come on/);
  assert.equal(await dc.value('#5061'), '10');
});

test('the console says it in Chinese in a Chinese locale', async () => {
  await dc.begin({ program: BORE }, { breakpoints: { 'probing/probe_bore.nc': [{ line: 4 }] }, locale: 'zh-CN' });
  assert.match(dc.output, /提示（probe_bore\.nc:3）：G31 停在 X24\.99：跳转信号接通（机床设置文件的第 1 个接触点）/);
});

test('stepping back over a G31 gives its contact point back to the next run of it', async () => {
  await dc.begin({ program: BORE }, { breakpoints: { 'probing/probe_bore.nc': [{ line: 7 }] } });
  assert.equal(await dc.value('#5061'), '-25');
  for (let k = 0; k < 4; k += 1) await dc.step('stepBackRequest'); // back before the first G31
  assert.equal((await dc.top()).line, 3);
  await dc.step('nextRequest');
  assert.equal(await dc.value('#5061'), '24.99'); // the first contact point again, not the bore
  await dc.step('nextRequest');
  await dc.step('nextRequest');
  await dc.step('nextRequest');
  assert.equal((await dc.top()).line, 7);
  assert.equal(await dc.value('#5061'), '-25');
});
