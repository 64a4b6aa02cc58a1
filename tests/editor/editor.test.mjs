// The extension in a real VS Code: the built .vsix installed into a fresh code-server, driven
// through Chromium as a user would (colours, Problems, hover, breakpoint and step into a G65
// macro, Run Program), then the extension-host tests of api/index.js. Screenshots go to
// test-output/editor/. Run: node --test tests/editor/ (after npm run package). With
// CNCMACRO_README_PICTURES set (npm run screenshots), the four that the README shows are copied to
// docs/images/ as well.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test as nodeTest } from 'node:test';
import { OUTPUT, ROOT, screenshot, startWorkbench } from './codeServer.mjs';
import { exact, hoverOver, openFile as openIn, tokenColour as colourIn } from './workbench.mjs';
import { characterColours, editorForeground, oneColour } from './workbench.mjs';

const STEP = 60000; // ms for one test (most take 1-5 s)
const WAIT = 20000; // ms for one thing to appear
let server;
let page;

/** The screenshots the README shows, by the name they have in docs/images/. */
const README_PICTURES = {
  '2-hover-5001': 'hover-5001',
  '3-problems': 'problems',
  '5-stepped-into-O9100': 'debug-g65',
  '9-toolpath': 'toolpath',
};

/** A screenshot; `settled` when the test has already waited for what the picture must show. */
async function shot(name, { settled = false } = {}) {
  await screenshot(page, name, { docs: README_PICTURES[name], settle: settled ? 0 : 300 });
}

const openFile = (name) => openIn(page, name);
const tokenColour = (text) => colourIn(page, text);

/** The picture a failing test leaves, named after the test. */
const failedPicture = (name) => `failed-${name.replace(/[^A-Za-z0-9]+/g, '-').slice(0, 50)}.png`;
const failedPictures = new Set();

/** A test that, when it fails, leaves a picture of the workbench as it was. */
function test(name, options, fn) {
  failedPictures.add(failedPicture(name));
  nodeTest(name, options, async (t) => {
    try {
      await fn(t);
    } catch (e) {
      await page?.screenshot({ path: path.join(OUTPUT, failedPicture(name)) }).catch(() => undefined);
      throw e;
    }
  });
}

/**
 * This file's pictures of an earlier run: its screenshots, whose names start with their number
 * (1-colours-light.png), and its tests' failure pictures. The other editor test files name
 * theirs otherwise (cycle-, debug-, zh-, huge-, seq-, probing-) and keep them: in a run of the
 * whole folder they run first.
 */
function removeOwnPictures() {
  if (!fs.existsSync(OUTPUT)) return;
  for (const file of fs.readdirSync(OUTPUT)) {
    if (/^[0-9]+[a-z]?-.*\.png$/.test(file) || failedPictures.has(file)) fs.rmSync(path.join(OUTPUT, file), { force: true });
  }
}

before(async () => {
  removeOwnPictures();
  ({ server, page } = await startWorkbench({ timeout: WAIT }));
}, { timeout: 180000 });

after(async () => {
  await server?.stop();
});

test('a macro program is CNC Macro, coloured by kind, with the dialect in the status bar', { timeout: 2 * STEP }, async () => {
  await openFile('colours.nc');
  await page.locator('.statusbar-item', { hasText: exact('CNC Macro') }).waitFor();
  await page.locator('.statusbar-item', { hasText: 'FANUC 0i' }).waitFor();
  const colour = (line, text) => oneColour(page, line, text);
  const loop = 'WHILE[#30 LT 3] DO1';
  const shortLoop = 'WH[#30 LT 6] DO2';
  const motion = 'G90 G81 X#32 Y#33 Z-5. R2. F100';
  const alarm = 'IF[#30 EQ 7] THEN #3000=1(TOOL BROKEN)';
  /** The colours of each kind of word once the language server's colours are on the screen. */
  const coloured = async (theme, unlike) => {
    // Only the language server knows that WH is WHILE shortened: once WH has WHILE's colour
    // (in this theme), the server's colours are drawn, and each colour below is the one a user keeps.
    let keyword;
    const served = async () => {
      keyword = await colour(loop, 'WHILE');
      return keyword !== unlike && (await characterColours(page, shortLoop, 'WH'))?.every((c) => c === keyword);
    };
    for (const end = Date.now() + 40000; !(await served()); await page.waitForTimeout(250)) {
      assert.ok(Date.now() < end, `${theme}: WH has not WHILE's colour ${keyword}: ${await characterColours(page, shortLoop, 'WH')}`);
    }
    const colours = {
      keyword,
      variable: await colour('#30=#30+1', '#30'),
      number: await colour(motion, '100'),
      comment: await tokenColour('(COUNT)'),
    };
    await shot(`1-colours-${theme}`);
    assert.equal(new Set(Object.values(colours)).size, 4, `${theme}: four different colours: ${JSON.stringify(colours)}`);
    for (const [line, word] of [[alarm, 'IF'], [alarm, 'THEN'], ['IF[#30 NE 6] GOTO 10', 'GOTO'], ['END1', 'END']]) {
      assert.equal(await colour(line, word), keyword, `${theme}: ${word} of ${line} has the keyword colour`);
    }
    assert.notEqual(keyword, await editorForeground(page), `${theme}: keywords have a colour of their own`);
    await colour(motion, 'G90'); // one colour over the whole code
    assert.notEqual(await colour(motion, 'X'), await colour(motion, '#32'), `${theme}: the address X stands apart from #32`);
    assert.notEqual(await colour(alarm, '(TOOL BROKEN)'), colours.comment, `${theme}: an alarm text is not a comment`);
    return keyword;
  };
  const light = await coloured('light', undefined);
  // Dark Modern, set for the workspace and taken away again.
  const folder = path.join(server.workspace, '.vscode');
  const file = path.join(folder, 'settings.json');
  const made = !fs.existsSync(folder);
  const kept = fs.existsSync(file) ? fs.readFileSync(file, 'utf8') : undefined;
  fs.mkdirSync(folder, { recursive: true });
  fs.writeFileSync(file, JSON.stringify({ ...JSON.parse(kept ?? '{}'), 'workbench.colorTheme': 'Default Dark Modern' }));
  try {
    await coloured('dark', light);
  } finally {
    if (kept !== undefined) fs.writeFileSync(file, kept);
    else fs.rmSync(made ? folder : file, { recursive: true });
  }
  for (const end = Date.now() + WAIT; (await colour(loop, 'WHILE')) !== light; await page.waitForTimeout(250)) {
    assert.ok(Date.now() < end, 'the light theme is back');
  }
  await openFile('O9100.nc'); // the next test hovers its #5001
  await page.locator('.statusbar-item', { hasText: 'FANUC 0i' }).waitFor();
});

test('hovering #5001 shows its documentation', { timeout: STEP }, async () => {
  const hover = await hoverOver(page, /^#5001$/, 'block end position');
  assert.match(await hover.innerText(), /#5001/);
  await shot('2-hover-5001');
  await page.mouse.move(5, 500);
});

test('the Problems panel lists the planted undefined-label error', { timeout: STEP }, async () => {
  await openFile('planted_goto.nc');
  await page.locator('.editor-instance .squiggly-error').first().waitFor();
  await page.keyboard.press('Control+Shift+M');
  const row = page.locator('.markers-panel .monaco-list-row', { hasText: 'there is no N99' }).first();
  await row.waitFor();
  assert.match(await row.innerText(), /undefined-label/);
  assert.equal(await page.locator('.markers-panel .monaco-list-row', { hasText: 'there is no N99' }).count(), 1);
  await shot('3-problems');
});

/** The process ids of the language servers code-server's extension host started. */
function languageServers() {
  const found = spawnSync('pgrep', ['-g', String(server.child.pid), '-f', 'cncmacro lsp'], { encoding: 'utf8' });
  return found.stdout.split('\n').filter(Boolean).map(Number);
}

test('a language server killed mid-session is started again and the diagnostics come back', { timeout: STEP }, async () => {
  const before = languageServers();
  assert.ok(before.length > 0, 'no language server is running');
  for (const pid of before) process.kill(pid, 'SIGKILL');
  await openFile('planted_goto.nc');
  await page.keyboard.press('Control+G');
  await page.keyboard.type('7');
  await page.keyboard.press('Enter');
  await page.keyboard.press('End');
  await page.keyboard.press('Backspace');
  await page.keyboard.type('8'); // GOTO 99 becomes GOTO 98: only a new server can report that
  await page.keyboard.press('Control+Shift+M');
  const row = page.locator('.markers-panel .monaco-list-row', { hasText: 'there is no N98' }).first();
  await row.waitFor({ timeout: 45000 });
  const now = languageServers();
  assert.ok(now.length > 0 && now.every((pid) => !before.includes(pid)), `servers before ${before}, now ${now}`);
  await shot('3b-server-restarted');
  await page.keyboard.press('Control+Z');
  await page.keyboard.press('Control+Z');
});

test('F9 then F5 stops at a breakpoint, F11 steps into the G65 macro, Variables shows #24 (X)', { timeout: 2 * STEP }, async () => {
  await openFile('bolt_circle.nc');
  await page.locator('.editor-instance .view-lines').click();
  await page.keyboard.press('Control+G');
  await page.keyboard.type('12');
  await page.keyboard.press('Enter');
  await page.keyboard.press('F9');
  await page.locator('.codicon-debug-breakpoint').first().waitFor();
  await page.keyboard.press('F5');
  await page.locator('.debug-toolbar').waitFor({ state: 'visible' });
  await page.locator('.debug-top-stack-frame-line').first().waitFor();
  const frames = page.locator('.debug-call-stack .monaco-list-row');
  await frames.filter({ hasText: 'bolt_circle.nc' }).filter({ hasText: '12' }).first().waitFor();
  await shot('4-breakpoint');

  await page.keyboard.press('F11');
  await page.locator('.tabs-container .tab.active', { hasText: 'O9100.nc' }).waitFor();
  await frames.filter({ hasText: 'O9100' }).first().waitFor();
  // Locals lists #1-#33. The main program's are vacant: the G65 line's arguments (A15. -> #1,
  // X0 -> #24, Z-12. -> #26) show that the pane shows the macro's, not the rows it showed before.
  const variables = page.locator('.pane', { has: page.locator('.pane-header', { hasText: /variables/i }) });
  const row = (name, value) =>
    variables.locator('.monaco-list-row', { hasText: new RegExp(`^${name.replace(/[()]/g, '\\$&')}\\s*[:=]?\\s*${value}(?![\\d.])`) });
  await row('#1 (A)', '15').first().waitFor();
  const last = row('#26 (Z)', '-12').first(); // scrolled to: #24 (X) shows just above it
  for (let i = 0; i < 30 && !(await last.isVisible()); i++) {
    await variables.locator('.monaco-list').first().hover();
    await page.mouse.wheel(0, 60);
    await page.waitForTimeout(100);
  }
  await page.mouse.wheel(0, 60); // #26 whole, not cut by the pane's edge
  await page.mouse.move(5, 500); // no hover over a variable in the picture
  for (const [name, value] of [['#24 (X)', '0'], ['#25 (Y)', '0'], ['#26 (Z)', '-12']]) {
    await row(name, value).first().waitFor();
  }
  await shot('5-stepped-into-O9100', { settled: true });

  await page.keyboard.press('Shift+F5');
  await page.locator('.debug-toolbar').waitFor({ state: 'hidden' });
});

test('Run Program shows the run in the "CNC Macro" output channel', { timeout: STEP }, async () => {
  await openFile('bolt_circle.nc');
  await page.keyboard.press('F1');
  await page.keyboard.type('CNC Macro: Run Program');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Run Program' }).first().waitFor();
  await page.keyboard.press('Enter');
  await page.locator('.panel .view-lines', { hasText: 'status: completed after 205 blocks' }).waitFor();
  await shot('6-run-program');
});

test('the "CNC Macro Server" output channel names the running server\'s version and the extension\'s', { timeout: STEP }, async () => {
  const serverVersion = /__version__ = "([^"]+)"/.exec(fs.readFileSync(path.join(ROOT, 'server', 'cncmacro', '__init__.py'), 'utf8'))[1];
  await page.keyboard.press('F1');
  await page.keyboard.type('Output: Show Output Channels');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Show Output Channels' }).first().waitFor();
  await page.keyboard.press('Enter');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: exact('CNC Macro Server') }).first().click();
  const line = page.locator('.panel .view-lines .view-line', { hasText: 'the language server' }).filter({ hasText: 'is running' }).last();
  await line.waitFor();
  const text = (await line.innerText()).replace(/\u00a0/g, ' ');
  assert.match(text, new RegExp(`the language server cncmacro ${serverVersion} is running \\(CNC Macro extension ${server.version}\\)`), text);
  await shot('6b-server-version');
  await page.keyboard.press('Control+1'); // back to the program: the status bar shows its dialect again
  await page.locator('.statusbar-item', { hasText: 'FANUC 0i' }).waitFor();
});

test('clicking the dialect in the status bar offers the server\'s profiles and writes cncMacro.dialect', { timeout: STEP }, async () => {
  const settingsFile = path.join(server.workspace, '.vscode', 'settings.json');
  const pick = async (from, to) => {
    await page.locator('.statusbar-item', { hasText: from }).click();
    await page.locator('.quick-input-list .monaco-list-row', { hasText: to }).first().click();
    await page.locator('.statusbar-item', { hasText: to }).waitFor();
  };
  await pick('FANUC 0i', 'GSK980TDi');
  await shot('7-dialect-gsk980tdi');
  assert.equal(JSON.parse(fs.readFileSync(settingsFile, 'utf8'))['cncMacro.dialect'], 'gsk980tdi');
  await pick('GSK980TDi', 'FANUC 30i');
  await shot('7a-dialect-fanuc-30i');
  assert.equal(JSON.parse(fs.readFileSync(settingsFile, 'utf8'))['cncMacro.dialect'], 'fanuc-30i');
  await pick('FANUC 30i', 'FANUC 0i');
  assert.equal(JSON.parse(fs.readFileSync(settingsFile, 'utf8'))['cncMacro.dialect'], 'fanuc-0i');
});

test("the status bar shows the dialect a file is read in: its own comment wins over the setting", { timeout: STEP }, async () => {
  await openFile('lathe_part.nc'); // (cncmacro: dialect=gsk980tdi), the setting is fanuc-0i
  const item = page.locator('.statusbar-item', { hasText: 'GSK980TDi' });
  await item.waitFor();
  await shot('7b-dialect-from-the-file');
  await openFile('O9100.nc');
  await page.locator('.statusbar-item', { hasText: 'FANUC 0i' }).waitFor();
  assert.equal(await item.count(), 0);
});

// A Mitsubishi M70/M80 program: the block IF of its profile (docs/semantics.md §4 "Block IF")
const MITSUBISHI = [
  '(cncmacro: dialect=mitsubishi-m70)',
  'O1000 (PART FAMILY)',
  '#1=2',
  'IF [#1 EQ 1] THEN',
  '#2=10.',
  'G01 X#2 F100',
  'ELSE',
  '#2=20.',
  'G01 X#2 F100',
  'ENDIF',
  'M30',
  '',
].join('\n');

test('a Mitsubishi program: the status bar names its profile, its block IF is no error, and the THEN branch folds', { timeout: STEP }, async () => {
  fs.writeFileSync(path.join(server.workspace, 'mitsubishi_if.nc'), MITSUBISHI);
  await openFile('mitsubishi_if.nc');
  await page.locator('.statusbar-item', { hasText: 'Mitsubishi M70/M80' }).waitFor();
  await page.locator('.editor-instance .view-line', { hasText: '#2=20.' }).waitFor();
  // the run has ended (its cycle time is shown above the program): its findings are in
  await page.locator('.editor-instance .codelens-decoration', { hasText: '≈' }).first().waitFor({ timeout: WAIT });
  await page.locator('.editor-instance .view-lines').click();
  await page.keyboard.press('Control+G');
  await page.keyboard.type('4'); // IF [#1 EQ 1] THEN: its branch runs to the ELSE
  await page.keyboard.press('Enter');
  await page.keyboard.press('Control+Shift+BracketLeft'); // Fold
  await page.locator('.editor-instance .view-line', { hasText: '#2=10.' }).waitFor({ state: 'detached' });
  assert.equal(await page.locator('.editor-instance .view-line', { hasText: '#2=20.' }).count(), 1); // ELSE's branch shown
  assert.equal(await page.locator('.editor-instance .squiggly-error').count(), 0); // read as Mitsubishi: no error
  await shot('7c-mitsubishi-block-if-folded');
  await page.keyboard.press('Control+Shift+BracketRight'); // Unfold
});

/** The moves `cncmacro run --json` makes for an example program: what the toolpath view must draw. */
function movesOf(folder, name) {
  const cncmacro = path.join(ROOT, '.venv', 'bin', 'cncmacro');
  const run = spawnSync(cncmacro, ['run', '--json', '--no-save', name], { cwd: folder, encoding: 'utf8' });
  assert.ok(run.stdout, `cncmacro run printed nothing: ${run.stderr}`);
  return JSON.parse(run.stdout).moves;
}

test('Show Toolpath draws each move of the run, and a click on a move goes to its line', { timeout: 2 * STEP }, async () => {
  const moves = movesOf(path.join(ROOT, 'examples', 'fanuc'), 'bolt_circle.nc');
  assert.ok(moves.length > 20, `bolt_circle.nc makes ${moves.length} moves`);
  await openFile('bolt_circle.nc');
  if (await page.locator('.part.panel').isVisible()) await page.keyboard.press('Control+J'); // room for the drawing
  await page.keyboard.press('F1');
  await page.keyboard.type('CNC Macro: Show Toolpath');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Show Toolpath' }).first().waitFor();
  await page.keyboard.press('Enter');
  // The webview's page sits in an iframe (the active frame) inside the workbench's webview iframe.
  const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
  const drawn = view.locator('#plot g.move');
  await drawn.first().waitFor({ state: 'attached', timeout: 45000 }); // the first moves have no length in XY
  assert.equal(await drawn.count(), moves.length, 'one <g class="move"> per move of the run');
  const status = await view.locator('#status').innerText();
  assert.match(status, new RegExp(`Completed.*\\b${moves.length} moves`), status);
  assert.match(status, /extents X -60 … 60, Y -60 … 60, Z -15 … 100/, status);
  assert.equal(await view.locator('#plot g.move.cycle .hole').count(), moves.filter((m) => m.mode === 'G81').length);
  assert.match(await view.locator('#legend').innerText(), /rapid \(G00\)[\s\S]*canned cycle/);
  await page.locator('.tab', { hasText: 'Toolpath: bolt_circle.nc' }).waitFor();
  await shot('9-toolpath');

  // The first drilled hole is made by the G81 block of the macro O9100: its move goes there.
  const index = moves.findIndex((m) => m.mode === 'G81');
  const target = moves[index];
  assert.equal(path.basename(target.file), 'O9100.nc');
  const move = view.locator(`#plot g.move[data-index="${index}"]`);
  assert.match(await move.locator('title').textContent(), new RegExp(`^O9100\\.nc:${target.line}  G81 `));
  // Click a point on the move's positioning line (the middle of its box could miss a thin line).
  const at = await move.locator('path.hit').evaluate((el) => {
    const p = el.getPointAtLength(el.getTotalLength() / 4);
    const screen = new DOMPoint(p.x, p.y).matrixTransform(el.getScreenCTM());
    const box = el.ownerSVGElement.getBoundingClientRect();
    return { x: screen.x - box.left, y: screen.y - box.top };
  });
  await view.locator('#plot').click({ position: at });
  await page.locator('.tabs-container .tab.active', { hasText: 'O9100.nc' }).waitFor();
  await page.locator('.statusbar-item', { hasText: `Ln ${target.line}, Col 1` }).waitFor();
  await shot('9b-toolpath-click');
});

test('Show Toolpath draws a GSK lathe program with Z across and X up, to scale, the X scale in diameters', { timeout: 2 * STEP }, async () => {
  const folder = path.join(ROOT, 'examples', 'gsk980tdi');
  const moves = movesOf(folder, 'ellipse_turning.nc');
  fs.copyFileSync(path.join(folder, 'ellipse_turning.nc'), path.join(server.workspace, 'ellipse_turning.nc'));
  await page.locator('.explorer-folders-view .label-name', { hasText: exact('ellipse_turning.nc') }).waitFor();
  await openFile('ellipse_turning.nc');
  await page.keyboard.press('F1');
  await page.keyboard.type('CNC Macro: Show Toolpath');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Show Toolpath' }).first().waitFor();
  await page.keyboard.press('Enter');
  await page.locator('.tab', { hasText: 'Toolpath: ellipse_turning.nc' }).waitFor();
  const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
  const status = view.locator('#status', { hasText: `${moves.length} moves` });
  await status.waitFor({ timeout: 45000 });
  assert.equal(await view.locator('#plot g.move').count(), moves.length);
  assert.equal(await view.locator('#plot g.move.feed').count(), moves.filter((m) => m.mode === 'G01').length);
  assert.match(await view.locator('#legend').innerText(), /Lathe: Z across \(the spindle axis\), X up, to scale; the X scale reads diameters/);
  assert.match(await status.innerText(), /extents X 0 … 100, Z -45 … 100/);
  await shot('9c-toolpath-lathe');

  // An edit draws it again, unsaved: twice the depth of cut per roughing layer, fewer passes.
  await page.locator('.editor-instance .view-lines').click();
  await page.keyboard.press('Control+G');
  await page.keyboard.type('9:6'); // line 9, before the 3 of #104=3
  await page.keyboard.press('Enter');
  await page.locator('.statusbar-item', { hasText: 'Ln 9, Col 6' }).waitFor();
  await page.keyboard.press('Shift+ArrowRight');
  await page.keyboard.type('6'); // #104=3 becomes #104=6, not saved
  const edited = fs.mkdtempSync(path.join(server.dir, 'edited-'));
  const text = fs.readFileSync(path.join(folder, 'ellipse_turning.nc'), 'utf8').replace('#104=3', '#104=6');
  fs.writeFileSync(path.join(edited, 'ellipse_turning.nc'), text);
  const fewer = movesOf(edited, 'ellipse_turning.nc');
  assert.ok(fewer.length < moves.length, `${fewer.length} moves after the edit, ${moves.length} before`);
  await view.locator('#status', { hasText: `${fewer.length} moves` }).waitFor({ timeout: 45000 });
  assert.equal(await view.locator('#plot g.move').count(), fewer.length);
  assert.match(await view.locator('body').innerText(), /unsaved changes included/);
  assert.ok(!fs.readFileSync(path.join(server.workspace, 'ellipse_turning.nc'), 'utf8').includes('#104=6'));
  await page.keyboard.press('Control+S');
});

test('Show Toolpath of a program that alarms draws the moves before the alarm and names it', { timeout: 2 * STEP }, async () => {
  const program = ['O0010 (ALARM AFTER TWO CUTS)', 'G90 G00 X0 Y0', 'G01 X20. F100.', 'G01 Y20.'];
  program.push('#3000=1(TOOL BROKEN)', 'G01 X0', 'M30', '');
  fs.writeFileSync(path.join(server.workspace, 'alarm_after_cuts.nc'), program.join('\n'));
  const moves = movesOf(server.workspace, 'alarm_after_cuts.nc');
  await page.locator('.explorer-folders-view .label-name', { hasText: exact('alarm_after_cuts.nc') }).waitFor();
  await openFile('alarm_after_cuts.nc');
  await page.keyboard.press('F1');
  await page.keyboard.type('CNC Macro: Show Toolpath');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Show Toolpath' }).first().waitFor();
  await page.keyboard.press('Enter');
  await page.locator('.tab', { hasText: 'Toolpath: alarm_after_cuts.nc' }).waitFor();
  const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
  const status = view.locator('#status', { hasText: 'Alarm 3001: TOOL BROKEN (alarm_after_cuts.nc:5)' });
  await status.waitFor({ timeout: 45000 });
  assert.match(await status.innerText(), new RegExp(`\\b${moves.length} moves`));
  assert.equal(await view.locator('#plot g.move').count(), moves.length);
  assert.equal(await view.locator('#plot g.move.feed').count(), 2, 'the two cuts before the alarm');
  await view.locator('#plot g.end').waitFor(); // where the tool stopped
  await shot('9d-toolpath-alarm');

  // Typed over so that it alarms before any move: an empty picture with readable coordinates.
  await page.locator('.editor-instance .view-lines').click();
  await page.keyboard.press('Control+A');
  await page.keyboard.type('O0011\n#3000=2(NO STOCK)\nM30\n');
  await view.locator('#status', { hasText: 'Alarm 3002: NO STOCK' }).waitFor({ timeout: 45000 });
  assert.equal(await view.locator('#plot g.move').count(), 0);
  const labels = await view.locator('#plot g.labels text').allTextContents();
  assert.ok(new Set(labels).size > 4, `distinct grid labels: ${labels.join(' ')}`);
  await page.keyboard.press('Control+S');
});

test('a Haas program: the status bar names its profile, #3026 has its Haas hover, the toolpath draws the M97 subroutine', { timeout: 2 * STEP }, async () => {
  // haas_pocket.nc: (cncmacro: dialect=haas), G154 P1, T5 M06, #10500=#3026, then M97 P100 L2
  // runs N100 (lines 17-24: 4 mm down, a ring round 20 x 20) twice.
  const moves = movesOf(server.workspace, 'haas_pocket.nc');
  const inSubroutine = (line) => line >= 17 && line <= 24;
  assert.equal(moves.filter((m) => inSubroutine(m.line)).length, 16, 'two passes of 8 moves from N100');
  await openFile('haas_pocket.nc');
  const item = page.locator('.statusbar-item', { hasText: 'Haas NGC mill' });
  await item.waitFor();
  const hover = await hoverOver(page, /^#3026$/, 'Tool in the spindle');
  assert.match(await hover.innerText(), /Tool in the spindle: the number of the tool now loaded[\s\S]*Haas NGC mill/);
  await shot('10-haas-hover-3026');
  await page.mouse.move(5, 500);
  await page.keyboard.press('Escape');

  if (await page.locator('.part.panel').isVisible()) await page.keyboard.press('Control+J'); // room for the drawing
  await page.keyboard.press('F1');
  await page.keyboard.type('CNC Macro: Show Toolpath');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: 'Show Toolpath' }).first().waitFor();
  await page.keyboard.press('Enter');
  await page.locator('.tab', { hasText: 'Toolpath: haas_pocket.nc' }).waitFor();
  const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
  const status = view.locator('#status', { hasText: `${moves.length} moves` });
  await status.waitFor({ timeout: 45000 });
  assert.match(await status.innerText(), /Completed/);
  assert.equal(await view.locator('#plot g.move').count(), moves.length, 'one <g class="move"> per move of the run');
  const titles = await view.locator('#plot g.move title').allTextContents();
  const drawnInSubroutine = titles.filter((t) => inSubroutine(Number(/^haas_pocket\.nc:(\d+) /.exec(t)?.[1])));
  assert.equal(drawnInSubroutine.length, 16, titles.join('\n'));
  assert.equal(await view.locator('#plot g.move.feed').count(), moves.filter((m) => m.mode === 'G01').length);
  await shot('10b-haas-toolpath');
});

test('extension-host API tests pass in the same VS Code', { timeout: 3 * STEP }, async () => {
  await page.close();
  const { code, lines, page: apiPage } = await server.runExtensionTests(2 * STEP);
  page = apiPage;
  await shot('8-extension-host-tests');
  const results = lines.map((l) => /\b(PASS|FAIL) .*/s.exec(l)?.[0]).filter(Boolean);
  for (const line of results) console.log(`  ${line.split('\n')[0]}`);
  assert.ok(results.some((l) => l.startsWith('PASS')), `test results arrived: ${lines.slice(-20).join('\n')}`);
  assert.deepEqual(results.filter((l) => l.startsWith('FAIL')), []);
  assert.equal(code, 0);
  // The bad cncMacro.python.path of one API test left the user an error that says what to do.
  await page.locator('.notifications-toasts', { hasText: 'cncMacro.python.path (/nonexistent/python3) does not run' }).waitFor();
});

test('the editor tried no host but this machine: no gallery, telemetry or update check', { timeout: STEP }, async () => {
  assert.deepEqual(server.outsideHostAttempts(), []);
});
