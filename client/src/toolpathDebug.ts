/**
 * The toolpath view and the debugger: while a `cnc-macro` debug session is paused, the panel of
 * the program it runs draws the moves run so far, the move of the block the run stands on
 * (highlighted) and the rest of the run faint. Each stop (a step, step back, a breakpoint, "run
 * to here") asks the debug adapter for the run's `toolpath` (a custom DAP request, answered from
 * the paused machine) and hands it to the panel; the end of the session takes it away. "Run to
 * here" on a move sends the adapter `runToMove` with the move's number, and the adapter decides
 * where that is, forward or back.
 */
import * as path from 'node:path';
import * as vscode from 'vscode';
import { DEBUG_TYPE } from './debugAdapter';
import { type LatheAxes, parseLatheAxes, parseRunResult, type RunMove } from './toolpathGeometry';
import { MAX_DRAWN_MOVES } from './toolpathView';

/** What the paused run says of its toolpath (the adapter's `toolpath` response). */
export interface DebugPath {
  session: vscode.DebugSession;
  moves: RunMove[]; // run so far (the first MAX_DRAWN_MOVES of them)
  made: number; // the moves run so far, all of them
  current: RunMove[]; // made by the block the run stands on, not run yet
  file: string;
  line: number;
  lathe: boolean | undefined; // whether the machine is a lathe, and its axes (`lathe_axes`), as the adapter says
  latheAxes: LatheAxes | undefined;
}

/** Whoever draws a program's toolpath: the panels, by the program's path. */
export interface DebugPathListener {
  programPath(): string;
  setDebugPath(state: DebugPath | undefined): void;
}

function programOf(session: vscode.DebugSession): string | undefined {
  const program: unknown = session.configuration.program;
  return typeof program === 'string' ? path.resolve(program) : undefined;
}

/** The adapter's `toolpath` body read with the run's own checks; undefined when it is malformed. */
function readBody(session: vscode.DebugSession, body: unknown): DebugPath | undefined {
  if (body === null || typeof body !== 'object') return undefined;
  const b = body as Record<string, unknown>;
  const done = parseRunResult(JSON.stringify({ status: 'paused', moves: b.moves }));
  const current = parseRunResult(JSON.stringify({ status: 'paused', moves: b.current }));
  if (typeof done === 'string' || typeof current === 'string') return undefined;
  return {
    session,
    moves: done.moves,
    made: typeof b.made === 'number' ? b.made : done.moves.length,
    current: current.moves,
    file: typeof b.file === 'string' ? b.file : '',
    line: typeof b.line === 'number' ? b.line : 0,
    lathe: typeof b.lathe === 'boolean' ? b.lathe : undefined,
    latheAxes: parseLatheAxes(b.lathe_axes),
  };
}

export class DebugPaths implements vscode.Disposable {
  private readonly paused = new Map<string, DebugPath>(); // by session id
  private readonly listeners = new Set<DebugPathListener>();
  private readonly subscriptions: vscode.Disposable[] = [];
  private asked = 0;

  constructor() {
    this.subscriptions.push(
      vscode.debug.registerDebugAdapterTrackerFactory(DEBUG_TYPE, {
        createDebugAdapterTracker: (session) => ({
          onDidSendMessage: (message: unknown) => {
            const m = message as { type?: unknown; event?: unknown };
            if (m.type === 'event' && m.event === 'stopped') void this.stopped(session);
          },
        }),
      }),
      vscode.debug.onDidTerminateDebugSession((session) => this.ended(session)),
    );
  }

  /** A panel to keep up to date; it gets the paused state at once when there is one. */
  listen(listener: DebugPathListener): vscode.Disposable {
    this.listeners.add(listener);
    for (const state of this.paused.values()) {
      if (programOf(state.session) === path.resolve(listener.programPath())) listener.setDebugPath(state);
    }
    return { dispose: () => this.listeners.delete(listener) };
  }

  /** Ask the session to run to move `index` of the run (forward or back, the adapter decides). */
  async runTo(session: vscode.DebugSession, index: number): Promise<void> {
    try {
      await session.customRequest('runToMove', { index });
    } catch (e) {
      void vscode.window.showErrorMessage(vscode.l10n.t('Could not run to the move: {0}', (e as Error).message));
    }
  }

  private async stopped(session: vscode.DebugSession): Promise<void> {
    const program = programOf(session);
    const asked = ++this.asked;
    let state: DebugPath | undefined;
    try {
      state = readBody(session, await session.customRequest('toolpath', { limit: MAX_DRAWN_MOVES }));
    } catch {
      state = undefined; // the session ended meanwhile, or the run went on
    }
    if (asked !== this.asked || !state) return; // a newer stop is being asked about
    this.paused.set(session.id, state);
    for (const listener of this.listeners) {
      if (program === path.resolve(listener.programPath())) listener.setDebugPath(state);
    }
  }

  private ended(session: vscode.DebugSession): void {
    if (!this.paused.delete(session.id)) return;
    const program = programOf(session);
    for (const listener of this.listeners) {
      if (program === path.resolve(listener.programPath())) listener.setDebugPath(undefined);
    }
  }

  dispose(): void {
    for (const s of this.subscriptions.splice(0)) s.dispose();
    this.listeners.clear();
    this.paused.clear();
  }
}

/** The moves to draw while paused: those run so far, the current block's, and the rest of the
 * whole run (`full`, from `cncmacro run`) when its start is the run so far (the same program and
 * path); `done` and `current` count the first two parts, so a move's index is its number in the run. */
export function pausedMoves(full: RunMove[] | undefined, state: DebugPath): { moves: RunMove[]; done: number; current: number } {
  if (state.made > state.moves.length) return { moves: state.moves, done: state.moves.length, current: 0 }; // beyond what is drawn
  const known = [...state.moves, ...state.current];
  const same = (a: RunMove, b: RunMove): boolean =>
    a.line === b.line && a.mode === b.mode && path.basename(a.file) === path.basename(b.file) &&
    Object.entries(a.to).every(([k, v]) => Math.abs((b.to[k] ?? 0) - v) < 1e-6);
  const follows = full !== undefined && full.length >= known.length && known.every((m, i) => { const f = full[i]; return f !== undefined && same(m, f); });
  const ahead = follows && full ? full.slice(known.length) : [];
  return { moves: [...known, ...ahead], done: state.moves.length, current: state.current.length };
}
