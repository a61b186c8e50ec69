# SPDX-License-Identifier: MIT
# An example toolchain file for GCC's arm-none-eabi (Debian:
# gcc-arm-none-eabi), bare metal:
#
#   cmake -B build/m0 -DCMAKE_TOOLCHAIN_FILE=path/to/fixtrace/cmake/arm-none-eabi.cmake \
#         -DFIXTRACE_CPU="-mcpu=cortex-m0 -mthumb"
#
# FIXTRACE_CPU holds the code generation flags (PLATFORM.md has those of
# the M0, M3, M4F and M33); the default is the Cortex-M0, the smallest.
# Executables link with -nostdlib (there is no newlib here) and need a
# linker script, the startup code and memcpy/memset/memmove of your own
# (fixtrace's port/baremetal/ has ready ones); add -lgcc last, for the
# 64-bit multiply and divide helpers of the M0.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(FIXTRACE_CPU "-mcpu=cortex-m0 -mthumb" CACHE STRING
    "Code generation flags for the target CPU")

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-ar)
set(CMAKE_RANLIB arm-none-eabi-ranlib)
# Without a C library the compiler checks cannot link a program.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(CMAKE_C_FLAGS_INIT "${FIXTRACE_CPU}")
set(CMAKE_ASM_FLAGS_INIT "${FIXTRACE_CPU}")
set(CMAKE_EXE_LINKER_FLAGS_INIT
    "${FIXTRACE_CPU} -nostdlib -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
