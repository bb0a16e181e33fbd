#!/usr/bin/env bash
# Builds the package as `pip install .` does: a wheel, in pip's isolated build environment
# (only build-system.requires from PyPI, no numpy), from a copy of the source tree without its
# build products. Fails if the build fails or the wheel lacks the library or either FMU.
# Usage: pip_wheel_isolated.sh SOURCE_DIR PYTHON
set -euo pipefail
src=$1; py=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# the tracked files only (as a fresh clone has them), so that no local build/ leaks in
mkdir -p "$tmp/src"
(cd "$src" && git ls-files -z --cached --others --exclude-standard | xargs -0 cp --parents -t "$tmp/src")
unset PYTHONPATH UDMAP_LIBRARY UDMAP_BUILD_DIR UDMAP_PREFIX
start=$(date +%s)
PIP_DISABLE_PIP_VERSION_CHECK=1 "$py" -m pip wheel -q --no-deps --wheel-dir "$tmp/dist" "$tmp/src"
echo "pip wheel (isolated build) took $(( $(date +%s) - start )) s"
wheel=$(ls "$tmp"/dist/udmap-*.whl)
"$py" - "$wheel" <<'PYEOF'
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
need = ["udmap/libudmap.so", "udmap/fmu/udmap.fmu", "udmap/fmu/udmap-fmi3.fmu", "udmap/_capi.py",
        "udmap/parameters.py", "udmap/case/schema.py", "udmap/doe/run.py", "udmap/cli/__init__.py"]
missing = [n for n in need if n not in names]
if missing:
    sys.exit(f"pip_wheel_isolated: the wheel lacks {missing}")
print(f"pip_wheel_isolated: {sys.argv[1].rsplit('/', 1)[-1]} holds the library, both FMUs and "
      f"the package ({len(names)} files)")
PYEOF
