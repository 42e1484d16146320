# symmesh — the two commands of the README contract.
#   make demo : install deps, build Release, run the main job on a built-in example into out/
#   make test : install deps, build, run every test (unit, proofs-checks, CLI end-to-end)
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps configure build demo test clean format fuzz

all: build

deps:
	bash scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	bash scripts/demo.sh $(BUILD)/symmesh out

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 1500

format:
	clang-format -i $$(git ls-files '*.h' '*.cpp')

fuzz: deps
	bash fuzz/run.sh

clean:
	rm -rf $(BUILD) out
