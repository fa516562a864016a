#!/bin/sh
# Every relative link of every README.md under a tree leads to a path that exists (anchors aside).
# Prints "README: target" for each link that does not and exits 1 then.
# Usage: readme_links.sh TREE
set -eu
tree=$1
(cd "$tree" && find . -name README.md -not -path './build/*') | while read -r readme; do
  dir=$tree/${readme%/*}
  grep -o '\]([^) ]*)' "$tree/$readme" | sed 's/^](//; s/)$//' | while read -r target; do
    case $target in '' | '#'* | *://* | mailto:*) continue ;; esac
    [ -e "$dir/${target%%#*}" ] || echo "${readme#./}: $target"
  done
done | { if grep .; then exit 1; fi; }
