// Cutter radius compensation in a real VS Code: the bundled example contour_g41.nc (a plate 80 x 50
// with R8 corners, cut clockwise with G41 D01, radius 5) drawn with its programmed contour and,
// beside it, the tool centre's path 5 mm outside, in a colour of its own and named in the legend;
// the Tool centre button hides it and shows it again. The picture is docs/images/cutter-toolpath.png
// when CNCMACRO_README_PICTURES is set.
// Run: node --test tests/editor/cutter_toolpath.test.mjs (after npm run package).
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { ROOT, screenshot, startWorkbench } from './codeServer.mjs';
import { openFile } from './workbench.mjs';

const STEP = 120000;
const EXAMPLE = path.join(ROOT, 'examples', 'fanuc', 'contour_g41.nc');
const TOP_SIDE = 18; // G01 X32.: the plate's top edge at Y25, the tool centre at Y30
const RIGHT_SIDE = 20; // G01 Y-17.: the right edge at X40, the tool centre at X45
let server;
let page;

before(async () => {
  ({ server, page } = await startWorkbench({
    prepare: (started) => fs.copyFileSync(EXAMPLE, path.join(started.workspace, 'contour_g41.nc')),
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

/** The screen box (in the webview's page) of the first element `selector` finds in the drawing. */
const box = (view, selector) => view.locator(selector).first().evaluate((el) => {
  const r = el.getBoundingClientRect();
  return { left: r.left, right: r.right, top: r.top, bottom: r.bottom };
});

/** The sash between the program and its toolpath dragged left: a larger drawing, the program still readable. */
async function widenToolpath() {
  const sashes = await page.locator('.part.editor .monaco-sash.vertical').evaluateAll((els) =>
    els.map((e) => e.getBoundingClientRect()).filter((r) => r.width > 0 && r.height > 200).map((r) => ({ x: r.left + r.width / 2, y: r.top + r.height / 2 })));
  const sash = sashes.find((r) => r.x > 400 && r.x < 900);
  if (!sash) return;
  await page.mouse.move(sash.x, sash.y);
  await page.mouse.down();
  await page.mouse.move(sash.x - 60, sash.y, { steps: 4 });
  await page.mouse.move(560, sash.y, { steps: 4 });
  await page.mouse.up();
}

test('a G41 contour: the tool centre is drawn a radius outside the plate, named in the legend, and the Tool centre button hides and shows it', { timeout: 2 * STEP }, async () => {
  const moves = exampleMoves();
  const compensated = moves.filter((m) => m.tool_path);
  assert.equal(compensated.length, 11); // the start-up on line 15 to the cancel on line 25
  await openFile(page, 'contour_g41.nc');
  if (await page.locator('.part.panel').isVisible()) await page.keyboard.press('Control+J'); // room for the drawing
  await page.keyboard.press('F1');
  await page.keyboard.type('CNC Macro: Show Toolpath');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Show Toolpath' }).first().waitFor();
  await page.keyboard.press('Enter');
  await page.locator('.tab', { hasText: 'Toolpath: contour_g41.nc' }).waitFor();
  const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
  await view.locator('#status', { hasText: `${moves.length} moves` }).waitFor({ timeout: 45000 });
  assert.equal(await view.locator('#plot g.move').count(), moves.length);
  // one centre path per compensated move, in the move's own group, and none elsewhere
  const centres = view.locator('#plot g.move path.centre');
  assert.equal(await centres.count(), compensated.length);
  for (const m of compensated) {
    assert.equal(await view.locator(`#plot g.move[data-line="${m.line}"] path.centre`).count(), 1, `line ${m.line}`);
  }
  assert.match(await view.locator('#legend').innerText(), /tool centre \(cutter compensation G41\/G42\)/);
  // drawn in a colour of its own: not the feed's
  const colour = (selector) => view.locator(selector).first().evaluate((el) => getComputedStyle(el).stroke);
  assert.notEqual(await colour(`#plot g.move[data-line="${TOP_SIDE}"] path.centre`), await colour(`#plot g.move[data-line="${TOP_SIDE}"] path.leg`));
  // outside the plate: above its top edge and right of its right edge (screen y grows downwards)
  const topLeg = await box(view, `#plot g.move[data-line="${TOP_SIDE}"] path.leg`);
  const topCentre = await box(view, `#plot g.move[data-line="${TOP_SIDE}"] path.centre`);
  assert.ok(topCentre.bottom < topLeg.top, `top side: centre ${JSON.stringify(topCentre)}, programmed ${JSON.stringify(topLeg)}`);
  const rightLeg = await box(view, `#plot g.move[data-line="${RIGHT_SIDE}"] path.leg`);
  const rightCentre = await box(view, `#plot g.move[data-line="${RIGHT_SIDE}"] path.centre`);
  assert.ok(rightCentre.left > rightLeg.right, `right side: centre ${JSON.stringify(rightCentre)}, programmed ${JSON.stringify(rightLeg)}`);
  // at the drawing's scale, 5 mm apart on both sides alike
  const gapTop = (topLeg.top + topLeg.bottom) / 2 - (topCentre.top + topCentre.bottom) / 2;
  const gapRight = (rightCentre.left + rightCentre.right) / 2 - (rightLeg.left + rightLeg.right) / 2;
  assert.ok(Math.abs(gapTop - gapRight) < 1.5, `gaps ${gapTop} and ${gapRight} px`);

  // the Tool centre button: on, then off hides every centre path, then on shows them again
  const button = view.locator('#centre-path');
  assert.equal(await button.innerText(), 'Tool centre');
  assert.equal(await view.locator('#centre-path.on').count(), 1);
  await button.click();
  await view.locator('#centre-path:not(.on)').waitFor();
  await centres.first().waitFor({ state: 'hidden' });
  assert.equal(await centres.evaluateAll((els) => els.filter((e) => getComputedStyle(e).display !== 'none').length), 0);
  // the programmed path stays: every move but those from or to a place the run does not know (not drawn)
  assert.equal(await view.locator('#plot g.move path.leg').count() >= moves.filter((m) => !m.unknown).length, true);
  await screenshot(page, 'cutter-1-centre-hidden');
  await button.click();
  await view.locator('#centre-path.on').waitFor();
  await centres.first().waitFor({ state: 'visible' });
  assert.equal(await centres.evaluateAll((els) => els.filter((e) => getComputedStyle(e).display !== 'none').length), compensated.length);

  await page.keyboard.press('Control+B'); // the side bar away: room for the drawing
  await page.locator('.part.sidebar').waitFor({ state: 'hidden' });
  await widenToolpath();
  await page.mouse.move(5, 500);
  await screenshot(page, 'cutter-2-centre-shown', { docs: 'cutter-toolpath', settle: 600 });
  await page.keyboard.press('Control+B');
});

test('the editor tried no host but this machine: no gallery, telemetry or update check', { timeout: STEP }, async () => {
  assert.deepEqual(server.outsideHostAttempts(), []);
});
