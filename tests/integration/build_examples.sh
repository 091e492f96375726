#!/usr/bin/env bash
# Installs gdnav from BUILD_DIR into BUILD_DIR/install and builds examples/ against that installed package, as a
# user's own project would (find_package(gdnav)). Used by the ExamplesPackage test fixture.
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:?usage: build_examples.sh BUILD_DIR}
prefix="$build/install"
rm -rf "$prefix" "$build/examples-build"
cmake --install "$build" --prefix "$prefix" > "$build/examples-install.log"
# The installed package must work away from the source tree: no path of the source or build tree may leak into it.
if grep -rl "$src/common\|$src/components\|$build/idl" "$prefix/lib/cmake/gdnav" ; then
  echo "build_examples.sh: the installed CMake package refers to the source or build tree" >&2; exit 1
fi
gen=Unix\ Makefiles; command -v ninja > /dev/null && gen=Ninja
cmake -S "$src/examples" -B "$build/examples-build" -G "$gen" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER}
cmake --build "$build/examples-build" -j "${JOBS:-2}"
ls "$build/examples-build/bin"
