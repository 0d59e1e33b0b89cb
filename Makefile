# A thin wrapper: install what is missing, configure, build, run. CMake does the real work.
BUILD    ?= build
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)
DEMO     ?= scenes/poll_bar_impulse.yaml
# the last line is for the tests: the page in a real browser, HTML checked by tidy, the GNU Parallel
# recipe, and the scripts' JSON checks
PACKAGES := g++ cmake make pkg-config libeigen3-dev libyaml-cpp-dev doctest-dev libcli11-dev \
            libosmesa6-dev libpng-dev libfreetype-dev fonts-dejavu-core ffmpeg gnuplot-nox \
            chromium tidy parallel python3
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps build demo lecture test bench clean

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

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# the poll's state as JSON, its videos (out/poll_bar_impulse/) and the three-collisions poll slide
demo: build
	./$(BUILD)/rigidreel simulate $(DEMO) --variant end --json
	./$(BUILD)/rigidreel render $(DEMO) --all-variants
	./$(BUILD)/rigidreel snapshot scenes/three_collisions_poll.yaml --impacts --panels

# the course's pack: every scene in scenes/lecture/, its videos, posters and poll panels (README)
lecture: build
	./$(BUILD)/rigidreel lecture scenes/lecture -o out/lecture

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# timings (never asserted in tests): pyramids, 720p render fps, render against ffmpeg alone
bench: build
	@cmake --build $(BUILD) -j $(JOBS) --target rigidreel_bench
	./$(BUILD)/rigidreel_bench ./$(BUILD)/rigidreel scenes/three_collisions_poll.yaml

clean:
	rm -rf $(BUILD)

# regenerate tests/golden/*.png on purpose, after a deliberate change to how frames, charts or the
# lecture page look (see tests/golden/README.md); review the new images before committing them
.PHONY: golden
golden: build
	RIGIDREEL_UPDATE_GOLDEN=1 ./$(BUILD)/tests/golden_test
	RIGIDREEL_UPDATE_GOLDEN=1 ./$(BUILD)/tests/lecture_golden_test
	RIGIDREEL_UPDATE_GOLDEN=1 ./$(BUILD)/tests/chart_test
	RIGIDREEL_UPDATE_GOLDEN=1 ctest --test-dir $(BUILD) -R '^(lecture_parallel|page_browser)$$' --output-on-failure
