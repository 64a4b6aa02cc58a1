// The extension in a VS Code whose display language is Chinese (code-server --locale zh-cn):
// what a Chinese-reading user sees of CNC Macro — the command titles, a hover, the Problems
// panel, the toolpath view and the debugger's exception filters in Chinese. Screenshots go to test-output/editor/zh-*.png. Run with the other editor
// tests: node --test tests/editor/ (after npm run package).
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { screenshot, startWorkbench } from './codeServer.mjs';
import { hoverOver, openFile } from './workbench.mjs';

const STEP = 60000;
let server;
let page;

const shot = (name) => screenshot(page, `zh-${name}`);

before(async () => {
  ({ server, page } = await startWorkbench({ locale: 'zh-cn' }));
}, { timeout: 180000 });

after(async () => {
  await server?.stop();
});

test('hovering #5001 describes it in Chinese', { timeout: STEP }, async () => {
  await openFile(page, 'O9100.nc');
  const hover = await hoverOver(page, /^#5001$/, '程序段终点位置');
  assert.match(await hover.innerText(), /工件坐标系/);
  await shot('1-hover-5001');
  await page.mouse.move(5, 500);
});

test('the Problems panel reports the planted GOTO in Chinese', { timeout: STEP }, async () => {
  await openFile(page, 'planted_goto.nc');
  await page.locator('.editor-instance .squiggly-error').first().waitFor();
  await page.keyboard.press('Control+Shift+M');
  const row = page.locator('.markers-panel .monaco-list-row', { hasText: 'O0998 中没有 N99' }).first();
  await row.waitFor();
  assert.match(await row.innerText(), /报警 128/);
  await shot('2-problems');
});

test('the commands are named in Chinese', { timeout: STEP }, async () => {
  const rows = page.locator('.quick-input-list .monaco-list-row');
  for (let attempt = 1; ; attempt++) {
    await page.locator('.editor-instance .view-lines').first().click();
    await page.keyboard.press('Control+Shift+P');
    await page.keyboard.type('CNC Macro');
    try {
      await rows.filter({ hasText: 'CNC Macro: 重启服务器' }).first().waitFor({ timeout: 10000 });
      break;
    } catch (e) {
      if (attempt === 3) throw e; // the palette opened before the workbench had the keyboard
      await page.keyboard.press('Escape');
    }
  }
  await rows.filter({ hasText: 'CNC Macro: 选择方言' }).first().waitFor();
  await shot('3-commands');
  await page.keyboard.press('Escape');
});

test('the toolpath view speaks Chinese, and a short view keeps its axis names and status items whole', { timeout: 2 * STEP }, async () => {
  await openFile(page, 'bolt_circle.nc');
  // The bottom panel open (Problems) leaves the view little height.
  if (!(await page.locator('.part.panel').isVisible())) await page.keyboard.press('Control+Shift+M');
  await page.locator('.part.panel .markers-panel').waitFor();
  await page.keyboard.press('F1');
  await page.keyboard.type('CNC Macro: 显示刀具路径');
  await page.locator('.quick-input-list .monaco-list-row', { hasText: '显示刀具路径' }).first().waitFor();
  await page.keyboard.press('Enter');
  await page.locator('.tab', { hasText: '刀具路径：bolt_circle.nc' }).waitFor();
  const view = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
  const status = view.locator('#status', { hasText: '完成' });
  await status.waitFor({ timeout: 45000 });
  assert.match(await status.innerText(), /个程序段，\d+ 段运动/);
  assert.match(await view.locator('#legend').innerText(), /快速定位（G00）[\s\S]*固定循环/);
  assert.ok(await page.locator('.part.panel').isVisible(), 'the bottom panel is open');
  await shot('4-toolpath');

  const layout = await view.locator('body').evaluate(() => {
    const box = (el) => {
      const r = el.getBoundingClientRect();
      return { text: el.textContent, left: r.left, right: r.right, top: r.top, bottom: r.bottom };
    };
    const svg = document.getElementById('plot');
    return {
      plot: box(svg),
      names: [...svg.querySelectorAll('text.axis-name')].map(box),
      labels: [...svg.querySelectorAll('g.labels text:not(.axis-name)')].map(box),
      status: box(document.getElementById('status')),
      lineHeight: (() => {
        const probe = document.getElementById('status').appendChild(document.createElement('span'));
        probe.textContent = '0';
        const height = probe.getBoundingClientRect().height;
        probe.remove();
        return height;
      })(),
      items: [...document.querySelectorAll('#status .item')].map((el) => ({ text: el.textContent, lines: el.getClientRects().length })),
    };
  });
  const where = JSON.stringify(layout);
  assert.ok(layout.plot.bottom - layout.plot.top < 400, `the drawing is short: ${where}`);
  assert.deepEqual(layout.names.map((n) => n.text).sort(), ['X →', '↑ Y']);
  const overlap = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
  for (const name of layout.names) {
    const inside = name.left >= layout.plot.left && name.right <= layout.plot.right;
    assert.ok(inside && name.top >= layout.plot.top && name.bottom <= layout.plot.bottom, `${name.text} inside the drawing: ${where}`);
    for (const label of layout.labels) assert.ok(!overlap(name, label), `${name.text} clear of the label ${label.text}: ${where}`);
  }
  // The status line is wider than the view: it wraps, between its items only.
  assert.ok(layout.status.bottom - layout.status.top > 1.5 * layout.lineHeight, `the status line wraps: ${where}`);
  assert.ok(layout.items.length >= 4, `status items: ${where}`);
  for (const item of layout.items) assert.equal(item.lines, 1, `"${item.text}" on one line: ${where}`);
});

test('debugging, the Breakpoints view names the exception filters in Chinese', { timeout: 2 * STEP }, async () => {
  await openFile(page, 'profile_steps.nc');
  await page.locator('.editor-instance .view-lines').first().click();
  await page.keyboard.press('Control+G');
  await page.keyboard.type('11'); // G01 Y#2
  await page.keyboard.press('Enter');
  await page.keyboard.press('F9');
  await page.locator('.codicon-debug-breakpoint').first().waitFor();
  await page.keyboard.press('F5');
  await page.locator('.debug-toolbar').waitFor({ state: 'visible' });
  await page.locator('.debug-top-stack-frame-line').first().waitFor();
  const filters = page.locator('.debug-breakpoints .monaco-list-row');
  await filters.filter({ hasText: '所有报警' }).first().waitFor();
  await filters.filter({ hasText: '#3006 信息' }).first().waitFor();
  assert.equal(await filters.filter({ hasText: /All alarms|#3006 messages/ }).count(), 0);
  await page.locator('.debug-view-content .monaco-list-row', { hasText: '局部变量' }).first().waitFor(); // the scope, as before
  await shot('5-debugging');
  await page.keyboard.press('Shift+F5');
  await page.locator('.debug-toolbar').waitFor({ state: 'hidden' });
});

test('the editor tried no host but this machine: no gallery, telemetry or update check', { timeout: STEP }, async () => {
  assert.deepEqual(server.outsideHostAttempts(), []);
});
