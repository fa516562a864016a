#!/bin/sh
# The engine guide's install (docs/engine.md), run as it stands. The fenced sh blocks between its markers
# <!-- project.install: engine --> and <!-- project.install: consumer --> (and their closing
# <!-- /project.install: ... -->) run verbatim, each with `sh -e`, in a copy of the source tree
# (without build/, out/ and .git), with HOME in a scratch folder:
#   engine    configures with BUILD_TESTING=OFF, builds and installs, with Catch2 hidden from
#             CMake (the engine does not need it); it must build libraries only, no program
#   consumer  builds examples/ against the installed package with Catch2 and Spectra hidden, and
#             runs both programs (each checks its own physics and exits 1 on a failure)
# The commands get the compiler and flags given here (the enclosing build's: the package's
# objects need its standard library, libc++ under clang-libcxx) through the environment that
# CMake honours (CXX, CXXFLAGS, LDFLAGS), Ninja (CMAKE_GENERATOR), CMAKE_BUILD_PARALLEL_LEVEL
# jobs (default 2), and a toolchain file (CMAKE_TOOLCHAIN_FILE) that hides the packages. The
# engine's commands build at -O1 without debug information (CMAKE_BUILD_TYPE=None, which CMake
# takes from the environment, and -O1 in CXXFLAGS): the same commands, in a third less time than
# the default RelWithDebInfo; the consumer builds with the project's default.
# Usage: install_check.sh SOURCE_DIR WORK_DIR CXX CXX_FLAGS LINKER_FLAGS
set -eu
source=$1
work=$2
cxx=$3
cxx_flags=$4
linker_flags=$5
# The scratch folder is removed first: never a source tree (a call with the arguments in another
# order would name one).
if [ -e "$work/.git" ] || [ -e "$work/workbook" ] || [ -e "$work/CMakeLists.txt" ]; then
  echo "install check: $work looks like a source tree, not a scratch folder; refusing to remove it" >&2
  exit 2
fi
rm -rf "$work"
mkdir -p "$work/tree" "$work/home"

fail() {
  echo "install check: $*" >&2
  exit 1
}

# block NAME: the lines of the fenced sh block between the engine guide's markers of NAME.
block() {
  awk -v name="$1" '$0 == "<!-- project.install: " name " -->" { marked = 1; next }
    $0 == "<!-- /project.install: " name " -->" { marked = 0 }
    marked && /^```sh$/ { code = 1; next }
    marked && /^```$/ { code = 0 }
    marked && code' "$source/docs/engine.md"
}
block engine >"$work/engine.sh"
block consumer >"$work/consumer.sh"
grep -q "cmake --install" "$work/engine.sh" ||
  fail "no cmake --install in docs/engine.md between <!-- project.install: engine --> markers"
grep -q "examples" "$work/consumer.sh" ||
  fail "no examples/ build in docs/engine.md between <!-- project.install: consumer --> markers"

tar -C "$source" --exclude=./build --exclude=./out --exclude=./.git -cf - . | tar -C "$work/tree" -xf -
touch "$work/copied"
printf 'set(CMAKE_DISABLE_FIND_PACKAGE_Catch2 ON)\n' >"$work/no-catch2.cmake"
printf 'set(CMAKE_DISABLE_FIND_PACKAGE_Catch2 ON)\nset(CMAKE_DISABLE_FIND_PACKAGE_spectra ON)\n' \
  >"$work/no-catch2-spectra.cmake"

# run NAME TOOLCHAIN [BUILD_TYPE EXTRA_FLAGS]: the block NAME in the copy; prints its time in
# seconds.
run() {
  start=$(date +%s)
  if ! (cd "$work/tree" &&
        env -u DESTDIR -u CMAKE_BUILD_TYPE -u CMAKE_GENERATOR_PLATFORM -u CMAKE_GENERATOR_TOOLSET \
          ${3:+CMAKE_BUILD_TYPE=$3} \
          HOME="$work/home" CXX="$cxx" CXXFLAGS="$cxx_flags${4:+ $4}" LDFLAGS="$linker_flags" \
          CMAKE_GENERATOR=Ninja CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}" \
          CMAKE_TOOLCHAIN_FILE="$2" sh -ex "$work/$1.sh") >"$work/$1.log" 2>&1; then
    tail -n 40 "$work/$1.log" >&2
    fail "the engine guide's $1 commands failed (above; the whole log: $work/$1.log)"
  fi
  echo $(($(date +%s) - start))
}

engine_time=$(run engine "$work/no-catch2.cmake" None -O1)
configs=$(find "$work/home" -path "*/cmake/fmbd/fmbdConfig.cmake")
[ "$(echo "$configs" | grep -c .)" -eq 1 ] || fail "the engine commands installed no single package under HOME: $configs"
prefix=${configs%/*/cmake/fmbd/fmbdConfig.cmake}
for header in fmbd/fmbd.hpp fmbd/model.hpp fmbd/ffrf.hpp fmbd/generalized_alpha.hpp fmbd/sparse_body.hpp; do
  [ -f "$prefix/include/$header" ] || fail "include/$header is not installed"
done
if grep -l -i -E "catch2|spectra" "${configs%/*}"/*.cmake; then
  fail "the package files above name Catch2 or Spectra"
fi
# The engine alone: libraries, not one program (tests, tools, demos, benchmarks) of the course.
programs=$(find "$work/tree" -newer "$work/copied" -type f -perm -u+x ! -path "*/CMakeFiles/*")
[ -z "$programs" ] || fail "the engine build built programs: $programs"

consumer_time=$(run consumer "$work/no-catch2-spectra.cmake")
rm -rf "${work:?}/tree" "${work:?}/home"
echo "install check: the engine guide's engine commands (${engine_time} s) and consumer commands" \
     "(${consumer_time} s) ran as they stand"
