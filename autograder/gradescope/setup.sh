#!/bin/sh
# Gradescope image setup (run once, as root, in /autograder/source; written by
# ./workbook gradescope). Installs the distribution's packages and builds the grader by grading
# the reference solutions as a submission, so that a student's run compiles only their files.
# Needs a Debian 12 or Ubuntu 22.04 base image (Ubuntu 24.04 ships Catch2 v3).
set -eu
source=$(CDPATH='' cd -- "$(dirname -- "$0")" && pwd)
. "$source/gradescope.conf"
export DEBIAN_FRONTEND=noninteractive
if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
  if ! dpkg-query -W -f='${Status}' catch2 2>/dev/null | grep -q "install ok installed"; then
    apt-get update -qq
  fi
  catch_version=$(apt-cache policy catch2 2>/dev/null | sed -n 's/^ *Candidate: *//p')
  case $catch_version in
    3*) echo "setup.sh: this image offers Catch2 $catch_version; the grader needs Catch2 2.13:" \
             "choose the Ubuntu 22.04 (or a Debian 12) base image" >&2
        exit 1 ;;
  esac
fi
# The first grading installs the build packages (./workbook does, as root) and builds everything.
# shellcheck disable=SC2086
"$source/workbook" grade --submission "$source/solutions" $MODULE_ARGS --strict
echo "setup.sh: the grader is built and gives the reference solutions full marks"
