/**
 * The sequence-number commands: Renumber Sequence Numbers (asks for the step), Add Missing
 * Sequence Numbers (asks for the step) and Remove Unused Sequence Numbers, on the active program or
 * its selection. The language server decides every change, asks whatever it must ask and applies
 * the edit (`workspace/executeCommand` with the `cncmacro.server.*` commands it announces); the
 * client only gathers the step and the selection.
 */
import * as vscode from 'vscode';
import { LANGUAGE_ID } from './languageClient';

const COMMANDS: [string, string, boolean][] = [
  ['cncMacro.renumberSequenceNumbers', 'cncmacro.server.renumberSequenceNumbers', true],
  ['cncMacro.addSequenceNumbers', 'cncmacro.server.addSequenceNumbers', true],
  ['cncMacro.removeSequenceNumbers', 'cncmacro.server.removeSequenceNumbers', false],
];

async function askStep(): Promise<number | undefined> {
  const answer = await vscode.window.showInputBox({
    title: vscode.l10n.t('Sequence number step'),
    prompt: vscode.l10n.t('The step between sequence numbers (N10, N20, … for 10)'),
    value: '10',
    validateInput: (text) =>
      /^\s*[1-9]\d{0,4}\s*$/.test(text) ? undefined : vscode.l10n.t('A whole number from 1 to 99999'),
  });
  return answer === undefined ? undefined : Number(answer.trim());
}

async function run(serverCommand: string, withStep: boolean): Promise<void> {
  const editor = vscode.window.activeTextEditor;
  if (!editor || editor.document.languageId !== LANGUAGE_ID) {
    void vscode.window.showInformationMessage(vscode.l10n.t('Open a CNC macro program first.'));
    return;
  }
  const step = withStep ? await askStep() : undefined;
  if (withStep && step === undefined) {
    return;
  }
  const s = editor.selection;
  const range = s.isEmpty
    ? undefined
    : { start: { line: s.start.line, character: s.start.character }, end: { line: s.end.line, character: s.end.character } };
  try {
    await vscode.commands.executeCommand(serverCommand, { uri: editor.document.uri.toString(), step, range });
  } catch (error) {
    void vscode.window.showWarningMessage(
      vscode.l10n.t('The CNC Macro language server could not do it: {0}', error instanceof Error ? error.message : String(error)),
    );
  }
}

export function registerSequenceNumberCommands(context: vscode.ExtensionContext): void {
  for (const [command, serverCommand, withStep] of COMMANDS) {
    context.subscriptions.push(vscode.commands.registerCommand(command, () => run(serverCommand, withStep)));
  }
}
