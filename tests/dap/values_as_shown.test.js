// A log point and a data breakpoint's "changed" text print values as the Variables view shows
// them (docs/debugging.md): up to 6 decimals, never a rounded 6 significant digits or an exponent.
// `cncmacro dap` driven through a real DAP client.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const dc = clientPerTest();

describe('values printed by breakpoints', () => {
  // log_values.nc: #1=25*SIN[180] (3.06e-15 in floating point), #2=50/2*COS[30] (25 × 0.8660254 =
  // 21.650635094…), #3=21650635, #4 vacant; the log point is on the M30 at line 5
  for (const [locale, vacant] of [[undefined, '<vacant>'], ['zh-CN', '<空>']]) {
    test(`a log point prints values as the Variables view shows them (${locale || 'en'})`, async () => {
      const logMessage = 'A{#1} B{#2} C{#3} D{#4}';
      await dc.begin({ program: program('log_values.nc'), stopAtEnd: false, stopOnEntry: false },
        { breakpoints: { 'log_values.nc': [{ line: 5, logMessage }] }, locale, until: 'terminated' });
      assert.match(dc.output, new RegExp(`A0 B21\\.650635 C21650635 D${vacant}\n`));
    });
  }

  test('a data breakpoint says what changed with the same values', async () => {
    await dc.begin({ program: program('log_values.nc'), stopOnEntry: true });
    await dc.setDataBreakpointsRequest({ breakpoints: [{ dataId: '#2' }] });
    const stop = await dc.step('continueRequest');
    assert.equal(stop.body.description, '#2 changed: vacant -> 21.650635');
  });
});
