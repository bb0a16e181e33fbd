# The README commands: make demo, make test (and build, bench, deps).
# Each installs what is missing first, so a fresh Debian 12 machine needs nothing else.
PYTHON ?= python3
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
APT_PACKAGES := gfortran liblapack-dev libblas-dev libarpack2-dev pkg-config valgrind calculix-ccx
PY_PACKAGES := numpy scipy matplotlib fmpy pytest wheel dask distributed
export PYTHONPATH := $(CURDIR)/wrappers/python$(if $(PYTHONPATH),:$(PYTHONPATH))
export PIP_BREAK_SYSTEM_PACKAGES := 1
export PIP_DISABLE_PIP_VERSION_CHECK := 1

.PHONY: all deps build test demo bench clean

all: build

deps:
	@missing=""; for p in $(APT_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" != 0 ]; then echo "deps: missing Debian packages:$$missing (run as root or install them)"; exit 1; fi; \
	  echo "deps: installing$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi
	@missing=""; for p in $(PY_PACKAGES); do \
	  $(PYTHON) -c "import $$p" 2>/dev/null || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then echo "deps: pip installing$$missing"; $(PYTHON) -m pip install -q $$missing; fi

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=$$(command -v $(PYTHON))
	cmake --build $(BUILD) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

demo: build
	$(PYTHON) -m udmap demo

# make bench UDMAP_BENCH_DTI=1 also runs the time integration of bench/bench_model_error.py
# (a few minutes more; its numbers are kept in docs/bench/model_error_dti.json for the README)
bench: build
	$(PYTHON) bench/run.py

clean:
	rm -rf $(BUILD) out
