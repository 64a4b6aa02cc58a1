/**
 * The language client: starts `python -m cncmacro lsp` over stdio and keeps it in step with
 * the settings.
 *
 * The server asks for the section `cncMacro` through `workspace/configuration`; the middleware
 * answers it with `serverSettings` (the names the server reads). A change of the dialect,
 * severities or budget is pushed with `workspace/didChangeConfiguration`; a change of the Python
 * path restarts the server. Diagnostics are taken as pushed (see `PushDiagnosticsClient`). Its
 * log goes to the "CNC Macro Server" output channel, which names the server and its version once it
 * runs, and the extension's version.
 */
import * as vscode from 'vscode';
import {
  type DynamicFeature,
  DocumentDiagnosticRequest,
  LanguageClient,
  type LanguageClientOptions,
  type ResponseError,
  type ServerOptions,
  State,
  type StaticFeature,
} from 'vscode-languageclient/node';
import { findPython, type FoundPython } from './python';
import { cncmacroCommand, serverEnvironment, serverLayout } from './serverProcess';
import { SECTION, serverSettings } from './settings';

export const LANGUAGE_ID = 'cnc-macro';

/**
 * A client that takes diagnostics only as the server pushes them. The server publishes every
 * analysis result, for open files and for the macros they call, and after a settings change;
 * pulling as well would show each finding twice and keep a stale copy after the settings change.
 * Without this feature the client does not announce pull support.
 */
class PushDiagnosticsClient extends LanguageClient {
  override registerFeature(feature: StaticFeature | DynamicFeature<unknown>): void {
    if ('registrationType' in feature && feature.registrationType.method === DocumentDiagnosticRequest.method) {
      return;
    }
    super.registerFeature(feature);
  }
}

/** The server's answer to `cncmacro/documentDialect`. */
export interface DocumentDialect {
  dialect: string;
  title: string;
  lathe?: boolean;
  source: 'file' | 'workspace' | 'setting' | 'default';
}

/** One control profile, as the server's `cncmacro/profiles` describes it. */
export interface Profile {
  name: string;
  title: string;
  titleZh: string;
  summary: string;
  summaryZh: string;
  aliases: string[];
  lathe: boolean;
  default: boolean;
}

/**
 * The log line of a started server: its name and version as its initialize result tells them
 * (`serverInfo`), and the extension's version, so that a report names both.
 */
export function runningLine(serverInfo: { name: string; version?: string } | undefined, packageJSON: unknown): string {
  const server = serverInfo ? [serverInfo.name, serverInfo.version ?? '(no version)'].join(' ') : '(unnamed)';
  const version = (packageJSON as { version?: unknown } | undefined)?.version;
  return `the language server ${server} is running (CNC Macro extension ${typeof version === 'string' ? version : 'of unknown version'})`;
}

export class ServerController implements vscode.Disposable {
  private client: LanguageClient | undefined;
  private starting: Promise<void> | undefined;
  python: FoundPython | undefined;

  constructor(
    private readonly context: vscode.ExtensionContext,
    readonly log: vscode.LogOutputChannel,
  ) {}

  get running(): boolean {
    return this.client?.isRunning() ?? false;
  }

  /** Whether the server was asked to start (it runs, starts, or failed to and waits for a fix). */
  get wanted(): boolean {
    return this.asked;
  }

  private asked = false;

  /** Find Python (telling the user when there is none that fits) and start the server. */
  start(): Promise<void> {
    this.asked = true;
    this.starting ??= this.doStart().finally(() => {
      this.starting = undefined;
    });
    return this.starting;
  }

  async restart(): Promise<void> {
    await this.stop();
    await this.start();
  }

  async stop(): Promise<void> {
    await this.starting;
    const client = this.client;
    this.client = undefined;
    if (client) {
      try {
        await client.stop(5000);
      } catch (e) {
        this.log.warn(`stopping the language server: ${String(e)}`);
      }
      await client.dispose();
    }
  }

  /**
   * The dialect the server reads an open document in and what decided it (`file`, `workspace`,
   * `setting` or `default`); undefined while the server is not running or the document is not open.
   */
  async documentDialect(uri: vscode.Uri): Promise<DocumentDialect | undefined> {
    if (!this.client?.isRunning()) {
      return undefined;
    }
    try {
      const answer = await this.client.sendRequest<DocumentDialect | null>('cncmacro/documentDialect', {
        uri: this.client.code2ProtocolConverter.asUri(uri),
      });
      return answer ?? undefined;
    } catch {
      return undefined;
    }
  }

  /** The control profiles the server knows (empty while it is not running). */
  async profiles(): Promise<Profile[]> {
    if (!this.client?.isRunning()) {
      return [];
    }
    try {
      const answer = await this.client.sendRequest<Profile[] | null>('cncmacro/profiles', {});
      return Array.isArray(answer) ? answer : [];
    } catch {
      return [];
    }
  }

  /** Push the settings the server reads (it asks for them again as well). */
  async settingsChanged(): Promise<void> {
    if (this.client?.isRunning()) {
      await this.client.sendNotification('workspace/didChangeConfiguration', { settings: null });
    }
  }

  /** The interpreter to use, found again each time (the settings may have changed). */
  async resolvePython(resource?: vscode.Uri): Promise<FoundPython | undefined> {
    const found = await findPython(resource);
    for (const line of found.log) {
      this.log.info(`python: ${line}`);
    }
    if (!found.ok) {
      this.log.error(found.message);
      const open = vscode.l10n.t('Open Settings');
      void vscode.window.showErrorMessage(found.message, open).then((choice) => {
        if (choice === open) {
          void vscode.commands.executeCommand('workbench.action.openSettings', `${SECTION}.python.path`);
        }
      });
      return undefined;
    }
    return found.python;
  }

  private async doStart(): Promise<void> {
    const python = await this.resolvePython();
    this.python = python;
    if (!python) {
      return;
    }
    const layout = serverLayout(this.context.extensionPath);
    const { command, args } = cncmacroCommand(python, ['lsp']);
    this.log.info(
      `starting the language server: ${command} ${args.join(' ')} (Python ${python.version.join('.')}, ${layout.kind} server, PYTHONPATH ${layout.pythonPath.join(', ')})`,
    );
    const serverOptions: ServerOptions = {
      command,
      args,
      options: { env: serverEnvironment(layout) },
    };
    const clientOptions: LanguageClientOptions = {
      documentSelector: [
        { scheme: 'file', language: LANGUAGE_ID },
        { scheme: 'untitled', language: LANGUAGE_ID },
      ],
      outputChannel: this.log,
      initializationOptions: serverSettings(),
      // No watcher of our own: the server registers one on the program files and the machine
      // file (workspace/didChangeWatchedFiles), with the same patterns for every editor.
      middleware: {
        workspace: {
          configuration: async (params, token, next): Promise<unknown[] | ResponseError<void>> => {
            const answer = await next(params, token);
            if (!Array.isArray(answer)) {
              return answer;
            }
            const answers: unknown[] = answer;
            return params.items.map((item, i): unknown =>
              item.section === SECTION
                ? serverSettings(item.scopeUri ? vscode.Uri.parse(item.scopeUri) : undefined)
                : answers[i],
            );
          },
        },
      },
    };
    const client = new PushDiagnosticsClient(SECTION, 'CNC Macro Language Server', serverOptions, clientOptions);
    // each time it runs: started here, or started again by the client after the server died
    client.onDidChangeState((e) => {
      if (e.newState === State.Running) {
        this.log.info(runningLine(client.initializeResult?.serverInfo, this.context.extension.packageJSON));
      }
    });
    try {
      await client.start();
      this.client = client;
    } catch (e) {
      this.log.error(`the language server did not start: ${String(e)}`);
      void vscode.window.showErrorMessage(
        vscode.l10n.t('The CNC Macro language server did not start: {0}. See the output channel "CNC Macro Server".', String(e)),
      );
      await client.dispose().catch(() => undefined);
    }
  }

  dispose(): void {
    void this.stop();
  }
}
