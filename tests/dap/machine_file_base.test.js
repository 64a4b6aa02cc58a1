// The machine file's `base` through the debugger (docs/machine-file.md): the workspace
// tests/data/machine_30i_workspace is a 30i mill (base = "fanuc-30i" with its commons, 8-digit
// program numbers in M98 P and O9000-O9999 kept on the control); as_fanuc_0i.toml there is the
// same machine with the base fanuc-0i, under which the same program stops with an alarm.
'use strict';

const assert = require('node:assert/strict');
const path = require('node:path');
const { test } = require('node:test');
const { clientPerTest } = require('./client.js');

const CELL = path.resolve(__dirname, '..', 'data', 'machine_30i_workspace');
const PROGRAM = path.join(CELL, 'O3000.nc');
const dc = clientPerTest();

async function row(frameId, scopeName, name) {
  const found = await dc.scopeRow(frameId, scopeName, name);
  assert.ok(found, `no ${name} in ${scopeName}`);
  return found.value;
}

test('base = "fanuc-30i" wins over the launch dialect: names, #3101, #98000, O9810 on the control, M98 P12345678', async () => {
  // the extension fills `dialect` from the cncMacro.dialect setting (fanuc-0i by default)
  const { event } = await dc.begin({ program: PROGRAM, dialect: 'fanuc-0i', stopOnEntry: true });
  assert.equal(event.body.reason, 'entry');
  assert.equal(await dc.value('[#_PI]'), '3.141593');
  assert.equal(await dc.value('#3101'), '3.141593');
  let top = await dc.top();
  const scopes = (await dc.scopesRequest({ frameId: top.id })).body.scopes.map((s) => s.name);
  assert.ok(scopes.includes('Common #100–#199'), scopes.join(', '));
  assert.ok(scopes.includes('Persistent #500–#999, #98000–#98099'), scopes.join(', '));

  await dc.step('nextRequest'); // #101=[#_PI]
  await dc.step('nextRequest'); // #102=#3101
  await dc.step('nextRequest'); // #98000=#98000+1
  top = await dc.top();
  assert.equal(top.line, 6); // G65 P9810
  assert.equal(await row(top.id, 'Common', '#101'), '3.141593');
  assert.equal(await row(top.id, 'Common', '#102'), '3.141593');
  assert.equal(await row(top.id, 'Persistent', '#98000'), '1');

  await dc.step('stepInRequest'); // O9810 lives on the control: no source to stop in
  top = await dc.top();
  assert.deepEqual([top.line, path.basename(top.source.path)], [7, 'O3000.nc']);
  await dc.step('stepInRequest'); // M98 P12345678 L2: the whole P is the program number
  top = await dc.top();
  assert.deepEqual([top.name, path.basename(top.source.path), top.line], ["O12345678 (M98, main's locals, pass 1 of 2)", 'O12345678.nc', 3]);

  const end = await dc.step('continueRequest');
  assert.deepEqual([end.body.reason, end.body.description], ['step', 'program end (M30)']);
  assert.equal(await dc.value('#103'), '2'); // L2: two passes
});

test('the same program on the same machine with base = "fanuc-0i" stops at [#_PI] with alarm 114', async () => {
  const { event } = await dc.begin({ program: PROGRAM, machine: path.join(CELL, 'as_fanuc_0i.toml'), stopOnEntry: true });
  assert.equal(event.body.reason, 'entry');
  await assert.rejects(dc.value('[#_PI]'), /system variable names are not a feature of FANUC 0i/);
  await assert.rejects(dc.value('#3101'), /#3101 does not exist on FANUC 0i/);
  await assert.rejects(dc.value('#98000'), /#98000 does not exist on FANUC 0i/);
  const top = await dc.top();
  const scopes = (await dc.scopesRequest({ frameId: top.id })).body.scopes.map((s) => s.name);
  assert.ok(scopes.includes('Persistent #500–#999'), scopes.join(', '));

  const stop = await dc.step('continueRequest');
  assert.equal(stop.body.reason, 'exception');
  assert.equal((await dc.top()).line, 3);
  const info = await dc.exceptionInfoRequest({ threadId: 1 });
  assert.match(info.body.description, /ALARM 114: #_PI: system variable names are not a feature of FANUC 0i/);
});
