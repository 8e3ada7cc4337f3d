# Thin wrapper over CMake. `make demo` and `make test` work on a fresh Debian 12 machine as root.
BUILD      ?= build
SANITIZE_BUILD ?= build-sanitize
JOBS       ?= $(shell nproc)
PACKAGES   := cmake g++ make libopenvdb-dev libboost-iostreams-dev liblua5.4-dev libopenmesh-dev libvtk9-dev \
              libtbb-dev libgtest-dev libgmock-dev libbenchmark-dev python3-vtk9 xvfb xauth libgl1-mesa-dri \
              libglx-mesa0 librsvg2-bin clang-format ghostscript python3-openvdb
# Only `make fuzz` installs these (clang with libFuzzer and the sanitizer runtimes); `make test` never does.
FUZZ_PACKAGES := clang-14 libclang-rt-14-dev
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60

.PHONY: deps build demo test sanitize bench fuzz clean

# Installs only what is missing: one dpkg query when everything is there.
deps:
	@missing=$$(for p in $(PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing:" $$missing; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# Runs the gallery, then renders each SVG to a PNG beside it (librsvg) for a quick look.
demo: deps build
	rm -rf out
	$(BUILD)/selfsim run examples/gallery.lua -o out
	@for f in out/*.svg; do rsvg-convert -w 400 -b white "$$f" -o "$${f%.svg}.png"; done
	@echo
	@echo "Done: out/ holds .vtp files (open them in ParaView, colour by 'arclength'), .svg files (any"
	@echo "browser) and .png previews of each: $$(ls out | wc -l) files in $$(pwd)/out"

test: deps build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

sanitize: deps
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSELFSIM_SANITIZE=ON
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	cd $(SANITIZE_BUILD) && ctest --output-on-failure -j $(JOBS) -LE viewer

bench: deps
	cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DSELFSIM_BENCH=ON
	cmake --build build-bench -j $(JOBS)
	build-bench/bench/selfsim_bench

# libFuzzer targets (fuzz/README.md) built with clang in $(FUZZ_BUILD)/, never in the main build: replays
# fuzz/regressions/, fuzzes each target for FUZZ_SECONDS, and turns each new crash or hang into a
# regression input. Fails if any regression input still fails or anything new was found.
fuzz:
	@$(MAKE) --no-print-directory deps PACKAGES="$(PACKAGES) $(FUZZ_PACKAGES)"
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 -DSELFSIM_FUZZ=ON
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_all
	FUZZ_SECONDS=$(FUZZ_SECONDS) fuzz/run.sh $(FUZZ_BUILD)

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) build-bench out
