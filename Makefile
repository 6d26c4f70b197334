# Everything runs inside .venv, created and filled on first use from nothing but python3.
PYTHON ?= python3
VENV := .venv
VPY := $(VENV)/bin/python
STAMP := $(VENV)/.installed-stamp
BENCH_STAMP := $(VENV)/.bench-stamp
DOCS_STAMP := $(VENV)/.docs-stamp
export PYTHONHASHSEED := 0

.PHONY: derive test bench figures atlas docs explore clean-venv

$(STAMP): pyproject.toml constraints.txt
	test -x $(VPY) || $(PYTHON) -m venv $(VENV)
	$(VPY) -m pip install --quiet -c constraints.txt -e '.[derive,test,map,explore]'
	touch $(STAMP)

## make derive: re-derive every result with sympy and rewrite generated/ (kernels + DERIVATION.md)
derive: $(STAMP)
	$(VPY) -m derive --out generated

## make test: run the test suite (derivation up-to-date check, kernels vs paper and vs mpmath)
test: $(STAMP)
	$(VPY) -m pytest -q

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
	@echo "docs: open docs/_build/html/index.html"

## make explore: the interactive explorer on an open port of 127.0.0.1 (prints the URL; Ctrl-C stops it)
explore: $(STAMP)
	$(VENV)/bin/jkrcyl explore

clean-venv:
	rm -rf $(VENV)
