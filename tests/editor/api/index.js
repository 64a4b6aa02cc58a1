/**
 * Extension-host tests: run inside the real VS Code (code-server) through the `payload` URL's
 * extensionTestsPath, against the installed .vsix, with the real `vscode` API. Each test logs
 * "PASS name" or "FAIL name: why" to the console (the driver collects them); run() throws when
 * one failed, which the workbench reports as exit code 1.
 */
const assert = require('node:assert/strict');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const vscode = require('vscode');

const EXTENSION_ID = 'cncmacro.cncmacro';

function workspaceFile(name) {
  const folder = vscode.workspace.workspaceFolders?.[0];
  assert.ok(folder, 'a workspace folder is open');
  return vscode.Uri.file(path.join(folder.uri.fsPath, name));
}

async function waitFor(what, probe, timeoutMs = 30000) {
  const end = Date.now() + timeoutMs;
  for (;;) {
    const value = await probe();
    if (value) return value;
    if (Date.now() > end) throw new Error(`timed out waiting for ${what}`);
    await new Promise((r) => setTimeout(r, 200));
  }
}

const codeOf = (d) => (typeof d.code === 'object' && d.code !== null ? d.code.value : d.code);

const tests = {
  async 'the extension activates when a program opens'() {
    await vscode.workspace.openTextDocument(workspaceFile('O9100.nc'));
    const ext = vscode.extensions.getExtension(EXTENSION_ID);
    assert.ok(ext, `${EXTENSION_ID} is installed`);
    await waitFor('activation', () => ext.isActive, 20000);
  },

  async 'a .NC file, an O1234 file and a file starting with % are CNC macro programs'() {
    for (const name of ['UPPER.NC', 'O1234', 'o2345', 'PART_WITH_TAPE_MARK']) {
      const doc = await vscode.workspace.openTextDocument(workspaceFile(name));
      assert.equal(doc.languageId, 'cnc-macro', `language of ${name}`);
    }
    const text = await vscode.workspace.openTextDocument(workspaceFile('notes.txt'));
    assert.equal(text.languageId, 'plaintext', 'a .txt file stays plain text');
  },

  async 'the commands are registered'() {
    const all = await vscode.commands.getCommands(true);
    for (const id of ['cncMacro.runProgram', 'cncMacro.selectDialect', 'cncMacro.restartServer', 'cncMacro.showToolpath']) {
      assert.ok(all.includes(id), `${id} is registered`);
    }
  },

  async 'Show Toolpath opens one panel per file and reuses it when run again'() {
    const toolpaths = () =>
      vscode.window.tabGroups.all
        .flatMap((g) => g.tabs)
        .filter((t) => t.input instanceof vscode.TabInputWebview && t.input.viewType.endsWith('cncMacro.toolpath'));
    const before = toolpaths().length;
    for (const name of ['bolt_circle.nc', 'while_loop.nc', 'bolt_circle.nc']) {
      await vscode.commands.executeCommand('cncMacro.showToolpath', workspaceFile(name));
    }
    const opened = toolpaths().slice(before);
    assert.deepEqual(opened.map((t) => t.label).sort(), ['Toolpath: bolt_circle.nc', 'Toolpath: while_loop.nc']);
    await vscode.window.tabGroups.close(opened);
  },

  async 'the planted GOTO 99 is reported as undefined-label'() {
    const uri = workspaceFile('planted_goto.nc');
    await vscode.window.showTextDocument(await vscode.workspace.openTextDocument(uri));
    const found = await waitFor('the undefined-label diagnostic', () =>
      vscode.languages.getDiagnostics(uri).find((d) => codeOf(d) === 'undefined-label'),
    );
    assert.equal(found.range.start.line, 6, 'on the IF..GOTO 99 line');
    assert.equal(found.severity, vscode.DiagnosticSeverity.Error);
    assert.match(found.message, /N99/);
    const all = vscode.languages.getDiagnostics(uri).filter((d) => codeOf(d) === 'undefined-label');
    assert.equal(all.length, 1, 'reported once');
  },

  async 'cncMacro.diagnostics.severity reaches the server'() {
    const uri = workspaceFile('planted_goto.nc');
    const all = (severity) => () => {
      const found = vscode.languages.getDiagnostics(uri).filter((d) => codeOf(d) === 'undefined-label');
      return found.length > 0 && found.every((d) => d.severity === severity);
    };
    const config = vscode.workspace.getConfiguration('cncMacro');
    await config.update('diagnostics.severity', { 'undefined-label': 'warning' }, vscode.ConfigurationTarget.Workspace);
    try {
      await waitFor('undefined-label to become a warning', all(vscode.DiagnosticSeverity.Warning));
    } finally {
      await config.update('diagnostics.severity', undefined, vscode.ConfigurationTarget.Workspace);
    }
    await waitFor('undefined-label to be an error again', all(vscode.DiagnosticSeverity.Error));
  },

  async 'cncMacro.analysis.maxBlocks is the budget of each analysis run'() {
    const uri = workspaceFile('long_loop.nc');
    await vscode.window.showTextDocument(await vscode.workspace.openTextDocument(uri));
    const runLimit = () => vscode.languages.getDiagnostics(uri).some((d) => codeOf(d) === 'run-limit');
    const config = vscode.workspace.getConfiguration('cncMacro');
    await config.update('analysis.maxBlocks', 1000, vscode.ConfigurationTarget.Workspace);
    try {
      await waitFor('run-limit with a budget of 1,000 blocks for a 9,000-block loop', runLimit);
    } finally {
      await config.update('analysis.maxBlocks', undefined, vscode.ConfigurationTarget.Workspace);
    }
    await waitFor('run-limit to go with the default budget', () => !runLimit());
  },

  async 'hovering #5001 shows its documentation'() {
    const uri = workspaceFile('O9100.nc');
    const doc = await vscode.workspace.openTextDocument(uri);
    const offset = doc.getText().indexOf('#5001');
    assert.ok(offset >= 0, 'O9100.nc reads #5001');
    const position = doc.positionAt(offset + 2);
    const text = await waitFor('a hover', async () => {
      const hovers = await vscode.commands.executeCommand('vscode.executeHoverProvider', uri, position);
      const all = (hovers ?? [])
        .flatMap((h) => h.contents)
        .map((c) => (typeof c === 'string' ? c : c.value))
        .join('\n');
      return all.includes('5001') ? all : undefined;
    });
    assert.match(text, /block end position/i);
  },

  async 'a Python that does not run is reported; clearing it and Restart Server bring the server back'() {
    const uri = workspaceFile('O9100.nc');
    const doc = await vscode.workspace.openTextDocument(uri);
    const position = doc.positionAt(doc.getText().indexOf('#5001') + 2);
    const hoverText = async () => {
      const hovers = await vscode.commands.executeCommand('vscode.executeHoverProvider', uri, position);
      return (hovers ?? []).flatMap((h) => h.contents).map((c) => (typeof c === 'string' ? c : c.value)).join('\n');
    };
    const config = vscode.workspace.getConfiguration('cncMacro');
    await config.update('python.path', '/nonexistent/python3', vscode.ConfigurationTarget.Workspace);
    try {
      await waitFor('the server to stop answering', async () => !(await hoverText()).includes('5001'));
    } finally {
      await config.update('python.path', undefined, vscode.ConfigurationTarget.Workspace);
    }
    await waitFor('the server to answer again', async () => (await hoverText()).includes('5001'));
    await vscode.commands.executeCommand('cncMacro.restartServer');
    await waitFor('the restarted server to answer', async () => (await hoverText()).includes('block end position'));
  },

  async "with cncMacro.python.path empty, the interpreter picked in the Python extension runs the server"() {
    const standIn = vscode.extensions.getExtension('ms-python.python');
    assert.ok(standIn, 'the Python extension stand-in is installed');
    const pythonExtension = standIn.isActive ? standIn.exports : await standIn.activate();
    const config = vscode.workspace.getConfiguration('cncMacro');
    const bare = config.get('python.path'); // the test machine's Python without packages
    assert.ok(bare, 'the machine setting names a Python');
    // Two interpreters that note each run in a log file, then run that Python. The extension
    // runs the one it finds to ask its version and executable, then starts the server with it.
    const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-pick-'));
    const wrapper = (name) => {
      const file = path.join(dir, name);
      fs.writeFileSync(file, `#!/bin/sh\necho "$*" >> "${file}.log"\nexec "${bare}" "$@"\n`, { mode: 0o755 });
      return file;
    };
    const first = wrapper('first-python');
    const second = wrapper('second-python');
    const runs = (file) => (fs.existsSync(`${file}.log`) ? fs.readFileSync(`${file}.log`, 'utf8').split('\n').length - 1 : 0);
    const uri = workspaceFile('O9100.nc');
    const doc = await vscode.workspace.openTextDocument(uri);
    const position = doc.positionAt(doc.getText().indexOf('#5001') + 2);
    const answers = async () => {
      const hovers = await vscode.commands.executeCommand('vscode.executeHoverProvider', uri, position);
      return (hovers ?? []).some((h) => h.contents.some((c) => (typeof c === 'string' ? c : c.value).includes('5001')));
    };
    pythonExtension.selectForTest(first);
    await config.update('python.path', '', vscode.ConfigurationTarget.Workspace);
    try {
      await waitFor('the Python extension\'s interpreter to be asked', () => runs(first) > 0, 60000);
      await waitFor('that server to answer', answers);
      pythonExtension.selectForTest(second); // the user picks another interpreter there
      await waitFor('a restart with the newly picked interpreter', () => runs(second) > 0, 60000);
      await waitFor('the restarted server to answer', answers);
    } finally {
      await config.update('python.path', undefined, vscode.ConfigurationTarget.Workspace);
    }
    await waitFor('the server to answer with the set interpreter', answers);
    const before = runs(first);
    pythonExtension.selectForTest(first); // the setting wins again: no restart with this one
    await new Promise((r) => setTimeout(r, 1500));
    assert.equal(runs(first), before, 'a pick in the Python extension is ignored while cncMacro.python.path is set');
    await waitFor('the server to answer with the set interpreter', answers);
  },
};

async function run() {
  let failed = 0;
  for (const [name, test] of Object.entries(tests)) {
    try {
      await test();
      console.log(`PASS ${name}`);
    } catch (e) {
      failed += 1;
      console.log(`FAIL ${name}: ${e && e.stack ? e.stack : e}`);
    }
  }
  if (failed) {
    throw new Error(`${failed} extension-host test(s) failed`);
  }
}

module.exports = { run };
