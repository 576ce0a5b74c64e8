#!/bin/sh
# An installed copy works from any directory: `cmake --install` into a temporary prefix, then,
# from /, `list`, `figure schaefer95-fig3 --scale quick` and `check`, with the data files found
# next to the installed binary (not in the source tree, not through $GRANREPRO_HOME).
# Usage: install_test.sh BUILD_DIR
set -eu
build=$1
prefix=$(mktemp -d "${TMPDIR:-/tmp}/granrepro-install.XXXXXX")
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > "$prefix.log" 2>&1 || { cat "$prefix.log"; rm -f "$prefix.log"; exit 1; }
rm -f "$prefix.log"
bin=$prefix/bin/granrepro
cd /
unset GRANREPRO_HOME
"$bin" --version | grep -qx "data: $prefix/share/granrepro (installed next to the binary)" ||
  { echo "install_test: the installed binary does not use $prefix/share/granrepro:"; "$bin" --version; exit 1; }
"$bin" list | grep -q "figure schaefer95-fig3" || { echo "install_test: list does not name schaefer95-fig3"; exit 1; }
"$bin" figure schaefer95-fig3 --scale quick --quiet --out "$prefix/out" > /dev/null
test -s "$prefix/out/brake-failure/schaefer95-fig3.png" || { echo "install_test: no schaefer95-fig3.png"; exit 1; }
"$bin" check brake-failure --out "$prefix/out" > /dev/null
echo "install_test: list, figure schaefer95-fig3 and check ran from / with $bin"
