# Sourced by the tests that use an installed jostle through pkg-config (run_pkgconfig_test.sh,
# tests/packaging/run_deb_test.sh): builds the C and the C++ consumer programs
# (tests/c/consumer, tests/consumer) with the compiler and `pkg-config --cflags --libs jostle`
# alone, PKG_CONFIG_PATH already naming the jostle.pc to use.
#   build_pkgconfig_consumers SOURCE_DIR WORK_DIR CC CXX "CFLAGS" "CXXFLAGS" "LDFLAGS"
# makes WORK_DIR/c_consumer and WORK_DIR/cxx_consumer.
build_pkgconfig_consumers() {
  local source=$1 work=$2 cc=$3 cxx=$4 cflags=$5 cxxflags=$6 ldflags=$7
  # A sanitized clang build's library needs the sanitizers' C++ runtime in a C link too.
  local c_ldflags=$ldflags
  if [[ $ldflags == *-fsanitize* ]] && $cc --version | grep -q clang; then
    c_ldflags="$ldflags -fsanitize-link-c++-runtime"
  fi
  # shellcheck disable=SC2046,SC2086
  $cc $cflags "$source/tests/c/consumer/main.c" -o "$work/c_consumer" $c_ldflags \
    $(pkg-config --cflags --libs jostle)
  # shellcheck disable=SC2046,SC2086
  $cxx -std=c++20 $cxxflags "$source/tests/consumer/main.cpp" -o "$work/cxx_consumer" $ldflags \
    $(pkg-config --cflags --libs jostle)
}

# The level library's consumer (tests/consumer/level.cpp) with `pkg-config --cflags --libs
# jostle-level`: a static library, with pugixml, zlib and zstd after it.
#   build_pkgconfig_level_consumer SOURCE_DIR WORK_DIR CXX "CXXFLAGS" "LDFLAGS"
# makes WORK_DIR/level_consumer.
build_pkgconfig_level_consumer() {
  local source=$1 work=$2 cxx=$3 cxxflags=$4 ldflags=$5
  # shellcheck disable=SC2046,SC2086
  $cxx -std=c++20 $cxxflags "$source/tests/consumer/level.cpp" -o "$work/level_consumer" \
    $ldflags $(pkg-config --cflags --libs jostle-level)
}
