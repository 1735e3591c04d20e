#!/usr/bin/env bash
# hilight's one set-up script, for a fresh Debian 12 machine (as root) or an
# existing checkout:
#   bash setup.sh demo   install dependencies, build, run the demo on the bundled room
#   bash setup.sh test   install dependencies, build, run the whole test suite
#   bash setup.sh deps | build
# BUILD_DIR (default build/) and BUILD_TYPE (default Release) may be set.
set -euo pipefail
cd "$(dirname "$0")"
BUILD_DIR=${BUILD_DIR:-build}
BUILD_TYPE=${BUILD_TYPE:-Release}

PACKAGES=(
  build-essential cmake ninja-build pkg-config python3
  libembree-dev libassimp-dev libglm-dev libopenexr-dev libpng-dev libtbb-dev
  nlohmann-json3-dev libcli11-dev catch2 libeigen3-dev libstb-dev libtinygltf-dev
  coinor-libclp-dev   # linear programs: illuminance criteria at least flux (pipeline/illuminance_design)
  libifcplusplus-dev libboost-dev  # IFC out: luminaires as IfcLightFixture in a copy of the input IFC (its headers need boost's)
  assimp-testmodels   # real broken and valid models the tests load
  blender python3-numpy  # the glTF round trip through Blender's own importer and exporter (tests)
  chromium            # the solve's HTML report opened in a real headless browser (tests)
  clang-14 libfuzzer-14-dev  # fuzzing the readers of untrusted files (tools/fuzz.sh, a test step)
  povray              # the reference renderer (renderers/povray)
  libvulkan-dev mesa-vulkan-drivers glslc vulkan-validationlayers  # renderers/ism-vulkan (lavapipe without a GPU)
  libglfw3-dev libgl-dev libimgui-dev xvfb xauth  # frontends/painter (OpenGL through Mesa; Xvfb for headless tests)
)

install_deps() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#PACKAGES[@]} packages already installed"
    return
  fi
  echo "setup: installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE="$BUILD_TYPE" >/dev/null
  cmake --build "$BUILD_DIR" -j "$(nproc)"
}

demo() {
  local out="$BUILD_DIR/demo" hl="$BUILD_DIR/bin/hilight" camera="5.6,2.6,4.7,2,0.6,1.5,70"
  mkdir -p "$out"
  # The target: the bundled room lit by four known lights (a designer would paint it).
  "$hl" render scenes/room.obj --lights scenes/room-4lights.json -o "$out/target.ply" -o "$out/target.png" --camera "$camera"
  # The solve: find the lights that produce that target (its lamps hang at 1.6-2.5 m, not on
  # the ceiling where a closed room's lights go by default: --place anywhere).
  "$hl" solve scenes/room.obj --target "$out/target.ply" -o "$out/lights.json" --report "$out/report.json" \
    --cache-dir "$out/cache" --place anywhere
  "$hl" render scenes/room.obj --lights "$out/lights.json" -o "$out/result.png" --camera "$camera"
  echo "demo: found lights in $out/lights.json (report: $out/report.json);"
  echo "      compare $out/target.png (wanted) with $out/result.png (what the found lights give)"
}

run_tests() {
  # The painter's tests open windows: give them a virtual display when there is none.
  # -noreset: by default Xvfb resets when its last client leaves and drops any
  # client that connects meanwhile, so a painter starting as another exits fails.
  local display=()
  [ -n "${DISPLAY:-}" ] || display=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")
  (cd "$BUILD_DIR" && "${display[@]}" ctest --output-on-failure -j "$(nproc)")
  # Each file reader fuzzed for a few seconds; any crash, leak or hang fails.
  bash tools/fuzz.sh 8
  # A subset of the suite under AddressSanitizer + UBSan: every file reader and
  # one whole solve (tools/sanitize-subset.txt); any report fails.
  SANITIZE_BUILD_DIR="$BUILD_DIR-asan" bash tools/sanitize.sh
  # The other CMake generator: Unix Makefiles, Debug, builds the generated sources (the shaders).
  cmake -S . -B "$BUILD_DIR-make" -G "Unix Makefiles" -DCMAKE_BUILD_TYPE=Debug >/dev/null
  cmake --build "$BUILD_DIR-make" --target hilight-ism-shaders -j "$(nproc)" >/dev/null
  echo "setup: Unix Makefiles (Debug) configure and build the generated shader sources"
}

case "${1:-}" in
  deps) install_deps ;;
  build) install_deps; build ;;
  demo) install_deps; build; demo ;;
  test) install_deps; build; run_tests ;;
  *) echo "usage: bash setup.sh demo|test|deps|build" >&2; exit 2 ;;
esac
