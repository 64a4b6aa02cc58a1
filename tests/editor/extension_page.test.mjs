// The extension's own page in a real VS Code, offline: the Extensions view lists CNC Macro as
// installed from the .vsix, and its page shows the README with every picture decoded from the
// package itself (inlined as data: URIs by client/scripts/vsix-readme.mjs: the page loads
// pictures only from https: or data:), with no request to another host. Screenshot: test-output/editor/extension-page.png.
// Run: node --test tests/editor/extension_page.test.mjs (after npm run package).
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { screenshot, startWorkbench } from './codeServer.mjs';

const STEP = 90000;
let server;
let page;

before(async () => {
  ({ server, page } = await startWorkbench());
}, { timeout: 180000 });

after(async () => {
  await server?.stop();
});

test("the extension's page shows its README's pictures from the package, offline", { timeout: STEP }, async () => {
  await page.keyboard.press('Control+Shift+X');
  const search = page.locator('.extensions-viewlet .monaco-editor textarea').first();
  await search.waitFor();
  await search.fill('@installed cncmacro');
  const item = page.locator('.extensions-viewlet .monaco-list-row', { hasText: 'CNC Macro' }).first();
  await item.waitFor({ timeout: 30000 });
  await item.click();
  await page.locator('.extension-editor .header .name', { hasText: 'CNC Macro' }).waitFor();
  const readme = page.frameLocator('iframe.webview.ready').frameLocator('iframe#active-frame');
  const pictures = readme.locator('img[alt]');
  await pictures.first().waitFor({ timeout: 30000 });
  // every picture of the README (eight screenshots) decoded from the README itself
  let shown = [];
  for (let tries = 0; tries < 50; tries += 1) {
    shown = await pictures.evaluateAll((images) =>
      images.map((img) => ({ src: img.getAttribute('src'), loaded: img.complete && img.naturalWidth > 0 })),
    );
    if (shown.length >= 8 && shown.every((p) => p.loaded)) break;
    await page.waitForTimeout(200);
  }
  const brief = shown.map((p) => ({ src: (p.src ?? '').slice(0, 40), loaded: p.loaded }));
  assert.ok(shown.length >= 8, `the README's screenshots: ${JSON.stringify(brief)}`);
  assert.deepEqual(brief.filter((p) => !p.loaded), [], 'pictures that did not load');
  assert.deepEqual(brief.filter((p) => !p.src.startsWith('data:image/png;base64,')), [], 'pictures not in the package');
  await readme.locator('img[alt^="The toolpath view"]').scrollIntoViewIfNeeded();
  await screenshot(page, 'extension-page', { settle: 500 });
});

test('the page tried no host but this machine', { timeout: STEP }, async () => {
  assert.deepEqual(server.outsideHostAttempts(), []);
});
