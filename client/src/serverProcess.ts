/**
 * How to start the Python side (`python -m cncmacro lsp|dap|run`) from the extension's folder.
 *
 * An installed extension carries the `cncmacro` package in `bundled/tool` and its pure-Python
 * libraries (pygls, lsprotocol, lark, ...) in `bundled/libs`; both go on `PYTHONPATH` ahead of
 * anything else, so that a bare Python is enough. In the repository (no `bundled/tool`), the
 * package comes from `server/` and the libraries from `bundled/libs` when it was filled, else
 * from the interpreter's own site-packages.
 */
import * as fs from 'node:fs';
import * as path from 'node:path';
import type { FoundPython } from './python';

export interface ServerLayout {
  /** Folders put in front of PYTHONPATH. */
  pythonPath: string[];
  /** "bundled" for an installed extension, "development" in the repository. */
  kind: 'bundled' | 'development';
}

export function serverLayout(extensionPath: string): ServerLayout {
  const tool = path.join(extensionPath, 'bundled', 'tool');
  const libs = path.join(extensionPath, 'bundled', 'libs');
  const hasLibs = fs.existsSync(libs);
  if (fs.existsSync(path.join(tool, 'cncmacro'))) {
    return { pythonPath: hasLibs ? [tool, libs] : [tool], kind: 'bundled' };
  }
  const server = path.join(extensionPath, 'server');
  return { pythonPath: hasLibs ? [server, libs] : [server], kind: 'development' };
}

/** The environment for a Python child process: our folders first on PYTHONPATH, UTF-8 I/O. */
export function serverEnvironment(layout: ServerLayout, base: NodeJS.ProcessEnv = process.env): NodeJS.ProcessEnv {
  const existing = base.PYTHONPATH ? [base.PYTHONPATH] : [];
  return {
    ...base,
    PYTHONPATH: [...layout.pythonPath, ...existing].join(path.delimiter),
    PYTHONUTF8: '1',
    PYTHONIOENCODING: 'utf-8',
  };
}

/** The command line for `python -m cncmacro <args>`. */
export function cncmacroCommand(python: FoundPython, args: string[]): { command: string; args: string[] } {
  if (python.executable) {
    return { command: python.executable, args: ['-m', 'cncmacro', ...args] };
  }
  return { command: python.command, args: [...python.args, '-m', 'cncmacro', ...args] };
}
