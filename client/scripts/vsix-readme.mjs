// The README the .vsix carries (vsce package --readme-path): the repository's README.md with
// each picture inlined as a data: URI, so that the extension's page in VS Code shows them
// offline (the page loads pictures only from https: or data:, never from the package's files),
// and each relative link made absolute to the repository (the page follows only http(s) links).
// Written to .cache/vsix/README.md.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const manifest = JSON.parse(fs.readFileSync(path.join(root, 'package.json'), 'utf8'));
const repository = manifest.repository.url.replace(/\.git$/, '');
const TYPES = { '.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.gif': 'image/gif' };

const readme = fs.readFileSync(path.join(root, 'README.md'), 'utf8');
const out = readme.replace(/(!?)\[([^\]]*)\]\(([^)\s]+)\)/g, (whole, bang, text, target) => {
  if (/^[a-z][a-z0-9+.-]*:/i.test(target) || target.startsWith('#')) return whole;
  if (bang) {
    const type = TYPES[path.extname(target).toLowerCase()];
    if (!type) throw new Error(`README.md: a picture the page cannot show inline: ${target}`);
    const data = fs.readFileSync(path.join(root, target)).toString('base64');
    return `![${text}](data:${type};base64,${data})`;
  }
  return `[${text}](${repository}/blob/HEAD/${target})`;
});
fs.mkdirSync(path.join(root, '.cache', 'vsix'), { recursive: true });
fs.writeFileSync(path.join(root, '.cache', 'vsix', 'README.md'), out);
