/**
 * The extension's entry point: output channels, the language server, the debugger, the
 * commands, the toolpath view and the dialect status-bar item, and the reaction to settings
 * changes and to another interpreter picked in the Python extension.
 */
import * as vscode from 'vscode';
import { registerCommands } from './commands';
import { registerDebugger } from './debugAdapter';
import { ServerController } from './languageClient';
import { onDidChangePythonExtensionEnvironment } from './python';
import { pythonPath, SECTION } from './settings';
import { registerSequenceNumberCommands } from './sequenceNumbers';
import { DialectStatus } from './statusBar';
import { registerToolpath } from './toolpath';

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
      if (pythonPath()) {
        return; // cncMacro.python.path wins over the Python extension's choice
      }
      log.info("the Python extension's interpreter changed: restarting the language server");
      await server.restart();
    }),
  );
  void server.start();
}

export async function deactivate(): Promise<void> {
  await controller?.stop();
  controller = undefined;
}
