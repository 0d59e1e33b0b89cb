# A thin wrapper: install what is missing, configure, build, run. CMake does the real work.
BUILD    ?= build
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)
DEMO     ?= scenes/poll_bar_impulse.yaml
# the last line is for the tests: the page in a real browser, HTML checked by tidy, the GNU Parallel
# recipe, the scripts' JSON checks, and the functions' lengths (tests/support/function_length_test.sh)
PACKAGES := g++ cmake make pkg-config libeigen3-dev libyaml-cpp-dev doctest-dev libcli11-dev \
            libosmesa6-dev libpng-dev libfreetype-dev fonts-dejavu-core ffmpeg gnuplot-nox \
            chromium tidy parallel python3 universal-ctags
# `make bench` only: Box2D 2.4, the stacks' peer in the same run (the build and the tests never need it)
BENCH_PACKAGES := libbox2d-dev
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
# clang and its runtimes (ASan, UBSan, libFuzzer) for `make sanitize` and `make fuzz` only
CLANG_PACKAGES := clang libclang-rt-14-dev
SANITIZE_BUILD ?= build-sanitize
FUZZ_BUILD     ?= build-fuzz
# seconds each fuzzer runs in `make fuzz`
FUZZ_SECONDS   ?= 60
# WERROR=1: warnings are errors (CI); said on every configure, so that the build follows the command
WERROR         ?=

.PHONY: all deps configure build build-tests build-benches demo lecture test bench clean sanitize fuzz clang-deps format format-check

all: build

# install only the Debian packages that are missing (apt-get update only when needed)
deps:
	@missing=""; for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	fi

# the same, for the clang packages
clang-deps:
	@$(MAKE) --no-print-directory deps PACKAGES="$(PACKAGES) $(CLANG_PACKAGES)"

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DRIGIDREEL_WERROR=$(if $(WERROR),ON,OFF) >/dev/null

# the program alone, $(BUILD)/rigidreel: all that demo, lecture and bench run (no test executables)
build: configure
	@cmake --build $(BUILD) -j $(JOBS) --target rigidreel

# the program and every test executable: what the suite runs (`cmake --build` builds them all too)
build-tests: configure
	@cmake --build $(BUILD) -j $(JOBS)

# the benchmarks, built and not run (CI: they compile under WERROR as the rest does); Box2D 2.4 is
# the stack bench's peer where Debian's package can be installed, and the bench builds without it
build-benches: configure
	@$(MAKE) --no-print-directory deps PACKAGES="$(BENCH_PACKAGES)" || echo "build-benches: without $(BENCH_PACKAGES), the stack bench builds without Box2D 2.4"
	@cmake -S . -B $(BUILD) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target rigidreel_bench rigidreel_frame_bench rigidreel_stack_bench

# the poll's state as JSON, its videos (out/poll_bar_impulse/) and the three-collisions poll slide
demo: build
	./$(BUILD)/rigidreel simulate $(DEMO) --variant end --json
	./$(BUILD)/rigidreel render $(DEMO) --all-variants
	./$(BUILD)/rigidreel snapshot scenes/three_collisions_poll.yaml --impacts --panels

# the course's pack: every scene in scenes/lecture/, its videos, posters and poll panels (render/README.md)
lecture: build
	./$(BUILD)/rigidreel lecture scenes/lecture -o out/lecture

test: build-tests
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# every C++ file as .clang-format writes it: `format-check` fails on any difference (`.ci/run`),
# `format` rewrites the files
# (Debian 12's clang-format 14, pinned: another major version formats some lines differently)
FORMAT_FILES = $(shell git ls-files '*.h' '*.cpp')
CLANG_FORMAT := clang-format-14
format-check:
	@$(MAKE) --no-print-directory deps PACKAGES="$(CLANG_FORMAT)"
	@test -n "$(FORMAT_FILES)" || { echo "format-check: no C++ files from git ls-files (run it in a git clone)"; exit 1; }
	@$(CLANG_FORMAT) --dry-run -Werror $(FORMAT_FILES) && echo "format-check: $(words $(FORMAT_FILES)) files as .clang-format writes them"
format:
	@$(MAKE) --no-print-directory deps PACKAGES="$(CLANG_FORMAT)"
	@test -n "$(FORMAT_FILES)" || { echo "format: no C++ files from git ls-files (run it in a git clone)"; exit 1; }
	$(CLANG_FORMAT) -i $(FORMAT_FILES)

# timings (never asserted in tests), written as data beside the bench: render/bench/results/stacks.csv
# (stacks against Box2D 2.4, and Box2D v3 with BOX2D3, in the same run: both pyramids, their three
# layouts and Box2D's arch, 600 steps; soft_step in doubles and floats, recycling off and on, one
# and two threads) and render/bench/results/renders.csv (check's start-up, the video pipeline's parts
# per frame and the whole render against ffmpeg alone at 720p and 1080p, the lecture pack's wall
# time); each opens with the command, the machine, the date and the commit (render/bench/README.md).
# BENCH_BASELINE=path/to/another/rigidreel times that build too, in the same run
BENCH_BASELINE ?=
# BOX2D3=DIR: Box2D v3's column in the stack table, from DIR/b3_pyramid (built by
# ../shared/peers/box2d-v3/build.sh DIR); without it the table has Box2D 2.4 and ours
BOX2D3 ?=
# BENCH_FLAGS=--renders-only: the 720p render rows alone (the poll and both pyramids), a few minutes
BENCH_FLAGS ?=
# where the CSVs go (committed: the runs the docs link to)
BENCH_RESULTS ?= render/bench/results
bench: build
	@$(MAKE) --no-print-directory deps PACKAGES="$(BENCH_PACKAGES)"
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target rigidreel_bench rigidreel_stack_bench
	@mkdir -p out/bench $(BENCH_RESULTS)
	./$(BUILD)/rigidreel_stack_bench --method sequential --method soft_step --precision double --precision float --recycle off --recycle on --threads 1 --threads 2 --csv $(BENCH_RESULTS)/stacks.csv $(if $(BOX2D3),--box2d3 $(BOX2D3))
	./$(BUILD)/rigidreel_bench ./$(BUILD)/rigidreel scenes/three_collisions_poll.yaml $(BENCH_BASELINE) --csv $(BENCH_RESULTS)/renders.csv $(BENCH_FLAGS)

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(FUZZ_BUILD)

# regenerate tests/golden/*.png on purpose, after a deliberate change to how frames, charts or the
# lecture page look (see tests/golden/README.md); review the new images before committing them
.PHONY: golden
golden: build-tests
	RIGIDREEL_UPDATE_GOLDEN=1 ./$(BUILD)/tests/golden_test
	RIGIDREEL_UPDATE_GOLDEN=1 ./$(BUILD)/tests/lecture_golden_test
	RIGIDREEL_UPDATE_GOLDEN=1 ./$(BUILD)/tests/golden3d_test
	RIGIDREEL_UPDATE_GOLDEN=1 ./$(BUILD)/tests/chart_test
	RIGIDREEL_UPDATE_GOLDEN=1 ctest --test-dir $(BUILD) -R '^(lecture_parallel|page_browser)$$' --output-on-failure

# the whole suite built by clang with AddressSanitizer and UndefinedBehaviorSanitizer, leaks checked;
# the only leaks suppressed are Mesa's own inside libOSMesa (tests/sanitize/lsan.supp says why).
# intercept_tls_get_addr=0: LeakSanitizer's tracking of dynamic TLS blocks (those of the OSMesa
# libraries we dlopen) misreads glibc's block header when a block happens to start at a certain
# offset in its page, then scans a bogus range and its tracer crashes at exit ("Tracer caught
# signal 11"; google/sanitizers#1322). Static TLS, stacks and the heap are still scanned
SANITIZE_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
sanitize: clang-deps
	@cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
	  -DCMAKE_CXX_FLAGS="$(SANITIZE_FLAGS)" -DCMAKE_EXE_LINKER_FLAGS="$(SANITIZE_FLAGS)" >/dev/null
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0 \
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitize/lsan.supp:print_suppressions=0 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --test-dir $(SANITIZE_BUILD) --output-on-failure -j $(JOBS)

# libFuzzer on the scene loader (the `check` path) and on the pair collision functions, each for
# FUZZ_SECONDS, seeded with scenes/ and the hostile inputs kept in tests/fuzz/; what a fuzzer
# finds is written to $(FUZZ_BUILD)/<target>-crash-* (see tests/README.md: Sanitizers and fuzzing)
fuzz: clang-deps
	@cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ -DRIGIDREEL_FUZZ=ON >/dev/null
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target scene_loader_fuzz collide_fuzz trace_reader_fuzz manifest_reader_fuzz
	@mkdir -p $(FUZZ_BUILD)/corpus/scene_loader $(FUZZ_BUILD)/corpus/collide $(FUZZ_BUILD)/corpus/trace_reader \
	  $(FUZZ_BUILD)/corpus/manifest_reader
	$(FUZZ_BUILD)/tests/scene_loader_fuzz -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	  -max_len=4096 -dict=tests/fuzz/scene.dict -artifact_prefix=$(FUZZ_BUILD)/scene_loader- \
	  $(FUZZ_BUILD)/corpus/scene_loader tests/fuzz/scene_loader scenes
	$(FUZZ_BUILD)/tests/collide_fuzz -max_total_time=$(FUZZ_SECONDS) -timeout=10 \
	  -artifact_prefix=$(FUZZ_BUILD)/collide- $(FUZZ_BUILD)/corpus/collide tests/fuzz/collide
	$(FUZZ_BUILD)/tests/trace_reader_fuzz -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	  -max_len=4096 -artifact_prefix=$(FUZZ_BUILD)/trace_reader- $(FUZZ_BUILD)/corpus/trace_reader tests/fuzz/trace_reader
	$(FUZZ_BUILD)/tests/manifest_reader_fuzz -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	  -max_len=4096 -artifact_prefix=$(FUZZ_BUILD)/manifest_reader- $(FUZZ_BUILD)/corpus/manifest_reader \
	  tests/fuzz/manifest_reader
