# pyadore: `make run` and `make test` work on a fresh machine (see README).
SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
.DEFAULT_GOAL := help

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.pyadore-installed
CONSTRAINTS := constraints.txt
NATIVE := build/native
DEBUG  := build/debug
ADORE  := $(NATIVE)/adore
DECK   := decks/appendix_c_ball.inp
OUT    := out/appendix_c_ball.prt
# Engine unit-test executables (meson targets) that `make test` builds and pytest runs.
ENGINE_TESTS := test_deck_text test_deck_reader test_model test_life test_print test_tribology test_roller test_cage test_roller_traction test_traction_law test_forces test_traction_fast test_integrator test_dynamics test_cage_contacts test_cage_whirl test_bearing_system
# Build tools (meson, ninja, f2py) are taken from the venv, never from the system.
VPATH_ENV := PATH="$(CURDIR)/$(VENV)/bin:$$PATH"
# the run loop's bookkeeping (time averages, time history rows; issue #20)
ENGINE_TESTS += test_run_loop
# the thermal model's physics modules (issue #27)
ENGINE_TESTS += test_thermal test_thermal_transient
# the roller bearing's dynamics (issue #26)
ENGINE_TESTS += test_roller_dynamics
# the mixed-film traction of model 3 (issue #28)
ENGINE_TESTS += test_mixed_film

.PHONY: help setup gfortran run test bench debug clean distclean exe

help:
	@echo "make run      set up, run $(DECK), write $(OUT)"
	@echo "make test     set up, run the test suite (Python and engine tests)"
	@echo "make bench    set up, run the benchmarks in bench/"
	@echo "make debug    build the engine with run-time checks and run the suite against it"
	@echo "make setup    install gfortran if missing, create $(VENV), install pyadore into it"
	@echo "make clean    remove build/ and out/   (make distclean also removes $(VENV))"

# gfortran from Debian's packages, installed only when missing.
gfortran:
	@if ! command -v gfortran >/dev/null 2>&1; then \
	  echo "gfortran not found: installing it with apt-get (Debian package gfortran)"; \
	  if [ "$$(id -u)" = 0 ]; then SUDO=""; \
	  elif command -v sudo >/dev/null 2>&1; then SUDO="sudo"; \
	  else echo "error: gfortran is missing and apt-get needs root; install gfortran yourself" >&2; exit 1; fi; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq gfortran >/dev/null \
	    || { echo "error: 'apt-get install gfortran' failed; install gfortran yourself" >&2; exit 1; }; \
	  command -v gfortran >/dev/null || { echo "error: gfortran still not on PATH" >&2; exit 1; }; \
	fi

# The venv is rebuilt when the build description or the pinned versions change; editable
# installs rebuild the engine extensions by themselves when Fortran sources change.
# $(CONSTRAINTS) pins every package's version, so a fresh machine (and CI) installs the set
# the suite was run with.  The install also builds pyadore._probes (meson option probes),
# the test-only extension the tests use.
$(STAMP): pyproject.toml meson.build meson.options $(CONSTRAINTS) | gfortran
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(VPATH_ENV) $(PY) -m pip install -q --disable-pip-version-check -c $(CONSTRAINTS) "meson-python>=0.15" "meson>=1.1" ninja "numpy>=2.0"
	$(VPATH_ENV) $(PY) -m pip install -q --disable-pip-version-check -c $(CONSTRAINTS) --no-build-isolation \
	  -Csetup-args=-Dprobes=true -e '.[test]'
	@touch $(STAMP)

setup: gfortran $(STAMP)
	@# bytecode of the package's modules: the editable install's loader never writes it, so without
	@# this every command compiles them again (30-40 ms of each start-up; docs/sweeps.md, "Start-up")
	@$(PY) -m compileall -q pyadore

# Standalone executable: same sources, same meson.build, its own build directory.
exe: setup
	@test -f $(NATIVE)/build.ninja || $(VPATH_ENV) $(VENV)/bin/meson setup $(NATIVE) --buildtype=release >/dev/null
	@# regenerate an existing build directory first, so targets new in meson.build are known
	@$(VPATH_ENV) $(VENV)/bin/ninja -C $(NATIVE) build.ninja >/dev/null
	@$(VPATH_ENV) $(VENV)/bin/meson compile -C $(NATIVE) adore $(ENGINE_TESTS) >/dev/null

run: exe
	@mkdir -p out
	$(VENV)/bin/pyadore run $(DECK) -o $(OUT)

test: exe
	ADORE_EXE=$(CURDIR)/$(ADORE) ADORE_BUILD_DIR=$(CURDIR)/$(NATIVE) $(PY) -m pytest

debug: setup
	@test -f $(DEBUG)/build.ninja || $(VPATH_ENV) $(VENV)/bin/meson setup $(DEBUG) --buildtype=debug -Dchecks=true >/dev/null
	@$(VPATH_ENV) $(VENV)/bin/ninja -C $(DEBUG) build.ninja >/dev/null
	@$(VPATH_ENV) $(VENV)/bin/meson compile -C $(DEBUG) adore $(ENGINE_TESTS) >/dev/null
	ADORE_EXE=$(CURDIR)/$(DEBUG)/adore ADORE_BUILD_DIR=$(CURDIR)/$(DEBUG) $(PY) -m pytest

bench: exe
	ADORE_EXE=$(CURDIR)/$(ADORE) $(PY) bench/run_bench.py

clean:
	rm -rf build out $(STAMP)

distclean: clean
	rm -rf $(VENV)
