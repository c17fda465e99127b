#!/usr/bin/env bash
# The shared library's ABI, as a list of what it exports (docs/packaging.md):
#   scripts/abi.sh check LIB     fails if LIB (libjostle.so) lost a symbol that its ABI's
#                                list, abi/libjostle.so.<abi>.symbols, holds, or its
#                                soname's ABI has no list
#   scripts/abi.sh record LIB    writes that list from LIB: once per ABI, at its first release
# (JOSTLE_ABI_DIR names another directory of lists: the test of the check itself.)
# The list holds the functions and data the library defines (nm's T, D, B, R) and the type
# information of its exceptions (V), each with its version node; not the inline functions
# (W, u), which a program compiles for itself. A symbol may be added within an ABI, never
# removed or changed: then JOSTLE_ABI_VERSION (CMakeLists.txt) changes and a list is recorded.
set -euo pipefail
action=$1 lib=$2
cd "$(dirname "$0")/.."
soname=$(readelf -d "$lib" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')
[ -n "$soname" ] || { echo "$lib has no soname"; exit 1; }
list=${JOSTLE_ABI_DIR:-abi}/$soname.symbols
exported() { nm -D --defined-only --with-symbol-versions "$lib" | awk '$2 ~ /^[TDBRV]$/ {print $3}' | sort -u; }
case $action in
  record) exported >"$list"; echo "recorded $(wc -l <"$list") symbols in $list" ;;
  check)
    [ -f "$list" ] || { echo "no $list: a new ABI ($soname) is recorded with scripts/abi.sh record $lib"; exit 1; }
    lost=$(comm -23 "$list" <(exported))
    if [ -n "$lost" ]; then
      echo "$soname lost what $list says it exports; the ABI changed, so JOSTLE_ABI_VERSION"
      echo "(CMakeLists.txt) must change and the new ABI's list be recorded:"
      echo "$lost" | c++filt | sed 's/^/  /'
      exit 1
    fi
    echo "$soname exports all $(wc -l <"$list") symbols of $list ($(exported | wc -l) now)" ;;
  *) echo "usage: scripts/abi.sh check|record LIB"; exit 2 ;;
esac
