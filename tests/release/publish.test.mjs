// The release workflow's publish steps, run here as the workflow runs them: each `run:` line of
// .github/workflows/release.yml that publishes is taken from the file and run word for word, from
// the repository with the .vsix and the Python package that `make test` built, against stand-ins
// of the VS Code Marketplace, Open VSX and PyPI on 127.0.0.1. Only the address differs from a real
// release: vsce reads VSCE_MARKETPLACE_URL, ovsx OVSX_REGISTRY_URL, twine TWINE_REPOSITORY_URL.
// The tools are the pinned ones of package-lock.json, so this runs with the network cut off.
//
// Needs `make package` (cncmacro.vsix) and the release check (.cache/dist): make test runs this
// file right after both.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { createServer } from 'node:http';
import { existsSync, readFileSync, readdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import yaml from 'js-yaml';

const root = resolve(fileURLToPath(new URL('../..', import.meta.url)));
const vsixPath = join(root, 'cncmacro.vsix');
const distDir = join(root, process.env.CNCMACRO_DIST ?? '.cache/dist');
const python = process.env.PYTHON ?? join(root, '.venv', 'bin', 'python');
const workflow = yaml.load(readFileSync(join(root, '.github/workflows/release.yml'), 'utf8'));
const manifest = JSON.parse(readFileSync(join(root, 'package.json'), 'utf8'));

/** The one step of `job` that runs `tool publish` (the tool pinned with @version or not). */
function publishStep(job, tool) {
    const command = new RegExp(`\\b${tool}(@[0-9.]+)? publish\\b`);
    const steps = workflow.jobs[job].steps.filter((step) => command.test(step.run ?? ''));
    assert.equal(steps.length, 1, `release.yml job ${job} has one step that runs ${tool} publish`);
    return steps[0];
}

/** Runs a workflow step's run line under bash, from the repository, as a runner would. */
function runStep(step, env) {
    return new Promise((done) => {
        const child = spawn('bash', ['-eo', 'pipefail', '-c', step.run], {
            cwd: root,
            env: { ...process.env, ...env },
            stdio: ['ignore', 'pipe', 'pipe'],
        });
        let output = '';
        child.stdout.on('data', (chunk) => (output += chunk));
        child.stderr.on('data', (chunk) => (output += chunk));
        const timer = setTimeout(() => child.kill('SIGKILL'), 120_000);
        child.on('close', (code) => {
            clearTimeout(timer);
            done({ code, output });
        });
    });
}

/** A local HTTP server whose `handle(request, body)` answers [status, json]; it records requests. */
async function standIn(handle) {
    const requests = [];
    const server = createServer((request, response) => {
        const chunks = [];
        request.on('data', (chunk) => chunks.push(chunk));
        request.on('end', () => {
            const body = Buffer.concat(chunks);
            requests.push({ method: request.method, url: request.url, headers: request.headers, body });
            const [status, json] = handle(request, body);
            const text = json === undefined ? '' : JSON.stringify(json);
            response.writeHead(status, { 'Content-Type': 'application/json' });
            response.end(text);
        });
    });
    await new Promise((ready) => server.listen(0, '127.0.0.1', ready));
    const { port } = server.address();
    return { url: `http://127.0.0.1:${port}`, requests, close: () => server.close() };
}

before(() => {
    assert.ok(existsSync(vsixPath), 'cncmacro.vsix is built (make package) before this test');
    assert.ok(existsSync(distDir), `${distDir} holds the Python package (the release check builds it)`);
});

// The Marketplace's gallery API as vsce 3 reaches it: a location lookup, then the extension's
// versions, then the upload (a new extension is created; a known one is updated).
const GET_EXTENSION = 'e11ea35a-16fe-4b80-ab11-c4cab88a0966';
const CREATE_EXTENSION = 'a41192c8-9525-4b58-bc86-179fa549d80d';

function marketplace(publishedVersions) {
    return standIn((request) => {
        if (request.method === 'OPTIONS') {
            const location = (id, routeTemplate) => ({
                id, area: 'gallery', resourceName: 'extensions', routeTemplate,
                minVersion: '1.0', maxVersion: '7.2', releasedVersion: '7.1', resourceVersion: 2,
            });
            return [200, { count: 2, value: [
                location(GET_EXTENSION, '_apis/gallery/publishers/{publisherName}/extensions/{extensionName}'),
                location(CREATE_EXTENSION, '_apis/gallery/extensions'),
            ] }];
        }
        if (request.method === 'GET') {
            if (publishedVersions.length === 0) {
                return [404, { message: 'not found' }];
            }
            return [200, { extensionName: manifest.name, versions: publishedVersions.map((version) => ({ version })) }];
        }
        return [200, { extensionName: manifest.name, versions: [{ version: manifest.version }] }];
    });
}

test('vsce publish, as release.yml runs it, uploads the built .vsix with the VSCE_PAT secret', async () => {
    const step = publishStep('marketplace', 'vsce');
    assert.deepEqual(Object.keys(step.env), ['VSCE_PAT'], 'the token reaches vsce as VSCE_PAT');
    const server = await marketplace([]);
    try {
        const { code, output } = await runStep(step, { VSCE_PAT: 'marketplace-token', VSCE_MARKETPLACE_URL: server.url });
        assert.equal(code, 0, output);
        const uploads = server.requests.filter((r) => r.method === 'POST');
        assert.equal(uploads.length, 1, output);
        assert.ok(uploads[0].body.equals(readFileSync(vsixPath)), 'the upload is cncmacro.vsix, byte for byte');
        const basic = Buffer.from('OAuth:marketplace-token').toString('base64');
        assert.equal(uploads[0].headers.authorization, `Basic ${basic}`);
        assert.match(output, new RegExp(`Published ${manifest.publisher}\\.${manifest.name} v${manifest.version}`));
    } finally {
        server.close();
    }
});

test('vsce publish run again on a version the Marketplace has skips it and succeeds (a re-run release)', async () => {
    const step = publishStep('marketplace', 'vsce');
    const server = await marketplace([manifest.version]);
    try {
        const { code, output } = await runStep(step, { VSCE_PAT: 'marketplace-token', VSCE_MARKETPLACE_URL: server.url });
        assert.equal(code, 0, output);
        assert.equal(server.requests.filter((r) => r.method === 'POST' || r.method === 'PUT').length, 0);
        assert.match(output, /already published/);
    } finally {
        server.close();
    }
});

test('vsce publish with a token the Marketplace refuses fails the release job', async () => {
    const step = publishStep('marketplace', 'vsce');
    const server = await standIn((request) => (request.method === 'OPTIONS' ? [401, { message: 'Access denied' }] : [401, { message: 'Access denied' }]));
    try {
        const { code } = await runStep(step, { VSCE_PAT: 'expired', VSCE_MARKETPLACE_URL: server.url });
        assert.notEqual(code, 0);
    } finally {
        server.close();
    }
});

// Open VSX as ovsx reaches it: the registry's version, then one upload to /api/-/publish.
function openVsx(alreadyPublished) {
    return standIn((request) => {
        if (request.method === 'GET' && request.url.startsWith('/api/version')) {
            return [200, { version: '0.9.0' }];
        }
        if (request.method === 'POST' && request.url.startsWith('/api/-/publish')) {
            if (alreadyPublished) {
                return [400, { error: `${manifest.publisher}.${manifest.name} ${manifest.version} is already published.` }];
            }
            return [201, { namespace: manifest.publisher, name: manifest.name, version: manifest.version, targetPlatform: 'universal' }];
        }
        return [404, { error: 'not found' }];
    });
}

test('ovsx publish, as release.yml runs it, uploads the built .vsix with the OVSX_PAT secret', async () => {
    const step = publishStep('open-vsx', 'ovsx');
    assert.deepEqual(Object.keys(step.env), ['OVSX_PAT']);
    const server = await openVsx(false);
    try {
        const { code, output } = await runStep(step, { OVSX_PAT: 'open-vsx-token', OVSX_REGISTRY_URL: server.url });
        assert.equal(code, 0, output);
        const uploads = server.requests.filter((r) => r.method === 'POST');
        assert.equal(uploads.length, 1, output);
        assert.ok(uploads[0].body.equals(readFileSync(vsixPath)), 'the upload is cncmacro.vsix, byte for byte');
        const tokenSent = uploads[0].headers.authorization === 'Bearer open-vsx-token'
            || new URL(uploads[0].url, server.url).searchParams.get('token') === 'open-vsx-token';
        assert.ok(tokenSent, 'the token travels with the upload');
        assert.match(output, new RegExp(`Published ${manifest.publisher}\\.${manifest.name} v${manifest.version}`));
    } finally {
        server.close();
    }
});

test('ovsx publish run again on a version Open VSX has skips it and succeeds (a re-run release)', async () => {
    const step = publishStep('open-vsx', 'ovsx');
    const server = await openVsx(true);
    try {
        const { code, output } = await runStep(step, { OVSX_PAT: 'open-vsx-token', OVSX_REGISTRY_URL: server.url });
        assert.equal(code, 0, output);
        assert.match(output, /already published\. Skipping publish/);
    } finally {
        server.close();
    }
});

// PyPI: the publish action uploads dist/ with twine; the same upload, against a stand-in of the
// upload endpoint, proves that the files the release builds are ones PyPI's upload accepts.
test('the Python package the release builds uploads with twine, each file whole', async () => {
    const step = workflow.jobs.pypi.steps.find((s) => (s.uses ?? '').startsWith('pypa/gh-action-pypi-publish'));
    assert.equal(step.with['packages-dir'], 'dist/', 'the action uploads what the build job put in dist/');
    const files = readdirSync(distDir).filter((name) => name.endsWith('.whl') || name.endsWith('.tar.gz'));
    assert.equal(files.length, 2, 'a wheel and an sdist');
    const server = await standIn(() => [200, {}]);
    try {
        const upload = {
            run: `"${python}" -m twine upload --non-interactive --disable-progress-bar ${files.map((f) => JSON.stringify(join(distDir, f))).join(' ')}`,
        };
        const { code, output } = await runStep(upload, {
            TWINE_REPOSITORY_URL: `${server.url}/legacy/`, TWINE_USERNAME: '__token__', TWINE_PASSWORD: 'pypi-token',
        });
        assert.equal(code, 0, output);
        const posts = server.requests.filter((r) => r.method === 'POST');
        assert.equal(posts.length, 2, output);
        for (const [index, name] of files.entries()) {
            const post = posts.find((p) => p.body.includes(Buffer.from(`filename="${name}"`)));
            assert.ok(post, `${name} was uploaded`);
            assert.ok(post.body.includes(readFileSync(join(distDir, name))), `${name} arrived whole (${index})`);
            assert.ok(post.body.includes(Buffer.from(`name="version"\r\n\r\n${manifest.version}`)), 'with the release version');
        }
    } finally {
        server.close();
    }
});
