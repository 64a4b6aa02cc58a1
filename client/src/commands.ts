/**
 * The commands: Run Program (`python -m cncmacro run --no-save FILE` on the simulated machine,
 * its output in the "CNC Macro" output channel), Select Dialect (writes `cncMacro.dialect`) and
 * Restart Server.
 */
import { spawn } from 'node:child_process';
import * as path from 'node:path';
import * as vscode from 'vscode';
import { LANGUAGE_ID, type ServerController } from './languageClient';
import { cncmacroCommand, serverEnvironment, serverLayout } from './serverProcess';
import * as settings from './settings';

/**
 * The program a command acts on: the file it was given (an Explorer or editor-title click) or the
 * active editor's, when it is a CNC macro program saved to a file; otherwise the user is told
 * (`notAProgram` says what the command needs) and the answer is undefined.
 */
export async function programDocument(uri: vscode.Uri | undefined, notAProgram: string): Promise<vscode.TextDocument | undefined> {
  const document =
    uri !== undefined ? await vscode.workspace.openTextDocument(uri) : vscode.window.activeTextEditor?.document;
  if (!document || document.languageId !== LANGUAGE_ID) {
    void vscode.window.showInformationMessage(notAProgram);
    return undefined;
  }
  if (document.isUntitled) {
    void vscode.window.showInformationMessage(vscode.l10n.t('Save the program to a file before running it.'));
    return undefined;
  }
  return document;
}

async function runProgram(
  context: vscode.ExtensionContext,
  server: ServerController,
  output: vscode.OutputChannel,
  uri?: vscode.Uri,
): Promise<void> {
  const document = await programDocument(uri, vscode.l10n.t('Open a CNC macro program to run it.'));
  if (!document) {
    return;
  }
  if (document.isDirty && !(await document.save())) {
    return;
  }
  const python = await server.resolvePython(document.uri);
  if (!python) {
    return;
  }
  const file = document.uri.fsPath;
  const { command, args } = cncmacroCommand(python, [
    'run',
    '--no-save',
    '--dialect',
    settings.dialect(document.uri),
    file,
  ]);
  output.clear();
  output.show(true);
  output.appendLine(`$ cncmacro ${args.slice(2).join(' ')}`);
  const child = spawn(command, args, {
    cwd: path.dirname(file),
    env: serverEnvironment(serverLayout(context.extensionPath)),
    windowsHide: true,
  });
  child.stdout.setEncoding('utf8').on('data', (chunk: string) => output.append(chunk));
  child.stderr.setEncoding('utf8').on('data', (chunk: string) => output.append(chunk));
  await new Promise<void>((resolve) => {
    child.on('error', (error) => {
      output.appendLine(vscode.l10n.t('Could not run the program: {0}', error.message));
      resolve();
    });
    child.on('close', (code) => {
      output.appendLine(vscode.l10n.t('[exit status {0}]', String(code)));
      resolve();
    });
  });
}

async function selectDialect(server: ServerController): Promise<void> {
  const current = settings.dialect(vscode.window.activeTextEditor?.document.uri);
  const profiles = await server.profiles();
  if (profiles.length === 0) {
    void vscode.window.showWarningMessage(
      vscode.l10n.t('The CNC Macro language server is not running, so the control profiles are not known yet.'),
    );
    return;
  }
  const chinese = vscode.env.language.toLowerCase().startsWith('zh');
  const items: (vscode.QuickPickItem & { dialect: settings.Dialect })[] = profiles.map((p) => ({
    dialect: p.name,
    label: chinese && p.titleZh ? p.titleZh : p.title,
    description: `${p.name} · ${chinese && p.summaryZh ? p.summaryZh : p.summary}`,
  }));
  for (const item of items) {
    const profile = profiles.find((p) => p.name === item.dialect);
    if (item.dialect === current || profile?.aliases.includes(current)) {
      item.detail = vscode.l10n.t('current');
    }
  }
  const picked = await vscode.window.showQuickPick(items, {
    placeHolder: vscode.l10n.t('Dialect for CNC macro programs (a dialect comment or .cncmacro.toml still takes precedence)'),
  });
  if (picked) {
    await settings.setDialect(picked.dialect);
  }
}

export function registerCommands(
  context: vscode.ExtensionContext,
  server: ServerController,
  output: vscode.OutputChannel,
): void {
  context.subscriptions.push(
    vscode.commands.registerCommand('cncMacro.runProgram', (uri?: vscode.Uri) =>
      runProgram(context, server, output, uri instanceof vscode.Uri ? uri : undefined),
    ),
    vscode.commands.registerCommand('cncMacro.selectDialect', () => selectDialect(server)),
    vscode.commands.registerCommand('cncMacro.restartServer', async () => {
      server.log.info('restarting the language server');
      await server.restart();
    }),
  );
}
