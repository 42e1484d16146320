#!/usr/bin/env bash
# The installed C++ package (docs/api.md#cmake): installs BUILD into a fresh prefix, configures and
# builds examples/cpp against it with find_package(symmesh) in a separate CMake run, runs it, and
# compares with the CLI: the same cell counts as `generate --report` and the same .vtu bytes. The
# installed library must load the Gmsh module from the prefix, and the installed Python package
# must import from it.
# Usage: test_install.sh BUILD_DIR SOURCE_DIR SYMMESH_CLI
set -uo pipefail
BUILD=$1 ROOT=$2 CLI=$3
# shellcheck source=../cli/common.sh
source "$ROOT/tests/cli/common.sh" "$CLI" "$ROOT"
PREFIX="$TMP/prefix"
INPUT=data/ngon_slice_8.json

if cmake --install "$BUILD" --prefix "$PREFIX" > "$TMP/install.log" 2>&1; then
  pass "cmake --install into a fresh prefix"
else
  fail "cmake --install"; sed 's/^/  | /' "$TMP/install.log"; finish; exit 1
fi
for f in include/symmesh/symmesh.h lib/cmake/symmesh/symmeshConfig.cmake \
         lib/cmake/symmesh/symmeshConfigVersion.cmake lib/symmesh/libsymmesh_gmsh.so \
         lib/symmesh/libsymmesh_petsc.so; do
  [ -f "$PREFIX/$f" ] && pass "installed $f" || fail "missing $f"
done
ls "$PREFIX"/lib/libsymmesh.so* > /dev/null 2>&1 && pass "installed libsymmesh.so" \
  || fail "missing lib/libsymmesh.so"
# The public header includes standard headers only (CGAL & co. stay inside the library).
if grep -E '^#include' "$PREFIX/include/symmesh/symmesh.h" | grep -vqE '<[a-z_]+>$'; then
  fail "symmesh.h includes a non-standard header: $(grep '^#include' "$PREFIX/include/symmesh/symmesh.h" | tr '\n' ' ')"
else
  pass "symmesh.h includes standard headers only"
fi

launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if cmake -S "$ROOT/examples/cpp" -B "$TMP/example" -G Ninja -DCMAKE_BUILD_TYPE=Release \
     -DCMAKE_PREFIX_PATH="$PREFIX" "${launcher[@]}" > "$TMP/configure.log" 2>&1 \
   && cmake --build "$TMP/example" > "$TMP/build.log" 2>&1; then
  pass "examples/cpp configured and built against the prefix"
else
  fail "examples/cpp against the prefix"
  cat "$TMP/configure.log" "$TMP/build.log" 2> /dev/null | tail -30 | sed 's/^/  | /'
  finish; exit 1
fi
grep -q "symmesh_DIR:PATH=$PREFIX/lib/cmake/symmesh" "$TMP/example/CMakeCache.txt" \
  && pass "find_package(symmesh) found the installed package" \
  || fail "find_package(symmesh) did not use $PREFIX: $(grep symmesh_DIR "$TMP/example/CMakeCache.txt")"
# A version the package does not offer is refused (symmeshConfigVersion.cmake).
mkdir -p "$TMP/v1"
printf 'cmake_minimum_required(VERSION 3.20)\nproject(v NONE)\nfind_package(symmesh 1.0 REQUIRED)\n' \
  > "$TMP/v1/CMakeLists.txt"
if cmake -S "$TMP/v1" -B "$TMP/v1/build" -DCMAKE_PREFIX_PATH="$PREFIX" > "$TMP/v1.log" 2>&1; then
  fail "find_package(symmesh 1.0) accepted version 0.1"
else
  grep -q "0.1.0" "$TMP/v1.log" && pass "find_package(symmesh 1.0) refused, naming 0.1.0" \
    || fail "find_package(symmesh 1.0): $(tail -5 "$TMP/v1.log")"
fi

EXAMPLE="$TMP/example/symmesh_example"
expect_exit 0 "the example on $INPUT" -- "$EXAMPLE" "$INPUT" 0.1 "$TMP/api.vtu"
cp "$TMP/stdout" "$TMP/example.out"
sed 's/^/  | /' "$TMP/example.out"
expect_exit 0 "the CLI on $INPUT" -- "$BIN" generate "$INPUT" --size 0.1 -o "$TMP/cli.vtu" \
  --report "$TMP/report.json" --quiet
want=$(/usr/bin/python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print(r["cells_structure_instance"], r["cells_templates"])' "$TMP/report.json")
got=$(sed -n 's/.*cells_structure_instance \([0-9]*\), cells_templates \([0-9]*\).*/\1 \2/p' "$TMP/example.out")
[ -n "$want" ] && [ "$got" = "$want" ] && pass "cell counts equal the CLI's report ($got)" \
  || fail "cell counts: example '$got', CLI report '$want'"
grep -q "arrays [0-9]* points ${want%% *} cells" "$TMP/example.out" \
  && pass "the plain arrays hold every cell" || fail "arrays: $(grep arrays "$TMP/example.out")"
cmp -s "$TMP/api.vtu" "$TMP/cli.vtu" && pass "the example's .vtu is the CLI's, byte for byte" \
  || fail "the example's .vtu differs from the CLI's"
expect_exit 2 "a missing input file" -- "$EXAMPLE" "$TMP/none.json" 0.1 "$TMP/x.vtu"
"$BIN" check "$TMP/none.json" 2> "$TMP/cli.err"
[ "$(sed 's/^symmesh: error: //' "$TMP/cli.err")" = "$(sed 's/^symmesh_example: error: //' "$TMP/stderr")" ] \
  && pass "the same message as the CLI" || fail "messages: $(cat "$TMP/cli.err" "$TMP/stderr")"
expect_exit 2 "an unknown built-in object" -- "$EXAMPLE" no-such-object 0.1 "$TMP/x.vtu"
grep -q "unknown example 'no-such-object'" "$TMP/stderr" && pass "the error names the object" \
  || fail "error: $(cat "$TMP/stderr")"

# The installed library loads the Gmsh module from the prefix, not from the build tree.
LD_DEBUG=files "$EXAMPLE" "$INPUT" 0.1 "$TMP/gmsh.vtu" gmsh > "$TMP/gmsh.out" 2> "$TMP/gmsh.err"
grep -q "file=$PREFIX/lib/symmesh/libsymmesh_gmsh.so" "$TMP/gmsh.err" \
  && grep -q "method gmsh" "$TMP/gmsh.out" \
  && pass "--method gmsh loads $PREFIX/lib/symmesh/libsymmesh_gmsh.so" \
  || fail "gmsh module: $(grep -m3 -E 'libsymmesh_gmsh|error' "$TMP/gmsh.err" "$TMP/gmsh.out")"

# $SYMMESH_MODULE_DIR comes first.
mkdir -p "$TMP/modules" && cp "$PREFIX/lib/symmesh/libsymmesh_gmsh.so" "$TMP/modules/"
SYMMESH_MODULE_DIR="$TMP/modules" LD_DEBUG=files "$EXAMPLE" "$INPUT" 0.1 "$TMP/gmsh2.vtu" gmsh \
  > /dev/null 2> "$TMP/gmsh2.err"
grep -q "file=$TMP/modules/libsymmesh_gmsh.so" "$TMP/gmsh2.err" \
  && pass "SYMMESH_MODULE_DIR is looked at first" \
  || fail "SYMMESH_MODULE_DIR: $(grep -m3 -E 'libsymmesh_gmsh|error' "$TMP/gmsh2.err")"

# The installed Python package, when the build has one.
PYDIR=$(find "$PREFIX" -path '*/dist-packages/symmesh/__init__.py' -printf '%h\n' | head -1)
if [ -n "$PYDIR" ]; then
  PYTHONPATH=$(dirname "$PYDIR") /usr/bin/python3 -c '
import sys, symmesh
assert symmesh.__file__.startswith(sys.argv[1]), symmesh.__file__
libs = {l.split()[-1] for l in open("/proc/self/maps") if "libsymmesh.so" in l}
assert libs and all(l.startswith(sys.argv[1]) for l in libs), libs
g = symmesh.generate(sys.argv[2], size=0.1)
print(g.cell_count)' "$PREFIX" "$INPUT" > "$TMP/py.out" 2>&1
  [ "$(cat "$TMP/py.out")" = "${want%% *}" ] && pass "the installed Python module imports and generates" \
    || fail "installed Python module: $(cat "$TMP/py.out")"
fi
finish
