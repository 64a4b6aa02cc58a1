/**
 * The Model Context Protocol server for the editor's AI agent: `python -m cncmacro mcp`, offered
 * through VS Code's MCP support (`contributes.mcpServerDefinitionProviders`), so that the agent
 * can check and run the programs it writes and look up a variable or a code on the user's control.
 *
 * That API came with VS Code 1.101, after the extension's engine floor, and is newer than the
 * `@types/vscode` the extension builds against: it is looked up at run time, and an editor
 * without it activates the extension as before, with no server offered. The server is started
 * with the same Python and `PYTHONPATH` as the language server (`serverProcess.ts`); the Python is
 * found only when the editor starts the server, not when it lists what it could start. That Python
 * needs the `mcp` package (`pip install 'cncmacro[mcp]'`); without it the server's start fails
 * with a message saying so (docs/cli.md).
 */
import * as vscode from 'vscode';
import type { ServerController } from './languageClient';
import { cncmacroCommand, serverEnvironment, serverLayout } from './serverProcess';

/** The provider's id, as package.json's `contributes.mcpServerDefinitionProviders` names it. */
export const MCP_PROVIDER_ID = 'cncmacro.mcpServer';
const LABEL = 'cncmacro';

/** A server started as a child process on stdio: VS Code's `McpStdioServerDefinition`. */
interface McpStdioDefinition {
  label: string;
  command: string;
  args: string[];
  env: Record<string, string | number | null>;
  cwd?: vscode.Uri;
  version?: string;
}

type McpStdioDefinitionClass = new (
  label: string,
  command: string,
  args?: string[],
  env?: Record<string, string | number | null>,
  version?: string,
) => McpStdioDefinition;

interface McpDefinitionProvider {
  provideMcpServerDefinitions(token: vscode.CancellationToken): McpStdioDefinition[];
  resolveMcpServerDefinition(
    server: McpStdioDefinition,
    token: vscode.CancellationToken,
  ): Promise<McpStdioDefinition | undefined>;
}

/** The part of VS Code's API (1.101 and later) this module uses; each piece may be missing. */
interface McpApi {
  lm?: {
    registerMcpServerDefinitionProvider?: (id: string, provider: McpDefinitionProvider) => vscode.Disposable;
  };
  McpStdioServerDefinition?: McpStdioDefinitionClass;
}

/** Offer `cncmacro mcp` to the editor's agent where the editor has MCP support; false where it has not. */
export function registerMcpServer(context: vscode.ExtensionContext, server: ServerController): boolean {
  const api = vscode as unknown as McpApi;
  const register = api.lm?.registerMcpServerDefinitionProvider;
  const Definition = api.McpStdioServerDefinition;
  if (typeof register !== 'function' || typeof Definition !== 'function') {
    return false;
  }
  const declared = (context.extension.packageJSON as { version?: unknown }).version;
  const version = typeof declared === 'string' ? declared : undefined;
  const layout = serverLayout(context.extensionPath);
  const env: Record<string, string> = {};
  for (const [key, value] of Object.entries(serverEnvironment(layout, { PYTHONPATH: process.env.PYTHONPATH }))) {
    if (value !== undefined) {
      env[key] = value;
    }
  }
  const folder = (): vscode.Uri | undefined => vscode.workspace.workspaceFolders?.[0]?.uri;
  const provider: McpDefinitionProvider = {
    provideMcpServerDefinitions: () => {
      // the command is settled when the server starts (resolveMcpServerDefinition): finding
      // Python runs it, which listing the servers should not
      const listed = new Definition(LABEL, 'python', ['-m', 'cncmacro', 'mcp'], env, version);
      listed.cwd = folder();
      return [listed];
    },
    resolveMcpServerDefinition: async (listed) => {
      const python = await server.resolvePython(folder());
      if (!python) {
        return undefined; // resolvePython has told the user what to do
      }
      const { command, args } = cncmacroCommand(python, ['mcp']);
      server.log.info(`offering the MCP server: ${command} ${args.join(' ')}`);
      const resolved = new Definition(listed.label, command, args, env, version);
      resolved.cwd = folder();
      return resolved;
    },
  };
  try {
    context.subscriptions.push(register.call(api.lm, MCP_PROVIDER_ID, provider));
  } catch (e) {
    // VS Code 1.100 has the function as a proposed API, which throws for an extension that did
    // not ask for the proposal: the server is not offered, and nothing else changes
    server.log.info(`the MCP server is not offered in this editor: ${e instanceof Error ? e.message : String(e)}`);
    return false;
  }
  return true;
}
