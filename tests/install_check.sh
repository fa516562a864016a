#!/bin/sh
# The installed engine: `cmake --install` of this build into a fresh prefix, then the consumer
# project examples/ configured against it with Catch2 and Spectra hidden from CMake, built, and
# run (each example checks its own physics and exits 1 on a failure).
# The consumer uses the build's compiler and flags (CXX, CXX_FLAGS, LINKER_FLAGS), whose standard
# library the package's objects need.
# Usage: install_check.sh BUILD_DIR SOURCE_DIR WORK_DIR CXX CXX_FLAGS LINKER_FLAGS
set -eu
build=$1
source=$2
work=$3
cxx=$4
cxx_flags=$5
linker_flags=$6
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
for header in fmbd/fmbd.hpp fmbd/model.hpp fmbd/ffrf.hpp fmbd/generalized_alpha.hpp fmbd/sparse_body.hpp; do
  [ -f "$work/prefix/include/$header" ] || { echo "install check: include/$header is not installed" >&2; exit 1; }
done
if grep -l -i -E "catch2|spectra" "$work"/prefix/lib*/cmake/fmbd/*.cmake; then
  echo "install check: the package files above name Catch2 or Spectra" >&2
  exit 1
fi
cmake -S "$source/examples" -B "$work/examples" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="$cxx_flags" -DCMAKE_EXE_LINKER_FLAGS="$linker_flags" \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_DISABLE_FIND_PACKAGE_Catch2=ON \
  -DCMAKE_DISABLE_FIND_PACKAGE_spectra=ON >"$work/configure.log" ||
  { cat "$work/configure.log" >&2; exit 1; }
cmake --build "$work/examples"
[ -x "$work/examples/stiff_flexible_pendulum" ] ||
  { echo "install check: the component fmbd::implicit was not found" >&2; exit 1; }
"$work/examples/double_pendulum"
"$work/examples/stiff_flexible_pendulum"
echo "install check: the consumer project built and ran against the installed package"
