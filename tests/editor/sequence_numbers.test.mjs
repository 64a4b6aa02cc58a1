// The sequence-number commands in a real VS Code: "CNC Macro: Renumber Sequence Numbers" asks for
// the step, and the language server rewrites the labels and the jumps to them in the editor; a
// jump whose label is computed makes the server ask, naming the line, whether to keep the labels
// it could reach; Format Document formats a program and Show Call Hierarchy lists a macro's
// callers. Screenshots go to test-output/editor/. Run after npm run package:
// node --test --test-concurrency=1 tests/editor/sequence_numbers.test.mjs
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { screenshot, startWorkbench } from './codeServer.mjs';
import { openFile } from './workbench.mjs';

const STEP = 60000;
let server;
let page;

const LOOP = ['O0001 (RENUMBER ME)', '#1=0', 'N3 #1=#1+1', 'IF[#1 LT 3] GOTO3', 'GOTO 7', '#2=99', 'N7 M98 P0002 Q8', 'M30', 'O0002', 'N8 #3=1', 'M99', ''];
const COMPUTED = ['O0001 (COMPUTED JUMP)', '#1=7', 'N5 GOTO #1', 'N7 #2=1', 'M30', ''];

const shot = (name) => screenshot(page, name);

/** The editor's text, as drawn (no-break spaces read as spaces). */
async function editorLines() {
  const rows = await page.locator('.editor-instance .view-lines .view-line').evaluateAll((els) =>
    els.map((el) => ({ top: parseFloat(el.style.top), text: el.textContent.replace(/\u00a0/g, ' ') })),
  );
  return rows.sort((a, b) => a.top - b.top).map((r) => r.text);
}

async function command(title, category = 'CNC Macro: ') {
  await page.keyboard.press('F1');
  await page.keyboard.type(`${category}${title}`);
  await page.locator('.quick-input-list .monaco-list-row', { hasText: title }).first().waitFor();
  await page.keyboard.press('Enter');
}

/** The programs the tests open, written into the workspace before the workbench starts. */
const PROGRAMS = {
  'renumber.nc': LOOP,
  'computed.nc': COMPUTED,
  'format_me.nc': ['o0002 (Lower Title)', 'n10 g01x10.y5. f100(cut)', 'if[#1gt2]goto10', 'm30', ''],
};

async function openProgram(name) {
  await openFile(page, name);
  await page.locator('.statusbar-item', { hasText: 'FANUC 0i' }).waitFor();
}

async function until(what, check) {
  for (const end = Date.now() + 30000; !(await check()); await page.waitForTimeout(200)) {
    assert.ok(Date.now() < end, what);
  }
}

before(async () => {
  ({ server, page } = await startWorkbench({
    prepare: (started) => {
      for (const [name, lines] of Object.entries(PROGRAMS)) {
        fs.writeFileSync(path.join(started.workspace, name), lines.join('\n'));
      }
    },
  }));
}, { timeout: 180000 });

after(async () => {
  await server?.stop();
});

test('Renumber Sequence Numbers asks for the step and rewrites the labels and every jump to them', { timeout: 2 * STEP }, async () => {
  await openProgram('renumber.nc');
  await command('Renumber Sequence Numbers');
  const input = page.locator('.quick-input-widget input');
  await input.waitFor();
  assert.equal(await input.inputValue(), '10');
  await input.fill('10');
  await page.keyboard.press('Enter');
  const wanted = ['O0001 (RENUMBER ME)', '#1=0', 'N10 #1=#1+1', 'IF[#1 LT 3] GOTO10', 'GOTO 20', '#2=99', 'N20 M98 P0002 Q10', 'M30', 'O0002', 'N10 #3=1', 'M99'];
  await until('the labels are renumbered', async () => (await editorLines()).slice(0, 11).join('\n') === wanted.join('\n'));
  await shot('seq-1-renumbered');
  await page.keyboard.press('Control+Z'); // one edit: one undo brings the program back
  await until('undo brings the old labels back', async () => (await editorLines())[2] === 'N3 #1=#1+1');
  await page.keyboard.press('Control+S');
});

test('a computed GOTO makes the server ask, naming its line; keeping leaves those labels alone', { timeout: 2 * STEP }, async () => {
  await openProgram('computed.nc');
  await command('Renumber Sequence Numbers');
  await page.locator('.quick-input-widget input').waitFor();
  await page.keyboard.press('Enter');
  const toast = page.locator('.notification-toast', { hasText: 'line 3' });
  await toast.waitFor();
  assert.match(await toast.innerText(), /computed/);
  await shot('seq-2-computed-goto-asks');
  await toast.locator('.monaco-button', { hasText: 'Keep those labels unchanged' }).click();
  await until('nothing renumbered in the program of the computed jump', async () =>
    page.locator('.notification-toast', { hasText: 'Nothing to change' }).isVisible(),
  );
  assert.deepEqual((await editorLines()).slice(0, 5), COMPUTED.slice(0, 5));
});

test('Format Document upper-cases the words and spaces them, comments as written', { timeout: STEP }, async () => {
  await openProgram('format_me.nc');
  await page.locator('.editor-instance .view-lines').click();
  await command('Format Document', '');
  const wanted = ['O0002 (Lower Title)', 'N10 G01 X10. Y5. F100 (cut)', 'IF [#1 GT 2] GOTO 10', 'M30'];
  await until('the program is formatted', async () => (await editorLines()).slice(0, 4).join('\n') === wanted.join('\n'));
  await shot('seq-3-formatted');
  await page.keyboard.press('Control+S');
});

test('Show Call Hierarchy on the macro O9100 lists the main program that calls it', { timeout: STEP }, async () => {
  await openFile(page, 'O9100.nc');
  await page.locator('.editor-instance .view-lines').click();
  await page.keyboard.press('Control+Home');
  await command('Show Call Hierarchy', 'Calls: ');
  const caller = page.locator('.monaco-list-row', { hasText: 'O1000' }).first();
  await caller.waitFor();
  assert.match(await caller.innerText(), /BOLT CIRCLE DRILLING - MAIN PROGRAM/);
  await shot('seq-4-call-hierarchy');
});

test('the editor tried no host but this machine: no gallery, telemetry or update check', { timeout: STEP }, async () => {
  assert.deepEqual(server.outsideHostAttempts(), []);
});
