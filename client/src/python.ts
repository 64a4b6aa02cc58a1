/**
 * Finding a Python interpreter for the server and checking its version (each command asked
 * through `pythonProbe.ts`, which needs no editor).
 *
 * The order is: the `cncMacro.python.path` setting; the active environment of the Python
 * extension, when that extension is installed (it is never required); then `python3`, `py -3`
 * (Windows) and `python` on the PATH. An interpreter older than 3.10 is skipped with a note (and
 * Windows's Microsoft Store placeholder, which runs no Python, is named as such), and
 * when none fits the user is told plainly what to do. Once the Python extension has been asked,
 * `onDidChangePythonExtensionEnvironment` fires whenever the user picks another interpreter there.
 */
import * as os from 'node:os';
import * as path from 'node:path';
import * as vscode from 'vscode';
import { MIN_VERSION, pathCandidates, probeCommand, versionOk, type FoundPython, type PythonCommand } from './pythonProbe';
import * as settings from './settings';

export { MIN_VERSION, type FoundPython, type PythonCommand } from './pythonProbe';

export type Discovery =
  | { ok: true; python: FoundPython; log: string[] }
  | { ok: false; message: string; log: string[] };

/** Probe one command: its version and real executable, or why it is not a Python, in words. */
export async function probe(candidate: PythonCommand, timeoutMs = 10000): Promise<FoundPython | string> {
  const found = await probeCommand(candidate, timeoutMs);
  if (!('why' in found)) {
    return found;
  }
  if (found.why === 'missing') {
    return vscode.l10n.t('no such program');
  }
  if (found.why === 'store-placeholder') {
    return vscode.l10n.t("the Microsoft Store's placeholder, not a Python: none is installed under that name");
  }
  return found.text;
}

/** `~` and `${workspaceFolder}` in the setting, resolved. */
export function expandPath(value: string, folder?: vscode.WorkspaceFolder): string {
  let out = value;
  if (out === '~' || out.startsWith('~/') || out.startsWith('~\\')) {
    out = path.join(os.homedir(), out.slice(1));
  }
  const root = folder?.uri.fsPath ?? vscode.workspace.workspaceFolders?.[0]?.uri.fsPath;
  if (root) {
    out = out.replace(/\$\{workspaceFolder\}/g, root);
  }
  return out;
}

/** The shape of the Python extension's API that is used here (it may be absent or change). */
interface PythonExtensionApi {
  environments?: {
    getActiveEnvironmentPath(resource?: vscode.Uri): { path: string } | undefined;
    resolveEnvironment(env: { path: string } | string): Promise<{ executable?: { uri?: vscode.Uri } } | undefined>;
    onDidChangeActiveEnvironmentPath?: vscode.Event<unknown>;
  };
}

const environmentChanged = new vscode.EventEmitter<void>();
let watchingPythonExtension = false;

/** Fires when the user picks another interpreter in the Python extension (once it was asked). */
export const onDidChangePythonExtensionEnvironment: vscode.Event<void> = environmentChanged.event;

async function fromPythonExtension(resource?: vscode.Uri): Promise<string | undefined> {
  const extension = vscode.extensions.getExtension<PythonExtensionApi>('ms-python.python');
  if (!extension) {
    return undefined;
  }
  try {
    const api = extension.isActive ? extension.exports : await extension.activate();
    const environments = api?.environments;
    if (environments?.onDidChangeActiveEnvironmentPath && !watchingPythonExtension) {
      watchingPythonExtension = true;
      environments.onDidChangeActiveEnvironmentPath(() => environmentChanged.fire());
    }
    const active = environments?.getActiveEnvironmentPath(resource);
    if (!environments || !active) {
      return undefined;
    }
    const resolved = await environments.resolveEnvironment(active);
    return resolved?.executable?.uri?.fsPath ?? active.path;
  } catch {
    return undefined;
  }
}

const versionText = (v: readonly number[]): string => v.join('.');

/** Find a Python ≥ 3.10 in the documented order. */
export async function findPython(resource?: vscode.Uri): Promise<Discovery> {
  const log: string[] = [];
  const need = versionText(MIN_VERSION);
  const configured = settings.pythonPath(resource);
  if (configured) {
    const folder = resource ? vscode.workspace.getWorkspaceFolder(resource) : undefined;
    const command = expandPath(configured, folder);
    const found = await probe({ command, args: [], source: 'setting' });
    if (typeof found === 'string') {
      return {
        ok: false,
        log,
        message: vscode.l10n.t(
          'The Python set in cncMacro.python.path ({0}) does not run: {1}. Set it to a Python {2} or newer, or clear it to let CNC Macro look for one.',
          command,
          found,
          need,
        ),
      };
    }
    if (!versionOk(found.version)) {
      return {
        ok: false,
        log,
        message: vscode.l10n.t(
          'The Python set in cncMacro.python.path ({0}) is version {1}; CNC Macro needs Python {2} or newer. Install a newer Python and set cncMacro.python.path to it.',
          command,
          versionText(found.version),
          need,
        ),
      };
    }
    return { ok: true, python: found, log };
  }

  const candidates: PythonCommand[] = [];
  const fromExtension = await fromPythonExtension(resource);
  if (fromExtension) {
    candidates.push({ command: fromExtension, args: [], source: 'Python extension' });
  }
  candidates.push(...pathCandidates());
  const tooOld: string[] = [];
  for (const candidate of candidates) {
    const found = await probe(candidate);
    const name = [candidate.command, ...candidate.args].join(' ');
    if (typeof found === 'string') {
      log.push(`${name} (${candidate.source}): ${found}`);
      continue;
    }
    log.push(`${name} (${candidate.source}): Python ${versionText(found.version)} at ${found.executable}`);
    if (versionOk(found.version)) {
      return { ok: true, python: found, log };
    }
    tooOld.push(`${found.executable} (${versionText(found.version)})`);
  }
  const message = tooOld.length
    ? vscode.l10n.t(
        'CNC Macro needs Python {0} or newer, but found only {1}. Install a newer Python, or set cncMacro.python.path to one.',
        need,
        tooOld.join(', '),
      )
    : vscode.l10n.t(
        'CNC Macro needs Python {0} or newer and found none. Install Python (on Windows, tick "Add python.exe to PATH"), or set cncMacro.python.path to the python executable.',
        need,
      );
  return { ok: false, message, log };
}
