#!/usr/bin/env bash
# ctest "sdk: ..." (issue 17): `cpack -G DEB` makes hilight and hilight-dev
# packages; hilight's run-time dependencies come from dpkg-shlibdeps; both
# unpack into a scratch root (dpkg -x), and the unpacked `hilight` lists its
# plugins and reads a scene from there.
#   test_debian_package.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1 build=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/hilight-deb.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*" >&2; exit 1; }
trap 'echo "FAILED: line $LINENO: $BASH_COMMAND" >&2' ERR
command -v dpkg-deb >/dev/null || { echo "SKIPPED: no dpkg-deb here"; exit 0; }

(cd "$work" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/out") >"$work/cpack.log" 2>&1 ||
  { tail -30 "$work/cpack.log" >&2; fail "cpack -G DEB"; }
version=$(sed -n 's/^set(CPACK_PACKAGE_VERSION "\(.*\)")$/\1/p' "$build/CPackConfig.cmake")
[ -n "$version" ] || fail "no CPACK_PACKAGE_VERSION in CPackConfig.cmake"
deb=$work/out/hilight_${version}_amd64.deb dev=$work/out/hilight-dev_${version}_amd64.deb
[ -f "$deb" ] || { ls "$work/out" >&2; fail "no $(basename "$deb")"; }
[ -f "$dev" ] || { ls "$work/out" >&2; fail "no $(basename "$dev")"; }

# Run-time dependencies found by dpkg-shlibdeps: the libraries the modules link.
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libembree3 libassimp libtbb libc6; do
  echo "$depends" | grep -q "$lib" || fail "Depends lacks $lib"
done
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "the package's version is not $version"
# POV-Ray is the reference renderer's program: recommended, not required.
grep -qw povray <<<"$(dpkg-deb -f "$deb" Recommends)" || fail "hilight does not recommend povray"
grep -q "hilight (= $version)" <<<"$(dpkg-deb -f "$dev" Depends)" || fail "hilight-dev does not depend on hilight (= $version)"
# (Listed first: grep -q stops reading early, and dpkg-deb would fail on the broken pipe.)
dev_files=$(dpkg-deb -c "$dev") deb_files=$(dpkg-deb -c "$deb")
grep -q './usr/include/hilight/plugin.hpp' <<<"$dev_files" || fail "hilight-dev has no plugin.hpp"
grep -q './usr/lib/cmake/hilight/hilightConfig.cmake' <<<"$dev_files" || fail "hilight-dev has no hilightConfig.cmake"
grep -q './usr/lib/hilight/hilight-renderer-embree.so' <<<"$deb_files" || fail "hilight has no embree plugin"
if grep -q './usr/include/' <<<"$deb_files"; then fail "headers are in the run-time package"; fi

root=$work/root
dpkg -x "$deb" "$root"
dpkg -x "$dev" "$root"
hl=$root/usr/bin/hilight
[ -x "$hl" ] || fail "no usr/bin/hilight in the package"
grep -q "^hilight $version " <<<"$("$hl" --version)" || fail "hilight --version is not $version"
listing=$(env -u HILIGHT_PLUGIN_PATH HOME="$work/home" "$hl" plugins)
echo "$listing"
for plugin in "renderer +embree" "frontend +cli" "frontend +bench" "optimizer +varpro" "sampler +importance" "cache +grid"; do
  echo "$listing" | grep -E "^$plugin +$version +ok" >/dev/null || fail "the unpacked hilight does not load $plugin $version"
done
echo "$listing" | grep -F "from $root/usr/lib/hilight/hilight-renderer-embree.so (installed)" >/dev/null ||
  fail "the plugins do not come from the unpacked usr/lib/hilight"
info=$(HOME="$work/home" "$hl" info "$src/scenes/room.obj")
echo "$info" | grep -q "triangles" || fail "hilight info from the package printed: $info"
# The unpacked SDK's CMake package reports the same version.
grep -q "set(PACKAGE_VERSION \"$version\")" "$root/usr/lib/cmake/hilight/hilightConfigVersion.cmake" ||
  fail "hilightConfigVersion.cmake is not $version"
echo "sdk: $(basename "$deb") and $(basename "$dev") unpack and run"
