// ESLint for the extension's TypeScript (client/src), run by `make test` as
// `npm run --silent lint:client`. It lives with the test stack (tests/package.json), which
// installs ESLint; building the extension does not need it. Type-aware rules read
// client/tsconfig.json, whose `strict` they extend.
import js from '@eslint/js';
import tseslint from 'typescript-eslint';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

export default tseslint.config(
  {
    files: ['client/src/**/*.ts'],
    extends: [js.configs.recommended, ...tseslint.configs.recommendedTypeChecked],
    languageOptions: {
      parserOptions: { project: path.join(ROOT, 'client', 'tsconfig.json'), tsconfigRootDir: ROOT },
    },
    rules: {
      eqeqeq: ['error', 'always'],
      'no-console': 'error', // the extension logs to its output channels, never to the console
      '@typescript-eslint/no-floating-promises': 'error',
      '@typescript-eslint/explicit-module-boundary-types': 'error',
    },
  },
);
