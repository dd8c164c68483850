# Convenience wrapper around CMake/CTest. See README.md.
BUILD       ?= build
BUILD_DEBUG ?= build-debug
JOBS        ?= 2

.PHONY: all deps build build-debug run test test-release test-debug clean

all: build

deps:
	@sh tools/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS)

build-debug: deps
	cmake -S . -B $(BUILD_DEBUG) -DCMAKE_BUILD_TYPE=Debug
	cmake --build $(BUILD_DEBUG) -j$(JOBS)

# The tutorial of manual Section 2.1: three batch decks run in order in one folder
# (slope1 writes SLOPE.SAV, slope2 and slope3 restart from it).
# Only the program is built (not the test executables): a first run is quicker.
run: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS) --target udec
	rm -rf $(BUILD)/tutorial && mkdir -p $(BUILD)/tutorial
	cd $(BUILD)/tutorial && for deck in slope1 slope2 slope3; do \
	  $(CURDIR)/$(BUILD)/bin/udec $(CURDIR)/examples/tutorial/$$deck.dat || exit 1; done

test-release: build
	ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS)

test-debug: build-debug
	ctest --test-dir $(BUILD_DEBUG) --output-on-failure -j$(JOBS)

# Every test, in the Release and in the Debug (-fcheck=all, FP traps, sanitizers) builds.
test: test-release test-debug

clean:
	rm -rf $(BUILD) $(BUILD_DEBUG)
