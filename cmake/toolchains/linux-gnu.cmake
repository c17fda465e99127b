# Cross-compiling for Linux on another CPU with Debian's g++-<cpu>-linux-gnu, the CPU named
# by JOSTLE_CROSS_CPU (aarch64, s390x, ...); programs run under qemu-user (qemu-<cpu>), which
# finds the target's libraries in /usr/<cpu>-linux-gnu. scripts/cross.sh uses it.
if(NOT JOSTLE_CROSS_CPU)
  message(FATAL_ERROR "cmake/toolchains/linux-gnu.cmake needs -DJOSTLE_CROSS_CPU=<cpu>")
endif()
# CMake's own test builds read this file again: they are handed the CPU too.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES JOSTLE_CROSS_CPU)
set(triple ${JOSTLE_CROSS_CPU}-linux-gnu)
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR ${JOSTLE_CROSS_CPU})
set(CMAKE_C_COMPILER ${triple}-gcc)
set(CMAKE_CXX_COMPILER ${triple}-g++)
set(CMAKE_FIND_ROOT_PATH /usr/${triple})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-${JOSTLE_CROSS_CPU} -L /usr/${triple})
