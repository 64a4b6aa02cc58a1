/**
 * The extension's entry point: output channels, the language server, the debugger, the
 * commands, the toolpath view and the dialect status-bar item, the `.txt` programs, the MCP
 * server offered to the editor's AI agent (`mcpServer.ts`), and the
 * reaction to settings changes and to another interpreter picked in the Python extension.
 *
 * The extension wakes for every plain-text file as well (to find the `.txt` programs among
 * them), so the language server starts only once a CNC macro program is open: a README read in
 * another project starts no Python.
 */
import * as vscode from 'vscode';
import { registerCommands } from './commands';
import { registerDebugger } from './debugAdapter';
import { LANGUAGE_ID, ServerController } from './languageClient';
import { registerMcpServer } from './mcpServer';
import { onDidChangePythonExtensionEnvironment } from './python';
import { pythonPath, SECTION } from './settings';
import { registerSequenceNumberCommands } from './sequenceNumbers';
import { DialectStatus } from './statusBar';
import { registerToolpath } from './toolpath';
import { programFirstLine, registerTxtPrograms } from './txtPrograms';

let controller: ServerController | undefined;

export function activate(context: vscode.ExtensionContext): void {
  const log = vscode.window.createOutputChannel('CNC Macro Server', { log: true });
  const output = vscode.window.createOutputChannel('CNC Macro');
  const server = new ServerController(context, log);
  controller = server;
  context.subscriptions.push(log, output, server, new DialectStatus(server));
  registerCommands(context, server, output);
  registerToolpath(context, server);
  registerDebugger(context, server);
  registerSequenceNumberCommands(context);
  context.subscriptions.push(
    vscode.workspace.onDidChangeConfiguration(async (e) => {
      if (!server.wanted) {
        return; // not started yet: it reads the settings when it starts
      }
      if (e.affectsConfiguration(`${SECTION}.python.path`)) {
        log.info('cncMacro.python.path changed: restarting the language server');
        await server.restart();
      } else if (
        e.affectsConfiguration(`${SECTION}.dialect`) ||
        e.affectsConfiguration(`${SECTION}.diagnostics`) ||
        e.affectsConfiguration(`${SECTION}.analysis`)
      ) {
        await server.settingsChanged();
      }
    }),
    onDidChangePythonExtensionEnvironment(async () => {
      if (pythonPath() || !server.wanted) {
        return; // cncMacro.python.path wins over the Python extension's choice
      }
      log.info("the Python extension's interpreter changed: restarting the language server");
      await server.restart();
    }),
  );
  startWithFirstProgram(context, server);
  const firstLine = programFirstLine(context.extension.packageJSON);
  if (firstLine) {
    registerTxtPrograms(context, firstLine);
  }
  registerMcpServer(context, server); // where the editor has MCP support (VS Code 1.101 and later), last
}

/** Start the language server now if a CNC macro program is open, else when the first one opens. */
function startWithFirstProgram(context: vscode.ExtensionContext, server: ServerController): void {
  const isProgram = (d: vscode.TextDocument): boolean => d.languageId === LANGUAGE_ID;
  if (vscode.workspace.textDocuments.some(isProgram)) {
    void server.start();
    return;
  }
  const opened = vscode.workspace.onDidOpenTextDocument((d) => {
    if (isProgram(d)) {
      opened.dispose();
      void server.start();
    }
  });
  context.subscriptions.push(opened);
}

export async function deactivate(): Promise<void> {
  await controller?.stop();
  controller = undefined;
}
