#!/usr/bin/env bash
# ctest "sdk: ..." (issue 17): a plugin built outside the tree, as its author
# would build it. Installs this build into a scratch prefix, builds
# examples/plugin-renderer against it with find_package(hilight), loads it in
# the installed `hilight` through HILIGHT_PLUGIN_PATH and the user folder, runs
# the renderer contract on it, and checks that a build for another compiler is
# refused with the reason.
#   test_example_plugin.sh SOURCE_DIR BUILD_DIR HILIGHT_TESTS_BINARY
set -euo pipefail
src=$1 build=$2 tests=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/hilight-sdk.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*" >&2; exit 1; }
trap 'echo "FAILED: line $LINENO: $BASH_COMMAND" >&2' ERR
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" >"$work/install.log" || fail "cmake --install (log above)"
for f in include/hilight/plugin.hpp include/hilight/registry.hpp include/hilight/renderer.hpp include/hilight/version.hpp \
         lib/cmake/hilight/hilightConfig.cmake lib/cmake/hilight/hilightConfigVersion.cmake \
         lib/cmake/hilight/HilightPlugin.cmake bin/hilight lib/hilight/hilight-renderer-embree.so; do
  [ -e "$prefix/$f" ] || fail "the install has no $f"
done
# The framework library carries a version and a SONAME.
soname=$(objdump -p "$prefix"/lib/libhilight_framework.so | awk '/SONAME/ {print $2}')
[[ $soname =~ ^libhilight_framework\.so\.[0-9]+\.[0-9]+$ ]] || fail "SONAME is '$soname'"
[ -e "$prefix/lib/$soname" ] || fail "no $soname in lib/"
# Every installed header includes only installed headers: the SDK is closed.
while read -r header; do
  { grep -oE '^#include "hilight/[^"]+"' "$header" || true; } | sed 's/^#include "//; s/"$//' | while read -r inc; do
    [ -e "$prefix/include/$inc" ] || fail "$header includes $inc, which is not installed"
  done
done < <(find "$prefix/include/hilight" -name '*.hpp')

# The example, configured and built against the prefix only.
cmake -S "$src/examples/plugin-renderer" -B "$work/example" -G "Unix Makefiles" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log" >&2; fail "the example does not configure against the installed prefix"; }
grep -q "$prefix/lib/cmake/hilight" "$work/example/CMakeCache.txt" || fail "find_package(hilight) did not find the installed prefix"
cmake --build "$work/example" -j "$(nproc)" >"$work/build.log" 2>&1 || { tail -30 "$work/build.log" >&2; fail "the example does not build"; }
module_dir=$work/example/lib/hilight
[ -e "$module_dir/hilight-renderer-unshadowed.so" ] || fail "no hilight-renderer-unshadowed.so in $module_dir"
# No empty RUNPATH entry (the loader's current folder) in the built module (issue 35).
runpath=$(readelf -d "$module_dir/hilight-renderer-unshadowed.so" | sed -n 's/.*R\(UN\)\{0,1\}PATH.*\[\(.*\)\]/\2/p')
[ -n "$runpath" ] && [[ ":$runpath:" == *"::"* ]] && fail "the example's RUNPATH [$runpath] has an empty entry"

# The installed launcher loads it from HILIGHT_PLUGIN_PATH and says so.
listing=$(env -u XDG_DATA_HOME HOME="$work/home" HILIGHT_PLUGIN_PATH="$module_dir" "$prefix/bin/hilight" plugins)
echo "$listing"
echo "$listing" | grep -E '^renderer +unshadowed +1\.0\.0 +ok' >/dev/null || fail "hilight plugins does not list unshadowed 1.0.0 as ok"
echo "$listing" | grep -F "from $module_dir/hilight-renderer-unshadowed.so (HILIGHT_PLUGIN_PATH)" >/dev/null ||
  fail "hilight plugins does not say where unshadowed came from"
echo "$listing" | grep -F "from $prefix/lib/hilight/hilight-renderer-embree.so (installed)" >/dev/null ||
  fail "hilight plugins does not say embree came from the installed folder"
version=$("$prefix/bin/hilight" --version)
echo "$version" | grep -E '^hilight [0-9]+\.[0-9]+\.[0-9]+ ' >/dev/null || fail "hilight --version printed '$version'"

# It renders through the installed hilight: the lights of a plane, unoccluded,
# as Embree's direct light (the same rendering model, shadows aside).
cat >"$work/lights.json" <<'JSON'
{"lights": [{"type": "point", "position": [0.4, 1.5, -0.3], "intensity": [2, 2, 2]}]}
JSON
cat >"$work/plane.obj" <<'OBJ'
v -2 0 -2
v 2 0 -2
v 2 0 2
v -2 0 2
f 1 3 2
f 1 4 3
OBJ
HILIGHT_PLUGIN_PATH="$module_dir" "$prefix/bin/hilight" render "$work/plane.obj" --lights "$work/lights.json" \
  --renderer unshadowed --bounces 0 -o "$work/unshadowed.ply" 2>"$work/render.err" || { cat "$work/render.err" >&2; fail "render --renderer unshadowed"; }
"$prefix/bin/hilight" render "$work/plane.obj" --lights "$work/lights.json" --bounces 0 -o "$work/embree.ply" 2>/dev/null
python3 - "$work/unshadowed.ply" "$work/embree.ply" <<'PY' || fail "unshadowed and embree disagree on an unoccluded plane"
import struct, sys
def colours(path):
    """The red, green, blue of every vertex of a PLY that `hilight render` wrote."""
    data = open(path, 'rb').read()
    head, _, body = data.partition(b'end_header\n')
    lines = head.decode().splitlines()
    assert 'format binary_little_endian 1.0' in lines, lines[:2]
    count = int(next(l.split()[2] for l in lines if l.startswith('element vertex')))
    props = [l.split()[1:] for l in lines if l.startswith('property') and 'list' not in l][:9]
    fmt = '<' + ''.join('d' if t == 'double' else 'f' for t, _ in props)
    names = [n for _, n in props]
    size = struct.calcsize(fmt)
    rows = [struct.unpack_from(fmt, body, i * size) for i in range(count)]
    return [[r[names.index(c)] for c in ('red', 'green', 'blue')] for r in rows]
a, b = colours(sys.argv[1]), colours(sys.argv[2])
assert len(a) == len(b) and len(a) > 0, (len(a), len(b))
worst = max(abs(x - y) / max(abs(y), 1e-9) for ra, rb in zip(a, b) for x, y in zip(ra, rb))
print(f'{len(a)} vertices, worst relative difference {worst:.2e}')
# Embree shades a point on the plane's rim a step inside it (docs/rendering-model.md):
# the contract's analytic case allows the same.
assert worst < 5e-3, worst
PY

# The renderer contract, on this renderer alone.
HILIGHT_PLUGIN_PATH="$module_dir" HILIGHT_CONTRACT_RENDERERS=unshadowed "$tests" "[contract]" --warn NoTests ||
  fail "the renderer contract fails on the example plugin"

# The user folder, and a second copy there shadowed by HILIGHT_PLUGIN_PATH with a warning.
user=$work/data/hilight/plugins
mkdir -p "$user"
cp "$module_dir/hilight-renderer-unshadowed.so" "$user/"
listing=$(XDG_DATA_HOME="$work/data" "$prefix/bin/hilight" plugins)
echo "$listing" | grep -F "from $user/hilight-renderer-unshadowed.so (user folder)" >/dev/null || fail "not loaded from the user folder"
XDG_DATA_HOME="$work/data" HILIGHT_PLUGIN_PATH="$module_dir" "$prefix/bin/hilight" plugins >"$work/both.out" 2>"$work/both.err"
grep -F "warning: $user/hilight-renderer-unshadowed.so is not loaded: shadowed by $module_dir/hilight-renderer-unshadowed.so (HILIGHT_PLUGIN_PATH)" \
  "$work/both.err" >/dev/null || { cat "$work/both.err" >&2; fail "no warning for the shadowed copy"; }
[ "$(wc -l <"$work/both.err")" -eq 1 ] || fail "more than one warning line"

# Built by another compiler, it is refused with the reason.
if command -v clang++-14 >/dev/null; then
  cmake -S "$src/examples/plugin-renderer" -B "$work/clang" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >/dev/null 2>&1 || fail "the example does not configure with clang"
  cmake --build "$work/clang" -j "$(nproc)" >/dev/null 2>&1 || fail "the example does not build with clang"
  listing=$(HILIGHT_PLUGIN_PATH="$work/clang/lib/hilight" "$prefix/bin/hilight" plugins)
  echo "$listing" | grep -E 'hilight-renderer-unshadowed +- +not loaded: built with clang-14/.*rebuild the module' >/dev/null ||
    { echo "$listing" >&2; fail "a clang build is not refused by its build key"; }
  if HILIGHT_PLUGIN_PATH="$work/clang/lib/hilight" "$prefix/bin/hilight" render "$work/plane.obj" --lights "$work/lights.json" \
      --renderer unshadowed --bounces 0 -o "$work/refused.ply" 2>"$work/refused.err"; then
    fail "a refused plugin rendered"
  fi
  grep -q "clang-14" "$work/refused.err" || fail "the refusal does not say why: $(cat "$work/refused.err")"
  [ ! -e "$work/refused.ply" ] || fail "a refused render wrote its output"
else
  echo "(clang++-14 not installed: the build-key refusal is not tried)"
fi
echo "sdk: the example plugin builds against the installed prefix, loads, renders and passes the contract"
