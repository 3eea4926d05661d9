# The two commands of the README: `make run` and `make test`. Both install the
# Debian packages the build needs when they are missing, then build into build/.
BUILD ?= build
JOBS ?= $(shell nproc)
DEBIAN_PACKAGES = cmake make g++ antlr4 default-jre-headless libantlr4-runtime-dev libfmt-dev catch2 libcli11-dev nlohmann-json3-dev libpugixml-dev
EXAMPLE ?= programs/bottle_counter.st
RUN_ARGS ?= --virtual --cycles 2000 --dump

.PHONY: deps build run test bench clean

deps:
	@missing=""; for p in $(DEBIAN_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  if [ "$$(id -u)" -eq 0 ]; then SUDO=""; else SUDO=sudo; fi; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; \
	fi

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS)

run: build
	$(BUILD)/strun run $(RUN_ARGS) $(EXAMPLE)

test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

bench: build
	benchmarks/run.sh $(BUILD)/strun

clean:
	rm -rf $(BUILD)
