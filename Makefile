# SPDX-License-Identifier: GPL-3.0-or-later
# robuterd — top-level entry points; CMake and ctest do the work underneath.
BUILD    ?= build
SAN_BUILD ?= build-san
GEN      := -G Ninja
JOBS     ?= $(shell nproc)
DEPS     := tools/deps/ensure.sh tools/deps/debian-packages.txt
PTY      ?= /tmp/robuter.pty
PREFIX   ?= /usr/local
SHELL    := /bin/bash
RUN_ARGS ?= --sim --pty $(PTY)

# Cross builds (docs/INSTALL.md): CROSS=aarch64-linux-gnu or arm-linux-gnueabihf (aliases arm64,
# aarch64, armhf) builds into build-$(CROSS) with Debian's cross toolchain; tests run under qemu-user.
ifeq ($(CROSS),armhf)
override CROSS := arm-linux-gnueabihf
endif
ifneq ($(filter arm64 aarch64,$(CROSS)),)
override CROSS := aarch64-linux-gnu
endif
CROSS_TRIPLET := $(or $(CROSS),aarch64-linux-gnu)
CROSS_BUILD   := build-$(CROSS_TRIPLET)
CROSS_CMAKE   := -DCMAKE_TOOLCHAIN_FILE=$(CURDIR)/cmake/toolchains/$(CROSS_TRIPLET).cmake -DROBUTER_BENCH=OFF
# armhf compiles against an extracted armhf root, not multiarch (tools/deps/cross.sh says why).
ARMHF_SYSROOT ?= $(or $(XDG_CACHE_HOME),$(HOME)/.cache)/robuterd-armhf-root
ifeq ($(CROSS_TRIPLET),arm-linux-gnueabihf)
CROSS_CMAKE   := -DCMAKE_TOOLCHAIN_FILE=$(CURDIR)/cmake/toolchains/arm-linux-gnueabihf-sysroot.cmake \
                 -DROBUTER_SYSROOT=$(ARMHF_SYSROOT) -DROBUTER_BENCH=OFF
export ROBUTER_ARMHF_SYSROOT := $(ARMHF_SYSROOT)
endif
ifneq ($(CROSS),)
BUILD := $(CROSS_BUILD)
endif

.PHONY: all deps build run test test-fast test-san bench fuzz install clean test-cross deb test-package test-vm

all: build

deps:
	@$(DEPS)

ifeq ($(CROSS),)
$(BUILD)/build.ninja:
	cmake -S . -B $(BUILD) $(GEN) -DCMAKE_BUILD_TYPE=RelWithDebInfo
endif

# The cross build folder: target architecture, toolchain, qemu-user and libraries first (as root).
$(CROSS_BUILD)/build.ninja:
	tools/deps/cross.sh $(CROSS_TRIPLET)
	cmake -S . -B $(CROSS_BUILD) $(GEN) -DCMAKE_BUILD_TYPE=RelWithDebInfo $(CROSS_CMAKE)

# The pure unit suites (ctest label `unit`) of the cross build, run under qemu-user; only their
# targets are built. The whole-firmware, pty and tool tests are left to the native `make test`.
test-cross: $(CROSS_BUILD)/build.ninja
	tools/deps/cross.sh $(CROSS_TRIPLET)
	cmake --build $(CROSS_BUILD) -j $(JOBS) --target robuter_unit_tests
	cd $(CROSS_BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 900 -L unit

build: $(BUILD)/build.ninja
	cmake --build $(BUILD) -j $(JOBS)

# Build and run the firmware on the simulated robot; a client attaches to $(PTY).
run: deps build
	$(BUILD)/bin/robuterd $(RUN_ARGS)

# The whole suite: the normal build, then the same tests under ASan and UBSan; the last line
# adds both up ("N passed, N failed"). The sanitizer tree is a unity build (docs/TESTING.md).
test: deps
	@set -o pipefail; $(MAKE) --no-print-directory test-fast 2>&1 | tee $(BUILD).test.log; a=$$?; \
	 set -o pipefail; $(MAKE) --no-print-directory test-san 2>&1 | tee $(SAN_BUILD).test.log; b=$$?; \
	 tools/test/summary.sh $(BUILD).test.log $(SAN_BUILD).test.log && [[ $$a -eq 0 && $$b -eq 0 ]]

test-fast: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 600

$(SAN_BUILD)/build.ninja:
	cmake -S . -B $(SAN_BUILD) $(GEN) -DCMAKE_BUILD_TYPE=Debug -DROBUTER_SANITIZE=ON -DROBUTER_BENCH=OFF -DCMAKE_UNITY_BUILD=ON

test-san: $(SAN_BUILD)/build.ninja
	cmake --build $(SAN_BUILD) -j $(JOBS)
	cd $(SAN_BUILD) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --output-on-failure -j $(JOBS) --timeout 900 -LE no-san

# Fuzz the protocol codec: FUZZ_TIME seconds per target (default 600), or FUZZ_RUNS executions.
FUZZ_TIME ?= 600
fuzz: deps
	tools/fuzz/run.sh $(if $(FUZZ_RUNS),-runs=$(FUZZ_RUNS),$(FUZZ_TIME))

bench: deps build
	@tools/deps/ensure.sh tools/deps/bench-packages.txt
	cmake --build $(BUILD) -j $(JOBS) --target robuter_bench_programs
	@ROBUTER_BUILD=$(BUILD) tools/bench/run.sh

# The prefix is set at configure time: the unit and the config paths depend on it (docs/INSTALL.md).
install: build
	cmake -S . -B $(BUILD) -DCMAKE_INSTALL_PREFIX=$(PREFIX)
	cmake --build $(BUILD) -j $(JOBS)
	cmake --install $(BUILD)

# The Debian package, built with debhelper from a copy of the tree (tests off); the .deb goes to
# $(DEB_DIR)/robuterd_<version>_<arch>.deb.
# ARCH=arm64 cross-builds it (dpkg-buildpackage -a arm64, the toolchain and arm64 libraries of
# `make CROSS=arm64` first) into build-deb-arm64.
NATIVE_ARCH := $(shell dpkg --print-architecture)
ARCH ?= $(NATIVE_ARCH)
DEB_CROSS := $(filter-out $(NATIVE_ARCH),$(ARCH))
DEB_DIR ?= build-deb$(if $(DEB_CROSS),-$(ARCH))
deb:
	@tools/deps/ensure.sh tools/deps/debian-packages.txt tools/deps/package-packages.txt
	$(if $(DEB_CROSS),tools/deps/cross.sh $(if $(filter arm64,$(ARCH)),aarch64-linux-gnu,$(ARCH)))
	rm -rf $(DEB_DIR) && mkdir -p $(DEB_DIR)/src
	git ls-files -co --exclude-standard -z | tar --null --ignore-failed-read -T - -cf - | tar -xf - -C $(DEB_DIR)/src
	cd $(DEB_DIR)/src && DEB_BUILD_OPTIONS="nocheck parallel=$(JOBS)" dpkg-buildpackage -b -us -uc $(if $(DEB_CROSS),-a $(ARCH))
	@ls -l $(DEB_DIR)/*.deb

# Installs the package on this machine (root), checks it and starts its service as systemd
# would, talks to robuterd over the service's pty, stops it and purges the package. Minutes, so
# not part of `make test`.
test-package: deb
	tools/test/package_test.py $$(ls $(DEB_DIR)/robuterd_*.deb | grep -v dbgsym)

# The package on real Linux (stays out of `make test`): a Debian 12 guest built once with mmdebstrap
# and cached in ~/.cache/robuterd-vm boots under QEMU (TCG; KVM where a probe shows it boots), installs
# the .deb and checks robuterd under systemd on a real kernel's SocketCAN (docs/INSTALL.md).
# ARCH=arm64: the arm64 package in an arm64 guest (qemu-system-aarch64, TCG).
test-vm: deb
	@tools/deps/ensure.sh tools/deps/vm-packages.txt $(if $(DEB_CROSS),tools/deps/vm-arm64-packages.txt)
	tools/vm/run.sh $$(ls $(DEB_DIR)/robuterd_*.deb | grep -v dbgsym)

clean:
	rm -rf $(BUILD) $(SAN_BUILD) $(BUILD).test.log $(SAN_BUILD).test.log
