#!/usr/bin/env bash
# Installs the built appell into a scratch prefix, then builds and runs the
# consumer project against it with find_package(appell CONFIG).
set -euo pipefail
build=$1; src=$2; scene=$3
prefix=$build/consumer-prefix; cbuild=$build/consumer-build
rm -rf "$prefix" "$cbuild"
cmake --install "$build" --prefix "$prefix" >/dev/null
cmake -S "$src" -B "$cbuild" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$cbuild" >/dev/null
# The installed command runs where it was installed (it finds libappell_rounding.so by its RPATH);
# a failure stops the script before the consumer prints the line the test passes on.
env -u LD_LIBRARY_PATH "$prefix/bin/appell" eval "$scene" >/dev/null
# The installed Python module, where the build made one, imports from the prefix and evaluates.
module=$(find "$prefix" -name '_core*.so' -path '*/appell/*' | head -n 1)
if [ -n "$module" ]; then
  packages=$(dirname "$(dirname "$module")")
  env -u LD_LIBRARY_PATH PYTHONPATH="$packages" /usr/bin/python3 -c "
import sys, appell
assert appell.__file__.startswith('$packages'), appell.__file__
appell.Scene.from_file(sys.argv[1]).eval('interval')" "$scene"
fi
"$cbuild/consumer" "$scene"
