#!/bin/sh
# The compiler launcher under ccache (CMakeLists.txt, APPELL_CCACHE): runs "$@" (ccache, the
# compiler and its arguments) after removing the output of a precompiled header's compile.
#
# Why: CMake compiles a precompiled header with `-include DIR/cmake_pch.hxx -o
# DIR/cmake_pch.hxx.gch`, so the .gch of the last build lies beside the header being compiled
# again; ccache then hashes that old .gch into the new one's key.  A precompiled header compiled
# in a build directory that holds an old .gch, and one compiled in a new directory, had different
# keys, and each missed the other's entry; the one compiled anew holds its build directory's path,
# so in a clone at another path every unit behind it missed too.  Removed first, the header's key
# is its sources' and flags' alone (ccache's base directory takes the paths out), the same in
# every clone: the .gch comes from the cache, byte for byte the one the units' keys were made with.
out=
prev=
for arg do
  if [ "$prev" = "-o" ]; then out=$arg; fi
  prev=$arg
done
case $out in
  *.gch) rm -f "$out" ;;
esac
exec "$@"
