# Shared by scripts/serve, scripts/test and scripts/fuzz: idempotent set-up and the builds.
# Source it; every function is safe to run again on a machine that already has everything.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="${PDESURF_BUILD_DIR:-$ROOT/build}"
export NODE_PATH=/usr/share/nodejs  # emscripten's optimiser needs Debian's acorn (toolchain note 1)

# clang and libclang-rt-14-dev: libFuzzer for the fuzz targets (scripts/fuzz, docs/testing.md).
# libocct-*-dev: Open CASCADE 7.6 for the CAD read-back tools in tests/occt (the rest of OCCT
# comes as their dependencies); libtbb-dev: OCCT's CMake targets link libtbb.so by path, and
# Debian's OCCT packages do not depend on it.
APT_PACKAGES=(cmake g++ make emscripten libeigen3-dev doctest-dev nlohmann-json3-dev zlib1g-dev chromium nodejs
              clang libclang-rt-14-dev libocct-data-exchange-dev libocct-modeling-algorithms-dev libtbb-dev lib3mf-dev)

log() { printf '\033[1m== %s\033[0m\n' "$*"; }

install_system_packages() {
  local missing=()
  for p in "${APT_PACKAGES[@]}"; do
    # nodejs may come from NodeSource or Debian; any node >= 18 will do.
    if [ "$p" = nodejs ] && command -v node >/dev/null 2>&1; then continue; fi
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
}

install_npm_packages() {
  # npm ci only when the lock file changed since the last install.
  local stamp="$ROOT/node_modules/.pdesurf-lock-sha"
  local want
  want="$(sha256sum "$ROOT/package-lock.json" | cut -d' ' -f1)"
  if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then return 0; fi
  log "npm ci"
  (cd "$ROOT" && npm ci --no-audit --no-fund)
  echo "$want" >"$stamp"
}

setup() {
  install_system_packages
  install_npm_packages
}

# build_native [TARGET...], build_wasm [TARGET...]: every target (the benchmark too) unless
# targets are named; scripts/test names only what its rows run.
build_native() {
  log "native build ($BUILD/native${*:+: $*})"
  cmake -S "$ROOT" -B "$BUILD/native" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$BUILD/native" -j"$(nproc)" ${1:+--target "$@"}
}

build_wasm() {
  log "wasm build ($BUILD/wasm${*:+: $*})"
  emcmake cmake -S "$ROOT" -B "$BUILD/wasm" -DCMAKE_BUILD_TYPE=Release \
    -DEigen3_DIR=/usr/share/eigen3/cmake -DCMAKE_CROSSCOMPILING_EMULATOR="$(command -v node)" >/dev/null
  cmake --build "$BUILD/wasm" -j"$(nproc)" ${1:+--target "$@"}
}

build_web() {
  log "web bundle ($BUILD/web)"
  node "$ROOT/scripts/build-web.mjs" --out "$BUILD/web" --wasm-dir "$BUILD/wasm"
}

# One clang tree, $BUILD/asan, for the sanitized native suite and the libFuzzer targets (CMake
# options PDESURF_SANITIZE and PDESURF_FUZZ together): the core is compiled once with
# AddressSanitizer + UndefinedBehaviorSanitizer (every report fatal) and libFuzzer's coverage
# instrumentation, and the doctest suite, the CLI and the fuzz targets all link it. -O1 -g
# with assertions on: usable stacks, and the doctest suite runs in about a minute.
# (Until 2026-12 the sanitized suite was a g++ tree of its own and the fuzz targets a second
# clang tree: the core was compiled twice more; docs/testing.md.)
# Line tables only: reports keep their file:line stacks; the full debug information made this
# build the slowest step of the suite (313 s against 188 s for the release build). A unity
# build (CMakeLists.txt says which sources stay out): 266 -> 210 s.
configure_asan() {
  local cache="$BUILD/asan/CMakeCache.txt"
  # A tree configured by g++ (before the merge) is started afresh rather than reconfigured.
  if [ -f "$cache" ] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang' "$cache"; then rm -rf "$BUILD/asan"; fi
  cmake -S "$ROOT" -B "$BUILD/asan" -DPDESURF_SANITIZE=ON -DPDESURF_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" \
    -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=8 >/dev/null
}

build_asan() {
  log "sanitized native build ($BUILD/asan: doctest suite, CLI)"
  configure_asan
  cmake --build "$BUILD/asan" -j"$(nproc)" --target pdesurf_tests pdesurf
}

# The libFuzzer targets of tests/fuzz, in the same tree (their work files: $BUILD/fuzz).
build_fuzz() {
  log "fuzz build ($BUILD/asan: scene_fuzz, link_fuzz)"
  configure_asan
  cmake --build "$BUILD/asan" -j"$(nproc)" --target scene_fuzz link_fuzz
}

# Sanitizer reports: a stack for UBSan too; leaks count (the default on x86-64 Linux).
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
