// A program kept as a .txt file (a GSK or DNC folder's O0810.txt) in a real VS Code: opened
// first, before any other program, it is CNC Macro (status bar), the language server starts for
// it, reports its mistake and answers a hover; a .txt of plain words beside it stays Plain Text.
// Screenshots go to test-output/editor/ (txt-*.png). Run after npm run package:
// node --test --test-concurrency=1 tests/editor/txt_programs.test.mjs
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { screenshot, startWorkbench } from './codeServer.mjs';
import { exact, hoverOver, openFile } from './workbench.mjs';

const STEP = 60000;
let server;
let page;

/** The files the test opens, written into the workspace before the workbench starts. */
const FILES = {
  'O0810.txt': ['O0810 (DRILL, KEPT AS A TXT FILE)', 'G90 G54 G00 X0 Y0', '#100=#5001', 'IF [#100 GT 10] GOTO 99', 'M99', ''],
  'SHIFT_NOTES.txt': ['Shift notes: O0810 drills the pallet holes; check T01 before the run.', ''],
};

before(async () => {
  ({ server, page } = await startWorkbench({
    prepare: (started) => {
      for (const [name, lines] of Object.entries(FILES)) {
        fs.writeFileSync(path.join(started.workspace, name), lines.join('\n'));
      }
    },
  }));
}, { timeout: 180000 });

after(async () => {
  await server?.stop();
});

test('a .txt program opened first is CNC Macro, checked and hovered; a .txt of notes stays Plain Text', { timeout: 2 * STEP }, async () => {
  await openFile(page, 'O0810.txt');
  await page.locator('.statusbar-item', { hasText: exact('CNC Macro') }).waitFor();
  await page.locator('.statusbar-item', { hasText: 'FANUC 0i' }).waitFor({ timeout: STEP });
  await page.locator('.editor-instance .squiggly-error').first().waitFor({ timeout: STEP });
  await page.keyboard.press('Control+Shift+M');
  await page.locator('.markers-panel .monaco-list-row', { hasText: 'there is no N99' }).first().waitFor();
  await hoverOver(page, /^#5001$/, 'block end position');
  await screenshot(page, 'txt-1-program');
  await page.mouse.move(5, 500);
  await page.keyboard.press('Escape');
  await openFile(page, 'SHIFT_NOTES.txt');
  await page.locator('.statusbar-item', { hasText: exact('Plain Text') }).waitFor();
  await screenshot(page, 'txt-2-notes');
});
