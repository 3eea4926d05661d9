# The two commands of the README: `make run` and `make test`. Both install the
# Debian packages the build needs when they are missing, then build into build/.
BUILD ?= build
JOBS ?= $(shell nproc)
# Tests run two per core: a third of the suite's time is waiting (npm
# installs, real-time runs, sockets, a browser), and with -j$(JOBS) the cores
# idled through it (ctest 55 s at -j2, 37 s at -j4 on two cores; decision 0495).
TEST_JOBS ?= $(shell echo $$(( $(JOBS) * 2 )))
DEBIAN_PACKAGES = cmake make g++ antlr4 default-jre-headless libantlr4-runtime-dev libfmt-dev catch2 libcli11-dev nlohmann-json3-dev dpkg-dev libpugixml-dev libcpp-httplib-dev libmodbus-dev
# The live monitor's tests (tests/live/): HTTP clients in Python, the page in headless Chromium driven from Node.
DEBIAN_PACKAGES += python3 chromium nodejs npm
# Modbus TCP's tests and example (tests/modbus/, programs/modbus_bench/): pymodbus as the peer.
DEBIAN_PACKAGES += python3-pymodbus python3-serial-asyncio
# The editor set-ups of docs/editors.md, tried by tests/editors/editor_setups: Neovim's built-in LSP client, Emacs with eglot.
DEBIAN_PACKAGES += neovim emacs-nox elpa-eglot
EXAMPLE ?= programs/bottle_counter.st
RUN_ARGS ?= --virtual --cycles 2000 --dump

.PHONY: deps build build-strun build-installed run test bench package install clean check-deep fuzz fuzz-smoke

deps:
	@missing=""; for p in $(DEBIAN_PACKAGES); do \
	  case $$p in nodejs) command -v node >/dev/null 2>&1 && continue;; npm) command -v npm >/dev/null 2>&1 && continue;; esac; \
	  dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  if [ "$$(id -u)" -eq 0 ]; then SUDO=""; else SUDO=sudo; fi; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; \
	fi

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS)

# Only the executable (not the unit tests and tools that `build` makes): what
# `run` needs, and the quickest way to a working strun from a fresh clone.
build-strun: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS) --target strun

run: build-strun
	$(BUILD)/strun run $(RUN_ARGS) $(EXAMPLE)

test: build
	cd $(BUILD) && ctest --output-on-failure -j$(TEST_JOBS)

bench: build-strun
	benchmarks/run.sh $(BUILD)/strun
	benchmarks/vcd/run_vcd_bench.sh $(BUILD)/strun
	benchmarks/startup.sh $(BUILD)/strun

# Only what `install` and `package` put in place: strun and its manual page
# (not the unit tests and tools that `build` makes).
build-installed: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS) --target strun man

# A Debian package of strun and its documentation, in $(BUILD)/ (CPack).
package: build-installed
	cd $(BUILD) && cpack -G DEB

# Installs strun (stripped of its symbols), its manual page and its
# documentation under PREFIX (default /usr/local).
PREFIX ?= /usr/local
install: build-installed
	cmake --install $(BUILD) --prefix $(PREFIX) --strip

# ASan + UBSan build of everything, then the whole ctest suite under them
# (docs/fuzzing.md). Too slow for CI on 2 cores: run it before a release.
check-deep: deps
	cmake -S . -B build-deep -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTRUN_SANITIZE=ON
	cmake --build build-deep -j$(JOBS)
	cd build-deep && ASAN_OPTIONS=detect_leaks=0 STRUN_SLOW_FACTOR=4 ctest --output-on-failure -j$(JOBS)

# libFuzzer (clang): three targets in build-fuzz/tests/fuzz/, run side by side
# for FUZZ_SECONDS each: fuzz_compile_run (ST, with the ST dictionary and the
# conformance programs as seeds), fuzz_xml (PLCopen XML and TwinCAT objects,
# the tests' XML files as seeds) and fuzz_retain (retain files, its program's
# own valid file as seed). FUZZ_SECONDS=60 for a smoke run.
FUZZ_SECONDS ?= 3600
FUZZ_FLAGS = -max_len=4096 -timeout=30 -rss_limit_mb=2048 -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1
fuzz: deps
	@command -v clang++ >/dev/null || { echo "make fuzz needs clang (apt-get install clang)"; exit 2; }
	cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DSTRUN_FUZZ=ON
	cmake --build build-fuzz -j$(JOBS) --target fuzz_compile_run fuzz_xml fuzz_retain
	mkdir -p build-fuzz/corpus build-fuzz/corpus-xml build-fuzz/corpus-retain build-fuzz/retain-seed
	cd build-fuzz && export ASAN_OPTIONS=detect_leaks=0:quarantine_size_mb=64; \
	  tests/fuzz/fuzz_compile_run corpus fuzz-seeds -dict=../tests/fuzz/st.dict $(FUZZ_FLAGS) -artifact_prefix=st- > fuzz-st.log 2>&1 & st=$$!; \
	  tests/fuzz/fuzz_xml corpus-xml fuzz-xml-seeds $(FUZZ_FLAGS) -artifact_prefix=xml- > fuzz-xml.log 2>&1 & xml=$$!; \
	  STRUN_FUZZ_RETAIN_SEED=retain-seed/valid.retain tests/fuzz/fuzz_retain corpus-retain retain-seed $(FUZZ_FLAGS) -artifact_prefix=retain- > fuzz-retain.log 2>&1 & retain=$$!; \
	  status=0; for pid in $$st $$xml $$retain; do wait $$pid || status=1; done; \
	  tail -n 12 fuzz-st.log fuzz-xml.log fuzz-retain.log; exit $$status

fuzz-smoke:
	$(MAKE) fuzz FUZZ_SECONDS=60

clean:
	rm -rf $(BUILD) build-deep build-fuzz
