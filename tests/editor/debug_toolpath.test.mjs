// The toolpath view while a debug session is paused, in a real VS Code: F9 and F5 stop at a
// move, the toolpath draws the run so far with the current block's move highlighted, the Debug
// toolbar's step back moves the highlight back to the move before, inline values show the
// variables of each line, and "Run to here" on a move of the drawing runs to its block. The
// picture after the step back is docs/images/debug-toolpath.png when CNCMACRO_README_PICTURES is
// set. Run: node --test tests/editor/debug_toolpath.test.mjs (after npm run package).
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { screenshot, startWorkbench } from './codeServer.mjs';
import { openFile } from './workbench.mjs';

const STEP = 90000;
let server;
let page;

const shot = (name, readme) => screenshot(page, name, { docs: readme, settle: 400 });

/** Click the move made on `line` and pick "Run to here" in the menu that opens there. */
async function runToHere(view, line, picture) {
  const move = view.locator(`#plot g.move[data-line="${line}"]`);
  const at = await move.locator('path.hit').evaluate((el) => {
    const p = el.getPointAtLength(el.getTotalLength() / 2);
    const screen = new DOMPoint(p.x, p.y).matrixTransform(el.getScreenCTM());
    const box = el.ownerSVGElement.getBoundingClientRect();
    return { x: screen.x - box.left, y: screen.y - box.top };
  });
  await view.locator('#plot').click({ position: at });
  const button = view.locator('#menu.open button', { hasText: 'Run to here' });
  await button.waitFor();
  if (picture) await shot(picture);
  await button.click();
}

before(async () => {
  ({ server, page } = await startWorkbench());
}, { timeout: 180000 });

after(async () => {
  await server?.stop();
});

test('paused, the toolpath highlights the current move; step back moves it back; run to here goes to a move', { timeout: STEP }, async () => {
  await openFile(page, 'profile_steps.nc');
  if (await page.locator('.part.panel').isVisible()) await page.keyboard.press('Control+J'); // room for the drawing
  await page.keyboard.press('F1');
  await page.keyboard.type('CNC Macro: Show Toolpath');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Show Toolpath' }).first().waitFor();
  await page.keyboard.press('Enter');
  const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
  await view.locator('#plot g.move').first().waitFor({ state: 'attached', timeout: 45000 });
  assert.equal(await view.locator('#plot g.move').count(), 10);

  // A breakpoint on G01 Y#2 (line 11), then F5.
  await page.locator('.editor-instance .view-lines').first().click();
  await page.keyboard.press('Control+G');
  await page.keyboard.type('11');
  await page.keyboard.press('Enter');
  await page.keyboard.press('F9');
  await page.locator('.codicon-debug-breakpoint').first().waitFor();
  await page.keyboard.press('F5');
  await page.locator('.debug-toolbar').waitFor({ state: 'visible' });
  await page.locator('.debug-top-stack-frame-line').first().waitFor();

  const current = view.locator('#plot g.move.current');
  await view.locator('#plot g.move.current[data-line="11"]').waitFor({ state: 'attached' });
  assert.equal(await current.count(), 1);
  assert.equal(await view.locator('#plot g.move.done').count(), 5); // lines 6-10 ran
  assert.equal(await view.locator('#plot g.move.ahead').count(), 4); // lines 12-15 are still to run
  assert.match(await view.locator('#status').innerText(), /Paused at profile_steps\.nc:11.*5 of 10 moves run/s);
  // inline values: VS Code asks the language server which expressions to show and the adapter for their values
  await page.locator('.editor-instance .view-line', { hasText: /#2[ \u00a0]=[ \u00a0]20/ }).first().waitFor();
  await page.locator('.editor-instance .view-line', { hasText: /#1[ \u00a0]=[ \u00a0]60,[ \u00a0]#2/ }).first().waitFor();
  if (await page.locator('.part.panel').isVisible()) await page.keyboard.press('Control+J'); // the Debug Console: room for the drawing
  await shot('debug-1-paused-toolpath');

  // Step back (the Debug toolbar's button): the highlight moves to G01 X#1 (line 10).
  await page.locator('.debug-toolbar .codicon-debug-step-back').click();
  await view.locator('#plot g.move.current[data-line="10"]').waitFor({ state: 'attached' });
  assert.equal(await current.count(), 1);
  assert.equal(await view.locator('#plot g.move.done').count(), 4);
  await page.locator('.debug-top-stack-frame-line').first().waitFor();
  await page.mouse.move(5, 500);
  await shot('debug-2-stepped-back', 'debug-toolpath');

  // "Run to here" on a move behind (G01 X0 Y0, line 9): the run goes back to its block.
  await runToHere(view, 9);
  await view.locator('#plot g.move.current[data-line="9"]').waitFor({ state: 'attached' });
  await page.locator('.debug-call-stack .monaco-list-row', { hasText: '9:1' }).first().waitFor();
  // Without the breakpoint on line 11 (F9 again), "Run to here" on the arc ahead (line 12) stops at its block.
  await page.locator('.editor-instance .view-lines').first().click();
  await page.keyboard.press('Control+G');
  await page.keyboard.type('11');
  await page.keyboard.press('Enter');
  await page.keyboard.press('F9');
  await page.locator('.codicon-debug-breakpoint').waitFor({ state: 'detached' });
  await runToHere(view, 12, 'debug-3-run-to-here-menu');
  await view.locator('#plot g.move.current[data-line="12"]').waitFor({ state: 'attached' });
  assert.match(await view.locator('#status').innerText(), /Paused at profile_steps\.nc:12/);
  await page.locator('.debug-call-stack .monaco-list-row', { hasText: '12:1' }).first().waitFor();
  await shot('debug-4-ran-to-the-arc');

  // The end of the session takes the debugger's picture away: the whole run again.
  await page.keyboard.press('Shift+F5');
  await page.locator('.debug-toolbar').waitFor({ state: 'hidden' });
  await view.locator('#status', { hasText: 'Completed' }).waitFor();
  assert.equal(await current.count(), 0);
});

test('the editor tried no host but this machine: no gallery, telemetry or update check', { timeout: STEP }, async () => {
  assert.deepEqual(server.outsideHostAttempts(), []);
});
