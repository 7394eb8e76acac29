# SPDX-License-Identifier: GPL-3.0-or-later
# Shared part of the Debian cross toolchain files: compilers, multiarch search paths, pkg-config, qemu-user.
# The including file sets ROBUTER_CROSS_TRIPLET (GNU triplet) and ROBUTER_CROSS_PROCESSOR (uname -m),
# ROBUTER_CROSS_QEMU (the qemu-user program's suffix: aarch64, arm).
#
# Debian's cross compilers (g++-<triplet>) find the target libraries installed through multiarch
# (/usr/lib/<triplet>, /usr/include/<triplet>), so the sysroot is the host's "/" and CMake only
# needs to be told the library architecture. Tests run under qemu-user through
# CMAKE_CROSSCOMPILING_EMULATOR (ctest and gtest_discover_tests both use it).

set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR ${ROBUTER_CROSS_PROCESSOR})
set(CMAKE_C_COMPILER ${ROBUTER_CROSS_TRIPLET}-gcc)
set(CMAKE_CXX_COMPILER ${ROBUTER_CROSS_TRIPLET}-g++)
set(CMAKE_LIBRARY_ARCHITECTURE ${ROBUTER_CROSS_TRIPLET})

# Search the multiarch folders of the target only for libraries, headers and CMake packages;
# programs (pkg-config, qemu, the compilers) are the host's.
set(CMAKE_FIND_ROOT_PATH /)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)

# pkgconf's per-triplet personality looks in /usr/lib/<triplet>/pkgconfig and /usr/share/pkgconfig.
set(PKG_CONFIG_EXECUTABLE /usr/bin/${ROBUTER_CROSS_TRIPLET}-pkg-config CACHE FILEPATH "pkg-config for the target")

# qemu-user runs the target's programs with "/" as the prefix: the loader and every library come
# from the multiarch packages (libc6:<arch> …) the target -dev packages pulled in. Not
# -L /usr/<triplet>: that is the cross toolchain's own glibc build (libc6-<arch>-cross), whose
# loader then runs with the multiarch libc.so.6 of another build, and thread creation hangs
# (docs/INSTALL.md, "Cross builds").
find_program(ROBUTER_QEMU NAMES qemu-${ROBUTER_CROSS_QEMU} qemu-${ROBUTER_CROSS_QEMU}-static)
if(ROBUTER_QEMU)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${ROBUTER_QEMU} -L /)
endif()
