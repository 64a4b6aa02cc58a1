// What the editor tests do in the workbench page as a user would: open a file from the Explorer,
// hover over a piece of text until its hover shows, read the colour of a token or of each character.
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
 * The computed colour of each character of `text` where it first stands on the editor line
 * that holds `line` (both as typed; Monaco's no-break spaces count as spaces), or undefined
 * while that line is not drawn. Unlike `tokenColour` it does not depend on how the line is cut
 * into spans, so it can tell one colour over `G90` from a `G` and a `90` coloured apart.
 */
export async function characterColours(page, line, text) {
  return page.evaluate(
    ([line, text]) => {
      for (const row of document.querySelectorAll('.editor-instance .view-lines .view-line')) {
        const drawn = row.textContent.replace(/\u00a0/g, ' ');
        const at = drawn.indexOf(line);
        if (at < 0 || line.indexOf(text) < 0) continue;
        const from = at + line.indexOf(text);
        const colours = [];
        let offset = 0;
        for (const span of row.querySelectorAll(':scope > span > span')) {
          const length = span.textContent.length;
          for (let i = Math.max(from, offset); i < Math.min(from + text.length, offset + length); i++) {
            colours.push(getComputedStyle(span).color);
          }
          offset += length;
        }
        return colours.length === text.length ? colours : undefined;
      }
      return undefined;
    },
    [line, text],
  );
}

/** The one colour of every character of `text` on the line holding `line`; fails if they differ. */
export async function oneColour(page, line, text) {
  const colours = await characterColours(page, line, text);
  assert.ok(colours, `${JSON.stringify(text)} on the line ${JSON.stringify(line)} is drawn`);
  assert.equal(new Set(colours).size, 1, `one colour over ${JSON.stringify(text)} of ${JSON.stringify(line)}: ${colours}`);
  return colours[0];
}

/** The colour of text no rule colours: Monaco's first token class, `mtk1`, the theme's default. */
export async function editorForeground(page) {
  return page
    .locator('.editor-instance .view-lines')
    .first()
    .evaluate((el) => {
      const probe = el.appendChild(document.createElement('span'));
      probe.className = 'mtk1';
      const colour = getComputedStyle(probe).color;
      probe.remove();
      return colour;
    });
}

/**
 * Move the mouse onto the first token `token` (a RegExp) until a hover containing `hasText`
 * shows, and return that hover. The mouse goes to where the token is drawn now (inlay hints
 * that arrive late move text sideways), and tries again twice: the answer can wait behind an
 * analysis run on a busy machine, and the line can be drawn anew under the mouse.
 */
export async function hoverOver(page, token, hasText) {
  const target = page.locator('.editor-instance .view-lines span span', { hasText: token }).first();
  const hover = page.locator('.monaco-hover', { hasText });
  for (let attempt = 1; ; attempt++) {
    try {
      // the line can be drawn again meanwhile (the server's colours or inlay hints arrive):
      // a token gone from the page is looked up again on the next attempt
      await target.scrollIntoViewIfNeeded({ timeout: 5000 });
      const box = await target.boundingBox();
      assert.ok(box, `${token} is on screen`);
      await page.mouse.move(box.x + 2, box.y + box.height / 2);
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2, { steps: 4 });
      await hover.waitFor({ state: 'visible', timeout: 10000 });
      return hover;
    } catch (e) {
      if (attempt === 3) throw e;
      await page.mouse.move(5, 500);
      await page.keyboard.press('Escape');
      await page.waitForTimeout(500); // let a line being drawn anew settle
    }
  }
}
