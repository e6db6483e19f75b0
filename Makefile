# runout: the README's two commands are `make demo` and `make test`.
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
export MPLBACKEND ?= Agg

.PHONY: install demo test lint typecheck pytest bench docs clean latest

$(STAMP): pyproject.toml constraints.txt
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	# the tested versions of every dependency (constraints.txt), so results do not move with a release
	$(BIN)/python -m pip install --quiet -c constraints.txt -e '.[dev,dask,docs,data]'
	# compile every model's kernels into numba's cache now, so that no first command waits
	$(BIN)/runout warm || echo "warning: warming the kernel cache failed"
	touch $(STAMP)

install: $(STAMP)

# ROSS (the rotor extra: about 45 packages) for the test that builds a ROSS bearing element from
# runout's coefficients; the suite needs it, `make demo` does not
ROTOR_STAMP := $(VENV)/.installed-rotor
$(ROTOR_STAMP): $(STAMP)
	$(BIN)/python -m pip install --quiet -c constraints.txt -e '.[rotor]'
	touch $(ROTOR_STAMP)

lint: install
	$(BIN)/ruff check src tests benchmarks examples docs_hooks
	$(BIN)/ruff format --check src tests benchmarks examples docs_hooks
	# the layer contract of the stage packages (pyproject.toml [tool.importlinter])
	$(BIN)/lint-imports

typecheck: install
	$(BIN)/mypy

pytest: install $(ROTOR_STAMP)
	$(BIN)/pytest

test: lint typecheck pytest

demo: install
	$(BIN)/python examples/demo.py

bench: install
	$(BIN)/python benchmarks/run.py

# The documentation site (out/site): getting started, concepts, case-file reference (generated
# from the schema), one theory page per model, validation, benchmarks, API reference.
docs: install
	$(BIN)/python -m runout.case.schema_doc > docs/case-file.md
	$(BIN)/python -m runout.case.conventions > docs/conventions.md
	$(BIN)/python -m runout.base.glossary > docs/glossary.md
	$(BIN)/python docs_hooks/build.py out/site

# The suite against the newest releases pyproject.toml allows (not the pinned constraints.txt),
# in its own environment and kernel cache.
latest:
	test -x .venv-latest/bin/python || $(PYTHON) -m venv .venv-latest
	.venv-latest/bin/python -m pip install --quiet --upgrade -e '.[dev,dask,docs,data,rotor]'
	NUMBA_CACHE_DIR=$(CURDIR)/.venv-latest/numba-cache .venv-latest/bin/runout warm
	NUMBA_CACHE_DIR=$(CURDIR)/.venv-latest/numba-cache .venv-latest/bin/pytest

clean:
	rm -rf $(VENV) .venv-latest out .pytest_cache .mypy_cache .ruff_cache
