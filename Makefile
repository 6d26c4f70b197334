# Everything runs inside .venv, created and filled on first use from nothing but python3.
PYTHON ?= python3
VENV := .venv
VPY := $(VENV)/bin/python
STAMP := $(VENV)/.installed-stamp
BENCH_STAMP := $(VENV)/.bench-stamp
DOCS_STAMP := $(VENV)/.docs-stamp
export PYTHONHASHSEED := 0

.PHONY: derive test test-slow test-boundscheck fuzz bench figures atlas docs explore clean-venv

$(STAMP): pyproject.toml constraints.txt
	test -x $(VPY) || $(PYTHON) -m venv $(VENV)
	$(VPY) -m pip install --quiet -c constraints.txt -e '.[derive,test,map,explore]'
	touch $(STAMP)

## make derive: re-derive every result with sympy and rewrite generated/ (kernels + DERIVATION.md)
derive: $(STAMP)
	$(VPY) -m derive --out generated

# pytest on every core (at most 4: a worker can hold a few GB), long tests first-come: worksteal balances them
PYTEST := $(VPY) -m pytest -q -n auto --maxprocesses 4 --dist worksteal

## make test: the test suite without the tests marked slow (kernels vs paper and vs mpmath, properties, README,
## CLI); the same tests for everyone: hypothesis draws derandomized examples (tests/conftest.py), no CI switch
test: $(STAMP)
	$(PYTEST) -m "not slow"

## make test-slow: the slow checks (pytest -m slow: generated/ equals a fresh `make derive`, limits, fits); CI too
test-slow: $(STAMP)
	$(PYTEST) -m slow

## make test-boundscheck: the property tests with every numba kernel's indexing checked (an IndexError instead of
## a read or write out of bounds); the kernels compile into a cache of their own (numba's cache key ignores it)
test-boundscheck: $(STAMP)
	NUMBA_BOUNDSCHECK=1 NUMBA_CACHE_DIR=$(CURDIR)/$(VENV)/numba-boundscheck-cache $(PYTEST) -m "hypothesis or boundscheck"

## make fuzz: the property tests with fresh random examples, 10x as many (hypothesis profile fuzz); a failure it
## finds becomes an @example on its test (hypothesis prints it and a `git apply` patch that adds it)
fuzz: $(STAMP)
	$(PYTEST) -m hypothesis --hypothesis-profile=fuzz

$(BENCH_STAMP): $(STAMP)
	$(VPY) -m pip install --quiet -c constraints.txt -e '.[derive,test,map,bench]'
	touch $(BENCH_STAMP)

## make bench: time the full state (n = 1e6) against lambdify, numpy, mpmath, quad and a floor
bench: $(BENCH_STAMP)
	$(VPY) benchmarks/bench_state.py

## make figures: draw the paper's Figures 2-12 (PNG, PDF, CSV) into figures/
figures: $(STAMP)
	$(VENV)/bin/jkrcyl figures --out figures

## make atlas: regime atlas over (M, vartheta), 1000 x 1000 + vartheta = inf, into atlas/ (npz, CSV, PNG, PDF)
atlas: $(STAMP)
	$(VENV)/bin/jkrcyl atlas --out atlas

$(DOCS_STAMP): $(STAMP)
	$(VPY) -m pip install --quiet -c constraints.txt -e '.[derive,test,map,explore,docs]'
	touch $(DOCS_STAMP)

## make docs: the Sphinx site (guide, gallery executed, theory, API reference) into docs/_build/html; -W: a warning fails
docs: $(DOCS_STAMP)
	MPLBACKEND=Agg $(VPY) -m sphinx -W --keep-going -q -b html docs docs/_build/html
	@! grep -rl --include=*.html "cdn.jsdelivr.net" docs/_build/html || (echo "docs: a page loads MathJax from a CDN" && false)
	@echo "docs: open docs/_build/html/index.html"

## make explore: the interactive explorer on an open port of 127.0.0.1 (prints the URL; Ctrl-C stops it)
explore: $(STAMP)
	$(VENV)/bin/jkrcyl explore

clean-venv:
	rm -rf $(VENV)
