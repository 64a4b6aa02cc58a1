/**
 * The extension's settings (`cncMacro.*`) and the object the language server reads.
 *
 * The user edits `cncMacro.dialect`, `cncMacro.python.path`, `cncMacro.diagnostics.severity`,
 * `cncMacro.analysis.maxBlocks` and `cncMacro.trace.server`. The server asks for the section
 * `cncMacro` through `workspace/configuration` and reads the keys `dialect`, `severity` and
 * `runBudget`; `serverSettings` builds that object from the user's settings.
 */
import * as vscode from 'vscode';

export const SECTION = 'cncMacro';
/** A control profile's name (`fanuc-0i`, `fanuc-30i`, `gsk980tdi`, ...): the server knows the list. */
export type Dialect = string;
/** The profile when nothing names one: the server's default, also the setting's default. */
export const DEFAULT_DIALECT = 'fanuc-0i';
export const SEVERITIES = ['error', 'warning', 'information', 'hint', 'off'] as const;

/** The settings the language server reads, under the names it reads them by. */
export interface ServerSettings {
  dialect: Dialect;
  severity: Record<string, string>;
  runBudget: number;
}

function config(scope?: vscode.ConfigurationScope): vscode.WorkspaceConfiguration {
  return vscode.workspace.getConfiguration(SECTION, scope);
}

/** The dialect setting as written (the server reads names and aliases such as `fanuc`), or the default. */
export function dialect(scope?: vscode.ConfigurationScope): Dialect {
  const value = config(scope).get<string>('dialect');
  return typeof value === 'string' && value.trim() !== '' ? value.trim() : DEFAULT_DIALECT;
}

/** The Python interpreter the user chose, or undefined when the setting is empty. */
export function pythonPath(scope?: vscode.ConfigurationScope): string | undefined {
  const value = config(scope).get<string>('python.path', '').trim();
  return value === '' ? undefined : value;
}

/** Severity overrides: diagnostic code -> error|warning|information|hint|off; bad entries dropped. */
export function severities(scope?: vscode.ConfigurationScope): Record<string, string> {
  const raw = config(scope).get<unknown>('diagnostics.severity', {});
  const out: Record<string, string> = {};
  if (raw !== null && typeof raw === 'object') {
    for (const [code, value] of Object.entries(raw as Record<string, unknown>)) {
      if (typeof value === 'string' && (SEVERITIES as readonly string[]).includes(value.toLowerCase())) {
        out[code] = value.toLowerCase();
      }
    }
  }
  return out;
}

/** The block budget of each analysis run. */
export function maxBlocks(scope?: vscode.ConfigurationScope): number {
  const value = config(scope).get<number>('analysis.maxBlocks', 100000);
  return Number.isInteger(value) && value > 0 ? value : 100000;
}

export function serverSettings(scope?: vscode.ConfigurationScope): ServerSettings {
  return { dialect: dialect(scope), severity: severities(scope), runBudget: maxBlocks(scope) };
}

/** Write the dialect: to the workspace when one is open, else to the user's settings. */
export async function setDialect(value: Dialect): Promise<void> {
  const target = vscode.workspace.workspaceFolders?.length
    ? vscode.ConfigurationTarget.Workspace
    : vscode.ConfigurationTarget.Global;
  await config().update('dialect', value, target);
}
