# gearhb: the two commands a user needs.
#   make figures   build (Release), run every chapter, draw every thesis figure
#   make test      build, then run the whole CTest suite
#   (make docs     regenerate the console output quoted in the chapter READMEs)
# Both first make sure the Debian packages are present (apt-get when root,
# otherwise the exact command is printed and make stops).

BUILD      ?= build
BUILD_TYPE ?= Release
JOBS       ?= $(shell nproc 2>/dev/null || echo 2)
PYTHON     ?= /usr/bin/python3

# Debian packages the project needs (Debian 12 names).
PACKAGES := cmake g++ make pkg-config libeigen3-dev libfftw3-dev libgsl-dev \
            libgtest-dev libbenchmark-dev nlohmann-json3-dev python3-matplotlib \
            python3-scipy snakemake libgmsh-dev libsuitesparse-dev

.PHONY: all deps configure build figures test bench docs clean

all: build

deps:
	@missing=""; for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = "0" ]; then \
	    echo "Installing missing Debian packages:$$missing"; \
	    export DEBIAN_FRONTEND=noninteractive; \
	    apt-get update -qq && apt-get install -y -qq --no-install-recommends $$missing || exit 1; \
	  else \
	    echo "Missing Debian packages. Run as root:"; \
	    echo "  sudo apt-get update && sudo apt-get install -y$$missing"; \
	    exit 1; \
	  fi; \
	fi

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

figures: build
	@$(PYTHON) figures/make_all.py --build $(BUILD)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Regenerate the console output quoted in the chapter READMEs (CTest checks it).
docs: build
	@$(PYTHON) tests/readme_console.py --write $(BUILD) chapters/*/README.md programs/*/README.md programs/*/NOTES.md

bench: build
	@$(BUILD)/bin/gearhb_bench

clean:
	rm -rf $(BUILD)
