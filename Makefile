# SPDX-License-Identifier: MIT
# The two set-up commands of the README:
#   make demo   install what is missing, build, run the racer demo
#   make test   install what is missing, build, run ctest --preset default
# CI (.ci/run) runs `make test`, then `make test-asan` (the sanitizer pass, below).
# `make deps` alone installs the Debian packages; it skips apt entirely when they are all present.

SHELL := /bin/bash
JOBS  ?= $(shell nproc)
PRESET ?= default
BUILD_DIR := build
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

# Debian 12 packages: compilers and tools, then the libraries found by find_package,
# then Mesa (EGL, the GLES dispatch the gles driver opens, llvmpipe) and Xvfb for the GL backends's headless and windowed tests, Vulkan
# (loader, lavapipe, the validation layers, shaderc) for the Vulkan backend and its tests,
# then the frame-capture tools engine teams use, whose captures of SSAM's frames the tests replay
# (tests/capture/tools: apitrace, with apitrace-tracers' EGL wrapper, for GL; gfxreconstruct 0.9.18,
# capture layer and replayer, for Vulkan), then Node.js for the Khronos glTF Validator the content
# test runs, then the page's toolchain and browser (make web, the browser test: tests/web):
# Emscripten 3.1.6 with binaryen's optimizer, and Chromium's headless shell, which
# puppeteer-core drives (it downloads no browser).
PACKAGES := build-essential cmake pkg-config ccache \
            libglfw3-dev libglm-dev libtinygltf-dev libdraco-dev nlohmann-json3-dev libpng-dev \
            libopenimageio-dev openimageio-tools libtbb-dev \
            libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev \
            libepoxy-dev libstb-dev libegl-dev libgles2 libgl1-mesa-dri libegl1-mesa xvfb xauth \
            libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslc libshaderc-dev spirv-tools \
            clang-format-14 \
            apitrace apitrace-tracers gfxreconstruct \
            emscripten binaryen chromium-headless-shell \
            $(NODE_PACKAGES)
# Debian's nodejs + npm, unless an npm is already on the PATH (e.g. a NodeSource nodejs,
# which bundles npm and which Debian's npm package would try to replace).
NODE_PACKAGES := $(if $(shell command -v npm 2>/dev/null),,nodejs npm)

.PHONY: all deps configure build test test-asan test-tsan format-check format lint demo bench readme-images readme-chart content clean node-tools web-tools web web-picture serve-web fuzz fuzz-campaign

all: build

deps:
	@missing=$$(for p in $(PACKAGES); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -z "$$missing" ]; then echo "deps: all $(words $(PACKAGES)) packages present"; \
	else echo "deps: installing" $$missing; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; fi

configure: deps
	@[ -f $(BUILD_DIR)/CMakeCache.txt ] || cmake --preset $(PRESET)

build: configure
	cmake --build --preset $(PRESET) -j $(JOBS)

# The Khronos glTF Validator (npm gltf-validator) for ctest Content.GltfValidatorFindsNoErrors,
# installed once into the git-ignored $(BUILD_DIR)/node.
GLTF_VALIDATOR := gltf-validator@2.0.0-dev.3.10
node-tools: deps
	@[ -d $(BUILD_DIR)/node/node_modules/gltf-validator ] || \
	  npm install --prefix $(BUILD_DIR)/node --no-audit --no-fund --loglevel=error $(GLTF_VALIDATOR)

# puppeteer-core for the browser test (tests/web/package-lock.json pins it), installed by
# `npm ci` into the git-ignored tests/web/node_modules; it drives Debian's chromium-headless-shell
# and downloads no browser (PUPPETEER_SKIP_DOWNLOAD says so to any that would).
web-tools: deps
	@[ -d tests/web/node_modules/puppeteer-core ] || \
	  PUPPETEER_SKIP_DOWNLOAD=1 npm ci --prefix tests/web --no-audit --no-fund --loglevel=error

# The racer as a web page (README "In a browser"): Emscripten's build in build-web (emcmake;
# game/web/CMakeLists.txt says what it takes and why), its content generated without Draco by the
# native content-generator (the WebAssembly build has no Draco decoder), and the page's files in
# out/web: index.html, racer.js, racer.wasm, racer.data (the content, preloaded) and content/ (the
# same files, for the browser test's native frames). NODE_PATH: Emscripten's JavaScript optimizer
# needs Debian's node-acorn, which a NodeSource node (PATH's, when not Debian's) does not look for.
WEB_BUILD_DIR := build-web
web: configure
	cmake --build --preset $(PRESET) -j $(JOBS) --target content-generator
	$(BUILD_DIR)/bin/content-generator --no-draco --out $(WEB_BUILD_DIR)/content > /dev/null
	@[ -f $(WEB_BUILD_DIR)/CMakeCache.txt ] || emcmake cmake -S . -B $(WEB_BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DSSAM_WERROR=ON
	NODE_PATH=/usr/share/nodejs cmake --build $(WEB_BUILD_DIR) -j $(JOBS) --target racer_page
	@rm -rf out/web && mkdir -p out/web && cp -r $(WEB_BUILD_DIR)/content out/web/content && \
	  cp $(WEB_BUILD_DIR)/bin/racer.js $(WEB_BUILD_DIR)/bin/racer.wasm $(WEB_BUILD_DIR)/bin/racer.data game/web/index.html out/web/
	@echo "web: out/web (make serve-web serves it)"

# out/web on http://127.0.0.1:8080/ only (WEB_PORT=...), with the COOP/COEP headers a threaded
# WebAssembly build would need (tests/web/serve.mjs), until Ctrl+C.
WEB_PORT ?= 8080
serve-web:
	@[ -f out/web/racer.wasm ] || { echo "serve-web: out/web has no page: run make web first"; exit 1; }
	node tests/web/serve.mjs out/web $(WEB_PORT)

# README's picture of the page (game/web/page.png): SSAM with its HUD (the light shafts' passes
# among them), chase camera, in headless Chromium (tests/web/page_picture.mjs says how it is taken).
web-picture: web-tools web
	node tests/web/page_picture.mjs --out out/web --png game/web/page.png

test: build node-tools web-tools web
	ctest --preset $(PRESET) -j $(JOBS)

# The sanitizer pass CI runs after `make test` (tests/README.md "What CI runs"): the asan preset
# (Debug's assertions at -O1, AddressSanitizer + UndefinedBehaviorSanitizer, no recovery; no
# benchmark binaries; why: tests/docs/ci.md) built in build-asan, then
# these ctest labels under it. Left out: the label `capture` (whole racer and ssam-bench runs:
# the largest share of the pass's time, and their pictures are proven the same in every build
# by `make test`; hostile input is the fuzzers' and the unit tests' under the sanitizers), tests
# that also carry the label `slow` (too long under the sanitizers; `make test` still runs them)
# and the glTF validator (Node.js, none of our code runs), and apitrace's replay of the GL example
# (label gl beside capture: its EGL wrapper is preloaded ahead of ASan's runtime, which refuses
# to run so, and its replay runs none of our code), and the GL-against-soft blend sweep (below).
# The Vulkan unit and conformance
# binaries carry `unit` / `conformance` beside `vk`, so they run here; the rest of `vk` (racer's
# goldens, the EXR layers) is capture work. The asan test preset sets ASAN_OPTIONS and
# UBSAN_OPTIONS (CMakePresets.json; why: tests/README.md "What CI runs").
ASAN_LABELS ?= unit|conformance|stress|gl
ASAN_EXCLUDE ?= ^Content\.GltfValidatorFindsNoErrors$$|^Capture\.ApitraceReplaysSsamGlFrame$$|$(ASAN_GL_BLEND_SWEEP)|$(ASAN_PACKAGING)
# The GL-against-soft blend sweep (1125 blend states a format, four formats): each state is a
# pipeline llvmpipe compiles, so nearly all of its time is Mesa's, under ASan's allocator (the
# longest tests of a cold run: 76-124 s each in step 1). What it proves is the numbers, which step
# 1 proves; our code on its path (pipeline creation, the draws, the soft blend) runs under the
# sanitizers in the GL and soft blend conformance suites and the GL backend's unit tests.
ASAN_GL_BLEND_SWEEP := ^Formats/GlBlendVsSoft\.
# The packaging tests that build the library again (the library-only build and each variant, each
# installed header): they prove CMake and install rules, not memory safety, and `make test` runs
# them; the library-only builds are plain Release builds even under the asan preset, so they
# would only repeat step 1's, and the headers' would rebuild with the sanitizer flags (minutes).
ASAN_PACKAGING := ^Install\.(LibraryOnlyBuildNeedsNoDemoDependency|LibraryGlOnlyBuildNeedsNoVulkan|LibraryVkOnlyBuildNeedsNoGl|ReadmePackageListsMatchConfigure|HeadersBuildThroughTheirComponent)$$
test-asan: deps
	@[ -f build-asan/CMakeCache.txt ] || cmake --preset asan
	cmake --build --preset asan -j $(JOBS)
	ctest --preset asan -j $(JOBS) -L '^($(ASAN_LABELS))$$' -LE '^slow$$' \
	  -E '$(ASAN_EXCLUDE)'

# ThreadSanitizer over the code that runs on oneTBB's threads (by hand, not in CI: it costs a
# build of its own): the soft backend's tiles and set-up, the frame graph, the core. Each test
# executable is run whole; tests/tsan.supp says what it suppresses and why.
TSAN_TESTS ?= unit_core unit_frame_graph unit_frame_pools unit_soft unit_soft_sampler unit_soft_float_mask conformance_soft
test-tsan: deps
	@[ -f build-tsan/CMakeCache.txt ] || cmake --preset tsan
	cmake --build --preset tsan -j $(JOBS) --target $(TSAN_TESTS)
	@for t in $(TSAN_TESTS); do echo "test-tsan: $$t"; \
	  TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$(CURDIR)/tests/tsan.supp" \
	  build-tsan/bin/$$t --gtest_brief=1 || exit 1; done

# The tree's layout (.clang-format, clang-format 14): format-check fails on any file that is not
# formatted (CI runs it first: it costs seconds), format rewrites them.
SOURCES_TO_FORMAT = $(shell git ls-files '*.cpp' '*.hpp' '*.h')
format-check: deps
	@clang-format-14 --dry-run -Werror $(SOURCES_TO_FORMAT)
	@echo "format-check: $(words $(SOURCES_TO_FORMAT)) files formatted"
format: deps
	clang-format-14 -i $(SOURCES_TO_FORMAT)

# clang-tidy 14 over the engine, ssam, the modules and the game (.clang-tidy says which checks
# and why the others are left out), from the default build's compile_commands.json less the one
# GCC-only option clang cannot parse (capture's metrics ask GCC for -fvect-cost-model). By hand, not
# in CI: it parses every translation unit again (about 20 minutes on 2 cores).
LINT_SOURCES = $(shell git ls-files 'engine/*.cpp' 'ssam/*.cpp' 'modules/*.cpp' 'game/*.cpp')
lint: build
	@command -v clang-tidy-14 >/dev/null || $(SUDO) apt-get install -y -qq --no-install-recommends clang-tidy-14
	@mkdir -p $(BUILD_DIR)/lint && sed 's/ -fvect-cost-model=dynamic//' $(BUILD_DIR)/compile_commands.json \
	  > $(BUILD_DIR)/lint/compile_commands.json
	@printf '%s\n' $(LINT_SOURCES) | xargs -P $(JOBS) -n 8 clang-tidy-14 -p $(BUILD_DIR)/lint --quiet
	@echo "lint: $(words $(LINT_SOURCES)) files clean"

# The demo: with a display, the racing scene in a window (GL) until it is closed (keys:
# game/README.md "Keys": drive, HUD, compare, ...); without one, a few seconds at a fixed time
# step, headless on the soft backend, written to out/racer.png and out/racer.exr (every layer),
# and the same frame side by side, SSAM against alpha testing with zoomed insets, to
# out/compare.png.
# It builds the racer alone (its content is committed), not the tests: `make test` builds those.
DEMO_FLAGS ?= --frames 90 --fixed-dt 0.0333333 --size 1280x720
demo: configure
	cmake --build --preset $(PRESET) -j $(JOBS) --target racer
	@if [ -n "$$DISPLAY$$WAYLAND_DISPLAY" ]; then $(BUILD_DIR)/bin/racer --size 1280x720; \
	else $(BUILD_DIR)/bin/racer --headless $(DEMO_FLAGS) --capture out/racer.png --capture-layers && \
	  $(BUILD_DIR)/bin/racer --headless $(DEMO_FLAGS) --compare ssam,alpha-test --capture out/compare.png; fi

# The README's pictures, rendered by the project itself (small PNGs in content/readme/):
# the default demo's chase view in the forest, the pre-race pan with SSAM (and each of its intermediate targets) and with alpha testing.
README_FLAGS := --headless --size 480x270 --frames 2 --camera pan
readme-images: build
	# The first picture: the default demo's last frame in the forest (make demo, at 480x270).
	$(BUILD_DIR)/bin/racer --headless --size 480x270 --frames 90 --fixed-dt 0.0333333 --capture content/readme/racer.png
	$(BUILD_DIR)/bin/racer $(README_FLAGS) --technique ssam --capture out/readme/ssam.png \
	  --capture-layers --layer-pictures content/readme
	# The living scene: the pan when the car passes the start line (55.9 s at 0.1 s steps).
	$(BUILD_DIR)/bin/racer --headless --size 480x270 --frames 559 --fixed-dt 0.1 --camera pan \
	  --capture content/readme/living_scene.png
	# SSAM against alpha testing side by side, with 4x insets where they differ most.
	$(BUILD_DIR)/bin/racer --headless --size 640x360 --frames 90 --fixed-dt 0.0333333 \
	  --compare ssam,alpha-test --capture content/readme/compare.png
	# SSAM against hashed alpha testing resolved by TAA (ssam/README.md), after 90 frames of history.
	$(BUILD_DIR)/bin/racer --headless --size 480x270 --frames 90 --fixed-dt 0.0333333 --threads 2 \
	  --compare ssam,hashed+taa --capture content/readme/compare_hashed_taa.png
	# ssam::gl's dark rims (ssam/README.md): the host's mist after SSAM, with the paper's depth and
	# with depthMaskThreshold 0.25, and the mist drawn before SSAM (exact here); a 2x crop of each.
	mkdir -p out/readme
	for t in 0 0.25; do $(BUILD_DIR)/bin/ssam_gl_embedding --mist after --depth-threshold $$t \
	  --out out/readme/rims_$$t.png || exit 1; done
	$(BUILD_DIR)/bin/ssam_gl_embedding --mist before --out out/readme/rims_reference.png
	oiiotool $(foreach f,0 0.25 reference,out/readme/rims_$(f).png --cut 160x112+40+250 --resample 320x224) \
	  --mosaic:pad=4 3x1 --ch R,G,B -o content/readme/ssam_gl_rims.png

# The README's chart and game/bench/FIGURES.md, from one ssam-bench run (soft backend, 2
# threads, with the paper preset's row for the time goal); the speed table of the last
# `make bench` is copied into FIGURES.md when out/bench/speed_table.md exists. At 320x180 the
# run took 6 min 55 s and 10 min 22 s on this project's shared 2-core machine (load average
# about 10); BENCH_SIZE=320x180 for that,
# BENCH_BACKENDS=soft,gl to add llvmpipe's rows.
BENCH_SIZE ?= 1280x720
BENCH_BACKENDS ?= soft
readme-chart: build
	DISPLAY= $(BUILD_DIR)/bin/ssam-bench --backend $(BENCH_BACKENDS) --threads 2 --size $(BENCH_SIZE) \
	  --with-paper-ssam --lod off --out out/bench --figures game/bench/FIGURES.md \
	  $(if $(wildcard out/bench/speed_table.md),--speed-table out/bench/speed_table.md)
	cp out/bench/bench.svg content/readme/bench.svg

# Regenerates the committed assets (deterministic: a test checks the bytes match).
content: build
	$(BUILD_DIR)/bin/content-generator --out content

# The benchmarks, the speed table (game/bench/speed_table.sh: the soft backend against Mesa
# llvmpipe with the same threads, measured in this one run; OLD_BIN=<dir of an older racer and
# ssam-bench> adds a "before" column, old and new binaries run alternately; BEFORE=lod-off makes
# the "before" column the same binaries with --lod off), then readme-chart, whose ssam-bench run
# writes game/bench/FIGURES.md with that speed table copied in.
bench: build
	$(BUILD_DIR)/bin/bench_ecs
	$(BUILD_DIR)/bin/ssam_bench
	BIN=$(BUILD_DIR)/bin OUT=out/bench OLD_BIN=$(OLD_BIN) BEFORE=$(BEFORE) game/bench/speed_table.sh
	$(MAKE) readme-chart

# Fuzzing, outside CI (tests/fuzz/run_fuzzers.sh): the fuzz targets built with Clang as
# libFuzzer binaries (ASan + UBSan) in build-fuzz, each run FUZZ_SECONDS on a copy of its
# seed corpus; findings land in out/fuzz/<target>/. Needs clang (not in PACKAGES: CI never fuzzes).
FUZZ_SECONDS ?= 60
fuzz: deps
	FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_BUILD_JOBS=$(JOBS) tests/fuzz/run_fuzzers.sh

# The campaign tests/README.md reports: every target at once for FUZZ_SECONDS (default 1800),
# niced, hangs at 30 s (the targets share the cores), then each grown corpus minimised into
# out/fuzz/<target>/minimised.
fuzz-campaign: deps
	FUZZ_SECONDS=$(if $(filter command line,$(origin FUZZ_SECONDS)),$(FUZZ_SECONDS),1800) \
	  FUZZ_CONCURRENT=1 FUZZ_NICE=19 FUZZ_TIMEOUT=30 FUZZ_MERGE=1 FUZZ_BUILD_JOBS=$(JOBS) \
	  tests/fuzz/run_fuzzers.sh

clean:
	rm -rf $(BUILD_DIR)
