# SPDX-License-Identifier: GPL-3.0-or-later
# CMake toolchain file: Debian's aarch64 (arm64) cross compiler, tests under qemu-aarch64 (docs/INSTALL.md).
set(ROBUTER_CROSS_TRIPLET aarch64-linux-gnu)
set(ROBUTER_CROSS_PROCESSOR aarch64)
set(ROBUTER_CROSS_QEMU aarch64)
include(${CMAKE_CURRENT_LIST_DIR}/debian-cross.cmake)
