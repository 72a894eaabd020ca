# Every target sets itself up: a local virtual environment, created once and refreshed only when
# pyproject.toml changes (the stamp file), so repeated runs are fast and silent.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed

.PHONY: derive verify test test-slow bench bench-peers docs clean setup

setup: $(STAMP)

$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	@$(PY) -m pip install -q --disable-pip-version-check -e '.[test]'
	@touch $(STAMP)

derive: $(STAMP)
	@$(PY) -m derive generate --verify

verify: $(STAMP)
	@$(PY) -m derive verify

# One test process per core (pytest-xdist): the suite is many independent compiles and runs;
# an idle process takes tests queued for the other (worksteal), so the last few long tests do
# not leave a core waiting. Bytecode caches are kept even where the environment turns them off:
# the suite starts many Python processes, and each would compile the package and its tests again.
test: $(STAMP)
	@PYTHONDONTWRITEBYTECODE= $(PY) -m pytest -q -n auto --dist worksteal

test-slow: $(STAMP)
	@$(PY) -m pytest -q -m slow

bench: $(STAMP)
	@$(PY) -m derive bench -o bench-out

# The API reference from the docstrings (numpydoc style), warning-free: docs/api/_build/html.
docs: $(STAMP)
	@$(PY) -m sphinx -W -q -b html docs/api docs/api/_build/html
	@echo "API reference: docs/api/_build/html/index.html"

# The same bench with the peers installed (the optional extras: CasADi, PyDy, heyoka, numbalsoda;
# MuJoCo for the tippe top) and raced. numbalsoda needs a Fortran compiler to build: without one, the others are installed
# and the bench says numbalsoda was not raced.
bench-peers: $(STAMP)
	@$(PY) -m pip install -q --disable-pip-version-check -e '.[test,peers,contact-peers]' 2>/dev/null \
		|| { echo "numbalsoda did not build (a Fortran compiler?): racing the other peers"; \
		     $(PY) -m pip install -q --disable-pip-version-check "casadi>=3.6" "pydy>=0.7" "cython>=3.0" \
		     "heyoka>=6.0" "mujoco>=3.0"; }
	@$(PY) -m derive bench -o bench-out

# The compile cache (DERIVE_CACHE, default ~/.cache/derive) is emptied through the tool itself,
# which removes only the libraries it put there; without the venv there is nothing to ask.
clean:
	@if [ -x $(PY) ]; then $(PY) -m derive cache --clear || true; fi
	rm -rf $(VENV) bench-out docs/api/_build .pytest_cache .hypothesis *.egg-info
	find . -name __pycache__ -type d -prune -exec rm -rf {} +
