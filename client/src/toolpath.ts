/**
 * The Show Toolpath command: runs the active program on the simulated machine
 * (`python -m cncmacro run --no-save --json --stdin FILE`, the editor's text, unsaved changes
 * included, under the file's name) and draws its moves in a webview panel beside the editor, one
 * panel per file. The panel is drawn again a moment after the program is edited, when a program
 * it called is saved, and on its Refresh button; clicking a move opens the file it was made in
 * (a called program's too) at its line. A program that is not open in the editor is run from its
 * file. While a debug session of the program is paused, the panel draws the run so far, the
 * current block's move highlighted and the rest faint, and a click on a move offers "run to here"
 * (toolpathDebug.ts). A lathe (as the run or the debug adapter says) is drawn as a lathe: what its
 * radial scale reads (radius or diameter) and whether the mirrored half is drawn are the user's
 * picks, kept for the next panels and sessions (the extension's global state).
 */
import { type ChildProcess, spawn } from 'node:child_process';
import * as path from 'node:path';
import * as vscode from 'vscode';
import { programDocument } from './commands';
import type { ServerController } from './languageClient';
import { cncmacroCommand, serverEnvironment, serverLayout } from './serverProcess';
import * as settings from './settings';
import {
  formatNumber,
  latheAxesOf,
  parseRunResult,
  type Plane,
  PLANES,
  plot,
  RADIAL_SCALES,
  type RadialScale,
  type RunMove,
  type RunResult,
  viewFor,
} from './toolpathGeometry';
import { type DebugPath, type DebugPathListener, DebugPaths, pausedMoves } from './toolpathDebug';
import { MAX_DRAWN_MOVES, nonce, type Texts, toolpathHtml } from './toolpathView';

const VIEW_TYPE = 'cncMacro.toolpath';
const MAX_OUTPUT_BYTES = 256 * 1024 * 1024; // a run that prints more is stopped
const EDIT_QUIET_MS = 800; // an edit is drawn once typing pauses this long
// a lathe's picks, kept in the extension's global state
const RADIAL_SCALE_KEY = 'cncMacro.toolpath.radialScale';
const BOTH_HALVES_KEY = 'cncMacro.toolpath.bothHalves';

type Outcome = { result: RunResult } | { error: string };

class ToolpathPanel implements vscode.Disposable, DebugPathListener {
  private readonly panel: vscode.WebviewPanel;
  private readonly subscriptions: vscode.Disposable[] = [];
  private child: ChildProcess | undefined;
  private result: RunResult | undefined;
  private plane: Plane = 'XY';
  private runs = 0;
  private fromEditor = false; // the last run read the editor's text, not the file
  private disposed = false;
  private debug: DebugPath | undefined; // the paused debug session's run of this program
  private drawn: RunMove[] = []; // the moves drawn, by their index in the drawing

  constructor(
    private readonly context: vscode.ExtensionContext,
    private readonly server: ServerController,
    readonly uri: vscode.Uri,
    private editorColumn: vscode.ViewColumn,
    private readonly onDispose: () => void,
    private readonly debugPaths: DebugPaths,
  ) {
    this.panel = vscode.window.createWebviewPanel(
      VIEW_TYPE,
      vscode.l10n.t('Toolpath: {0}', path.basename(uri.fsPath)),
      { viewColumn: vscode.ViewColumn.Beside, preserveFocus: true },
      { enableScripts: true, localResourceRoots: [] },
    );
    this.subscriptions.push(
      this.panel.onDidDispose(() => this.dispose()),
      this.panel.webview.onDidReceiveMessage((m: unknown) => this.onMessage(m)),
      debugPaths.listen(this),
    );
  }

  programPath(): string {
    return this.uri.fsPath;
  }

  setDebugPath(state: DebugPath | undefined): void {
    if (state === undefined && this.debug === undefined) return;
    this.debug = state;
    this.draw();
  }

  reveal(column: vscode.ViewColumn | undefined): void {
    if (column !== undefined) this.editorColumn = column;
    this.panel.reveal(undefined, true);
  }

  /** Whether saving `uri` changes what is drawn: the program itself or a file a move came from. */
  drawsFrom(uri: vscode.Uri): boolean {
    if (uri.fsPath === this.uri.fsPath) return true;
    const folder = path.dirname(this.uri.fsPath);
    return this.result?.moves.some((m) => path.resolve(folder, m.file) === uri.fsPath) ?? false;
  }

  async refresh(): Promise<void> {
    if (this.disposed) return;
    const run = ++this.runs;
    this.child?.kill();
    this.child = undefined;
    const name = path.basename(this.uri.fsPath);
    if (this.result === undefined) {
      this.show({ status: vscode.l10n.t('Running {0} on the simulated machine…', name), statusKind: 'running' });
    }
    const python = await this.server.resolvePython(this.uri);
    if (run !== this.runs) return;
    if (!python) {
      this.show({ status: vscode.l10n.t('No Python to run the program: see the message.'), statusKind: 'error' });
      return;
    }
    const document = vscode.workspace.textDocuments.find((d) => d.uri.toString() === this.uri.toString());
    this.fromEditor = document !== undefined;
    const dialect = document ? settings.dialect(document.uri) : settings.dialect(this.uri);
    const locale = vscode.env.language.toLowerCase().startsWith('zh') ? 'zh-CN' : 'en';
    const file = this.uri.fsPath;
    const { command, args } = cncmacroCommand(python, [
      'run',
      '--no-save',
      '--json',
      '--locale',
      locale,
      '--dialect',
      dialect,
      ...(document ? ['--stdin'] : []),
      file,
    ]);
    const outcome = await this.execute(command, args, path.dirname(file), document?.getText());
    if (run !== this.runs) return; // a newer run took over
    if ('error' in outcome) {
      this.result = undefined;
      this.show({ status: outcome.error, statusKind: 'error' });
      return;
    }
    this.result = outcome.result;
    this.draw();
  }


  /** Run `command`, with `input` on its standard input (the program's text), and read its JSON. */
  private execute(command: string, args: string[], cwd: string, input?: string): Promise<Outcome> {
    return new Promise((resolve) => {
      const child = spawn(command, args, {
        cwd,
        env: serverEnvironment(serverLayout(this.context.extensionPath)),
        windowsHide: true,
      });
      this.child = child;
      child.stdin.on('error', () => undefined); // a run that ends before reading it all
      child.stdin.end(input ?? '', 'utf8');
      const out: Buffer[] = [];
      const err: Buffer[] = [];
      let size = 0;
      let tooLarge = false;
      child.stdout.on('data', (chunk: Buffer) => {
        size += chunk.length;
        if (size > MAX_OUTPUT_BYTES) {
          tooLarge = true;
          child.kill();
          return;
        }
        out.push(chunk);
      });
      child.stderr.on('data', (chunk: Buffer) => err.push(chunk));
      child.on('error', (e) => resolve({ error: vscode.l10n.t('Could not run the program: {0}', e.message) }));
      child.on('close', (code) => {
        if (this.child === child) this.child = undefined;
        if (tooLarge) {
          resolve({ error: vscode.l10n.t('The run made too many moves to draw.') });
          return;
        }
        const stderr = Buffer.concat(err).toString('utf8').trim();
        if (code !== 0 && code !== 1 && code !== 3) {
          const why = stderr || vscode.l10n.t('[exit status {0}]', String(code));
          resolve({ error: vscode.l10n.t('The run failed: {0}', why) });
          return;
        }
        const parsed = parseRunResult(Buffer.concat(out).toString('utf8'));
        resolve(typeof parsed === 'string' ? { error: vscode.l10n.t('The run failed: {0}', parsed) } : { result: parsed });
      });
    });
  }

  private source(): string {
    const name = path.basename(this.uri.fsPath);
    return this.fromEditor
      ? vscode.l10n.t("Drawn from the editor's text of {0}, unsaved changes included.", name)
      : vscode.l10n.t('Drawn from the saved file {0}.', name);
  }

  private texts(status: Texts['status'], statusKind: Texts['statusKind'], verticalAxis: string, plane: string, note?: string): Texts {
    return {
      refresh: vscode.l10n.t('Refresh'),
      fit: vscode.l10n.t('Fit'),
      source: this.source(),
      status,
      statusKind,
      note,
      hint: vscode.l10n.t('Hover over a move to see its block; click it to go to its line. Wheel: zoom; drag: pan.'),
      legend: {
        rapid: vscode.l10n.t('rapid (G00)'),
        feed: vscode.l10n.t('feed (G01)'),
        arc: vscode.l10n.t('arc (G02/G03)'),
        cycle: vscode.l10n.t('canned cycle'),
        hole: vscode.l10n.t('hole of a drilling cycle'),
        origin: vscode.l10n.t('origin (program zero)'),
        alarm: vscode.l10n.t('where the alarm stopped the tool'),
        probe: vscode.l10n.t('probe move (G31)'),
        contact: vscode.l10n.t('contact point: where the skip signal came on'),
        spindle: vscode.l10n.t('spindle axis (centre line, X0)'),
        mirror: vscode.l10n.t('the other half, mirrored'),
        centre: vscode.l10n.t('tool centre (cutter compensation G41/G42)'),
      },
      centre: {
        button: vscode.l10n.t('Tool centre'),
        tip: vscode.l10n.t("Show or hide the tool centre's path under cutter radius compensation"),
      },
      passOf: vscode.l10n.t('pass of {0}'),
      lathe: {
        radius: vscode.l10n.t('Radius'),
        diameter: vscode.l10n.t('Diameter'),
        scaleTip: vscode.l10n.t('What the X scale reads: the radius or the diameter (the drawing stays to scale)'),
        bothHalves: vscode.l10n.t('Both halves'),
        bothHalvesTip: vscode.l10n.t('Also draw the other half of the part, mirrored about the spindle axis'),
      },
      plane,
      planeButton: vscode.l10n.t('Draw the moves in this plane'),
      verticalAxis,
    };
  }

  private show(state: { status: string; statusKind: Texts['statusKind'] }): void {
    const texts = this.texts(state.status, state.statusKind, '', '');
    this.panel.webview.html = toolpathHtml(
      { cspSource: this.panel.webview.cspSource, language: vscode.env.language, texts, planes: false },
      nonce(),
    );
  }

  private draw(): void {
    const result = this.result;
    const debug = this.debug;
    if (!result && !debug) return;
    const paused = debug ? pausedMoves(result?.moves, debug) : undefined;
    const all = paused?.moves ?? result?.moves ?? [];
    const lathe = debug ? latheAxesOf(debug) : result ? latheAxesOf(result) : undefined;
    const view = viewFor(lathe, this.plane, { scale: this.radialScale(), bothHalves: this.bothHalves() });
    const moves = all.length > MAX_DRAWN_MOVES ? all.slice(0, MAX_DRAWN_MOVES) : all;
    this.drawn = moves;
    const drawn = plot(moves, view, !paused && result?.status === 'alarm');
    const status: string[][] = [];
    if (debug && paused) {
      status.push([vscode.l10n.t('Paused at {0}:{1}', path.basename(debug.file), String(debug.line))]);
      const total = debug.made > paused.done ? debug.made : paused.moves.length;
      status.push([vscode.l10n.t('{0} of {1} moves run', String(debug.made), String(total))]);
    } else if (result) {
      status.push([this.statusText(result)]);
      status.push([vscode.l10n.t('{0} blocks, {1} moves', String(result.blocks), String(result.moves.length))]);
    }
    const extents = drawn.extents.map((e) => `${e.axis} ${formatNumber(e.min)} … ${formatNumber(e.max)}`);
    const [first, ...others] = extents;
    if (moves.length > 0 && first !== undefined) {
      status.push([vscode.l10n.t('extents {0}', first), ...others]); // one item per axis
    }
    let note: string | undefined;
    if (moves.length < all.length) {
      note = vscode.l10n.t('Only the first {0} of {1} moves are drawn.', String(moves.length), String(all.length));
    } else if (moves.length === 0) {
      note = vscode.l10n.t('The run made no moves.');
    }
    const diameters = view.lathe?.scale === 'diameter';
    const plane = lathe
      ? diameters
        ? vscode.l10n.t('Lathe: {0} across (the spindle axis), {1} up, to scale; the {1} scale reads diameters.', lathe.spindle, lathe.radial)
        : vscode.l10n.t('Lathe: {0} across (the spindle axis), {1} up, to scale; the {1} scale reads radii.', lathe.spindle, lathe.radial)
      : vscode.l10n.t('The {0} plane, {1} across and {2} up, equal scales.', view.plane, view.h, view.v);
    const kind: Texts['statusKind'] = paused ? 'paused' : result ? this.statusKind(result) : 'running';
    const vertical = !lathe
      ? view.v
      : diameters
        ? vscode.l10n.t('{0} (diameter)', lathe.radial)
        : vscode.l10n.t('{0} (radius)', lathe.radial);
    const texts = this.texts(status, kind, vertical, plane, note);
    const debugPage = paused && {
      done: paused.done,
      current: paused.current,
      runTo: vscode.l10n.t('Run to here'),
      goTo: vscode.l10n.t('Go to its line'),
      legend: {
        done: vscode.l10n.t('run so far'),
        current: vscode.l10n.t("the current block's move"),
        ahead: vscode.l10n.t('still to run'),
      },
    };
    if (debugPage) texts.hint = vscode.l10n.t('Paused in the debugger: click a move to run to it (forward or back) or to go to its line.');
    if (result) texts.totals = result.cycleText; // the cycle time, as the run wrote it in the editor's language
    this.panel.webview.html = toolpathHtml(
      {
        cspSource: this.panel.webview.cspSource,
        language: vscode.env.language,
        texts,
        plot: drawn,
        moves,
        view,
        planes: !lathe,
        ...(debugPage ? { debug: debugPage } : {}),
      },
      nonce(),
    );
  }

  /** What a lathe's radial scale reads, as the user last picked (diameters, as programmed, at first). */
  private radialScale(): RadialScale {
    const kept = this.context.globalState.get<string>(RADIAL_SCALE_KEY);
    return RADIAL_SCALES.find((s) => s === kept) ?? 'diameter';
  }

  private bothHalves(): boolean {
    return this.context.globalState.get<boolean>(BOTH_HALVES_KEY) === true;
  }

  private statusKind(result: RunResult): Texts['statusKind'] {
    return result.status === 'alarm' ? 'alarm' : result.status === 'limit' ? 'limit' : 'completed';
  }

  private statusText(result: RunResult): string {
    switch (result.status) {
      case 'completed':
        return vscode.l10n.t('Completed');
      case 'alarm': {
        const a = result.alarm;
        if (!a) return vscode.l10n.t('Alarm');
        return vscode.l10n.t('Alarm {0}: {1} ({2}:{3})', String(a.number), a.message, path.basename(a.file), String(a.line));
      }
      case 'limit':
        return vscode.l10n.t('Stopped: the block budget ran out (an endless loop?)');
      default:
        return result.status;
    }
  }

  private onMessage(message: unknown): void {
    if (message === null || typeof message !== 'object') return;
    const m = message as { type?: unknown; index?: unknown; plane?: unknown; value?: unknown };
    if (m.type === 'refresh') {
      void this.refresh();
    } else if (m.type === 'plane' && typeof m.plane === 'string' && (PLANES as readonly string[]).includes(m.plane)) {
      this.plane = m.plane as Plane;
      this.draw();
    } else if (m.type === 'radialScale' && typeof m.value === 'string') {
      const scale = RADIAL_SCALES.find((s) => s === m.value);
      if (scale) void this.context.globalState.update(RADIAL_SCALE_KEY, scale).then(() => this.draw());
    } else if (m.type === 'bothHalves') {
      void this.context.globalState.update(BOTH_HALVES_KEY, !this.bothHalves()).then(() => this.draw());
    } else if (m.type === 'reveal' && typeof m.index === 'number') {
      void this.revealMove(m.index);
    } else if (m.type === 'runTo' && typeof m.index === 'number' && this.debug) {
      void this.debugPaths.runTo(this.debug.session, m.index);
    }
  }

  /** Open the file a move was made in at its line, in the editor column the program was in. */
  private async revealMove(index: number): Promise<void> {
    const move = this.drawn[index];
    if (!move) return;
    const uri = vscode.Uri.file(path.resolve(path.dirname(this.uri.fsPath), move.file));
    try {
      const document = await vscode.workspace.openTextDocument(uri);
      const line = Math.min(Math.max(move.line - 1, 0), Math.max(document.lineCount - 1, 0));
      const visible = vscode.window.visibleTextEditors.find((e) => e.document.uri.toString() === uri.toString());
      const position = new vscode.Position(line, 0);
      await vscode.window.showTextDocument(document, {
        viewColumn: visible?.viewColumn ?? this.editorColumn,
        selection: new vscode.Selection(position, position),
        preserveFocus: false,
      });
      const editor = vscode.window.activeTextEditor;
      editor?.revealRange(new vscode.Range(position, position), vscode.TextEditorRevealType.InCenterIfOutsideViewport);
    } catch (e) {
      void vscode.window.showErrorMessage(vscode.l10n.t('Could not open {0}: {1}', uri.fsPath, (e as Error).message));
    }
  }

  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.runs++;
    this.child?.kill();
    this.child = undefined;
    for (const s of this.subscriptions.splice(0)) s.dispose();
    this.panel.dispose();
    this.onDispose();
  }
}

async function showToolpath(
  context: vscode.ExtensionContext,
  server: ServerController,
  panels: Map<string, ToolpathPanel>,
  debugPaths: DebugPaths,
  uri?: vscode.Uri,
): Promise<void> {
  const editor = vscode.window.activeTextEditor;
  const document = await programDocument(uri, vscode.l10n.t('Open a CNC macro program to draw its toolpath.'));
  if (!document) {
    return;
  }
  const column = editor?.document === document ? editor.viewColumn : undefined;
  const key = document.uri.toString();
  let panel = panels.get(key);
  if (panel) {
    panel.reveal(column);
  } else {
    panel = new ToolpathPanel(context, server, document.uri, column ?? vscode.ViewColumn.One, () => panels.delete(key), debugPaths);
    panels.set(key, panel);
  }
  await panel.refresh();
}

export function registerToolpath(context: vscode.ExtensionContext, server: ServerController): void {
  const panels = new Map<string, ToolpathPanel>();
  const debugPaths = new DebugPaths();
  const pending = new Map<ToolpathPanel, NodeJS.Timeout>();
  /** Draw again the panels `document` feeds, `delayMs` after the last such event; an edit only
   * redraws the panel of the edited program (a called program is read from its file). */
  const redraw = (document: vscode.TextDocument, delayMs: number, ownOnly = false): void => {
    for (const panel of panels.values()) {
      if (ownOnly ? panel.uri.toString() !== document.uri.toString() : !panel.drawsFrom(document.uri)) continue;
      clearTimeout(pending.get(panel));
      pending.set(
        panel,
        setTimeout(() => {
          pending.delete(panel);
          void panel.refresh();
        }, delayMs),
      );
    }
  };
  context.subscriptions.push(
    vscode.commands.registerCommand('cncMacro.showToolpath', (uri?: vscode.Uri) =>
      showToolpath(context, server, panels, debugPaths, uri instanceof vscode.Uri ? uri : undefined),
    ),
    vscode.workspace.onDidSaveTextDocument((document) => redraw(document, 150)),
    vscode.workspace.onDidChangeTextDocument((e) => {
      if (e.contentChanges.length > 0) redraw(e.document, EDIT_QUIET_MS, true);
    }),
    {
      dispose: () => {
        for (const timer of pending.values()) clearTimeout(timer);
        for (const panel of [...panels.values()]) panel.dispose();
      },
    },
    debugPaths,
  );
}
