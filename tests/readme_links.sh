#!/bin/sh
# Every relative link of every README.md under a tree, and of every guide docs/*.md, leads to a
# path that exists, and its anchor, where it names one in a Markdown file, to a heading there.
# Prints "PAGE: target" for each link that does not and exits 1 then.
# Usage: readme_links.sh TREE
set -eu
tree=$1

# anchors FILE: the anchors of FILE's headings, as GitHub makes them (lower case, punctuation
# dropped, spaces to hyphens), one a line.
anchors() {
  sed -n 's/^#\{1,6\} \{1,\}//p' "$1" | tr 'A-Z' 'a-z' | sed 's/[^a-z0-9 _-]//g; s/ /-/g'
}

(cd "$tree" && find . \( -name README.md -o -path './docs/*.md' \) -not -path './build/*') | while read -r page; do
  dir=$tree/${page%/*}
  grep -o '\]([^) ]*)' "$tree/$page" | sed 's/^](//; s/)$//' | while read -r target; do
    case $target in '' | *://* | mailto:*) continue ;; esac
    file=${target%%#*}
    [ -n "$file" ] || file=${page##*/}
    if [ ! -e "$dir/$file" ]; then
      echo "${page#./}: $target"
      continue
    fi
    case $target in *'#'*) ;; *) continue ;; esac
    case $file in *.md) ;; *) continue ;; esac
    # The anchor as its heading's would be made (letters beyond ASCII dropped on both sides), and
    # without the -N that GitHub appends to a repeated heading.
    anchor=$(printf '%s\n' "${target#*#}" | tr 'A-Z' 'a-z' | sed 's/[^a-z0-9 _-]//g')
    anchors "$dir/$file" | grep -qx -e "$anchor" -e "${anchor%-[0-9]*}" || echo "${page#./}: $target (no such heading)"
  done
done | { if grep .; then exit 1; fi; }
