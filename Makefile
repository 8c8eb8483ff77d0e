# frictionlab: the two commands of the quick start, and a few more for developers.
#   make demo   install what is missing, build, identify friction on the bundled EMPS data, write a report
#   make test   install what is missing, build, run every test (C++, CLI, Python, examples)
# Others: make build, make docs (the documentation site in $(BUILD)/docs/html), make sanitize (tests under
# ASan+UBSan), make bench, make install-test,
# make coverage (the whole coverage table of idim's standard deviations, docs/coverage.md),
# make fuzz (the libFuzzer targets of tests/fuzz, FUZZ_SECONDS each, and the seeded property tests with
# FUZZ_PROPERTY_CASES cases: make fuzz-properties), make fuzz-merge, make clean.

BUILD      ?= build
JOBS       ?= $(shell nproc)
PYTHON     ?= /usr/bin/python3
CMAKE_ARGS ?=
CONFIGURE   = cmake -S . -B $(1) -DPython_EXECUTABLE=$(PYTHON) $(CMAKE_ARGS) $(2) >/dev/null
# Inherited by cmake's own makes: the build prints its progress, not "Entering directory" lines.
MAKEFLAGS  += --no-print-directory
# ccache (when installed) keys objects by paths relative to the checkout, so clones share them.
export CCACHE_BASEDIR ?= $(CURDIR)
# The fuzzers (tests/fuzz): a Clang build of their own; seconds per target in make fuzz and in make test.
FUZZ_BUILD        ?= build-fuzz
FUZZ_SECONDS      ?= 600
FUZZ_TEST_SECONDS ?= 15
FUZZERS            = fuzz_csv fuzz_mat fuzz_scenario fuzz_law fuzz_merge fuzz_simulate

.PHONY: all deps build test docs demo sanitize bench install-test coverage gallery clean fuzz-build fuzz fuzz-test fuzz-merge fuzz-properties

all: build

deps:
	@bash scripts/setup.sh

build: deps
	@$(call CONFIGURE,$(BUILD),-DCMAKE_BUILD_TYPE=Release)
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory install-test
	@$(MAKE) --no-print-directory fuzz-test

# The documentation site: docs/*.md and the generated references (CLI, methods, Python, C++), with
# Sphinx + MyST and Doxygen, warnings as errors (tests/docs/build_site.py; ctest docs.site).
docs: build
	@$(PYTHON) tests/docs/build_site.py $(CURDIR) $(BUILD)
	@echo "site: $(BUILD)/docs/html/index.html"

demo: build
	@bash examples/demo.sh $(BUILD)

sanitize: deps
	@$(call CONFIGURE,$(BUILD)-sanitize,-DCMAKE_BUILD_TYPE=RelWithDebInfo -DFRICTIONLAB_SANITIZE=ON -DFRICTIONLAB_BUILD_PYTHON=OFF)
	@cmake --build $(BUILD)-sanitize -j $(JOBS)
	@cd $(BUILD)-sanitize && ctest --output-on-failure -j $(JOBS) -LE python

bench: deps
	@$(call CONFIGURE,$(BUILD)-bench,-DCMAKE_BUILD_TYPE=Release -DFRICTIONLAB_BUILD_BENCHMARKS=ON -DFRICTIONLAB_BUILD_TESTS=OFF)
	@cmake --build $(BUILD)-bench -j $(JOBS) --target frictionlab_bench frictionlab_compare frictionlab_cli frictionlab_python
	@$(BUILD)-bench/bench/frictionlab_bench
	@$(PYTHON) bench/compare --build $(BUILD)-bench --no-build --json bench/results.json

# The coverage of idim's 95 % intervals on every synthetic rig cell (tests/rigs/idim_coverage.py;
# make test runs a fast subset): the table goes to $(BUILD)/coverage.md and is compared with
# docs/coverage.md, cell by cell (tests/rigs/coverage_table.py: a difference fails, naming the cell); then
# breakaway's coverage and the residual checks' warning rates (lugre's full 100 + 100 records,
# make test runs 10 + 10), printed.
COVERAGE_CASES ?= 100
coverage: build
	@PYTHONPATH=$(BUILD)/python $(PYTHON) tests/rigs/idim_coverage.py --cells all --cases $(COVERAGE_CASES) \
		--markdown $(BUILD)/coverage.md --compare docs/coverage.md || { echo "table: $(BUILD)/coverage.md"; exit 1; }
	@echo "table: $(BUILD)/coverage.md (its rows are those of docs/coverage.md)"
	@cd $(BUILD) && FRICTIONLAB_FULL_RATES=1 ./tests/test_identify --gtest_filter='ResidualCheckRates.*:BreakawayCoverage.*' \
		| grep -E '^(decay|lugre|breakaway)'

# Installs the library into a scratch prefix and builds a consumer with find_package(frictionlab).
# docs/gallery.md and docs/gallery/*.png: every figure kind, from the bundled data (scripts/gallery.py).
gallery: build
	@$(PYTHON) scripts/gallery.py $(BUILD)

install-test: build
	@bash tests/install/run.sh $(BUILD)

# libFuzzer targets under ASan+UBSan, built with clang++ from the readers' sources only.
fuzz-build: deps
	@$(call CONFIGURE,$(FUZZ_BUILD),-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFRICTIONLAB_BUILD_FUZZERS=ON -DFRICTIONLAB_BUILD_TESTS=OFF -DFRICTIONLAB_BUILD_APP=OFF -DFRICTIONLAB_BUILD_PYTHON=OFF)
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzzers

# Replays every kept regression input, then fuzzes each target FUZZ_SECONDS (crashing inputs are
# copied into tests/fuzz/regressions/ to be committed with the fix); then the seeded property tests
# of the numerics at extreme values and of the C export with many more cases than make test runs.
fuzz: fuzz-build fuzz-properties
	@bash tests/fuzz/run.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(JOBS) keep

# identify.ExtremeValues.* (tests/identify/test_extreme_values.cpp) with FUZZ_PROPERTY_CASES cases,
# and the C export property (tests/cli/contract_c_export_property.sh) with a twentieth of them, on a
# seed drawn from the clock (printed; FRICTIONLAB_PROPERTY_SEED=N repeats a run).
FUZZ_PROPERTY_CASES ?= 20000
fuzz-properties: build
	@FRICTIONLAB_PROPERTY_CASES=$(FUZZ_PROPERTY_CASES) $(BUILD)/tests/test_identify --gtest_filter='ExtremeValues.*'
	@FRICTIONLAB_C_EXPORT_CASES=$$(( $(FUZZ_PROPERTY_CASES) / 20 )) FRICTIONLAB_PROPERTY_SEED=$${FRICTIONLAB_PROPERTY_SEED:-$$(date +%s)} \
	  bash tests/cli/contract_c_export_property.sh $(BUILD)/app/frictionlab $(CURDIR)

# The short run of make test: the regression inputs and the corpus replayed, then a few thousand
# fixed-seed inputs per target (at most FUZZ_TEST_SECONDS each), one PASS/FAIL line each.
fuzz-test: fuzz-build
	@bash tests/fuzz/run.sh $(FUZZ_BUILD) $(FUZZ_TEST_SECONDS) $(JOBS)

# Minimises the committed corpus together with what make fuzz found (libFuzzer -merge=1). The
# hand-made seeds (files with an extension: .csv, .mat, .yaml, .json) are always kept.
fuzz-merge: fuzz-build
	@for t in $(FUZZERS); do \
	  rm -rf $(FUZZ_BUILD)/fuzz/merged/$$t && mkdir -p $(FUZZ_BUILD)/fuzz/merged/$$t $(FUZZ_BUILD)/fuzz/corpus/$$t && \
	  cp tests/fuzz/corpus/$$t/*.* $(FUZZ_BUILD)/fuzz/merged/$$t/ && \
	  $(FUZZ_BUILD)/tests/fuzz/$$t -merge=1 $(FUZZ_BUILD)/fuzz/merged/$$t tests/fuzz/corpus/$$t $(FUZZ_BUILD)/fuzz/corpus/$$t \
	    >$(FUZZ_BUILD)/fuzz/$$t.merge.log 2>&1 || { echo "fuzz-merge: $$t failed (see $(FUZZ_BUILD)/fuzz/$$t.merge.log)"; exit 1; }; \
	  rm -rf tests/fuzz/corpus/$$t && cp -r $(FUZZ_BUILD)/fuzz/merged/$$t tests/fuzz/corpus/$$t && \
	  echo "fuzz-merge: $$t: $$(ls tests/fuzz/corpus/$$t | wc -l) inputs in tests/fuzz/corpus/$$t"; \
	done

clean:
	rm -rf $(BUILD) $(BUILD)-sanitize $(BUILD)-bench $(FUZZ_BUILD)
