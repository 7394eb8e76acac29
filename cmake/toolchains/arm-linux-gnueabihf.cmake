# SPDX-License-Identifier: GPL-3.0-or-later
# CMake toolchain file: Debian's armhf (32-bit ARMv7, hard float) cross compiler, tests under qemu-arm (docs/INSTALL.md).
set(ROBUTER_CROSS_TRIPLET arm-linux-gnueabihf)
set(ROBUTER_CROSS_PROCESSOR armv7l)
set(ROBUTER_CROSS_QEMU arm)
include(${CMAKE_CURRENT_LIST_DIR}/debian-cross.cmake)
