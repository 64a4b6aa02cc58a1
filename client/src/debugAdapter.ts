/**
 * The debugger: a configuration provider and the factory that starts `python -m cncmacro dap`.
 *
 * F5 without a launch.json debugs the program in the active editor. A configuration without a
 * dialect gets the `cncMacro.dialect` setting (a `(cncmacro: dialect=...)` comment or the machine
 * file still come first, as for the checker). The adapter runs on stdio with the same Python and
 * PYTHONPATH as the language server.
 */
import * as vscode from 'vscode';
import { LANGUAGE_ID, type ServerController } from './languageClient';
import { cncmacroCommand, serverEnvironment, serverLayout } from './serverProcess';
import * as settings from './settings';

export const DEBUG_TYPE = 'cnc-macro';

export class ConfigurationProvider implements vscode.DebugConfigurationProvider {
  resolveDebugConfiguration(
    folder: vscode.WorkspaceFolder | undefined,
    config: vscode.DebugConfiguration,
  ): vscode.ProviderResult<vscode.DebugConfiguration> {
    if (!config.type && !config.request && !config.name) {
      const editor = vscode.window.activeTextEditor;
      if (editor?.document.languageId !== LANGUAGE_ID) {
        void vscode.window.showInformationMessage(vscode.l10n.t('Open a CNC macro program to debug it.'));
        return undefined;
      }
      config.type = DEBUG_TYPE;
      config.request = 'launch';
      config.name = vscode.l10n.t('Debug CNC program');
      config.program = '${file}';
      config.echoMotion = true;
    }
    if (!config.program) {
      void vscode.window.showInformationMessage(vscode.l10n.t('The launch configuration names no program to debug.'));
      return undefined;
    }
    if (!config.dialect) {
      config.dialect = settings.dialect(folder?.uri);
    }
    return config;
  }
}

export class AdapterFactory implements vscode.DebugAdapterDescriptorFactory {
  constructor(
    private readonly context: vscode.ExtensionContext,
    private readonly server: ServerController,
  ) {}

  async createDebugAdapterDescriptor(session: vscode.DebugSession): Promise<vscode.DebugAdapterDescriptor | undefined> {
    const python = await this.server.resolvePython(session.workspaceFolder?.uri);
    if (!python) {
      return undefined;
    }
    const layout = serverLayout(this.context.extensionPath);
    const { command, args } = cncmacroCommand(python, ['dap']);
    this.server.log.info(`starting the debug adapter: ${command} ${args.join(' ')}`);
    return new vscode.DebugAdapterExecutable(command, args, { env: stringEnv(serverEnvironment(layout)) });
  }
}

function stringEnv(env: NodeJS.ProcessEnv): Record<string, string> {
  const out: Record<string, string> = {};
  for (const [key, value] of Object.entries(env)) {
    if (value !== undefined) {
      out[key] = value;
    }
  }
  return out;
}

export function registerDebugger(context: vscode.ExtensionContext, server: ServerController): void {
  context.subscriptions.push(
    vscode.debug.registerDebugConfigurationProvider(DEBUG_TYPE, new ConfigurationProvider()),
    vscode.debug.registerDebugAdapterDescriptorFactory(DEBUG_TYPE, new AdapterFactory(context, server)),
  );
}
