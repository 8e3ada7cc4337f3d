# Thin wrapper over CMake. `make demo` and `make test` work on a fresh Debian 12 machine as root.
BUILD      ?= build
SANITIZE_BUILD ?= build-sanitize
JOBS       ?= $(shell nproc)
PACKAGES   := cmake g++ make libopenvdb-dev libboost-iostreams-dev liblua5.4-dev libopenmesh-dev libvtk9-dev \
              libtbb-dev lib3mf-dev libgtest-dev libgmock-dev libbenchmark-dev python3-vtk9 xvfb xauth libgl1-mesa-dri \
              libglx-mesa0 librsvg2-bin clang-format ghostscript python3-openvdb paraview libjs-three
# Only `make test` installs these: GNU parallel and a Slurm with munge, which the sweep tests start on
# localhost in a temporary folder (tests/cli/check_slurm.sh), and headless Chromium with Selenium for the
# studio's browser test (tests/browser/check_studio.py), and PrusaSlicer, whose command line slices every print
# example (tests/print/check_slicer.py). selfsim itself never needs them.
TEST_PACKAGES := parallel slurmctld slurmd slurm-client munge chromium chromium-driver python3-selenium prusa-slicer
# ParaView's Python modules, unpacked from Debian's python3-paraview (never installed: it conflicts with
# python3-vtk9, which libvtk9-dev needs) for scripts/pvbatch-selfsim. README: "ParaView and selfsim on one machine".
PARAVIEW_PYTHON ?= /opt/selfsim/paraview-python
# Only `make fuzz` installs these (clang with libFuzzer and the sanitizer runtimes); `make test` never does.
FUZZ_PACKAGES := clang-14 libclang-rt-14-dev
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60

.PHONY: deps build demo test sanitize bench fuzz clean

# Installs only what is missing: one dpkg query when everything is there. Never removes a package (apt's
# --no-remove); if what is missing would remove an installed python3-paraview, changes nothing and says why.
# Then unpacks python3-paraview's modules (same version as paraview) into $(PARAVIEW_PYTHON), unless they are
# there or python3-paraview is installed as a package.
deps:
	@missing=$$(for p in $(PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  apt-get update -qq || exit 1; \
	  if dpkg-query -W -f='$${Status}\n' python3-paraview 2>/dev/null | grep -q 'install ok installed' && \
	     apt-get install -s --no-install-recommends $$missing 2>/dev/null | grep -q '^Remv python3-paraview '; then \
	    echo "make deps: changed nothing. Installing" $$missing "would remove python3-paraview, which is installed" \
	         "here and conflicts with python3-vtk9 (libvtk9-dev, which selfsim builds with, needs it). See" \
	         "README.md, section \"ParaView and selfsim on one machine\"." >&2; \
	    exit 1; \
	  fi; \
	  echo "installing:" $$missing; \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends --no-remove $$missing || exit 1; \
	fi; \
	pv=$$(dpkg-query -W -f='$${Version}' paraview); \
	if [ ! -f /usr/lib/python3/dist-packages/paraview/simple.py ] && \
	   [ "$$(cat $(PARAVIEW_PYTHON)/.selfsim-version 2>/dev/null)" != "$$pv" ]; then \
	  echo "unpacking python3-paraview $$pv's modules into $(PARAVIEW_PYTHON)"; \
	  tmp=$$(mktemp -d) && chown _apt "$$tmp" 2>/dev/null; \
	  ( cd "$$tmp" && { apt-get download -qq python3-paraview=$$pv || { apt-get update -qq && apt-get download -qq python3-paraview=$$pv; }; } && \
	    dpkg-deb -x python3-paraview_*.deb unpacked && \
	    rm -rf $(PARAVIEW_PYTHON) && mkdir -p $$(dirname $(PARAVIEW_PYTHON)) && \
	    mv unpacked/usr/lib/python3/dist-packages $(PARAVIEW_PYTHON) && \
	    echo "$$pv" > $(PARAVIEW_PYTHON)/.selfsim-version ); \
	  status=$$?; rm -rf "$$tmp"; exit $$status; \
	fi

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

# The selfsim executable and its plugins only (what `demo` runs); `test` builds the unit tests too.
build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target selfsim

# Runs the gallery (examples/gallery.lua: one result of each part of selfsim), draws a PNG of each output
# with `selfsim preview` (and of each growth every step, NAME.steps.png, and its animation, NAME.apng),
# and renders the run's ParaView view (out/view.py) to out/view.png with pvbatch.
demo: deps build
	rm -rf out
	$(BUILD)/selfsim run examples/gallery.lua -o out
	$(BUILD)/selfsim preview --steps out/*.svg out/*.vtp out/*.stl out/*.pvd
	SELFSIM_PARAVIEW_PYTHON=$(PARAVIEW_PYTHON) scripts/pvbatch-selfsim out/view.py --png out/view.png
	@echo
	@echo "Done: $$(find out -type f | wc -l) files in $$(pwd)/out: .png pictures of everything, .svg for a browser, .vtp and"
	@echo ".pvd time series for ParaView, .stl for a slicer. Open the whole gallery in ParaView, as designed:"
	@echo "    scripts/pvbatch-selfsim --gui out/view.py     (or: paraview --script=out/view.py)"

test: build
	@$(MAKE) --no-print-directory deps PACKAGES="$(PACKAGES) $(TEST_PACKAGES)"
	cmake --build $(BUILD) -j $(JOBS)
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

sanitize: deps
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSELFSIM_SANITIZE=ON
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	# errors.volume_vdb_crafted: under ASan's allocator the crafted file trips the reader's 3 s limit before
	# its memory limit, the same refusal in other words ("did not finish within 3 seconds").
	# tests/lsan.supp: leaks inside Debian's libraries (lib3mf's reader through libzip).
	cd $(SANITIZE_BUILD) && LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp ctest --output-on-failure -j $(JOBS) -LE viewer -E '^errors\.volume_vdb_crafted$$'

bench: deps
	cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DSELFSIM_BENCH=ON
	cmake --build build-bench -j $(JOBS)
	build-bench/bench/selfsim_bench

# libFuzzer targets (fuzz/README.md) built with clang in $(FUZZ_BUILD)/, never in the main build: replays
# fuzz/regressions/, fuzzes each target for FUZZ_SECONDS, and turns each new crash or hang into a
# regression input. Fails if any regression input still fails or anything new was found.
fuzz:
	@$(MAKE) --no-print-directory deps PACKAGES="$(PACKAGES) $(FUZZ_PACKAGES)"
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 -DSELFSIM_FUZZ=ON -DSELFSIM_PLUGINS=OFF
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_all
	FUZZ_SECONDS=$(FUZZ_SECONDS) fuzz/run.sh $(FUZZ_BUILD)

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) build-bench out
