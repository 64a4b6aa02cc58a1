// The machine file through the debugger (docs/profiles.md "The machine file"): the workspace
// tests/data/machine_workspace keeps O9000-O9999 on the control, reads M98 P with 6-digit
// program numbers, narrows the commons and adds a builder's variable.
'use strict';

const assert = require('node:assert/strict');
const path = require('node:path');
const { test } = require('node:test');
const { clientPerTest } = require('./client.js');

const SHOP = path.resolve(__dirname, '..', 'data', 'machine_workspace');
const dc = clientPerTest();

test('a call to a macro kept on the control is stepped over; M98 P915101 steps into O915101', async () => {
  const { event } = await dc.begin({ program: path.join(SHOP, 'O1000.nc'), stopOnEntry: true });
  assert.equal(event.body.reason, 'entry');
  assert.equal(await dc.value('#1100'), '1'); // preset by the machine file
  await dc.step('nextRequest'); // #101=#1100
  await dc.step('nextRequest'); // IF
  assert.equal((await dc.top()).line, 5); // G65 P9810
  await dc.step('stepInRequest'); // O9810 lives on the control: no source to stop in
  let top = await dc.top();
  assert.deepEqual([top.line, path.basename(top.source.path)], [6, 'O1000.nc']);
  await dc.step('stepInRequest'); // M98 P915101 L2
  top = await dc.top();
  assert.deepEqual([top.name, path.basename(top.source.path), top.line], ["O915101 (M98, main's locals, pass 1 of 2)", 'O915101.nc', 3]);
  const common = (await dc.scopesRequest({ frameId: top.id })).body.scopes.map((s) => s.name);
  assert.ok(common.includes('Common #100–#199'), common.join(', '));
});

test('a common the machine lacks stops the session with alarm 115 naming its commons', async () => {
  const { event } = await dc.begin({ program: path.join(SHOP, 'O1001.nc') }, { until: 'stopped' });
  assert.equal(event.body.reason, 'exception');
  const info = await dc.exceptionInfoRequest({ threadId: 1 });
  assert.match(info.body.description, /#300 is not a common variable of this machine/);
  assert.match(info.body.description, /#100-#199, #500-#999/);
});
