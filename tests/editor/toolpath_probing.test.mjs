// Probing offline in a real VS Code: the corpus's bore-measuring program (tests/corpus/fanuc-0i:
// probe_bore.nc calls the macro O9814, four G31 touches) in a folder of its own with the machine
// file that describes the bore. Show Toolpath draws the G31 moves as probe moves with a dot at
// each contact point, and names both in the legend. Screenshots: test-output/editor/probing-toolpath.png and
// probing-toolpath-zoomed.png (the bore zoomed in with the wheel).
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { OUTPUT, ROOT, startWorkbench } from './codeServer.mjs';
import { exact, openFile } from './workbench.mjs';

const CORPUS = path.join(ROOT, 'tests', 'corpus', 'fanuc-0i');
const FILES = ['.cncmacro.toml', 'probe_bore.nc', 'O9814.nc', 'O9001.nc'];
let server;
let page;

before(async () => {
  ({ server, page } = await startWorkbench({
    prepare: (started) => {
      const folder = path.join(started.workspace, 'probing');
      fs.mkdirSync(folder);
      for (const name of FILES) fs.copyFileSync(path.join(CORPUS, name), path.join(folder, name));
    },
  }));
}, { timeout: 180000 });

after(async () => {
  await server?.stop();
});

/** The moves `cncmacro run --json` makes for the corpus program: what the view must draw. */
function corpusMoves() {
  const cncmacro = path.join(ROOT, '.venv', 'bin', 'cncmacro');
  const run = spawnSync(cncmacro, ['run', '--json', '--no-save', 'probe_bore.nc'], { cwd: CORPUS, encoding: 'utf8' });
  assert.ok(run.stdout, `cncmacro run printed nothing: ${run.stderr}`);
  return JSON.parse(run.stdout).moves;
}

test('Show Toolpath draws the probe moves of a bore-measuring macro and a dot at each contact point', { timeout: 120000 }, async () => {
  const moves = corpusMoves();
  const touches = moves.filter((m) => m.mode === 'G31');
  assert.equal(touches.length, 4);
  assert.ok(touches.every((m) => m.skip === true));
  try {
    if (!(await page.locator('.explorer-folders-view').isVisible())) await page.keyboard.press('Control+Shift+E');
    await page.locator('.explorer-folders-view .label-name', { hasText: exact('probing') }).click(); // opens the folder
    await openFile(page, 'probe_bore.nc');
    if (await page.locator('.part.panel').isVisible()) await page.keyboard.press('Control+J');
    await page.keyboard.press('F1');
    await page.keyboard.type('CNC Macro: Show Toolpath');
    await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Show Toolpath' }).first().waitFor();
    await page.keyboard.press('Enter');
    await page.locator('.tab', { hasText: 'Toolpath: probe_bore.nc' }).waitFor();
    const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
    await view.locator('#status', { hasText: `${moves.length} moves` }).waitFor({ timeout: 45000 });
    assert.match(await view.locator('#status').innerText(), /Completed/);
    assert.equal(await view.locator('#plot g.move.probe').count(), 4, 'the four G31 touches');
    assert.equal(await view.locator('#plot g.move.probe circle.contact').count(), 4, 'a dot at each contact point');
    const title = await view.locator('#plot g.move.probe title').first().textContent();
    assert.match(title, /^O9814\.nc:25  G31  X120 → X142\.54  F200$/);
    const legend = await view.locator('#legend').innerText();
    assert.match(legend, /probe move \(G31\)[\s\S]*contact point: where the skip signal came on/);
    await page.waitForTimeout(300);
    await page.screenshot({ path: path.join(OUTPUT, 'probing-toolpath.png') });
    // Zoomed in on the bore, as a user does with the wheel: the four touches and their dots.
    const box = await view.locator('#plot g.move.probe').first().boundingBox();
    assert.ok(box, 'the first touch is drawn');
    const plot = await view.locator('#plot').boundingBox();
    assert.ok(plot, 'the drawing is shown');
    const centre = { x: plot.x + plot.width / 2, y: plot.y + plot.height / 2 };
    await page.mouse.move(box.x, box.y + box.height / 2); // its start: the bore's nominal centre
    await page.mouse.down();
    await page.mouse.move(centre.x, centre.y, { steps: 10 }); // dragged to the middle of the view
    await page.mouse.up();
    for (let k = 0; k < 5; k += 1) await page.mouse.wheel(0, -100);
    await page.waitForTimeout(300);
    await page.screenshot({ path: path.join(OUTPUT, 'probing-toolpath-zoomed.png') });
  } catch (e) {
    await page.screenshot({ path: path.join(OUTPUT, 'failed-probing-toolpath.png') }).catch(() => undefined);
    throw e;
  }
});

test('the editor tried no host but this machine: no gallery, telemetry or update check', { timeout: 90000 }, async () => {
  assert.deepEqual(server.outsideHostAttempts(), []);
});
