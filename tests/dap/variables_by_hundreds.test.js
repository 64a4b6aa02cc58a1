// docs/debugging.md, scopes: a Common or Persistent scope of more than 100 variables opens on
// one row per hundred numbers (#100–#199, ..., #500–#599, ...), valued with the first three of
// its numbers that hold a value, and each row opens on its hundred variables, so #512 is found
// without scrolling past 400 others. Run from the repository root: `node --test tests/dap/`.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

// tests/dap/programs/commons_by_hundreds.nc: #100=1.5 #199=2 #512=7 #513=-0.25 #600=3 #601=4
// #602=5 #603=6, then M30 on line 10 (a breakpoint there: every assignment has run).
const PROGRAM = 'commons_by_hundreds.nc';

const dc = clientPerTest();

async function open(ref, more = {}) {
  return (await dc.variablesRequest({ variablesReference: ref, ...more })).body.variables;
}

async function scope(name) {
  const scopes = (await dc.scopesRequest({ frameId: 1 })).body.scopes;
  return scopes.find((s) => s.name.startsWith(name)).variablesReference;
}

describe('large scopes open by hundreds', () => {
  test('fanuc-0i: Common #100–#499 is four hundreds, Persistent #500–#999 five; #512 is the 13th of its hundred', async () => {
    await dc.begin({ program: program(PROGRAM) }, { breakpoints: { [PROGRAM]: [{ line: 10 }] } });
    const common = await open(await scope('Common'));
    // #100–#499 cut at each hundred: 4 rows; #100 and #199 in the first, nothing in the others
    assert.deepEqual(common.map((v) => [v.name, v.value]), [
      ['#100–#199', '#100 = 1.5, #199 = 2'], ['#200–#299', 'all vacant'],
      ['#300–#399', 'all vacant'], ['#400–#499', 'all vacant'],
    ]);
    assert.ok(common.every((v) => v.variablesReference > 0 && v.namedVariables === 100));
    const persistent = await open(await scope('Persistent'));
    // #600–#603 hold four values: the row names the first three and '…'
    assert.deepEqual(persistent.map((v) => [v.name, v.value]), [
      ['#500–#599', '#512 = 7, #513 = -0.25'], ['#600–#699', '#600 = 3, #601 = 4, #602 = 5, …'],
      ['#700–#799', 'all vacant'], ['#800–#899', 'all vacant'], ['#900–#999', 'all vacant'],
    ]);
    const fives = await open(persistent[0].variablesReference);
    // #500 … #599 is 100 variables; #512 is at index 512 - 500 = 12
    assert.equal(fives.length, 100);
    assert.deepEqual([fives[0].name, fives[0].value, fives[99].name], ['#500', '<vacant>', '#599']);
    assert.deepEqual([fives[12].name, fives[12].value, fives[12].evaluateName], ['#512', '7', '#512']);
    // paged as a client pages: start 12, count 2 is #512 and #513
    const page = await open(persistent[0].variablesReference, { start: 12, count: 2 });
    assert.deepEqual(page.map((v) => [v.name, v.value]), [['#512', '7'], ['#513', '-0.25']]);
    assert.deepEqual(await open(persistent[0].variablesReference, { filter: 'indexed' }), []);
    // a variable in a hundred is set as any other: #513 = -0.25 + 1 = 0.75
    const set = await dc.setVariableRequest({ variablesReference: persistent[0].variablesReference, name: '#513', value: '#513+1' });
    assert.equal(set.body.value, '0.75');
    assert.equal((await open(await scope('Persistent')))[0].value, '#512 = 7, #513 = 0.75');
  });

  test('in a Chinese locale a hundred with nothing in it is 全部为空', async () => {
    await dc.begin({ program: program(PROGRAM) }, { breakpoints: { [PROGRAM]: [{ line: 10 }] }, locale: 'zh-CN' });
    const common = await open(await scope('公共变量'));
    assert.deepEqual(common.slice(0, 2).map((v) => [v.name, v.value]), [
      ['#100–#199', '#100 = 1.5, #199 = 2'], ['#200–#299', '全部为空'],
    ]);
  });

  test('a Locals scope of 33 and a reference to no hundred', async () => {
    await dc.begin({ program: program(PROGRAM) }, { breakpoints: { [PROGRAM]: [{ line: 10 }] } });
    assert.equal((await open(await scope('Locals'))).length, 33); // small: its variables at once
    // Persistent has five hundreds: a sixth does not exist
    const ref = (await open(await scope('Persistent')))[4].variablesReference;
    await assert.rejects(open(ref + 1), /no variables reference/);
  });
});
