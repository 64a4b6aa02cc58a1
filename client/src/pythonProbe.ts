/**
 * Asking a command whether it is a Python, and which: the part of finding Python that needs no
 * editor (`python.ts` puts it in the user's language), so that it runs under plain Node on every
 * system (`tests/client/python_probe.test.js`, on the Windows runner too).
 */
import { execFile } from 'node:child_process';

export const MIN_VERSION: readonly [number, number] = [3, 10];
/** The exit status of the `python`/`python3` that Windows puts on the PATH when no Python is
 * installed (an app execution alias of the Microsoft Store): it says so and runs nothing. */
export const STORE_PLACEHOLDER_EXIT = 9009;

/** A command that starts Python: the executable and the arguments before the script's own. */
export interface PythonCommand {
  command: string;
  args: string[];
  /** Where it came from, for messages: "setting", "Python extension" or "PATH". */
  source: string;
}

export interface FoundPython extends PythonCommand {
  version: [number, number, number];
  executable: string;
}

/** Why a command is not a Python: not there, Windows's Store placeholder, or what it said. */
export type NotPython = { why: 'missing' } | { why: 'store-placeholder' } | { why: 'failed'; text: string };

/** Run `candidate` with a line of Python that prints its version and executable. */
export function probeCommand(
  candidate: PythonCommand,
  timeoutMs = 10000,
  platform: NodeJS.Platform = process.platform,
): Promise<FoundPython | NotPython> {
  const script = 'import sys; print(*sys.version_info[:3], sys.executable)';
  return new Promise((resolve) => {
    execFile(
      candidate.command,
      [...candidate.args, '-c', script],
      { timeout: timeoutMs, windowsHide: true },
      (error, stdout) => {
        if (error) {
          resolve(notPython((error as { code?: unknown }).code, error.message, platform));
          return;
        }
        const match = /^(\d+) (\d+) (\d+) (.*)$/m.exec(stdout.trim());
        if (!match) {
          resolve({ why: 'failed', text: `unexpected answer: ${stdout.trim().slice(0, 80)}` });
          return;
        }
        resolve({
          ...candidate,
          version: [Number(match[1]), Number(match[2]), Number(match[3])],
          executable: match[4].trim(),
        });
      },
    );
  });
}

/** Why a command that failed is not a Python: ``code`` is a spawn error's name or the exit status. */
export function notPython(code: unknown, message: string, platform: NodeJS.Platform = process.platform): NotPython {
  if (code === 'ENOENT') {
    return { why: 'missing' };
  }
  if (platform === 'win32' && code === STORE_PLACEHOLDER_EXIT) {
    return { why: 'store-placeholder' };
  }
  return { why: 'failed', text: message.split('\n')[0] };
}

export function versionOk(version: readonly number[]): boolean {
  return version[0] > MIN_VERSION[0] || (version[0] === MIN_VERSION[0] && version[1] >= MIN_VERSION[1]);
}

/** The commands on the PATH tried after the setting and the Python extension, in order. */
export function pathCandidates(platform: NodeJS.Platform = process.platform): PythonCommand[] {
  const out: PythonCommand[] = [{ command: 'python3', args: [], source: 'PATH' }];
  if (platform === 'win32') {
    out.push({ command: 'py', args: ['-3'], source: 'PATH' });
  }
  out.push({ command: 'python', args: [], source: 'PATH' });
  return out;
}
