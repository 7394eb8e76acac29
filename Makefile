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

.PHONY: all deps build run test test-fast test-san bench fuzz install clean

all: build

deps:
	@$(DEPS)

$(BUILD)/build.ninja:
	cmake -S . -B $(BUILD) $(GEN) -DCMAKE_BUILD_TYPE=RelWithDebInfo

build: $(BUILD)/build.ninja
	cmake --build $(BUILD) -j $(JOBS)

# Build and run the firmware on the simulated robot; a client attaches to $(PTY).
run: deps build
	$(BUILD)/bin/robuterd $(RUN_ARGS)

# The whole suite: the normal build, then the same tests under ASan and UBSan; the last line
# adds both up ("N passed, N failed").
test: deps
	@set -o pipefail; $(MAKE) --no-print-directory test-fast 2>&1 | tee $(BUILD).test.log; a=$$?; \
	 set -o pipefail; $(MAKE) --no-print-directory test-san 2>&1 | tee $(SAN_BUILD).test.log; b=$$?; \
	 tools/test/summary.sh $(BUILD).test.log $(SAN_BUILD).test.log && [[ $$a -eq 0 && $$b -eq 0 ]]

test-fast: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 600

$(SAN_BUILD)/build.ninja:
	cmake -S . -B $(SAN_BUILD) $(GEN) -DCMAKE_BUILD_TYPE=Debug -DROBUTER_SANITIZE=ON -DROBUTER_BENCH=OFF

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
	@ROBUTER_BUILD=$(BUILD) tools/bench/run.sh

install: build
	cmake --install $(BUILD) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD) $(SAN_BUILD) $(BUILD).test.log $(SAN_BUILD).test.log
