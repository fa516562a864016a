#!/bin/sh
# Checks the parameter table of a demo (demo::run): --help lists each parameter with its default;
# an unknown parameter, a missing value, a word for a number, a fraction for a count and a word
# outside a choice each exit 2 with a message that says which. Nothing is simulated.
#   check_parameters.sh <demo executable> <number parameter> <its default with unit> <count parameter> <choice parameter>
exe=$1 number=$2 default=$3 count=$4 choice=$5
fail() { echo "parameter check: $*"; exit 1; }
help=$("$exe" --help) || fail "--help exited $?"
echo "$help" | grep -q -- "--$number X .*\[$default\]" || fail "--help does not list --$number with [$default]: $help"
echo "$help" | grep -q -- "--$choice [a-z-]* | " || fail "--help does not list the words of --$choice: $help"
refused() {  # refused <text the message must hold> <arguments...>
  expected=$1; shift
  status=0
  message=$("$exe" --out "${TMPDIR:-/tmp}/never-written" "$@" 2>&1) || status=$?
  [ "$status" -eq 2 ] || fail "'$*' exited $status, expected 2: $message"
  case $message in *"$expected"*) ;; *) fail "'$*': the message lacks '$expected': $message" ;; esac
}
refused "unknown parameter '--no-such-parameter'; its parameters are --" --no-such-parameter 1
refused "--$number needs a value" "--$number"
refused "--$number takes a number, not 'fast'" "--$number" fast
refused "--$number takes a number, not 'fast'" "--$number=fast"
refused "--$count takes a whole number, not '2.5'" "--$count" 2.5
refused "--$choice takes " "--$choice" no-such-word
echo "parameter check: --help lists the defaults; 6 wrong command lines refused with exit 2"
