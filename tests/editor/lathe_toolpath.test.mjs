// A lathe's toolpath in a real VS Code: the bundled example shaft_g71.nc (GSK980TDi: G71 roughing,
// G70 finishing, a G92 thread) drawn with Z across, X up and the spindle's centre line, every G71
// pass a move of its own; the Radius/Diameter and Both halves buttons change the X scale and draw
// the mirrored half, and a new panel keeps them; paused in the debugger at the G71 block, its
// passes are the current block's, highlighted. The picture of the paused lathe is
// docs/images/lathe-toolpath.png when CNCMACRO_README_PICTURES is set.
// Run: node --test tests/editor/lathe_toolpath.test.mjs (after npm run package).
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { ROOT, screenshot, startWorkbench } from './codeServer.mjs';
import { openFile } from './workbench.mjs';

const STEP = 120000;
const EXAMPLE = path.join(ROOT, 'examples', 'gsk980tdi', 'shaft_g71.nc');
const G71_LINE = 11; // G71 P10 Q20 U0.4 W0.1 F0.25
let server;
let page;

const shot = (name, readme) => screenshot(page, name, { docs: readme, settle: 600 });

before(async () => {
  ({ server, page } = await startWorkbench({
    prepare: (started) => fs.copyFileSync(EXAMPLE, path.join(started.workspace, 'shaft_g71.nc')),
  }));
}, { timeout: 180000 });

after(async () => {
  await server?.stop();
});

/** The moves `cncmacro run --json` makes for the example: what the view must draw. */
function exampleMoves() {
  const cncmacro = path.join(ROOT, '.venv', 'bin', 'cncmacro');
  const run = spawnSync(cncmacro, ['run', '--json', '--no-save', EXAMPLE], { encoding: 'utf8' });
  assert.ok(run.stdout, `cncmacro run printed nothing: ${run.stderr}`);
  return JSON.parse(run.stdout).moves;
}

/**
 * The legend's entries drawn on the line of its totals (the run's cycle time and path), once the
 * panel is laid out: none should be, or `still to run ≈ 1 min 26 s · …` reads as the time left.
 */
async function besideTotals(view) {
  await page.waitForTimeout(400);
  return view.locator('#legend').evaluate((legend) => {
    const totals = legend.querySelector('.totals').getBoundingClientRect();
    return [...legend.querySelectorAll('li:not(.totals):not(.plane)')]
      .filter((entry) => entry.getBoundingClientRect().bottom > totals.top + 1)
      .map((entry) => entry.textContent);
  });
}

async function showToolpath() {
  await page.keyboard.press('F1');
  await page.keyboard.type('CNC Macro: Show Toolpath');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Show Toolpath' }).first().waitFor();
  await page.keyboard.press('Enter');
  await page.locator('.tab', { hasText: 'Toolpath: shaft_g71.nc' }).waitFor();
  return page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
}

test('a lathe program: Z across, X up, the centre line drawn, each G71 pass drawn; radius, diameter and both halves kept', { timeout: 2 * STEP }, async () => {
  const moves = exampleMoves();
  const passes = moves.filter((m) => m.pass_of === 'G71');
  assert.ok(passes.length > 10);
  await openFile(page, 'shaft_g71.nc');
  if (await page.locator('.part.panel').isVisible()) await page.keyboard.press('Control+J'); // room for the drawing
  let view = await showToolpath();
  await view.locator('#status', { hasText: `${moves.length} moves` }).waitFor({ timeout: 45000 });
  assert.equal(await view.locator('#plot g.move').count(), moves.length);
  assert.equal(await view.locator(`#plot g.move[data-line="${G71_LINE}"]`).count(), passes.length);
  assert.equal(await view.locator('#plot line.spindle').count(), 1);
  // the first rapid comes from where the turret was, which the program does not say: not drawn across the part
  const astray = moves.map((m, i) => [m.unknown, i]).filter(([unknown]) => unknown);
  assert.deepEqual(astray, [['start', 0]]);
  assert.equal(await view.locator('#plot g.move[data-index="0"] path.leg').count(), 0);
  assert.ok(await view.locator('#plot g.move[data-index="1"] path.leg').count() > 0); // the approach from there on
  assert.equal(await view.locator('#plot .axis-name.h').textContent(), 'Z →');
  assert.equal(await view.locator('#plot .axis-name.v').textContent(), '↑ X (diameter)');
  assert.equal(await view.locator('button.on', { hasText: 'Diameter' }).count(), 1);
  assert.match(await view.locator('#legend').innerText(), /spindle axis \(centre line, X0\)/);
  // the planes of a mill are not offered on a lathe
  assert.equal(await view.locator('button[data-post="plane"]').count(), 0);
  const labels = async () => view.locator('#plot text.y-label').evaluateAll((els) => els.map((e) => Number(e.textContent)));
  const diameters = await labels();
  assert.ok(diameters.includes(40) && diameters.every((d) => d >= 0), diameters.join(' ')); // diameters, one half
  await shot('lathe-1-diameter');

  // Radius: the same drawing, its X scale at half
  await view.locator('button', { hasText: 'Radius' }).click();
  await view.locator('#plot .axis-name.v', { hasText: 'X (radius)' }).waitFor();
  assert.deepEqual(await labels(), diameters.map((d) => d / 2));
  // Both halves: every move again, mirrored about the centre line, not clickable
  await view.locator('#both-halves').click();
  await view.locator('#plot g.mirror').waitFor({ state: 'attached' });
  assert.equal(await view.locator('#plot g.mirror g.move').count(), moves.length);
  assert.ok((await labels()).includes(-20)); // the mirrored half: radii below the centre line
  await shot('lathe-2-radius-both-halves');

  // A new panel (closed and shown again) keeps both picks
  await page.locator('.tab', { hasText: 'Toolpath: shaft_g71.nc' }).locator('.codicon-close').click();
  await page.locator('.tab', { hasText: 'Toolpath: shaft_g71.nc' }).waitFor({ state: 'detached' });
  await page.locator('.editor-instance .view-lines').first().click();
  view = await showToolpath();
  await view.locator('#status', { hasText: `${moves.length} moves` }).waitFor({ timeout: 45000 });
  assert.equal(await view.locator('button.on', { hasText: 'Radius' }).count(), 1);
  assert.equal(await view.locator('#both-halves.on').count(), 1);
  await view.locator('button', { hasText: 'Diameter' }).click(); // back to diameters, both halves kept
  await view.locator('#plot .axis-name.v', { hasText: 'X (diameter)' }).waitFor();
});

test('paused at the G71 block, every one of its passes is highlighted as the current block\'s', { timeout: 2 * STEP }, async () => {
  const moves = exampleMoves();
  const passes = moves.filter((m) => m.pass_of === 'G71');
  const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
  await page.locator('.editor-instance .view-lines').first().click();
  await page.keyboard.press('Control+G');
  await page.keyboard.type(String(G71_LINE));
  await page.keyboard.press('Enter');
  await page.keyboard.press('F9');
  await page.locator('.codicon-debug-breakpoint').first().waitFor();
  await page.keyboard.press('F5');
  await page.locator('.debug-toolbar').waitFor({ state: 'visible' });
  await page.locator('.debug-top-stack-frame-line').first().waitFor();
  await view.locator(`#plot g.move.current[data-line="${G71_LINE}"]`).first().waitFor({ state: 'attached', timeout: 45000 });
  assert.equal(await view.locator('#plot g.move.current').count(), passes.length);
  assert.equal(await view.locator('#plot g.move.done').count(), 1); // G00 X44. Z2.
  assert.match(await view.locator('#status').innerText(), new RegExp(`Paused at shaft_g71\\.nc:${G71_LINE}.*1 of ${moves.length} moves run`, 's'));
  assert.equal(await view.locator('#plot line.spindle').count(), 1); // still a lathe: the adapter says so
  const title = await view.locator(`#plot g.move.current[data-line="${G71_LINE}"] title`).nth(1).textContent();
  assert.match(title, /\(pass of G71\)$/);
  if (await page.locator('.part.panel').isVisible()) await page.keyboard.press('Control+J'); // the Debug Console: room for the drawing
  assert.deepEqual(await besideTotals(view), [], 'with the side bar');
  await page.keyboard.press('Control+B'); // the side bar away: room for the drawing
  await page.locator('.part.sidebar').waitFor({ state: 'hidden' });
  await page.mouse.move(5, 500);
  assert.deepEqual(await besideTotals(view), [], 'without the side bar');
  await shot('lathe-3-paused-at-g71', 'lathe-toolpath');
  await page.keyboard.press('Control+B');

  // A step over the G71 block: the run goes on after the shape (N20 is line 20), the passes are done
  await page.keyboard.press('F10');
  await view.locator('#plot g.move.done').nth(passes.length).waitFor({ state: 'attached' });
  assert.equal(await view.locator(`#plot g.move.current[data-line="${G71_LINE}"]`).count(), 0);
  await page.keyboard.press('Shift+F5');
  await page.locator('.debug-toolbar').waitFor({ state: 'hidden' });
  await view.locator('#status', { hasText: 'Completed' }).waitFor();
});

test('the editor tried no host but this machine: no gallery, telemetry or update check', { timeout: STEP }, async () => {
  assert.deepEqual(server.outsideHostAttempts(), []);
});
