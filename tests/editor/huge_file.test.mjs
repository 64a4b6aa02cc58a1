// Opening a 1,000,000-line CAM program in a real VS Code: the language server shows the findings
// of the first screen at once, reads the file in steps and then analyses it, with its progress in
// the status bar (a click there shows the analysis in the notification centre, with Cancel),
// answers a hover far down the file meanwhile (the places a variable is written are still being
// found then), publishes every finding at the end, and lists the places once the file is indexed. The
// program is made at test time by the benchmarks' generator (benchmarks/camgen.py), with a syntax
// error on line 6 and, on line 900,000, a jump to a label that is not there. Screenshots go to
// test-output/editor/; the analysis's progress in the notification centre is also
// docs/images/huge-file-opening.png, and the hover docs/images/huge-file-hover.png, when
// CNCMACRO_README_PICTURES is set (npm run screenshots).
// Run after npm run package: node --test --test-concurrency=1 tests/editor/huge_file.test.mjs
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { ROOT, screenshot, startWorkbench } from './codeServer.mjs';
import { exact } from './workbench.mjs';

const LINES = 1_000_000;
const FAR_JUMP = 900_000; // the line of the jump to the missing label
const STEP = 60000;
const PYTHON = path.join(ROOT, '.venv', 'bin', 'python');
let server;
let page;
const progressSeen = new Set(); // every text the server's progress showed in the status bar

/**
 * The generated program with the planted lines. camgen writes `%`, the O header and three set-up
 * lines, then one generated line each, an N label every 10th (N1 to N99999 for a million lines):
 * line 6 is a plain motion line, line 900,000 is not a label line, and the label N99991 is
 * taken off its line, so that the jump to it finds none.
 */
const GENERATE = `
import sys
sys.path.insert(0, "benchmarks")
from camgen import cam_program
lines = cam_program(${LINES}).split("\\n")
lines[5] = "#1=[2+3"
lines[${FAR_JUMP - 1}] = "GOTO 99991"
label = next(i for i, line in enumerate(lines) if line.startswith("N99991 "))
lines[label] = lines[label][len("N99991 "):]
open(sys.argv[1], "w").write("\\n".join(lines))
`;

const shot = (name, docs) => screenshot(page, name, { docs });

/** The status-bar text of the server's progress ("cncmacro: reading ..." / "analysing ..."), or ''. */
async function progressText() {
  const texts = await page.locator('.statusbar-item').evaluateAll((els) =>
    els.map((el) => `${el.textContent} ${el.getAttribute('aria-label') ?? ''}`.trim()),
  );
  const found = texts.find((t) => /cncmacro|reading|analysing/.test(t)) ?? '';
  if (found) progressSeen.add(found);
  return found;
}

/**
 * Hover over `word` where it stands on the drawn line `line` until a hover with `hasText` shows.
 * VS Code does not colour a file this large (no tokenization), so each line is one span: the
 * mouse goes to the middle of the word's characters, measured with a DOM range.
 */
async function hoverAt(line, word, hasText, attempts = 3, wait = 20000) {
  const hover = page.locator('.monaco-hover', { hasText });
  for (let attempt = 1; ; attempt++) {
    const box = await page.evaluate(
      ([line, word]) => {
        for (const row of document.querySelectorAll('.editor-instance .view-lines .view-line')) {
          const drawn = row.textContent.replace(/\u00a0/g, ' ');
          const at = drawn.indexOf(line);
          if (at < 0) continue;
          const walker = document.createTreeWalker(row, NodeFilter.SHOW_TEXT);
          let offset = 0;
          for (let node = walker.nextNode(); node; node = walker.nextNode()) {
            const from = at + line.indexOf(word) - offset;
            if (from >= 0 && from < node.length) {
              const range = document.createRange();
              range.setStart(node, from);
              range.setEnd(node, Math.min(node.length, from + word.length));
              const r = range.getBoundingClientRect();
              return { x: r.x, y: r.y, width: r.width, height: r.height };
            }
            offset += node.length;
          }
        }
        return undefined;
      },
      [line, word],
    );
    assert.ok(box, `${word} of ${line} is on screen`);
    await page.mouse.move(box.x + 1, box.y + box.height / 2);
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2, { steps: 4 });
    try {
      await hover.waitFor({ state: 'visible', timeout: wait });
      return hover;
    } catch (e) {
      // what the hover showed instead (nothing, or the places still being found): said in the
      // test's output, so that a failure on a slow machine says which it was
      const shown = await page.locator('.monaco-hover').allInnerTexts();
      console.log(`hover attempt ${attempt} at ${new Date().toISOString()}: ${JSON.stringify(shown)}`);
      if (attempt === attempts) throw e;
      await page.mouse.move(5, 500);
      await page.keyboard.press('Escape');
      await page.waitForTimeout(500);
    }
  }
}

async function until(what, check, timeout = 30000) {
  for (const end = Date.now() + timeout; !(await check()); await page.waitForTimeout(100)) {
    assert.ok(Date.now() < end, what);
  }
}

before(async () => {
  ({ server, page } = await startWorkbench({
    prepare: (started) => {
      const made = spawnSync(PYTHON, ['-c', GENERATE, path.join(started.workspace, 'huge.nc')], {
        cwd: ROOT,
        encoding: 'utf8',
        timeout: 120000,
      });
      assert.equal(made.status, 0, `generating the program failed: ${made.stderr}`);
    },
  }));
}, { timeout: 240000 });

after(async () => {
  await server?.stop();
});

test('the first screen\'s syntax error shows alone, before the whole file is analysed', { timeout: 3 * STEP }, async () => {
  const started = Date.now();
  await page
    .locator('.explorer-folders-view .monaco-list-row')
    .filter({ has: page.locator('.label-name', { hasText: exact('huge.nc') }) })
    .click();
  // a remote workbench (code-server, Remote-SSH, WSL) asks before it opens a file over 10 MB
  // (workbench.editorLargeFileConfirmation); desktop VS Code asks over 1024 MB
  const openAnyway = page.locator('.monaco-button', { hasText: 'Open Anyway' });
  await openAnyway.waitFor();
  assert.match(await page.locator('.editor-container').first().innerText(), /very large \(24\.\d+MB\)/);
  await openAnyway.click();
  await page.locator('.editor-instance .view-lines .view-line').first().waitFor({ timeout: STEP });
  console.log(`the text shows after ${Date.now() - started} ms`);
  let progressAtSquiggle = '';
  await until(
    'the syntax error on line 6 is underlined',
    async () => {
      const now = await progressText();
      if (!(await page.locator('.editor-instance .squiggly-error').first().isVisible())) return false;
      progressAtSquiggle = now;
      return true;
    },
    2 * STEP,
  );
  console.log(`squiggle after ${Date.now() - started} ms, progress then: ${JSON.stringify(progressAtSquiggle)}`);
  await page.keyboard.press('Control+Shift+M');
  const problems = page.locator('.markers-panel .monaco-list-row');
  await problems.filter({ hasText: "expected ']'" }).waitFor();
  // the analysis of the whole file publishes the syntax error and the far jump together: the
  // syntax error alone is the first screen's
  const shown = await problems.allInnerTexts();
  assert.ok(!shown.some((row) => /N99991/.test(row)), `only the first screen's finding so far: ${shown}`);
  await page.locator('.editor-instance .view-lines').click({ position: { x: 300, y: 40 } });
  await progressText();
  await shot('huge-1-first-screen');
  console.log(`status bar after the first screen: ${JSON.stringify(await progressText())}`);
  console.log(`notifications: ${JSON.stringify(await page.locator('.notification-toast').allInnerTexts())}`);
});

test('a hover far down the file, on line 500,026, names the variable and where it is written', { timeout: 2 * STEP }, async () => {
  await page.keyboard.press('Control+G');
  await page.keyboard.type('500026');
  await page.keyboard.press('Enter');
  await page.locator('.editor-instance .view-lines .view-line', { hasText: '#125=#108+36.42' }).waitFor();
  const hover = await hoverAt('#125=#108+36.42', '#125', 'Common variable');
  const progress = await progressText();
  console.log(`hover: ${JSON.stringify(await hover.innerText())}; progress then: ${JSON.stringify(progress)}`);
  assert.match(await hover.innerText(), /written at:/);
  const far = page.locator('.markers-panel .monaco-list-row', { hasText: 'there is no N99991' });
  console.log(`the analysis ${(await far.isVisible()) ? 'had ended' : 'was still running'} when the hover showed`);
  await shot('huge-2-hover-while-analysing', 'huge-file-hover');
  // the status bar's progress is VS Code's silent notification of it: a click shows it in the
  // notification centre, with its bar and, for the analysis, a Cancel button
  await page.mouse.move(5, 500);
  await page.keyboard.press('Escape');
  // the reading ends in a few seconds; then the analysis reports what it does
  for (const end = Date.now() + 60000; Date.now() < end; await page.waitForTimeout(100)) {
    const now = await progressText();
    if (/checking|running|analysing/.test(now) || (await far.isVisible())) break;
  }
  const item = page.locator('.statusbar-item', { hasText: /cncmacro: (checking|running|analysing)/ }).first();
  if (await item.isVisible()) {
    await item.click().catch(() => undefined);
    await page.waitForTimeout(500);
    const centre = page.locator('.notifications-center');
    console.log(`notification centre: ${JSON.stringify(await centre.innerText().catch(() => ''))}`);
    console.log(`its buttons: ${JSON.stringify(await centre.locator('.monaco-button').allInnerTexts().catch(() => []))}`);
    await shot('huge-2b-progress-notification', 'huge-file-opening');
    await page.keyboard.press('Escape');
  } else {
    console.log('the progress had left the status bar before the hover showed');
  }
});

test('the jump to the missing label on line 900,000 is found at the end of the analysis', { timeout: 5 * STEP }, async () => {
  await page.mouse.move(5, 500);
  await page.keyboard.press('Escape');
  const far = page.locator('.markers-panel .monaco-list-row', { hasText: 'there is no N99991' });
  await until('the undefined label is reported', async () => (await progressText(), far.isVisible()), 4 * STEP);
  assert.ok([...progressSeen].some((text) => /cncmacro/.test(text)), 'the status bar showed the server\'s progress');
  assert.match(await far.innerText(), /900000|900,000/);
  await page.keyboard.press('Control+G');
  await page.keyboard.type(String(FAR_JUMP));
  await page.keyboard.press('Enter');
  await page.locator('.editor-instance .view-lines .view-line', { hasText: 'GOTO 99991' }).waitFor();
  await page.locator('.editor-instance .squiggly-error').first().waitFor();
  await shot('huge-3-all-diagnostics');
  console.log(`progress texts seen: ${JSON.stringify([...progressSeen])}`);
  console.log(`problems: ${JSON.stringify(await page.locator('.markers-panel .monaco-list-row').allInnerTexts())}`);
});

test('once the file is indexed, the hover on #125 lists where it is written', { timeout: 3 * STEP }, async () => {
  await page.mouse.move(5, 500);
  await page.keyboard.press('Escape');
  await page.keyboard.press('Control+G');
  await page.keyboard.type('500026');
  await page.keyboard.press('Enter');
  await page.locator('.editor-instance .view-lines .view-line', { hasText: '#125=#108+36.42' }).waitFor();
  // the index of where each variable is written takes seconds after the analysis (more on a busy
  // machine), and a hover shown while it fills says they are still being found: hover again
  // every few seconds until it lists the places (within the test's time)
  const hover = await hoverAt('#125=#108+36.42', '#125', /huge\.nc:\d+/, 30, 4000);
  const text = await hover.innerText();
  console.log(`hover once indexed: ${JSON.stringify(text)}`);
  assert.match(text, /written at:/);
  assert.doesNotMatch(text, /still being found/);
  await shot('huge-4-hover-once-indexed');
});

test('the editor tried no host but this machine: no gallery, telemetry or update check', { timeout: STEP }, async () => {
  assert.deepEqual(server.outsideHostAttempts(), []);
});
