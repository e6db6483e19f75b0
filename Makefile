# runout: the README's two commands are `make demo` and `make test`.
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
export MPLBACKEND ?= Agg

.PHONY: install demo test lint typecheck pytest bench docs clean

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet -e '.[dev,dask,docs,data]'
	# compile every model's kernels into numba's cache now, so that no first command waits
	$(BIN)/python -m runout._warm examples || echo "warning: warming the kernel cache failed"
	touch $(STAMP)

install: $(STAMP)

lint: install
	$(BIN)/ruff check src tests benchmarks examples docs_hooks
	$(BIN)/ruff format --check src tests benchmarks examples docs_hooks

typecheck: install
	$(BIN)/mypy

pytest: install
	$(BIN)/pytest

test: lint typecheck pytest

demo: install
	$(BIN)/python examples/demo.py

bench: install
	$(BIN)/python benchmarks/run.py

# The documentation site (out/site): getting started, concepts, case-file reference (generated
# from the schema), one theory page per model, validation, benchmarks, API reference.
docs: install
	$(BIN)/python -m runout.schema_doc > docs/case-file.md
	$(BIN)/python -m runout.conventions > docs/conventions.md
	$(BIN)/python -m runout.glossary > docs/glossary.md
	$(BIN)/python docs_hooks/build.py out/site

clean:
	rm -rf $(VENV) out .pytest_cache .mypy_cache .ruff_cache
