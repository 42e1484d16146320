# symmesh — the two commands of the README contract.
#   make demo : install deps, build Release, run the main job on a built-in example into out/
#   make test : install deps, build, run every test (unit, proofs-checks, CLI end-to-end)
#   make bench: build the benchmarks (Release, build-bench/), run them, write docs/benchmarks/
#               (rotation composition and the Lemma 4.2 n-gon check, K_m vs CORE; 2D templated
#               vs conventional generation, docs/benchmarks/2d.md; 3D n-TSVs vs TetGen on the
#               whole geometry, docs/benchmarks/3d.md, and the larger TSVs at 10^7 tetrahedra,
#               docs/benchmarks/3d-1e7.md, as rotational slices and as the 2n half-slices of
#               Algorithm 6.5, docs/benchmarks/3d-half-1e7.md)
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
BENCH_BUILD ?= build-bench
# ccache keys on the compiler's command line, which names the checkout's absolute paths; with the
# checkout as base directory they are relative, so a second clone (CI, a fresh-clone check)
# reuses the objects the first one compiled.
export CCACHE_BASEDIR ?= $(CURDIR)

.PHONY: all deps configure build demo test bench clean format fuzz

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

bench: deps
	cmake -S . -B $(BENCH_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DSYMMESH_BUILD_TESTS=OFF -DSYMMESH_BUILD_BENCH=ON $(CMAKE_FLAGS)
	cmake --build $(BENCH_BUILD) -j $(JOBS) --target bench_rotation_composition bench_lemma42_ngon bench_fem symmesh
	bash bench/run_rotation_composition.sh $(BENCH_BUILD)/bench/bench_rotation_composition docs/benchmarks
	bash bench/run_lemma42_ngon.sh $(BENCH_BUILD)/bench/bench_lemma42_ngon docs/benchmarks
	/usr/bin/python3 bench/generate_2d.py $(BENCH_BUILD)/symmesh docs/benchmarks
	/usr/bin/python3 bench/generate_3d.py $(BENCH_BUILD)/symmesh docs/benchmarks
	/usr/bin/python3 bench/generate_3d.py $(BENCH_BUILD)/symmesh docs/benchmarks --objects tsv-32,tsv-64,tsv-128 --counts 1e7 --no-huge --no-gmsh --name 3d-1e7
	/usr/bin/python3 bench/generate_3d.py $(BENCH_BUILD)/symmesh docs/benchmarks --objects tsv-half-32,tsv-half-64,tsv-half-128 --counts 1e7 --no-huge --no-gmsh --name 3d-half-1e7
	/usr/bin/python3 bench/dihedral_ab.py $(BENCH_BUILD)/symmesh docs/benchmarks
	/usr/bin/python3 bench/dihedral_ab.py $(BENCH_BUILD)/symmesh docs/benchmarks --count 1e7 --objects tsv-half-64 --name dihedral-1e7
	/usr/bin/python3 bench/merge_2d.py $(BENCH_BUILD)/symmesh docs/benchmarks
	/usr/bin/python3 bench/merge_3d.py $(BENCH_BUILD)/symmesh docs/benchmarks
	/usr/bin/python3 bench/gummel.py $(BENCH_BUILD)/symmesh docs/benchmarks
	/usr/bin/python3 bench/fem.py $(BENCH_BUILD)/bench/bench_fem docs/benchmarks
	/usr/bin/python3 bench/fem_command.py $(BENCH_BUILD)/symmesh docs/benchmarks

format:
	clang-format -i $$(git ls-files '*.h' '*.cpp')

fuzz: deps
	bash fuzz/run.sh

clean:
	rm -rf $(BUILD) out
