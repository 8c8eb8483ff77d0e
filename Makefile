# frictionlab: the two commands of the quick start, and a few more for developers.
#   make demo   install what is missing, build, identify friction on the bundled EMPS data, write a report
#   make test   install what is missing, build, run every test (C++, CLI, Python, examples)
# Others: make build, make sanitize (tests under ASan+UBSan), make bench, make install-test, make clean.

BUILD      ?= build
JOBS       ?= $(shell nproc)
PYTHON     ?= /usr/bin/python3
CMAKE_ARGS ?=
CONFIGURE   = cmake -S . -B $(1) -DPython_EXECUTABLE=$(PYTHON) $(CMAKE_ARGS) $(2) >/dev/null
# Inherited by cmake's own makes: the build prints its progress, not "Entering directory" lines.
MAKEFLAGS  += --no-print-directory

.PHONY: all deps build test demo sanitize bench install-test clean

all: build

deps:
	@bash scripts/setup.sh

build: deps
	@$(call CONFIGURE,$(BUILD),-DCMAKE_BUILD_TYPE=Release)
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory install-test

demo: build
	@bash examples/demo.sh $(BUILD)

sanitize: deps
	@$(call CONFIGURE,$(BUILD)-sanitize,-DCMAKE_BUILD_TYPE=RelWithDebInfo -DFRICTIONLAB_SANITIZE=ON -DFRICTIONLAB_BUILD_PYTHON=OFF)
	@cmake --build $(BUILD)-sanitize -j $(JOBS)
	@cd $(BUILD)-sanitize && ctest --output-on-failure -j $(JOBS) -LE python

bench: deps
	@$(call CONFIGURE,$(BUILD)-bench,-DCMAKE_BUILD_TYPE=Release -DFRICTIONLAB_BUILD_BENCHMARKS=ON -DFRICTIONLAB_BUILD_TESTS=OFF)
	@cmake --build $(BUILD)-bench -j $(JOBS) --target frictionlab_bench frictionlab_compare
	@$(BUILD)-bench/bench/frictionlab_bench
	@$(PYTHON) bench/compare --build $(BUILD)-bench --no-build --json bench/results.json

# Installs the library into a scratch prefix and builds a consumer with find_package(frictionlab).
install-test: build
	@bash tests/install/run.sh $(BUILD)

clean:
	rm -rf $(BUILD) $(BUILD)-sanitize $(BUILD)-bench
