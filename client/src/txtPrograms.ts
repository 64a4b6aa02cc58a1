/**
 * Programs kept as `.txt` files (a GSK980TDi's or a DNC folder's `O0810.txt`): VS Code gives a
 * `.txt` file the Plain Text language by its ending and reads no language's `firstLine` for it,
 * so the extension looks at the first line of each plain-text file that opens and gives it the
 * CNC Macro language when that line is one the manifest's `firstLine` takes (`%` alone,
 * `O1234` with or without a comment, `<NAME>`): the one pattern, held by the tests to the
 * server's rule of which files are programs (`library/files.py`). A file the user turns back to
 * Plain Text stays so while it is open.
 */
import * as vscode from 'vscode';
import { LANGUAGE_ID } from './languageClient';

const PLAIN_TEXT = 'plaintext';

/** The manifest's `firstLine` pattern of the CNC Macro language (undefined when it has none). */
export function programFirstLine(packageJSON: unknown): RegExp | undefined {
  const languages = (packageJSON as { contributes?: { languages?: { id?: string; firstLine?: unknown }[] } })
    .contributes?.languages;
  const pattern = languages?.find((l) => l.id === LANGUAGE_ID)?.firstLine;
  return typeof pattern === 'string' ? new RegExp(pattern) : undefined;
}

/** Whether a file whose first line is `line` starts as a program (a BOM is no part of the line). */
export function startsAsProgram(line: string, firstLine: RegExp): boolean {
  return firstLine.test(line.replace(/^\uFEFF/, ''));
}

/** Give the CNC Macro language to each plain-text file on disk that starts as a program. */
export function registerTxtPrograms(context: vscode.ExtensionContext, firstLine: RegExp): void {
  // The documents given the language: a language change keeps the document object, so one met
  // here again as plain text is one the user turned back.
  const given = new WeakSet<vscode.TextDocument>();
  const look = async (document: vscode.TextDocument): Promise<void> => {
    if (document.languageId !== PLAIN_TEXT || document.uri.scheme !== 'file' || given.has(document)) {
      return;
    }
    if (document.lineCount === 0 || !startsAsProgram(document.lineAt(0).text, firstLine)) {
      return;
    }
    given.add(document);
    try {
      given.add(await vscode.languages.setTextDocumentLanguage(document, LANGUAGE_ID));
    } catch {
      // closed meanwhile: nothing to do
    }
  };
  context.subscriptions.push(vscode.workspace.onDidOpenTextDocument((d) => void look(d)));
  for (const document of vscode.workspace.textDocuments) {
    void look(document);
  }
}
