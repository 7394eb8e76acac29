# SPDX-License-Identifier: GPL-3.0-or-later
# CMake toolchain file: Debian's armhf cross compiler against an extracted armhf root (ROBUTER_SYSROOT,
# from `mmdebstrap --variant=extract --architectures=armhf`), not multiarch: this machine's mirror
# serves an inconsistent armhf security index, so armhf -dev packages cannot be installed beside the
# host's (docs/INSTALL.md, "armhf"). Tests run under qemu-arm -L ROBUTER_SYSROOT.
set(ROBUTER_CROSS_TRIPLET arm-linux-gnueabihf)
set(ROBUTER_CROSS_PROCESSOR armv7l)
set(ROBUTER_CROSS_QEMU arm)
include(${CMAKE_CURRENT_LIST_DIR}/debian-cross.cmake)
if(NOT ROBUTER_SYSROOT)
  set(ROBUTER_SYSROOT $ENV{ROBUTER_SYSROOT})
endif()
if(NOT IS_DIRECTORY "${ROBUTER_SYSROOT}/usr/lib/arm-linux-gnueabihf")
  message(FATAL_ERROR "ROBUTER_SYSROOT must name an extracted armhf root (tools/deps/armhf-sysroot.sh)")
endif()
set(CMAKE_SYSROOT ${ROBUTER_SYSROOT})
set(CMAKE_FIND_ROOT_PATH ${ROBUTER_SYSROOT})
set(ENV{PKG_CONFIG_SYSROOT_DIR} ${ROBUTER_SYSROOT})
set(ENV{PKG_CONFIG_LIBDIR} ${ROBUTER_SYSROOT}/usr/lib/arm-linux-gnueabihf/pkgconfig:${ROBUTER_SYSROOT}/usr/share/pkgconfig)
set(PKG_CONFIG_EXECUTABLE /usr/bin/pkg-config CACHE FILEPATH "pkg-config, pointed at the sysroot" FORCE)
if(ROBUTER_QEMU)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${ROBUTER_QEMU} -L ${ROBUTER_SYSROOT})
endif()
