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

setup: $(VENV)/.installed node_modules/.installed tests/node_modules/.installed

# Run a bundled example on the simulated machine, then check all of them (needs only Python).
demo: $(VENV)/.installed
	@echo "--- Running examples/fanuc/bolt_circle.nc on the simulated machine:"
	@$(VENV)/bin/cncmacro run --no-save examples/fanuc/bolt_circle.nc
	@echo "--- Checking every program in examples/:"
	@$(VENV)/bin/cncmacro check examples && echo "examples: no problems found"
	@echo "--- Checking tests/data/O0999_broken.nc, a program with three planted mistakes:"
	@$(VENV)/bin/cncmacro check tests/data/O0999_broken.nc || echo "(cncmacro check exits with status 1 when it finds mistakes)"

# Every test: lint, the Python suite (then part of it again under the oldest and the newest
# Python on the machine, tests/other_pythons.py), the debug adapter through a real DAP client, the
# toolpath's plot on real runs, the grammar,
# then the .vsix is built and tested in a real VS Code (screenshots in test-output/editor/).
test: setup
	$(VENV)/bin/ruff check server tests benchmarks
	$(VENV)/bin/ruff format --check server tests benchmarks
	$(VENV)/bin/mypy
	npm run --silent lint:client
	$(PY) -m pytest
	$(PY) tests/other_pythons.py --quick
	node --test tests/dap/ tests/client/
	npm run --silent test:grammar
	PYTHON=$(PY) npm run --silent package
	timeout 900 node --test --test-concurrency=1 tests/editor/

# The everyday loop (docs/development.md): lint, types, the Python suite but its slow parts (the
# language server over stdio, the hardening storms; both run in make test) and the toolpath's plot.
check: $(VENV)/.installed node_modules/.installed
	$(VENV)/bin/ruff check server tests benchmarks
	$(VENV)/bin/ruff format --check server tests benchmarks
	$(VENV)/bin/mypy
	$(PY) -m pytest -x --ignore=tests/lsp --ignore=tests/hardening
	node --test tests/client/

# The VS Code extension: cncmacro.vsix (needs only Python >= 3.10 where it is installed). Building
# it needs Python with pip and `npm ci`, none of the test stack.
package: node_modules/.installed
	PYTHON=$(PYTHON) npm run --silent package

# The pictures of the README (docs/images/), taken in a real VS Code by the editor tests.
screenshots: setup
	PYTHON=$(PY) npm run --silent package
	timeout 600 npm run --silent screenshots
