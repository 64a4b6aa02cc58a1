// A throw-away code-server (the real VS Code workbench and extension host) with the built .vsix
// installed, and Debian's Chromium driving it through playwright-core. Everything lives in one
// temporary run folder (its own HOME, TMPDIR, XDG folders, user data and extensions), and
// code-server runs in its own process group, which `stop()` kills whole, so that the extension
// host, the language server and the debug adapter go with it. Nothing reaches another host: the
// extension gallery is switched off (EXTENSIONS_GALLERY names none), and so are telemetry, update
// checks and experiments; `outsideHostAttempts()` lists whatever tried all the same.
import { spawn, spawnSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const OUTPUT = path.join(ROOT, 'test-output', 'editor');
const CODE_SERVER = path.join(ROOT, 'tests', 'node_modules', '.bin', 'code-server');
const VSIX = path.join(ROOT, 'cncmacro.vsix');
const VSCE = path.join(ROOT, 'node_modules', '.bin', 'vsce');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const EXTENSION_ID = 'cncmacro.cncmacro';
/** The hosts the browser may talk to: code-server on this machine. */
const LOCAL_HOSTS = new Set(['127.0.0.1', 'localhost', '[::1]']);
/**
 * A log line of code-server or its VS Code that tried another host: the extension gallery
 * (open-vsx.org by default, or the Marketplace), an update check, or a name lookup or connection
 * that failed.
 */
const OUTSIDE_IN_LOG =
  /open-vsx|marketplace|extensionquery|update\.code|vscode-cdn|getaddrinfo|ENOTFOUND|EAI_AGAIN|ENETUNREACH|https?:\/\/(?!127\.0\.0\.1|localhost)[a-z0-9.-]+\.[a-z]{2,}\//i;
/**
 * Where the extensions each code-server starts with are installed once for all the test files
 * of a run (`installedOnce`): a folder per .vsix and stand-in, named by a digest of both.
 */
const INSTALLED = path.join(ROOT, '.cache', 'editor-extensions');
const STAND_IN = path.join(ROOT, 'tests', 'editor', 'python-extension');
/** What an installed folder's `extensions.json` says in place of the extensions folder's path. */
const PLACE = '/cncmacro-extensions-folder';
/** The browser's window: the size of the screenshots (docs/images/ takes some of them). */
export const VIEWPORT = { width: 1280, height: 800 };

function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

async function waitHealthy(url, child, timeoutMs) {
  const end = Date.now() + timeoutMs;
  while (Date.now() < end) {
    if (child.exitCode !== null) throw new Error(`code-server exited with status ${child.exitCode}`);
    try {
      const res = await fetch(`${url}/healthz`);
      if (res.ok) return;
    } catch {
      // not listening yet
    }
    await new Promise((r) => setTimeout(r, 200));
  }
  throw new Error(`code-server did not answer ${url}/healthz within ${timeoutMs / 1000} s`);
}

function copyTree(from, to) {
  fs.mkdirSync(to, { recursive: true });
  fs.cpSync(from, to, { recursive: true });
}

/** A Python with nothing installed: a fresh venv without pip and without site-packages. */
function barePython(dir) {
  const made = spawnSync('python3', ['-m', 'venv', '--without-pip', dir], { encoding: 'utf8', timeout: 60000 });
  if (made.status !== 0) throw new Error(`python3 -m venv failed: ${made.stderr}`);
  const python = path.join(dir, 'bin', 'python');
  const probe = spawnSync(python, ['-c', 'import pygls'], { encoding: 'utf8' });
  if (probe.status === 0) throw new Error('the bare venv can import pygls: the check would prove nothing');
  return python;
}

export class CodeServer {
  /** `locale`: the display language code-server gives the workbench (`--locale`), e.g. `zh-cn`. */
  constructor({ locale } = {}) {
    this.locale = locale;
    for (const [what, file] of [
      ['the .vsix (npm run package)', VSIX],
      ['code-server (npm ci)', CODE_SERVER],
      ['chromium (apt-get install chromium)', CHROMIUM],
    ]) {
      if (!fs.existsSync(file)) throw new Error(`missing ${what}: ${path.relative(ROOT, file) || file}`);
    }
    this.dir = fs.mkdtempSync(path.join(os.tmpdir(), 'cncmacro-editor-'));
    this.workspace = path.join(this.dir, 'workspace');
    this.child = undefined;
    this.context = undefined;
    this.outsideRequests = []; // the browser's requests to a host other than this machine
    this.log = path.join(OUTPUT, locale ? `code-server-${locale}.log` : 'code-server.log');
    this.onExit = () => this.killGroup('SIGKILL');
    this.onSignal = (signal) => {
      this.killGroup('SIGKILL');
      this.removeRunFolder();
      process.exit(signal === 'SIGINT' ? 130 : 143);
    };
  }

  get extensionPath() {
    return path.join(this.dir, 'extensions', `${EXTENSION_ID}-${this.version}`);
  }

  /** Workspace, settings, the extension installed from the .vsix, code-server, Chromium. */
  async start() {
    const d = (...p) => path.join(this.dir, ...p);
    for (const sub of ['home', 'tmp', 'config', 'data', 'cache', 'user-data/User', 'extensions', 'chromium']) {
      fs.mkdirSync(d(sub), { recursive: true });
    }
    copyTree(path.join(ROOT, 'examples', 'fanuc'), this.workspace);
    copyTree(path.join(ROOT, 'tests', 'editor', 'workspace'), this.workspace);
    this.python = barePython(d('bare-python'));
    this.version = JSON.parse(fs.readFileSync(path.join(ROOT, 'package.json'), 'utf8')).version;

    this.port = await freePort();
    this.url = `http://127.0.0.1:${this.port}`;
    fs.writeFileSync(d('config.yaml'), `bind-addr: 127.0.0.1:${this.port}\nauth: none\ncert: false\n`);
    fs.writeFileSync(
      d('user-data', 'User', 'settings.json'),
      JSON.stringify(
        {
          'security.workspace.trust.enabled': false,
          'workbench.startupEditor': 'none',
          'workbench.tips.enabled': false,
          'workbench.enableExperiments': false,
          'update.mode': 'none',
          'extensions.autoUpdate': false,
          'extensions.autoCheckUpdates': false,
          'extensions.ignoreRecommendations': true,
          'telemetry.telemetryLevel': 'off',
          'editor.minimap.enabled': false,
          'editor.hover.delay': 200,
          'chat.commandCenter.enabled': false,
          'window.restoreWindows': 'none',
          'files.autoSave': 'off', // the web workbench saves after a second by default; desktop VS Code does not
        },
        null,
        2,
      ),
    );
    // The interpreter is a setting of the machine the extension host runs on (code-server's
    // Machine settings): the web client's own user settings do not carry it.
    fs.mkdirSync(d('user-data', 'Machine'), { recursive: true });
    fs.writeFileSync(d('user-data', 'Machine', 'settings.json'), JSON.stringify({ 'cncMacro.python.path': this.python }));
    const { PYTHONPATH: _p, VSCODE_IPC_HOOK_CLI: _v, ...base } = process.env;
    this.env = {
      ...base,
      HOME: d('home'),
      TMPDIR: d('tmp'),
      XDG_CONFIG_HOME: d('config'),
      XDG_DATA_HOME: d('data'),
      XDG_CACHE_HOME: d('cache'),
      // code-server reads its gallery from here (open-vsx.org otherwise): one without a service URL is none
      EXTENSIONS_GALLERY: '{}',
    };
    const common = ['--config', d('config.yaml'), '--user-data-dir', d('user-data'), '--extensions-dir', d('extensions')];
    this.copyInstalled(this.installedOnce(), d('extensions'));
    if (!fs.existsSync(this.extensionPath)) throw new Error(`the .vsix's extension is not in ${d('extensions')}`);
    if (this.locale) this.registerDisplayLanguage(this.locale);

    const log = fs.openSync(this.log, 'w');
    this.child = spawn(
      CODE_SERVER,
      [
        ...common,
        '--disable-telemetry',
        '--disable-update-check',
        '--disable-workspace-trust',
        ...(this.locale ? ['--locale', this.locale] : []),
        this.workspace,
      ],
      { env: this.env, detached: true, stdio: ['ignore', log, log] },
    );
    fs.closeSync(log);
    process.on('exit', this.onExit);
    process.once('SIGTERM', this.onSignal);
    process.once('SIGINT', this.onSignal);
    await waitHealthy(this.url, this.child, 60000);

    this.context = await chromium.launchPersistentContext(d('chromium'), {
      executablePath: CHROMIUM,
      headless: true,
      viewport: VIEWPORT,
      env: this.env,
      timeout: 60000,
      args: [
        '--no-sandbox',
        '--disable-gpu',
        '--disable-quic',
        '--no-first-run',
        '--disable-background-networking',
        '--disable-component-update',
        '--disable-sync',
      ],
    });
    this.context.on('request', (request) => {
      const url = new URL(request.url());
      if (/^(https?|wss?):$/.test(url.protocol) && !LOCAL_HOSTS.has(url.hostname)) {
        this.outsideRequests.push(`browser: ${request.method()} ${request.url()}`);
      }
    });
  }

  /**
   * What tried to reach a host other than this machine so far: the browser's requests, and the
   * lines of code-server's log and of its VS Code's logs (the run folder's user data) that name
   * the gallery, an update check or a failed lookup or connection.
   */
  outsideHostAttempts() {
    const logs = [this.log];
    const walk = (dir) => {
      for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
        const file = path.join(dir, entry.name);
        if (entry.isDirectory()) walk(file);
        else if (entry.name.endsWith('.log')) logs.push(file);
      }
    };
    const logsDir = path.join(this.dir, 'user-data', 'logs');
    if (fs.existsSync(logsDir)) walk(logsDir);
    const lines = logs.flatMap((file) =>
      fs
        .readFileSync(file, 'utf8')
        .split('\n')
        .filter((line) => OUTSIDE_IN_LOG.test(line))
        .map((line) => `${path.basename(file)}: ${line.trim().slice(0, 300)}`),
    );
    return [...this.outsideRequests, ...lines];
  }

  /**
   * The stand-in for the Python extension (`tests/editor/python-extension`), packaged and
   * installed beside CNC Macro, so that a test can pick an interpreter "in the Python extension".
   */
  /**
   * The extensions folder code-server's own `--install-extension` makes from the .vsix and the
   * Python extension's stand-in, made by the first test file of a run that needs it and taken
   * by the others (four processes and about 4 s of CPU a file saved). Two files starting
   * together may both make it; the one that renames its folder into place second uses the
   * first's. Folders of other .vsix files are removed.
   */
  installedOnce() {
    const digest = createHash('sha256').update(fs.readFileSync(VSIX));
    for (const name of fs.readdirSync(STAND_IN).sort()) {
      const file = path.join(STAND_IN, name);
      if (fs.statSync(file).isFile()) digest.update(name).update(fs.readFileSync(file));
    }
    const key = digest.digest('hex').slice(0, 16);
    const done = path.join(INSTALLED, key);
    if (fs.existsSync(path.join(done, 'extensions.json'))) return done;
    fs.mkdirSync(INSTALLED, { recursive: true });
    for (const old of fs.readdirSync(INSTALLED)) {
      const at = path.join(INSTALLED, old);
      // another .vsix's, or one a test file that was stopped left half made
      const made = fs.statSync(at, { throwIfNoEntry: false }); // gone already: another test file's, done
      const left = old.startsWith('making-') ? made !== undefined && Date.now() - made.mtimeMs > 600000 : old !== key;
      if (left) fs.rmSync(at, { recursive: true, force: true });
    }
    const making = fs.mkdtempSync(path.join(INSTALLED, 'making-'));
    try {
      const common = ['--config', path.join(this.dir, 'config.yaml'), '--user-data-dir', path.join(making, 'user-data'),
        '--extensions-dir', path.join(making, 'extensions')];
      const installed = spawnSync(CODE_SERVER, [...common, '--install-extension', VSIX], {
        env: this.env,
        encoding: 'utf8',
        timeout: 120000,
      });
      if (installed.status !== 0 || !fs.existsSync(path.join(making, 'extensions', `${EXTENSION_ID}-${this.version}`))) {
        throw new Error(`installing the .vsix failed: ${installed.stdout}\n${installed.stderr}`);
      }
      this.installStandIn(common, path.join(making, 'python-extension.vsix'));
      const list = path.join(making, 'extensions', 'extensions.json');
      fs.writeFileSync(list, fs.readFileSync(list, 'utf8').split(path.join(making, 'extensions')).join(PLACE));
      try {
        fs.renameSync(path.join(making, 'extensions'), done);
      } catch (err) {
        if (!fs.existsSync(path.join(done, 'extensions.json'))) throw err;
      }
    } finally {
      fs.rmSync(making, { recursive: true, force: true });
    }
    return done;
  }

  /**
   * A copy of an installed extensions folder at `to`: its `extensions.json` names each extension
   * by its absolute place, kept there as `PLACE` and written out as `to`.
   */
  copyInstalled(from, to) {
    fs.cpSync(from, to, { recursive: true });
    const list = path.join(to, 'extensions.json');
    fs.writeFileSync(list, fs.readFileSync(list, 'utf8').split(PLACE).join(to));
  }

  installStandIn(common, vsix) {
    const packaged = spawnSync(
      VSCE,
      ['package', '--no-dependencies', '--allow-missing-repository', '--skip-license', '-o', vsix],
      { cwd: path.join(ROOT, 'tests', 'editor', 'python-extension'), encoding: 'utf8', timeout: 60000 },
    );
    if (packaged.status !== 0) throw new Error(`packaging the Python extension stand-in failed: ${packaged.stderr}`);
    const installed = spawnSync(CODE_SERVER, [...common, '--install-extension', vsix], {
      env: this.env,
      encoding: 'utf8',
      timeout: 120000,
    });
    if (installed.status !== 0) throw new Error(`installing the stand-in failed: ${installed.stdout}\n${installed.stderr}`);
  }

  /**
   * code-server honours `--locale` only for a display language that a language pack registered
   * in the user data's `languagepacks.json`; no language pack can be downloaded here. This entry
   * points to an empty translation file: the workbench's own texts stay English (their fallback),
   * while VS Code runs in `locale`, so extensions get their strings for it (`package.nls.zh-cn.json`,
   * `l10n/bundle.l10n.zh-cn.json`) and `vscode.env.language` — what a user with the language pack
   * sees of CNC Macro.
   */
  registerDisplayLanguage(locale) {
    const translation = path.join(this.dir, 'display-language', 'main.i18n.json');
    fs.mkdirSync(path.dirname(translation), { recursive: true });
    fs.writeFileSync(translation, JSON.stringify({ version: '1.0.0', contents: {} }));
    const pack = {
      hash: 'cncmacro-tests',
      extensions: [{ extensionIdentifier: { id: 'cncmacro-tests.display-language' }, version: '0.0.1' }],
      translations: { vscode: translation },
      label: locale,
    };
    fs.writeFileSync(path.join(this.dir, 'user-data', 'languagepacks.json'), JSON.stringify({ [locale]: pack }));
  }

  /** The workbench on the test workspace. */
  async openWorkbench() {
    const page = await this.context.newPage();
    await page.goto(`${this.url}/?folder=${encodeURIComponent(this.workspace)}`);
    await page.locator('.monaco-workbench').waitFor({ timeout: 60000 });
    await page.locator('.explorer-folders-view .monaco-list-row').first().waitFor({ timeout: 60000 });
    return page;
  }

  /**
   * Run `api/index.js` in the extension host through the payload URL, with the installed
   * extension as the development extension; resolves with the exit code and console lines.
   */
  async runExtensionTests(timeoutMs) {
    const page = await this.context.newPage();
    const lines = [];
    page.on('console', (message) => lines.push(message.text()));
    const remote = (p) => `vscode-remote://127.0.0.1:${this.port}${p}`;
    const payload = [
      ['extensionDevelopmentPath', remote(this.extensionPath)],
      ['extensionTestsPath', remote(path.join(ROOT, 'tests', 'editor', 'api', 'index.js'))],
    ];
    let timer;
    const exit = new Promise((resolve, reject) => {
      page.exposeFunction('codeAutomationExit', (code) => resolve(code)).catch(reject);
      timer = setTimeout(() => reject(new Error('the extension-host tests did not finish in time')), timeoutMs);
    });
    await page.goto(
      `${this.url}/?folder=${encodeURIComponent(this.workspace)}&payload=${encodeURIComponent(JSON.stringify(payload))}`,
    );
    try {
      const code = await exit;
      return { code, lines, page };
    } finally {
      clearTimeout(timer);
    }
  }

  killGroup(signal) {
    if (this.child?.pid === undefined) return;
    try {
      process.kill(-this.child.pid, signal);
    } catch {
      // already gone
    }
  }

  /** Close Chromium, kill code-server's whole process group, remove the run folder. */
  async stop() {
    if (this.context) {
      await Promise.race([this.context.close(), new Promise((r) => setTimeout(r, 10000))]).catch(() => undefined);
    }
    if (this.child) {
      this.killGroup('SIGTERM');
      const gone = new Promise((r) => (this.child.exitCode !== null ? r() : this.child.once('exit', r)));
      await Promise.race([gone, new Promise((r) => setTimeout(r, 5000))]);
      this.killGroup('SIGKILL');
      process.off('exit', this.onExit);
      process.off('SIGTERM', this.onSignal);
      process.off('SIGINT', this.onSignal);
    }
    this.removeRunFolder();
  }

  /** The run folder goes unless CNCMACRO_KEEP_EDITOR_RUN is set (to read its logs). */
  removeRunFolder() {
    if (!process.env.CNCMACRO_KEEP_EDITOR_RUN) fs.rmSync(this.dir, { recursive: true, force: true, maxRetries: 3 });
  }
}

/**
 * A code-server for one test file, its workbench open in Chromium: `prepare(server)` first writes
 * the file's own programs into `server.workspace`; `timeout` is the page's default wait (ms).
 */
export async function startWorkbench({ locale, prepare, timeout = 20000 } = {}) {
  fs.mkdirSync(OUTPUT, { recursive: true });
  const server = new CodeServer({ locale });
  await server.start();
  await prepare?.(server);
  const page = await server.openWorkbench();
  page.setDefaultTimeout(timeout);
  return { server, page };
}

/**
 * A screenshot of `page` as test-output/editor/`name`.png once `settle` ms have let hovers and
 * panels fade in; also docs/images/`docs`.png when CNCMACRO_README_PICTURES is set
 * (`npm run screenshots`).
 */
export async function screenshot(page, name, { docs, settle = 300 } = {}) {
  if (settle) await page.waitForTimeout(settle);
  const file = path.join(OUTPUT, `${name}.png`);
  await page.screenshot({ path: file });
  if (docs && process.env.CNCMACRO_README_PICTURES) {
    fs.mkdirSync(path.join(ROOT, 'docs', 'images'), { recursive: true });
    fs.copyFileSync(file, path.join(ROOT, 'docs', 'images', `${docs}.png`));
  }
}
