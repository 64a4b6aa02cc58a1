/**
 * The status-bar item that shows the dialect the active CNC macro program is read in — as the
 * language server decided it (the file's `(cncmacro: dialect=...)` comment, the workspace's
 * `.cncmacro.toml`, then the setting), the setting while the server is not running — and picks
 * another setting when clicked (the Select Dialect command).
 */
import * as vscode from 'vscode';
import { LANGUAGE_ID, type DocumentDialect, type ServerController } from './languageClient';
import * as settings from './settings';

const HEADER_LINES = 5; // the lines where the server looks for the dialect comment

export class DialectStatus implements vscode.Disposable {
  private readonly item: vscode.StatusBarItem;
  private readonly subscriptions: vscode.Disposable[] = [];

  private asked = 0; // the latest update's number: an older answer that arrives late is dropped

  constructor(private readonly server: ServerController) {
    this.item = vscode.window.createStatusBarItem('cncMacro.dialect', vscode.StatusBarAlignment.Right, 100);
    this.item.name = vscode.l10n.t('CNC Macro dialect');
    this.item.command = 'cncMacro.selectDialect';
    this.subscriptions.push(
      vscode.window.onDidChangeActiveTextEditor(() => this.update()),
      vscode.workspace.onDidOpenTextDocument((d) => {
        if (d === vscode.window.activeTextEditor?.document) {
          this.update(); // its language changed (a .txt program given CNC Macro)
        }
      }),
      vscode.workspace.onDidChangeConfiguration((e) => {
        if (e.affectsConfiguration(`${settings.SECTION}.dialect`)) {
          this.update(1000); // after the server has the new setting
        }
      }),
      vscode.workspace.onDidChangeTextDocument((e) => {
        const active = vscode.window.activeTextEditor?.document;
        if (e.document === active && e.contentChanges.some((c) => c.range.start.line < HEADER_LINES)) {
          this.update(300); // the dialect comment may have changed
        }
      }),
    );
    this.update();
  }

  /** Show the active document's dialect now, and again after `laterMs` (the server's view). */
  update(laterMs = 0): void {
    const editor = vscode.window.activeTextEditor;
    if (editor?.document.languageId !== LANGUAGE_ID) {
      this.item.hide();
      return;
    }
    const document = editor.document;
    const asked = ++this.asked;
    let tries = 0;
    const ask = async (): Promise<void> => {
      const answer = await this.server.documentDialect(document.uri);
      if (asked !== this.asked) {
        return;
      }
      this.show(answer, settings.dialect(document.uri));
      if (answer === undefined && ++tries < 20) {
        setTimeout(() => void ask(), 1000); // the server is starting, or has not opened it yet
      }
    };
    if (laterMs > 0) {
      setTimeout(() => void ask(), laterMs);
    } else {
      void ask();
    }
  }

  private show(answer: DocumentDialect | undefined, setting: settings.Dialect): void {
    const title = answer?.title ?? setting;
    this.item.text = `$(tools) ${title}`;
    const why: Record<DocumentDialect['source'], string> = {
      file: vscode.l10n.t("from the file's (cncmacro: dialect=...) comment"),
      workspace: vscode.l10n.t('from the workspace .cncmacro.toml'),
      setting: vscode.l10n.t('from the cncMacro.dialect setting'),
      default: vscode.l10n.t('the default'),
    };
    const source = answer ? why[answer.source] : why.setting;
    this.item.tooltip = vscode.l10n.t('CNC Macro dialect: {0} ({1}). Click to choose the setting.', title, source);
    this.item.show();
  }

  dispose(): void {
    this.item.dispose();
    for (const s of this.subscriptions) {
      s.dispose();
    }
  }
}
