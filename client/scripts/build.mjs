// Bundle the extension client (client/src/extension.ts and vscode-languageclient) into one
// CommonJS file, client/out/extension.js, which package.json names as "main".
import { build } from 'esbuild';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
await build({
  entryPoints: [path.join(root, 'src', 'extension.ts')],
  outfile: path.join(root, 'out', 'extension.js'),
  bundle: true,
  platform: 'node',
  format: 'cjs',
  target: 'node18',
  external: ['vscode'],
  minify: process.argv.includes('--minify'),
  sourcemap: false,
  logLevel: 'warning',
});
