# Sourced by the checks whose course the tests' user must reach. As root the tests run as nobody:
# where a folder above WORK_DIR is closed to nobody (a clone under mktemp -d, mode 700), the
# course goes to a fresh folder under the system's temporary folder instead, opened to all and
# removed at exit.
# Usage: . reachable_work.sh; reachable_work WORK_DIR   (sets `work`, emptied)
reachable_work() {
  work=$1
  rm -rf "$work"
  if [ "$(id -u)" -eq 0 ] && command -v su >/dev/null 2>&1 && mkdir -p "$work" &&
    ! su nobody -s /bin/sh -c "cd '$work'" 2>/dev/null; then
    rm -rf "$work"
    work=$(mktemp -d)
    chmod 755 "$work"
    trap 'rm -rf "$work"' EXIT
  fi
}
