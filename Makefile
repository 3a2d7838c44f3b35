# Set-up and everyday commands. Every target creates .venv and installs the package on a fresh machine.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
# pytest-xdist workers of `make test` and `make test-slow` (two cores: two workers; a single file run by hand is serial).
WORKERS ?= 2

.PHONY: demo test test-slow test-ross bench static-check skidding skidding-map cage-models clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[test]'
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/bearing-mbs run scenarios/seed_hss_startup.toml --out out/demo --overwrite

# With workers, tests/conftest.py first compiles the engines' kernels once, in two processes (tests/warm_cache.py), and a
# test module's tests stay on one worker (its module-scoped fixtures run once).
test: $(STAMP)
	$(BIN)/python -m pytest -q -n $(WORKERS) --dist loadscope

test-slow: $(STAMP)
	$(BIN)/python -m pytest -q -m slow -n $(WORKERS) --dist loadscope

# The ROSS comparisons (docs/fluid-film.md; ROSS's own tests are skipped by `make test`), in their own environment: ROSS 2.3 pins plotly<6 and brings its own stack.
test-ross:
	$(PYTHON) -m venv .venv-ross
	.venv-ross/bin/pip install --quiet --upgrade pip
	.venv-ross/bin/pip install --quiet -e '.[test,ross]'
	.venv-ross/bin/python -m pytest -q -p no:cacheprovider tests/test_ross_adapter.py tests/test_ross_fluid_flow.py \
		tests/test_ross_plain_journal.py

bench: $(STAMP)
	$(BIN)/python benchmarks/run_all.py

# The studies of docs/quasistatic.md, docs/skidding.md and docs/cage-models.md (--out docs/figures --overwrite redraws the docs').
static-check: $(STAMP)
	$(BIN)/bearing-mbs static-check scenarios/static_check.toml --out out/static_check --overwrite

skidding: $(STAMP)
	$(BIN)/bearing-mbs skidding scenarios/seed_hss_steady.toml --out out/skidding --overwrite \
		--set scenario.variant=dry --set scenario.end_time=0.3 --set analysis.start=0.1

skidding-map: $(STAMP)
	$(BIN)/bearing-mbs skidding-map scenarios/seed_hss_steady.toml --out out/skidding_map --overwrite \
		--minimum-load 4000,9000

cage-models: $(STAMP)
	$(BIN)/bearing-mbs cage-models scenarios/cage_models.toml --out out/cage_models --overwrite

clean:
	rm -rf $(VENV) out .pytest_cache
