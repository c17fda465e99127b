#!/usr/bin/env bash
# The map is true to the tree: every file a doc names in backquotes (`src/ground.hpp`,
# `physical/corners.cpp`, `contacts.cpp`, `src/box_grid.*`) exists, looked for from the top
# of the tree, then in src/, src/physical/ and docs/. Names the first that does not.
#   check_paths.sh SOURCE_DIR DOC...
set -euo pipefail
root=$1
shift
status=0
for doc in "$@"; do
  while IFS= read -r name; do
    found=0
    for base in "$root" "$root/src" "$root/src/physical" "$root/docs"; do
      # A trailing .* means any extension (src/box_grid.* is its .hpp and .cpp).
      if compgen -G "$base/$name" >/dev/null; then
        found=1
        break
      fi
    done
    if [ "$found" -eq 0 ]; then
      echo "$doc names \`$name\`, which is not in the tree" >&2
      status=1
    fi
  done < <(grep -o '`[A-Za-z0-9_/.*-]*\.\(cpp\|hpp\|h\|md\|\*\)`' "$root/$doc" | tr -d '`' | sort -u)
done
[ "$status" -eq 0 ] && echo "every file the docs name is in the tree"
exit "$status"
