/**
 * The status-bar item that shows the dialect setting while a CNC macro program is open, and
 * picks another one when clicked (the Select Dialect command).
 */
import * as vscode from 'vscode';
import { LANGUAGE_ID } from './languageClient';
import * as settings from './settings';

export const DIALECT_NAMES: Record<settings.Dialect, string> = {
  fanuc: 'FANUC 0i',
  gsk980tdi: 'GSK980TDi',
};

export class DialectStatus implements vscode.Disposable {
  private readonly item: vscode.StatusBarItem;
  private readonly subscriptions: vscode.Disposable[] = [];

  constructor() {
    this.item = vscode.window.createStatusBarItem('cncMacro.dialect', vscode.StatusBarAlignment.Right, 100);
    this.item.name = vscode.l10n.t('CNC Macro dialect');
    this.item.command = 'cncMacro.selectDialect';
    this.subscriptions.push(
      vscode.window.onDidChangeActiveTextEditor(() => this.update()),
      vscode.workspace.onDidChangeConfiguration((e) => {
        if (e.affectsConfiguration(`${settings.SECTION}.dialect`)) {
          this.update();
        }
      }),
    );
    this.update();
  }

  update(): void {
    const editor = vscode.window.activeTextEditor;
    if (editor?.document.languageId !== LANGUAGE_ID) {
      this.item.hide();
      return;
    }
    const dialect = settings.dialect(editor.document.uri);
    this.item.text = `$(tools) ${DIALECT_NAMES[dialect]}`;
    this.item.tooltip = vscode.l10n.t('CNC Macro dialect: {0}. Click to choose another.', DIALECT_NAMES[dialect]);
    this.item.show();
  }

  dispose(): void {
    this.item.dispose();
    for (const s of this.subscriptions) {
      s.dispose();
    }
  }
}
