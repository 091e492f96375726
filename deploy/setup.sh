#!/usr/bin/env bash
# gdnav one-command set-up for Debian 12 (as root, or with sudo available).
#   deploy/setup.sh run    install missing packages, build the gdnav program, run the default end-to-end scenario
#   deploy/setup.sh test   install missing packages, build, run the whole test suite (CTest)
#   deploy/setup.sh build  install missing packages and build everything (tests included)
# Idempotent: packages already present are not reinstalled and the build is incremental.
# Environment: BUILD_DIR (default build), JOBS (default nproc), GDNAV_SKIP_APT=1 to skip the package step.
set -euo pipefail

mode=${1:-run}
shift || true
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
jobs=${JOBS:-$(nproc)}

packages=(
  build-essential cmake ninja-build pkg-config git
  libfastrtps-dev libfastcdr-dev fastddsgen fastdds-tools
  cyclonedds-dev cyclonedds-tools
  libeigen3-dev libyaml-cpp-dev libspdlog-dev libfmt-dev libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev libgeographiclib-dev libhdf5-dev libzstd-dev
  libwebsocketpp-dev libasio-dev nlohmann-json3-dev  # the live view (gdnav run --live: common/io/foxglove_ws)
  libopenmpi-dev openmpi-bin
  python3 python3-numpy python3-matplotlib python3-h5py python3-plotly python3-dev pybind11-dev
  libssl-dev openssl
  iproute2 procps nftables iptables libnetfilter-queue-dev
  nodejs
  chromium  # the flight review test opens the HTML pages of gdnav report headless (tests/integration/viewing/review_node)
)
# npm: the MCAP test reads recordings with the official TypeScript reader (tests/integration/viewing/mcap_node). NodeSource's
# nodejs package brings its own npm (Debian's npm would conflict with it).
command -v npm > /dev/null 2>&1 || packages+=(npm)

if [ "${GDNAV_SKIP_APT:-0}" != 1 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  echo "gdnav setup: updating package lists"
  $sudo apt-get update -qq
  if [ ${#missing[@]} -gt 0 ]; then
    echo "gdnav setup: installing ${missing[*]}"
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
  else
    echo "gdnav setup: all ${#packages[@]} packages present"
  fi
fi

# `run` builds only the gdnav program (every component is linked into it); `build` and `test` build everything,
# tests included.
targets=()
[ "$mode" = run ] && targets=(--target gdnav)
echo "gdnav setup: building ${targets[1]:-everything} in $build ($jobs jobs)"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release > "$build.configure.log" 2>&1 || {
  cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j "$jobs" "${targets[@]}"

case "$mode" in
  build) ;;
  test)
    cd "$build"
    # Studies of several minutes (CTest label `study`) are left out: `ctest -L study` runs them.
    ctest --output-on-failure -j "$jobs" -LE study "$@"
    ;;
  run)
    out=${GDNAV_OUT:-$root/out/default}
    "$build/bin/gdnav" run --scenario default --layout distributed --out "$out" "$@"
    ;;
  *) echo "usage: deploy/setup.sh [run|test|build] [extra args]" >&2; exit 2 ;;
esac
