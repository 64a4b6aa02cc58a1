// A DAP client for the tests: @vscode/debugadapter-testsupport's DebugClient, starting
// `.venv/bin/python -m cncmacro dap` from the repository root (or the interpreter named by
// CNCMACRO_TEST_PYTHON, when the suite is run again under another Python), and a few scenario helpers.
'use strict';

const cp = require('node:child_process');
const path = require('node:path');
const { DebugClient } = require('@vscode/debugadapter-testsupport');

const ROOT = path.resolve(__dirname, '..', '..');
const PYTHON = process.env.CNCMACRO_TEST_PYTHON || path.join(ROOT, '.venv', 'bin', 'python');
const PROGRAMS = path.join(__dirname, 'programs');

function program(name) {
  return path.join(PROGRAMS, name);
}

class CncMacroClient extends DebugClient {
  constructor() {
    super(PYTHON, '-m', 'cncmacro');
    // the library waits 5 s for an event; starting Python takes longer than that on a machine
    // busy with make test's other lanes. A wait that times out is still a failure.
    this.defaultTimeout = 30000;
    this.output = '';
    this.on('output', (e) => { this.output += e.body.output; });
  }

  // DebugClient spawns `runtime executable`; the adapter needs `python -m cncmacro dap`.
  start() {
    return new Promise((resolve, reject) => {
      this._adapterProcess = cp.spawn(PYTHON, ['-m', 'cncmacro', 'dap'], { cwd: ROOT });
      this._adapterProcess.on('error', reject);
      this._adapterProcess.stderr.on('data', (data) => process.stderr.write(data));
      this.connect(this._adapterProcess.stdout, this._adapterProcess.stdin);
      resolve();
    });
  }

  // initialize, set the breakpoints, configurationDone and launch; resolves with the first stop
  // (or terminated event) and the initialize response.
  async begin(launchArgs, { breakpoints = {}, functionBreakpoints, filters, locale, until = 'stopped' } = {}) {
    const initialized = this.waitForEvent('initialized');
    const first = this.waitForEvent(until);
    const init = await this.initializeRequest({
      adapterID: 'cnc-macro', linesStartAt1: true, columnsStartAt1: true, pathFormat: 'path', locale,
    });
    await initialized;
    const verified = {};
    for (const [file, specs] of Object.entries(breakpoints)) {
      const response = await this.setBreakpointsRequest({ source: { path: program(file) }, breakpoints: specs });
      verified[file] = response.body.breakpoints;
    }
    if (functionBreakpoints) {
      await this.setFunctionBreakpointsRequest({ breakpoints: functionBreakpoints.map((name) => ({ name })) });
    }
    if (filters) {
      await this.setExceptionBreakpointsRequest({ filters });
    }
    await this.configurationDoneRequest();
    await this.launchRequest({ noSave: true, ...launchArgs });
    return { event: await first, init, verified };
  }

  async top() {
    const trace = await this.stackTraceRequest({ threadId: 1 });
    return trace.body.stackFrames[0];
  }

  async value(expression, frameId) {
    const response = await this.evaluateRequest({ expression, context: 'watch', frameId });
    return response.body.result;
  }

  // Send a stepping request and wait for the stop it ends with.
  async step(request, args = { threadId: 1 }) {
    const stopped = this.waitForEvent('stopped');
    await this[request](args);
    return stopped;
  }

  async scopeVariables(frameId, scopeName) {
    const scopes = (await this.scopesRequest({ frameId })).body.scopes;
    const scope = scopes.find((s) => s.name.startsWith(scopeName));
    if (!scope) throw new Error(`no scope ${scopeName} in ${scopes.map((s) => s.name)}`);
    const response = await this.variablesRequest({ variablesReference: scope.variablesReference });
    return { scope, variables: response.body.variables };
  }

  // The row named `name` in a scope, opening the row of its hundred first in a large Common or
  // Persistent scope (`#500–#599` holds #512).
  async scopeRow(frameId, scopeName, name) {
    let { variables } = await this.scopeVariables(frameId, scopeName);
    const number = Number(name.slice(1));
    const hundred = variables.find((v) => {
      const span = /^#(\d+)–#(\d+)$/.exec(v.name);
      return span && Number(span[1]) <= number && number <= Number(span[2]);
    });
    if (hundred) {
      variables = (await this.variablesRequest({ variablesReference: hundred.variablesReference })).body.variables;
    }
    return variables.find((v) => v.name === name);
  }
}

// A client started before each test of the calling file and stopped after it. What it returns
// stands for the client of the test that runs (`dc.begin(...)`, `dc.output`); `dc.restart()`
// stops it and starts a fresh one within the test.
function clientPerTest() {
  const { afterEach, beforeEach } = require('node:test');
  let current = null;
  const restart = async () => {
    await current.stop();
    current = new CncMacroClient();
    await current.start();
  };
  beforeEach(async () => {
    current = new CncMacroClient();
    await current.start();
  });
  afterEach(async () => {
    await current.stop();
  });
  return new Proxy({}, {
    get(_, name) {
      if (name === 'restart') return restart;
      const value = current[name];
      return typeof value === 'function' ? value.bind(current) : value;
    },
    set(_, name, value) {
      current[name] = value;
      return true;
    },
  });
}

module.exports = { CncMacroClient, clientPerTest, program, PROGRAMS, PYTHON, ROOT };
