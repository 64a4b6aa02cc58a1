# The two commands of the README. Both set up a virtual environment in .venv on first use.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python

.PHONY: demo test setup

$(VENV)/.installed: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test]'
	touch $@

# The DAP client tests' npm packages (pinned in package-lock.json), installed again only when it changes.
node_modules/.installed: package-lock.json
	npm ci --silent --no-audit --no-fund
	touch $@

setup: $(VENV)/.installed node_modules/.installed

# Run a bundled example on the simulated machine, then check all of them.
demo: setup
	$(VENV)/bin/cncmacro run --no-save examples/fanuc/bolt_circle.nc
	$(VENV)/bin/cncmacro check examples && echo "examples: no problems found"
	@echo "--- a program with mistakes:"
	-$(VENV)/bin/cncmacro check tests/data/O0999_broken.nc

# Every test: lint, then the Python suite, then the debug adapter through a real DAP client.
test: setup
	$(VENV)/bin/ruff check server tests benchmarks
	$(PY) -m pytest
	node --test tests/dap/
