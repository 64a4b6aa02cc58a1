/**
 * A stand-in for the Python extension (`ms-python.python`) in the editor tests: it offers the
 * part of that extension's API that CNC Macro reads (the active environment, resolving it, and
 * the event fired when the user picks another), and `selectForTest(path)`, which does what
 * picking an interpreter in the real extension does.
 */
const vscode = require('vscode');

function activate() {
  const changed = new vscode.EventEmitter();
  let active;
  return {
    environments: {
      getActiveEnvironmentPath: () => (active ? { id: active, path: active } : undefined),
      resolveEnvironment: async (env) => ({
        executable: { uri: vscode.Uri.file(typeof env === 'string' ? env : env.path) },
      }),
      onDidChangeActiveEnvironmentPath: changed.event,
    },
    selectForTest(path) {
      active = path;
      changed.fire({ id: path, path });
    },
  };
}

module.exports = { activate };
