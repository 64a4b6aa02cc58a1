// What the editor tests do in the workbench page as a user would: open a file from the Explorer,
// hover over a piece of text until its hover shows, read a token's colour.
import assert from 'node:assert/strict';

/** A pattern for exactly `text`; Monaco renders spaces as no-break spaces, so a space matches either. */
export const exact = (text) =>
  new RegExp(`^${text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&').replace(/ /g, '[ \\u00a0]')}$`);

/** Open a workspace file by clicking its row in the Explorer (shown first, if another view is). */
export async function openFile(page, name) {
  if (!(await page.locator('.explorer-folders-view').isVisible())) {
    await page.keyboard.press('Control+Shift+E');
  }
  const row = page
    .locator('.explorer-folders-view .monaco-list-row')
    .filter({ has: page.locator('.label-name', { hasText: exact(name) }) });
  await row.click();
  await page.locator('.tabs-container .tab.active', { hasText: name }).waitFor();
  await page.locator('.editor-instance .view-lines .view-line').first().waitFor();
}

/** The computed colour of the first token span in the editor whose text is `text`. */
export async function tokenColour(page, text) {
  const span = page.locator('.editor-instance .view-lines span span', { hasText: exact(text) }).first();
  await span.waitFor();
  return span.evaluate((el) => getComputedStyle(el).color);
}

/**
 * Move the mouse onto the first token `token` (a RegExp) until a hover containing `hasText`
 * shows, and return that hover. The mouse goes to where the token is drawn now (inlay hints
 * that arrive late move text sideways), and tries again twice: the answer can wait behind an
 * analysis run on a busy machine.
 */
export async function hoverOver(page, token, hasText) {
  const target = page.locator('.editor-instance .view-lines span span', { hasText: token }).first();
  const hover = page.locator('.monaco-hover', { hasText });
  for (let attempt = 1; ; attempt++) {
    await target.scrollIntoViewIfNeeded();
    const box = await target.boundingBox();
    assert.ok(box, `${token} is on screen`);
    await page.mouse.move(box.x + 2, box.y + box.height / 2);
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2, { steps: 4 });
    try {
      await hover.waitFor({ state: 'visible', timeout: 10000 });
      return hover;
    } catch (e) {
      if (attempt === 3) throw e;
      await page.mouse.move(5, 500);
      await page.keyboard.press('Escape');
    }
  }
}
