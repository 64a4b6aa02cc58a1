// The cycle time in a real VS Code: the code lenses above the O line and each tool change of a
// two-tool program, the hover of a block saying when it starts, and the totals in the toolpath
// view's legend. Screenshots go to test-output/editor/cycle-*.png; with CNCMACRO_README_PICTURES
// set (npm run screenshots) the lens picture is copied to docs/images/cycle-time.png, which the
// README shows. Run: node --test tests/editor/cycle_time.test.mjs (after npm run package).
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { VIEWPORT, screenshot, startWorkbench } from './codeServer.mjs';
import { hoverOver, openFile } from './workbench.mjs';

const STEP = 90000;
let server;
let page;

const shot = (name, readme) => screenshot(page, `cycle-${name}`, { docs: readme });

before(async () => {
  ({ server, page } = await startWorkbench());
}, { timeout: 180000 });

after(async () => {
  await server?.stop();
});

// two_tools.nc, timed by hand (fanuc-0i: rapids 24000 mm/min, a tool change 3 s):
//   T1: change 3 s, rapid 0.1 s, Z-3 F300 1.6 s, 80 mm F1200 4 s twice, two half circles of
//       R25 (78.54 mm) at F1200 3.93 s each, Z50 0.13 s: 20.7 s, 325 mm cut
//   T2: change 3 s, two holes of 17 mm at F250 8.16 s, dwell 0.5 s, rapids 0.5 s: 12.2 s
test('a code lens above the program and each tool change gives its time and path', { timeout: STEP }, async () => {
  await openFile(page, 'two_tools.nc');
  const lenses = page.locator('.editor-instance .codelens-decoration');
  await lenses.filter({ hasText: 'T2' }).first().waitFor({ timeout: 60000 });
  const texts = (await lenses.allInnerTexts()).map((t) => t.replace(/\u00a0/g, ' '));
  assert.deepEqual(texts, [
    '≈ 33 s · 359 mm cut · 292 mm rapid',
    'T1 ≈ 21 s · 325 mm cut · 100 mm rapid',
    'T2 ≈ 12 s · 34 mm cut · 191 mm rapid',
  ]);
  await shot('1-lenses', 'cycle-time');
});

test('the hover of a block says when it starts in the cycle', { timeout: STEP }, async () => {
  // the dwell starts after everything but itself (0.5 s) and the last rapid (45 mm, 0.11 s): 32.3 s
  const hover = await hoverOver(page, /^G04$/, 'this block starts at');
  assert.match(await hover.innerText(), /Dwell[\s\S]*Cycle time: this block starts at ≈ 32 s \(the first time it runs\)/);
  await shot('2-hover');
  await page.mouse.move(5, 500);
  await page.keyboard.press('Escape');
});

test("the toolpath view's legend shows the run's totals", { timeout: STEP }, async () => {
  await page.keyboard.press('F1');
  await page.keyboard.type('CNC Macro: Show Toolpath');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Show Toolpath' }).first().waitFor();
  await page.keyboard.press('Enter');
  await page.locator('.tab', { hasText: 'Toolpath: two_tools.nc' }).waitFor();
  const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
  const totals = view.locator('#legend .totals');
  await totals.waitFor({ timeout: 45000 });
  assert.equal((await totals.innerText()).replace(/\u00a0/g, ' '), '≈ 33 s · 359 mm cut · 292 mm rapid');
  await shot('3-toolpath-legend');
});

test('in a narrow toolpath panel the totals wrap between their parts, none cut off at the edge', { timeout: STEP }, async () => {
  // a smaller window: the toolpath panel beside the program is about 200 px wide, narrower than
  // the bold '≈ 33 s · 359 mm cut · 292 mm rapid'
  await page.setViewportSize({ width: 760, height: 800 });
  try {
    const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
    const totals = view.locator('#legend .totals');
    await page.waitForTimeout(800); // the panel is laid out anew
    const drawn = await totals.evaluate((el) => {
      const text = document.createRange();
      text.selectNodeContents(el);
      return {
        right: text.getBoundingClientRect().right, // where the text ends, overflowing or not
        width: document.documentElement.clientWidth,
        lines: [...el.querySelectorAll('.item')].map((part) => [part.textContent, part.getClientRects().length]),
      };
    });
    assert.ok(drawn.right <= drawn.width, `the totals end at ${drawn.right} px, in a panel ${drawn.width} px wide`);
    // each part whole on its line: '359 mm cut' is never cut into '359 mm' and 'cut'
    assert.deepEqual(drawn.lines, [['≈ 33 s', 1], ['359 mm cut', 1], ['292 mm rapid', 1]]);
    await shot('4-narrow-legend');
  } finally {
    await page.setViewportSize(VIEWPORT);
  }
});

test('the editor tried no host but this machine: no gallery, telemetry or update check', { timeout: STEP }, async () => {
  assert.deepEqual(server.outsideHostAttempts(), []);
});
