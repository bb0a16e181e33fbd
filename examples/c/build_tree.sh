#!/usr/bin/env bash
# The C example built from the build tree, right after `make build`, with the documented
# command (docs/install.md): pkg-config finds build/udmap-uninstalled.pc. Runs it and checks
# that it prints blade A's F_lim and three backbone points.
# Usage: build_tree.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
export PKG_CONFIG_PATH=$build
test "$(pkg-config --variable=libdir udmap)" = "$build/kernel"
cc -O2 -Wall -Wextra -Werror -std=c99 "$src/examples/c/backbone.c" -o "$tmp/backbone" \
  $(pkg-config --cflags --libs udmap) -Wl,-rpath,$(pkg-config --variable=libdir udmap)
"$tmp/backbone" > "$tmp/out.txt"
cat "$tmp/out.txt"
grep -q '^F_lim = 2\.16' "$tmp/out.txt"
test "$(grep -c '^[0-9]' "$tmp/out.txt")" -eq 3
