# 2D physics engine, the C++ port of the course's TP3 ("moteur physique").
#   make run    installs what is missing, builds, opens the default scene
#   make test   installs what is missing, builds, runs every test
# Variables: SANITIZE=1 (ASan+UBSan build in build/sanitize), OPT=-O0 ..., SCENE=name|file.json and
# ARGS="..." for run (make run SCENE=gas ARGS="--headless --frames 1000").

CXX      ?= g++
OPT      ?= -O2
# -ffp-contract=off: no fused multiply-add, so a run gives the same bits at
# every optimisation level and on every x86-64 (see the determinism test).
CXXFLAGS := -std=c++20 $(OPT) -g -Wall -Wextra -Werror -ffp-contract=off -Iinclude -Isrc -MMD -MP
LDFLAGS  :=
BUILD    := build
ifneq ($(OPT),-O2)
  BUILD    := build/opt$(subst -,,$(OPT))
endif

# As many jobs as the machine has cores, unless the user gave -j (on the
# command line, which wins anyway, or in MAKEFLAGS in the environment). Only
# the top-level make sets it; the $(MAKE) calls of run/test/... inherit its
# jobserver. --output-sync keeps each target's output (a compiler's errors)
# in one piece.
ifeq ($(MAKELEVEL),0)
  ifeq ($(filter -j%,$(shell printenv MAKEFLAGS)),)
    NPROC := $(shell nproc 2>/dev/null || echo 1)
    MAKEFLAGS += -j$(NPROC) --output-sync=target --no-print-directory
    # A build from scratch (no $(BUILD)/obj yet) says how long it will take,
    # from CPU seconds measured on a fresh clone (docs/reliability.md, "Tests
    # and their time"): make test, 405 (user and system, at d2b5129, the
    # test files in their unity groups, the machine otherwise idle: the
    # libraries, the game, the test files, the examples, the installed
    # copy's builds, the exercise trees, and the test binary, one process per
    # suite on every core); make run, 340 (user and system).
    ifeq ($(wildcard $(BUILD)/obj),)
      GOALS := $(or $(MAKECMDGOALS),all)
      ifneq ($(filter test,$(GOALS)),)
        $(info building from scratch and testing (about $(shell echo $$((405 / $(NPROC)))) s on $(NPROC) cores)...)
      else ifneq ($(filter run,$(GOALS)),)
        $(info building the game from scratch (about $(shell echo $$((340 / $(NPROC)))) s on $(NPROC) cores)...)
      else ifneq ($(filter all $(BUILD)/tests,$(GOALS)),)
        $(info building from scratch (about $(shell echo $$((150 / $(NPROC)))) s on $(NPROC) cores)...)
      endif
    endif
  endif
endif

ifeq ($(SANITIZE),1)
  BUILD    := $(BUILD)/sanitize
  # The long stability cases (label "slow") take minutes at -O2; under the
  # sanitizers, ten times that. Run them with TEST_ARGS= to override.
  TEST_ARGS ?= --run_test=!@slow
  SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
  CXXFLAGS += $(SAN_FLAGS)
  LDFLAGS  += -fsanitize=address,undefined
endif

# Debian packages each target needs; `deps` installs the missing ones.
PACKAGES := g++ make pkg-config libsdl2-dev libsdl2-ttf-dev libboost-test-dev fonts-dejavu-core \
            nlohmann-json3-dev libboost-program-options-dev libstb-dev python3 cmake
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

# Four libraries, one per layer, each linked only by what needs it:
#   libphysics.a        the course tree (src/course) and the engine (src/engine,
#                       src/api): what a game embeds (include/physics/); no JSON,
#                       PNG, SDL nor game code (`make check-lib` checks with nm)
#   libphysics_scene.a  scene files: spec, JSON read and write, built-in scenes, save
#   libphysics_games.a  the two games' rules
#   libphysics_app.a    the SDL-free application: command line, testbed logic,
#                       input logs, headless runs, dumps, offscreen pictures, styles
# The window and main (SDL) are the game's own objects.
COURSE_SRC := $(shell find src/course -name '*.cpp' | sort)
ENGINE_SRC := $(wildcard src/engine/*.cpp) $(wildcard src/api/*.cpp)
CORE_SRC   := $(COURSE_SRC) $(ENGINE_SRC)
SCENE_SRC  := $(wildcard src/scene/*.cpp)
GAMES_SRC  := $(wildcard src/games/*.cpp)
APP_SRC    := $(filter-out src/app/main.cpp src/app/window.cpp,$(wildcard src/app/*.cpp))
GAME_SRC   := src/app/main.cpp src/app/window.cpp
TEST_SRC   := $(wildcard tests/*.cpp)
# The test files are compiled a group at a time, each group one translation
# unit ($(BUILD)/obj/tests/unity_N.cpp, generated, which #includes them), so
# that what they share (the headers past the precompiled one, Boost.Test's
# templates, the inline functions they call) is compiled once a group rather
# than once a file. Each file wraps its own names in a namespace of its name
# (its helpers and using-directives stay its own); the PNG decoder is
# tests/png_decode.hpp, once a unit. The groups gather files that include the
# same headers (the command line and the app, the scenes and the engine, the
# numerics), balanced by compile time so that the cores stay busy (the 33
# files: 147 s of CPU compiled apart, about 68 s in these four groups, 13-19
# s each, at 69414c5 with the machine shared; touching one file rebuilds its
# group only, 13-19 s instead of its own 2-14). A test
# file in no group is compiled on its own, as are test_main.cpp (no
# precompiled header) and the per-question files that the exercise trees
# reuse by name (EX_REUSE).
TEST_UNITY   := 1 2 3 4
TEST_UNITY_1 := test_cli test_style test_keys test_run_tests test_hostile test_layers
TEST_UNITY_2 := test_testbed test_replay test_games test_save test_maps
TEST_UNITY_3 := test_scene test_scene_json test_fuzz_regressions test_api test_game_physics test_query test_geometry \
                test_course_world
TEST_UNITY_4 := test_auto test_ccd test_family test_seams test_stability test_tiles test_numerics test_integrator \
                test_reference test_determinism test_soak test_mover test_threads test_broadphase
TEST_UNITY_SRC = $(filter $(TEST_SRC),$(TEST_UNITY_$(1):%=tests/%.cpp))
TEST_GROUPED := $(foreach n,$(TEST_UNITY),$(call TEST_UNITY_SRC,$(n)))
APP_LIBS := -lboost_program_options
# The exact event-driven reference (not part of the engine): tests and report tools.
REF_SRC  := src/reference/event_sim.cpp src/reference/closed_forms.cpp

CORE_OBJ := $(CORE_SRC:%.cpp=$(BUILD)/obj/%.o)
SCENE_OBJ := $(SCENE_SRC:%.cpp=$(BUILD)/obj/%.o)
GAMES_OBJ := $(GAMES_SRC:%.cpp=$(BUILD)/obj/%.o)
APP_OBJ  := $(APP_SRC:%.cpp=$(BUILD)/obj/%.o)
# In link order: each library uses only those after it.
LIBS := $(BUILD)/libphysics_app.a $(BUILD)/libphysics_games.a $(BUILD)/libphysics_scene.a $(BUILD)/libphysics.a
GAME_OBJ := $(GAME_SRC:%.cpp=$(BUILD)/obj/%.o)
TEST_UNITY_OBJ := $(TEST_UNITY:%=$(BUILD)/obj/tests/unity_%.o)
TEST_OBJ := $(patsubst %.cpp,$(BUILD)/obj/%.o,$(filter-out $(TEST_GROUPED),$(TEST_SRC))) $(TEST_UNITY_OBJ)
REF_OBJ  := $(REF_SRC:%.cpp=$(BUILD)/obj/%.o)
# Scenes, modes and measures of `make report` / `make stability`, shared with their tests.
NUM_SRC  := tools/numerics/scenes.cpp tools/numerics/stability.cpp tools/numerics/report.cpp tools/numerics/friction.cpp \
            tools/numerics/family.cpp
NUM_OBJ  := $(NUM_SRC:%.cpp=$(BUILD)/obj/%.o)
TEST_OBJ += $(REF_OBJ) $(NUM_OBJ)

SDL_CFLAGS = $(shell pkg-config --cflags sdl2 SDL2_ttf)
SDL_LIBS   = $(shell pkg-config --libs sdl2 SDL2_ttf)

.PHONY: all run test deps clean check-lib layers links determinism memcheck soak fuzz report stability bench
all: $(BUILD)/game $(BUILD)/tests

deps:
	@missing=""; for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "installing Debian packages:$$missing"; \
	  $(SUDO) apt-get update -q && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -q $$missing; \
	fi

run: deps
	@$(MAKE) --no-print-directory $(BUILD)/game
	./$(BUILD)/game $(if $(SCENE),--scene $(SCENE)) $(ARGS)

# The test binary runs one process per suite on every core (tools/run_tests.py;
# a TEST_ARGS other than exclusions runs it once, as given), as soon as it is
# linked, beside what is left to build and check (test-run); what it prints
# is kept in $(BUILD)/test-run.log and printed last, the final line "N
# passed, N failed" last of all, and make test fails if it failed.
# Two makes, for the order the jobs start in: make -j starts, in one pass
# over the goals, every job whose prerequisites are done, and leaves a target
# whose prerequisites are still building to its next pass, after every job
# of the first has started (in one make, the exercise trees waited for their
# few objects until the end of the build, and so did every object built on a
# precompiled header). The first make builds what the rest waits for: the
# precompiled headers, libphysics.a and the objects the exercise trees reuse
# (check.sh --reuse); the second starts the trees at once (their builds and
# runs then share the jobs with the rest of the build instead of following
# it), then what needs only libphysics.a (examples, install-check, whose
# serial steps such as cmake's configure fill the other core), the scene
# files (the longest objects, on their .gch) before the test files, then
# the test binary and its run, the game and exercise-check.
TEST_RUN   := $(BUILD)/test-run
TEST_FIRST  = $(TEST_PCH).gch $(JSON_PCH).gch $(CORE_OBJ) $(BUILD)/libphysics.a $(if $(TEST_ARGS),,$(EX_REUSE))
test: deps
	@rm -f $(TEST_RUN).rc
	@$(MAKE) --no-print-directory test-first
	@$(MAKE) --no-print-directory $(if $(TEST_ARGS),,exercise-trees) layers links check-lib examples install-check \
	  test-scene-obj test-run $(BUILD)/game $(if $(TEST_ARGS),,exercise-check); st=$$?; \
	if [ -f $(TEST_RUN).rc ]; then cat $(TEST_RUN).log; [ $$st != 0 ] || st=$$(cat $(TEST_RUN).rc); fi; exit $$st
.PHONY: test-first test-scene-obj test-run
# (The game too: the CLI tests run it, and a game still linking is "Permission denied".)
test-run: $(BUILD)/tests $(BUILD)/game
	@python3 tools/run_tests.py ./$(BUILD)/tests -- $(TEST_ARGS) > $(TEST_RUN).log 2>&1; echo $$? > $(TEST_RUN).rc

# Includes under src/ and include/ go one way, one level per folder: include/physics < course/utils < engine
# < course/systems < course/entities < course < api < reference < scene < input < games < app; no folder cycle,
# no file cycle. It prints the known remaining violations (tools/check_layers.py, KNOWN) and fails on a new one.
layers:
	@python3 tools/check_layers.py

# Every relative link and quoted repository path in README.md and docs/ exists.
links:
	@python3 tools/check_links.py

# The library a game embeds holds the course and the engine only: no symbol
# (defined or used) of SDL, JSON (nlohmann), PNG (stb), scenes, games or the app.
LIB_FOREIGN := SDL_|TTF_|nlohmann|stbi|physics::(Scene|SceneSpec|Save|Platformer|Targets|Level|Testbed|Headless|Style|Dump)\b
check-lib: $(BUILD)/libphysics.a
	@found=$$(nm -C $< | grep -E '$(LIB_FOREIGN)' | head -3); \
	if [ -n "$$found" ]; then echo "libphysics.a holds or uses a symbol that is not the engine's or the course's:"; \
	  echo "$$found"; exit 1; fi; \
	echo "check-lib: libphysics.a holds the course and the engine only ($$(nm $< | grep -c ' T ') functions)"

$(BUILD)/libphysics.a: $(CORE_OBJ)
$(BUILD)/libphysics_scene.a: $(SCENE_OBJ)
$(BUILD)/libphysics_games.a: $(GAMES_OBJ)
$(BUILD)/libphysics_app.a: $(APP_OBJ)
$(LIBS):
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/game: $(GAME_OBJ) $(LIBS)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS) $(SDL_LIBS) $(APP_LIBS)

$(BUILD)/tests: $(TEST_OBJ) $(LIBS)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS) -lboost_unit_test_framework $(APP_LIBS)

$(BUILD)/obj/src/app/window.o $(BUILD)/obj/src/app/main.o: CXXFLAGS += $(SDL_CFLAGS)
# The scene, app and games objects keep line tables and function names
# (-g1: backtraces and profiles still name their lines), not the full debug
# information, which cost a quarter of their compile time (src/scene/keys.cpp
# 9.1 -> 7.2 s, src/app/cli.cpp 8.3 -> 5.8 s, at b49cee6); the engine and
# the course keep -g. The level of debug information does not change the code.
$(SCENE_OBJ) $(APP_OBJ) $(GAMES_OBJ) $(GAME_SRC:%.cpp=$(BUILD)/obj/%.o): private CXXFLAGS += -g1
# (private: not passed on to prerequisites, such as the precompiled header)
$(BUILD)/obj/tools/%.o: private CXXFLAGS += -Itools
# The test files were most of a build's time (their BOOST_TEST lines expand
# to much code): 103 s of CPU at -O2 -g, 43 s at -O1 -g1 with the header
# below precompiled. They drive the library, which keeps $(OPT) and -g (the
# test binary runs in the same 24 s), and -g1 keeps their line tables
# (backtraces, breakpoints by line). Results do not depend on -O
# (-ffp-contract=off; `make determinism` checks -O0 against -O2, and an
# OPT=-O0 build keeps its test files at -O0 too, so that no inline function
# the library calls comes from a more optimised test object).
TEST_FLAGS := -Itools -Itests -g1 $(if $(filter -O0,$(OPT)),,-O1)
# Precompiled headers (g++ .gch), each built once with the flags of the
# objects that include it first (-include; -Winvalid-pch, an error with
# -Werror, should they ever disagree). Each .gch has its .d file, listing the
# headers it holds (the objects' own .d files list only the others), so a
# change to one of them rebuilds it, and it its objects:
#  - tests/pch.hpp: Boost.Test and helpers.hpp (so course/game.hpp and the
#    engine's headers), for every test file but test_main.cpp, which includes
#    nothing of the project. Boost.Test alone saved ~1 s of each file's 3-14
#    s; helpers.hpp with it ~0.7 s more (185 -> 153 s of CPU for the 39 files,
#    the .gch 7 s instead of 4);
#  - tools/pch/scene_json.hpp: scene/json_reader.hpp (nlohmann/json as it
#    configures it, and game.hpp through scene.hpp), for the scene files that
#    include it (86 -> 67 s of CPU for the 8 files, the .gch 9 s).
# Not for the other objects of the libraries: course/game.hpp precompiled
# saved their 20 files 16 s of CPU for a .gch of 7, and changed what -O2
# inlines enough for a false -Warray-bounds (GCC 12, std::string's
# operator+) to stop src/app/input_log.cpp; never for the engine's.
TEST_PCH := $(BUILD)/obj/pch/test_pch.hpp
JSON_PCH := $(BUILD)/obj/pch/scene_json.hpp
TEST_PCH_OBJ := $(filter-out $(BUILD)/obj/tests/test_main.o,$(filter $(BUILD)/obj/tests/%,$(TEST_OBJ)))
JSON_PCH_OBJ := $(patsubst %.cpp,$(BUILD)/obj/%.o,\
  $(shell grep -l -E '^\#include "scene/(json_reader|json_parse|keys|map)\.hpp"' $(SCENE_SRC)))
$(TEST_PCH).gch: tests/pch.hpp
	@mkdir -p $(@D)
	cp $< $(TEST_PCH)
	$(CXX) $(CXXFLAGS) $(TEST_FLAGS) -x c++-header $(TEST_PCH) -o $@
$(JSON_PCH).gch: tools/pch/scene_json.hpp
	@mkdir -p $(@D)
	cp $< $(JSON_PCH)
	$(CXX) $(CXXFLAGS) -g1 -x c++-header $(JSON_PCH) -o $@
$(TEST_PCH_OBJ): $(TEST_PCH).gch
$(JSON_PCH_OBJ): $(JSON_PCH).gch
$(BUILD)/obj/tests/%.o: private CXXFLAGS += $(TEST_FLAGS)

# A group's source: one #include line a member (by its path from the top,
# through -iquote ., so that each file's __FILE__ is as when compiled alone);
# rewritten only when the group changes. Its object depends on its members
# (and, through its .d file, on their headers).
$(TEST_UNITY_OBJ:.o=.cpp): $(BUILD)/obj/tests/unity_%.cpp: Makefile
	@mkdir -p $(@D)
	@printf '#include "%s"\n' $(call TEST_UNITY_SRC,$*) > $@.new; cmp -s $@.new $@ && rm $@.new || mv $@.new $@
$(foreach n,$(TEST_UNITY),$(eval $(BUILD)/obj/tests/unity_$(n).o: $(call TEST_UNITY_SRC,$(n))))
$(TEST_UNITY_OBJ): $(BUILD)/obj/tests/%.o: $(BUILD)/obj/tests/%.cpp
	$(CXX) $(CXXFLAGS) -iquote . -c $< -o $@
$(TEST_PCH_OBJ): private CXXFLAGS += -include $(TEST_PCH) -Winvalid-pch
$(JSON_PCH_OBJ): private CXXFLAGS += -include $(JSON_PCH) -Winvalid-pch

# ---- numerics (docs/numerics.md) ----
$(BUILD)/stability: $(BUILD)/obj/tools/stability_main.o $(NUM_OBJ) $(REF_OBJ) $(LIBS)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS)

$(BUILD)/report: $(BUILD)/obj/tools/report_main.o $(NUM_OBJ) $(REF_OBJ) $(LIBS)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS)

# Error against run time: report/accuracy.csv, REPORT.md, work_precision.png (needs gnuplot).
# The errors are deterministic; the costs are re-timed only with TIMING=1 (into
# report/costs.csv), so a plain `make report` rewrites the committed files unchanged.
report: deps
	@dpkg-query -W -f='$${Status}' gnuplot-nox 2>/dev/null | grep -q "ok installed" || { \
	  echo "installing Debian packages: gnuplot-nox"; \
	  $(SUDO) apt-get update -q && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -q gnuplot-nox; }
	@$(MAKE) --no-print-directory $(BUILD)/report
	./$(BUILD)/report report $(BUILD)/report_work $(if $(filter 1,$(TIMING)),--time)

# The stability matrix: report/STABILITY.md (a few minutes: it runs the long cases).
stability: deps
	@$(MAKE) --no-print-directory $(BUILD)/stability
	@mkdir -p report
	./$(BUILD)/stability report/STABILITY.md

$(BUILD)/obj/%.o: %.cpp
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -c $< -o $@

# The committed state hash must come out of -O0 and -O2 builds alike.
determinism: deps
	@$(MAKE) --no-print-directory test TEST_ARGS=--run_test=determinism OPT=-O2
	@$(MAKE) --no-print-directory test TEST_ARGS=--run_test=determinism OPT=-O0

# valgrind memcheck on a headless run of the default scene: no error, no leak.
memcheck: deps
	@$(MAKE) --no-print-directory PACKAGES=valgrind deps
	@$(MAKE) --no-print-directory $(BUILD)/game
	valgrind --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect \
	  ./$(BUILD)/game --headless --frames 2000

# Long runs of the gas and stack scenes: 10^6 steps each, checked every 10^4.
SOAK_STEPS ?= 1000000
soak: deps
	@$(MAKE) --no-print-directory $(BUILD)/soak
	./$(BUILD)/soak $(SOAK_STEPS)

$(BUILD)/soak: $(BUILD)/obj/tools/soak.o $(LIBS)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS)

# Coverage-guided fuzzing (libFuzzer, clang from Debian) of the scene loader,
# seeded with scenes/ and the regression inputs, then of the map loaders
# (Tiled, LDtk), seeded with scenes/maps/ and tests/fuzz_regressions/maps/;
# SECONDS each. `make fuzz SECONDS=600`; FUZZERS=map for the maps alone.
FUZZ_SECONDS := $(if $(filter command line,$(origin SECONDS)),$(SECONDS),60)
FUZZ_DIR     := build/fuzz
FUZZERS      ?= scene map
FUZZ_SEEDS_scene := scenes/*.json tests/fuzz_regressions/*.json
FUZZ_SEEDS_map   := scenes/maps/*.tmj scenes/maps/*.ldtk tests/fuzz_regressions/maps/*
fuzz: deps
	@$(MAKE) --no-print-directory PACKAGES="clang libclang-rt-14-dev nlohmann-json3-dev" deps
	set -e; for f in $(FUZZERS); do \
	  mkdir -p $(FUZZ_DIR)/corpus-$$f; \
	  cp $$(if [ $$f = map ]; then echo $(FUZZ_SEEDS_map); else echo $(FUZZ_SEEDS_scene); fi) $(FUZZ_DIR)/corpus-$$f/; \
	  clang++ -std=c++20 -O1 -g -ffp-contract=off -Iinclude -Isrc -fsanitize=fuzzer,address,undefined \
	    -fno-sanitize-recover=all $(CORE_SRC) $(SCENE_SRC) fuzz/$${f}_fuzzer.cpp -o $(FUZZ_DIR)/$${f}_fuzzer; \
	  ./$(FUZZ_DIR)/$${f}_fuzzer -max_total_time=$(FUZZ_SECONDS) -max_len=8192 -timeout=10 -rss_limit_mb=4096 \
	    -artifact_prefix=$(FUZZ_DIR)/$$f- -print_final_stats=1 $(FUZZ_DIR)/corpus-$$f; \
	done

# ---- performance (bench/RESULTS.md) ----
# Our engine, Box2D 2.4.1 and Chipmunk 7.0.3 (Debian's) on the same scenes, in
# one run, always an -O2 build without sanitizers. BENCH_ARGS="--sizes 1000,10000" etc.
# PEERS=DIR (a folder holding box2d-3.2*.tar.gz and Chipmunk-7.0.3.tar.gz)
# adds the peers built from source in their release settings: columns box2d3
# and chipmunk-release (see "Peers built from source" below).
BENCH_SRC := $(wildcard bench/*.cpp)
BENCH_OBJ := $(BENCH_SRC:%.cpp=$(BUILD)/obj/%.o)
bench: deps
	@$(MAKE) --no-print-directory PACKAGES="libbox2d-dev libchipmunk-dev $(if $(PEERS),cmake)" deps
	$(if $(PEERS),@$(MAKE) --no-print-directory peers-unpack OPT=-O2 SANITIZE=)
	@$(MAKE) --no-print-directory build/bench $(if $(PEERS),build/bench-peers) OPT=-O2 SANITIZE=
	./build/bench $(if $(PEERS),--peers build/bench-peers --peer-sources "$(notdir $(PEER_TARS))") $(BENCH_ARGS)

$(BUILD)/bench: $(BENCH_OBJ) $(LIBS)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS) -lbox2d -lchipmunk -lpthread -lm

# ---- Peers built from source (make bench PEERS=DIR) ----
# The release Chipmunk cannot share a binary with Debian's: both define the
# same 408 C symbols (cpSpaceStep...), and the dynamic linker would silently
# bind every call to one of the two. (Box2D v3 and Debian's 2.4.1 do not
# collide, checked with nm: 2.4.1's symbols are C++-mangled but for a few
# globals such as b2Vec2_zero, which v3 does not define.) So the peers live in
# their own binary, build/bench-peers (the harness plus the peers' adapters,
# nothing of Debian's), which build/bench runs for those engines' runs (every
# run is a child process anyway); build/bench is the same with or without PEERS.
# Box2D v3's headers are also box2d/box2d.h: its adapter lives in bench/peers/
# (outside BENCH_SRC) and alone gets v3's include path. The release Chipmunk's
# adapter is bench/engine_chipmunk.cpp compiled a second time against the
# unpacked headers.
PEER_DIR     := build/peers
BOX2D3_TAR   := $(firstword $(wildcard $(PEERS)/box2d-3.2*.tar.gz))
CHIPMUNK_TAR := $(firstword $(wildcard $(PEERS)/Chipmunk-7.0.3.tar.gz))
PEER_TARS    := $(BOX2D3_TAR) $(CHIPMUNK_TAR)
BOX2D3_LIB   := $(PEER_DIR)/box2d3-build/src/libbox2d.a
CHIPMUNK_LIB := $(PEER_DIR)/libchipmunk-release.a
# Chipmunk's file list exists once unpacked: peers-unpack runs in a make of its
# own before the make that builds, so this wildcard sees the files.
# cpHastySpace.c (the threaded space) includes sys/sysctl.h, gone from glibc.
CHIPMUNK_SRC := $(filter-out %/cpHastySpace.c,$(wildcard $(PEER_DIR)/chipmunk/src/*.c))
CHIPMUNK_OBJ := $(CHIPMUNK_SRC:$(PEER_DIR)/chipmunk/src/%.c=$(PEER_DIR)/chipmunk-obj/%.o)
# The harness (main, scenes; the broadphase comparison and our adapter, which
# main links to) and the peers' adapters.
PEERS_OBJ    := $(BUILD)/obj/bench/main.o $(BUILD)/obj/bench/scenes.o $(BUILD)/obj/bench/broadphase_compare.o $(BUILD)/obj/bench/round_trip.o \
                $(BUILD)/obj/bench/engine_ours.o \
                $(BUILD)/obj/bench/peers/engines.o $(BUILD)/obj/bench/peers/engine_box2d3.o \
                $(BUILD)/obj/bench/peers/engine_chipmunk_release.o
CMAKE_GEN    := $(if $(shell command -v ninja),-G Ninja)

.PHONY: peers-unpack
peers-unpack: $(PEER_DIR)/box2d3/.unpacked $(PEER_DIR)/chipmunk/.unpacked

$(PEER_DIR)/box2d3/.unpacked $(PEER_DIR)/chipmunk/.unpacked:
	@[ -f "$<" ] || { echo "PEERS=$(PEERS) must hold box2d-3.2*.tar.gz and Chipmunk-7.0.3.tar.gz"; exit 2; }
	rm -rf $(@D) && mkdir -p $(@D)
	tar xzf $< -C $(@D) --strip-components=1
	@touch $@
$(PEER_DIR)/box2d3/.unpacked: $(BOX2D3_TAR)
$(PEER_DIR)/chipmunk/.unpacked: $(CHIPMUNK_TAR)

# Release, CMake's defaults otherwise, heavy validation off; only the library.
$(BOX2D3_LIB): $(PEER_DIR)/box2d3/.unpacked
	cmake -S $(PEER_DIR)/box2d3 -B $(PEER_DIR)/box2d3-build $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Release \
	  -DBOX2D_SAMPLES=OFF -DBOX2D_UNIT_TESTS=OFF -DBOX2D_BENCHMARKS=OFF -DBOX2D_DOCS=OFF -DBOX2D_VALIDATE=OFF > /dev/null
	cmake --build $(PEER_DIR)/box2d3-build --target box2d --parallel $$(nproc)

# -O2 -DNDEBUG: a release build (Debian's keeps its debug checks on); -w: its
# warnings are not ours to fix (gcc 12 flags a calloc size in cpBBTree.c).
$(PEER_DIR)/chipmunk-obj/%.o: $(PEER_DIR)/chipmunk/src/%.c $(PEER_DIR)/chipmunk/.unpacked
	@mkdir -p $(@D)
	gcc -std=gnu99 -O2 -DNDEBUG -w -I$(PEER_DIR)/chipmunk/include -c $< -o $@

$(CHIPMUNK_LIB): $(CHIPMUNK_OBJ)
	ar rcs $@ $^

$(BUILD)/obj/bench/peers/engine_box2d3.o: CXXFLAGS += -I$(PEER_DIR)/box2d3/include
$(BUILD)/obj/bench/peers/engine_box2d3.o: $(PEER_DIR)/box2d3/.unpacked
$(BUILD)/obj/bench/peers/engine_chipmunk_release.o: bench/engine_chipmunk.cpp $(PEER_DIR)/chipmunk/.unpacked
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -I$(PEER_DIR)/chipmunk/include -c $< -o $@

$(BUILD)/bench-peers: $(PEERS_OBJ) $(LIBS) $(BOX2D3_LIB) $(CHIPMUNK_LIB)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS) -lpthread -lm

# ---- the library, installed (docs/api.md) ----
# make install PREFIX=DIR: the public headers, libphysics.a, a pkg-config file
# (DIR/lib/pkgconfig/physics.pc) and a CMake package (DIR/lib/cmake/physics).
VERSION := 1.0.0
PREFIX  ?= /usr/local
.PHONY: install install-check examples
install: $(BUILD)/libphysics.a
	@[ -n "$(PREFIX)" ] || { echo "install: PREFIX is empty"; exit 2; }
	install -d "$(PREFIX)/include/physics" "$(PREFIX)/lib/pkgconfig" "$(PREFIX)/lib/cmake/physics"
	install -m 644 include/physics/*.hpp "$(PREFIX)/include/physics/"
	install -m 644 $(BUILD)/libphysics.a "$(PREFIX)/lib/"
	sed -e 's|@VERSION@|$(VERSION)|' tools/install/physics.pc.in > "$(PREFIX)/lib/pkgconfig/physics.pc"
	install -m 644 tools/install/physicsConfig.cmake "$(PREFIX)/lib/cmake/physics/"
	sed -e 's|@VERSION@|$(VERSION)|' -e 's|@MAJOR@|$(firstword $(subst ., ,$(VERSION)))|' \
	  tools/install/physicsConfigVersion.cmake.in > "$(PREFIX)/lib/cmake/physics/physicsConfigVersion.cmake"

# An installed copy in a scratch prefix, and examples/hello.cpp built out of
# the tree against it both ways (pkg-config, then CMake's find_package), run,
# and its answer checked: the box rests on the floor's top (y 520).
CHECK_PREFIX := $(abspath $(BUILD))/install-check
comma := ,
# The examples' answers, and $(call expect,COMMAND,PATTERN,LABEL): runs
# COMMAND, prints LABEL and its output, fails unless the output matches.
HELLO_ANSWER  := "the box rests at (380.0, 520.0)"
# crates drops one crate every 45 frames: 13 in 600.
CRATES_ANSWER := "crates: 600 frames, 13 crates fell, best height "*
expect = out=$$($(1)) && echo "$(3)$$out" && case "$$out" in $(2)) ;; *) echo "$(3)unexpected answer"; exit 1;; esac
install-check: $(BUILD)/libphysics.a
	@rm -rf $(CHECK_PREFIX) && $(MAKE) --no-print-directory install PREFIX=$(CHECK_PREFIX)/prefix > /dev/null
	@mkdir -p $(CHECK_PREFIX)/pc && cp examples/hello.cpp $(CHECK_PREFIX)/pc/
	cd $(CHECK_PREFIX)/pc && $(CXX) -std=c++20 -Wall -Wextra -Werror $(SAN_FLAGS) hello.cpp -o hello \
	  $$(PKG_CONFIG_PATH=$(CHECK_PREFIX)/prefix/lib/pkgconfig pkg-config --cflags --libs physics)
	cmake -S examples -B $(CHECK_PREFIX)/cmake -DCMAKE_PREFIX_PATH=$(CHECK_PREFIX)/prefix \
	  $(if $(SAN_FLAGS),-DCMAKE_CXX_FLAGS="$(SAN_FLAGS)") > /dev/null
	+cmake --build $(CHECK_PREFIX)/cmake > /dev/null
	@for way in pc cmake; do $(call expect,$(CHECK_PREFIX)/$$way/hello,$(HELLO_ANSWER),install-check ($$way): ); done
	@$(call expect,$(CHECK_PREFIX)/cmake/crates --headless 600,$(CRATES_ANSWER),install-check (cmake$(comma) SDL): )

# The examples, built in the tree from the public headers alone (-Iinclude,
# no -Isrc: they can use nothing else), and their headless runs.
EXAMPLE_FLAGS := -std=c++20 $(OPT) -Wall -Wextra -Werror $(SAN_FLAGS) -Iinclude
$(BUILD)/examples/hello: examples/hello.cpp include/physics/physics.hpp include/physics/math.hpp $(BUILD)/libphysics.a
	@mkdir -p $(@D)
	$(CXX) $(EXAMPLE_FLAGS) $< -o $@ $(BUILD)/libphysics.a $(LDFLAGS)
$(BUILD)/examples/crates: examples/crates.cpp include/physics/physics.hpp include/physics/math.hpp $(BUILD)/libphysics.a
	@mkdir -p $(@D)
	$(CXX) $(EXAMPLE_FLAGS) $$(pkg-config --cflags sdl2) $< -o $@ $(BUILD)/libphysics.a $$(pkg-config --libs sdl2) $(LDFLAGS)
examples: $(BUILD)/examples/hello $(BUILD)/examples/crates
	@$(call expect,./$(BUILD)/examples/hello,$(HELLO_ANSWER),examples: )
	@$(call expect,./$(BUILD)/examples/crates --headless 600,$(CRATES_ANSWER),examples: )

clean:
	rm -rf build

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)

# ---- exercise mode (README.md, "Working through the sheet") ----
# `make exercise`: exercise/, the course tree with every answer replaced by
# its stub (tools/exercise/make_exercise.py), the engine files it needs and
# the per-question tests; never overwritten unless FORCE=1.
# `make exercise-test Q=6`: builds exercise/ in exercise/build, runs the
# suites q6_* (every question's without Q). STRICT=1: fail with the tests.
# `make exercise-check`: the stubbed tree fails every question's suites, the
# answered one passes them, in the sheet's order (-O0 builds of the course
# files in their own tree, on this build's objects of the rest, ~30 s of CPU
# with their runs: `exercise-trees`), then the project's own
# q suites pass. `make test` runs it (the trees beside its own build) and the
# parse-level check of the markers (exercise-lint).
# `make exercise-run Q=4`: your answer in the window (the sheet: "Constater
# que le bloc se déplace"): the project's game built with the exercise
# tree's src/course/ in place of its own, on the question's built-in scene
# (Q1 walls, Q2-Q4 drift, Q5 impulse, Q6-Q8 bounce, Q9 many), built by the
# tree's own functions (--course: its init_walls, red blocks, init_scene and
# Block::make); SCENE= another, from its description; ARGS= more flags. With no display, a headless run that prints where each
# body starts and ends. `make run Q=4` inside the tree does the same.
.PHONY: exercise exercise-test exercise-check exercise-trees exercise-lint exercise-run exercise-game
EXERCISE ?= exercise
EX_RUN   := $(EXERCISE)/build/run
EX_FRAMES ?= 120
EX_COURSE_FLAG = $(if $(SCENE),,--course)
EX_SCENE  = $(or $(SCENE),$(word $(or $(filter 1 2 3 4 5 6 7 8 9,$(Q)),9),walls drift drift drift impulse bounce bounce bounce many))
# The tree's course files, compiled as in its own Makefile: warnings shown,
# not errors (a half-written answer still runs), -O0 for a debugger. Their
# headers are the project's (only .cpp files hold answers), so the objects
# fit the rest of the game, and the results are the same bits at any -O.
EX_COURSE_OBJ := $(COURSE_SRC:%.cpp=$(EX_RUN)/obj/%.o)
$(EX_RUN)/obj/%.o: $(EXERCISE)/%.cpp
	@mkdir -p $(@D)
	$(CXX) -I$(EXERCISE)/src $(filter-out -Werror,$(CXXFLAGS)) -O0 -c $< -o $@
# The tree's course objects come first: they define every symbol of
# libphysics.a's course members, so the linker takes none of those (had it
# to, the duplicates would stop the link, never pass silently).
$(EX_RUN)/game: $(EX_COURSE_OBJ) $(GAME_OBJ) $(LIBS)
	$(CXX) $(CXXFLAGS) -o $@ $^ $(LDFLAGS) $(SDL_LIBS) $(APP_LIBS)
exercise-game: $(EX_RUN)/game
-include $(shell find $(EX_RUN)/obj -name '*.d' 2>/dev/null)

exercise-run: deps
	@case "$(Q)" in ""|[1-9]) ;; *) echo "exercise-run: Q must be 1 to 9 (got '$(Q)')" >&2; exit 2;; esac
	@[ -f $(EXERCISE)/.exercise ] || python3 tools/exercise/make_exercise.py --out $(EXERCISE)
	@$(MAKE) --no-print-directory -s exercise-game
	@if [ -n "$$DISPLAY$$WAYLAND_DISPLAY$$SDL_VIDEODRIVER" ]; then \
	  echo "exercise-run: $(EXERCISE)/src/course on the scene $(EX_SCENE) (H: keys, Esc quits)"; \
	  $(EX_RUN)/game $(EX_COURSE_FLAG) --scene $(EX_SCENE) $(ARGS); \
	else \
	  echo "exercise-run: no display (DISPLAY, WAYLAND_DISPLAY unset): $(EXERCISE)/src/course on the scene" \
	    "$(EX_SCENE), headless, $(EX_FRAMES) frames; the window opens where there is a display"; \
	  $(EX_RUN)/game $(EX_COURSE_FLAG) --scene $(EX_SCENE) --headless --frames 0 --dump $(EX_RUN)/start.csv >/dev/null && \
	  $(EX_RUN)/game $(EX_COURSE_FLAG) --scene $(EX_SCENE) --headless --frames $(EX_FRAMES) --dump $(EX_RUN)/end.csv $(ARGS) && \
	  tools/exercise/moves.sh $(EX_RUN)/start.csv $(EX_RUN)/end.csv $(EX_FRAMES); \
	fi

exercise:
	python3 tools/exercise/make_exercise.py --out exercise $(if $(filter 1,$(FORCE)),--force)

exercise-test:
	@[ -f exercise/.exercise ] || python3 tools/exercise/make_exercise.py --out exercise
	@$(MAKE) --no-print-directory -C exercise test $(if $(Q),Q=$(Q)) $(if $(STRICT),STRICT=$(STRICT))

exercise-check: exercise-trees $(BUILD)/tests $(BUILD)/game
	@MAKE="$(MAKE)" tools/exercise/check.sh --main ./$(BUILD)/tests build/exercise-check

# The trees reuse this build's objects of the files they hold unchanged
# (check.sh --reuse: the engine's, app/headless.cpp's and the per-question
# test files', those of tools/exercise/make_exercise.py's TESTS), and compile
# only their course files; not under the sanitizers (their objects need
# their link flags).
EX_REUSE := $(if $(filter 1,$(SANITIZE)),,$(filter $(BUILD)/obj/src/engine/%,$(CORE_OBJ)) $(BUILD)/obj/src/app/headless.o \
  $(patsubst %,$(BUILD)/obj/tests/%.o,test_main test_walls test_components test_move_forces test_rect test_collision test_game))
exercise-trees: $(EX_REUSE)
	@echo "tools/exercise/check.sh --trees build/exercise-check$(if $(EX_REUSE), --reuse $(BUILD)/obj (its $(words $^) objects))"
	@MAKE="$(MAKE)" EXERCISE_OPT=-O0 tools/exercise/check.sh --trees build/exercise-check $(if $(EX_REUSE),--reuse $(BUILD)/obj $^)

# (make test's first make: TEST_FIRST, defined with the test target; then
# the scene files' objects, early in its second.)
test-first: $(TEST_FIRST)
	@:
test-scene-obj: $(SCENE_OBJ)
	@:

exercise-lint:
	@python3 tools/exercise/make_exercise.py --check

test: exercise-lint

# ---- the browser build (docs/web.md) ----
# `make web`: the engine, the scenes, the testbed's logic and the games built
# to WebAssembly with Debian's clang (wasm32-wasi, wasi-libc, libc++), into
# build/web/: index.html, front.js, physics.wasm and the scene files.
# `make serve` serves it on localhost; `make web-test` checks it under Node's
# WASI (the determinism hashes, the games' replays: the same bits as the
# native build) and in headless Chromium.
WEB_PACKAGES  := clang-14 lld-14 wasi-libc libc++-14-dev-wasm32 libc++abi-14-dev-wasm32 libclang-rt-14-dev-wasm32 \
                 binaryen nlohmann-json3-dev nodejs
WEB           ?= build/web
WEB_CXX       := clang++-14
# -ffp-contract=off as natively (no fused multiply-add: wasm has none anyway);
# -fwasm-exceptions: WebAssembly's exception handling, with our runtime
# (web/cxa_exceptions.cpp: Debian's wasm libc++abi has none);
# -Iweb/compat: <filesystem> and <charconv> pieces Debian's wasm libc++ lacks;
# nlohmann's headers through a folder of their own (-isystem /usr/include
# would bring glibc's headers in); no std::filesystem in its API.
# For size (the page loads it): -Oz with link-time optimisation and no RTTI
# (nothing asks a type's name: -3.6 KB; exceptions keep their type info), then
# binaryen's wasm-opt -Oz with --low-memory-unused (the low 1 KiB is the
# bottom of the 1 MiB stack, reached only on overflow: pointer offsets fold,
# -9.3 KB; emscripten's default): 861 KB at -O2 (docs/web.md has the sizes).
WEB_OPT       ?= -Oz -flto -fno-rtti $(WEB_FEATURES)
# WebAssembly 2.0's conversions that saturate instead of trapping (a double
# to an integer without range checks around each: -1.4 KB) and its
# sign-extension instructions (-0.7 KB), which current browsers and Node run
# (docs/web.md). Bulk memory would add 0.2 KB.
WEB_FEATURES  := -mnontrapping-fptoint -msign-ext
WEB_FLAGS     := --target=wasm32-wasi -std=c++20 $(WEB_OPT) -fwasm-exceptions -Wall -Wextra -Werror -ffp-contract=off -Iweb/compat -Iinclude \
                 -Isrc -Itests -isystem $(WEB)/include -DJSON_HAS_FILESYSTEM=0 -DJSON_HAS_EXPERIMENTAL_FILESYSTEM=0 -MMD -MP
# (src/scene/save.cpp: the save key S of the command line, with std::filesystem.)
WEB_APP_SRC   := src/app/testbed.cpp src/app/testbed_replay.cpp src/app/style.cpp src/app/input_log.cpp \
                 src/app/headless.cpp src/app/dump.cpp src/app/overlay.cpp src/app/camera.cpp
WEB_SRC       := $(CORE_SRC) $(filter-out src/scene/save.cpp,$(SCENE_SRC)) $(GAMES_SRC) $(WEB_APP_SRC) $(wildcard web/*.cpp)
WEB_OBJ       := $(WEB_SRC:%.cpp=$(WEB)/obj/%.o)
# The exception runtime outside the link-time optimiser: clang 14's inlines
# its throw intrinsic into callers' try blocks, and then stops ("Cannot
# invoke an intrinsic other than donothing...").
$(WEB)/obj/web/cxa_exceptions.o: WEB_FLAGS += -fno-lto
WEB_FILES     := $(WEB)/index.html $(WEB)/front.js $(WEB)/wasi.js $(WEB)/files.json
.PHONY: web serve web-test web-pinned
web: deps
	@$(MAKE) --no-print-directory PACKAGES="$(WEB_PACKAGES)" deps
	@$(MAKE) --no-print-directory $(WEB)/physics.wasm $(WEB_FILES)
	@echo "web: $(WEB)/: physics.wasm $$(stat -c %s $(WEB)/physics.wasm) bytes, JavaScript $$(cat $(WEB)/*.js | wc -c) bytes"

$(WEB)/include/nlohmann:
	@mkdir -p $(@D)
	ln -sfn /usr/include/nlohmann $@

$(WEB)/obj/%.o: %.cpp | $(WEB)/include/nlohmann
	@mkdir -p $(@D)
	$(WEB_CXX) $(WEB_FLAGS) -c $< -o $@

# A reactor (no main: the page calls the exports). wasm-ld's stack is 64 KiB
# by default, below the data: the scene reader's recursion ran past it.
# 1 MiB, first in memory, so that an overflow traps. Not stripped by the
# linker: clang runs wasm-opt itself when it is installed, which reads the
# features (exception handling) from the target_features section; ours then
# strips the names and sections. The link-time code generation does not get
# -fwasm-exceptions' backend options from the compile: given again (without
# them its code drops every catch clause).
WEB_EH_LTO := -Wl,-mllvm,-wasm-enable-eh,-mllvm,-exception-model=wasm
$(WEB)/physics-linked.wasm: $(WEB_OBJ)
	$(WEB_CXX) --target=wasm32-wasi $(WEB_OPT) -fwasm-exceptions $(WEB_EH_LTO) -mexec-model=reactor \
	  -Wl,-z,stack-size=1048576,--stack-first -o $@ $^
$(WEB)/physics.wasm: $(WEB)/physics-linked.wasm
	wasm-opt -Oz --low-memory-unused --enable-exception-handling --strip-debug --strip-producers --strip-target-features $< -o $@

$(WEB)/%: web/%
	@mkdir -p $(@D)
	cp $< $@

# The page's JavaScript as it loads it: the sources without their whole-line
# comments, the comments after a statement's `;` and their lines'
# indentation (2.5 KB of the budget below; the sources keep them; no string
# of theirs spans lines or holds `; //`).
$(WEB)/%.js: web/%.js Makefile
	@mkdir -p $(@D)
	sed -E '/^[[:space:]]*\/\//d; s/;[[:space:]]+\/\/ .*$$/;/; s/^[[:space:]]+//' $< > $@

# The scene files the page offers (and a game's next levels) and the
# replays, copied beside it, and their list, which the page loads.
$(WEB)/files.json: $(wildcard scenes/*.json) $(wildcard scenes/maps/*.tmj scenes/maps/*.tsj scenes/maps/*.ldtk) \
                  $(wildcard replays/*.log)
	@mkdir -p $(WEB)/scenes/maps $(WEB)/replays
	cp $(filter-out scenes/maps/%,$(filter scenes/%,$^)) $(WEB)/scenes/
	cp $(filter scenes/maps/%,$^) $(WEB)/scenes/maps/
	cp $(filter replays/%,$^) $(WEB)/replays/
	python3 -c 'import sys, json; print(json.dumps(sys.argv[1:]))' $^ > $@

# On localhost only; PORT=8000 by default.
PORT ?= 8000
serve: web
	@echo "serving $(WEB)/ on http://127.0.0.1:$(PORT)/ (Ctrl-C stops)"
	python3 -m http.server $(PORT) --bind 127.0.0.1 --directory $(WEB)

# The same bits as natively: the determinism hashes and the replays' final
# states under Node's WASI, against tests/test_determinism.cpp and build/game;
# then the page in headless Chromium (Debian's), driven by playwright-core
# (npm, pinned; it downloads no browser), screenshots in build/web-test/.
WEB_TEST_PACKAGES := chromium
PLAYWRIGHT        := playwright-core@1.65.1
NPM_DIR           := build/npm
$(NPM_DIR)/node_modules/playwright-core/package.json:
	@mkdir -p $(NPM_DIR)
	npm install --no-audit --no-fund --loglevel=error --prefix $(NPM_DIR) $(PLAYWRIGHT)
# The pinned functions (web/test/pinned_check.cpp): hypot, glibc's natively
# and ours in wasm; to_chars, libc++'s and ours with web/to_chars_fixed.cpp.
PIN     := $(WEB)/pinned
PIN_CXX := $(WEB_CXX) --target=wasm32-wasi -std=c++20 -O2 -ffp-contract=off -Wall -Wextra -Werror
$(PIN)/hypot-native: web/test/pinned_check.cpp
	@mkdir -p $(@D)
	$(CXX) -std=c++20 -O2 -ffp-contract=off -Wall -Wextra -Werror $< -o $@
$(PIN)/hypot.wasm: web/test/pinned_check.cpp web/hypot.cpp
	@mkdir -p $(@D)
	$(PIN_CXX) $^ -o $@
$(PIN)/to_chars-libcxx.wasm: web/test/pinned_check.cpp
	@mkdir -p $(@D)
	$(PIN_CXX) -DTO_CHARS $^ -o $@
$(PIN)/to_chars.wasm: web/test/pinned_check.cpp web/to_chars_fixed.cpp
	@mkdir -p $(@D)
	$(PIN_CXX) -DTO_CHARS $^ -o $@
web-pinned: $(PIN)/hypot-native $(PIN)/hypot.wasm $(PIN)/to_chars-libcxx.wasm $(PIN)/to_chars.wasm
	$(PIN)/hypot-native > $(PIN)/hypot-native.txt
	node --no-warnings web/test/wasi_run.mjs $(PIN)/hypot.wasm $(PIN)/hypot.txt
	node --no-warnings web/test/wasi_run.mjs $(PIN)/to_chars-libcxx.wasm $(PIN)/to_chars-libcxx.txt
	node --no-warnings web/test/wasi_run.mjs $(PIN)/to_chars.wasm $(PIN)/to_chars.txt
	@cmp $(PIN)/hypot-native.txt $(PIN)/hypot.txt && cmp $(PIN)/to_chars-libcxx.txt $(PIN)/to_chars.txt && \
	  echo "ok   pinned: hypot as glibc's on $$(wc -l < $(PIN)/hypot.txt) arguments, to_chars as libc++'s on $$(wc -l < $(PIN)/to_chars.txt) values"

# Issue 25's budget for what the page loads, the module and the JavaScript:
# one stream in the code the module runs would bring 147 KB back (docs/web.md).
WEB_MAX_BYTES := 500000
web-test: web
	@n=$$(cat $(WEB)/physics.wasm $(WEB)/*.js | wc -c); if [ $$n -le $(WEB_MAX_BYTES) ]; then \
	  echo "ok   size: the module and the JavaScript $$n bytes (at most $(WEB_MAX_BYTES))"; \
	else echo "FAIL size: the module and the JavaScript $$n bytes, over $(WEB_MAX_BYTES)"; exit 1; fi
	@$(MAKE) --no-print-directory PACKAGES="$(WEB_TEST_PACKAGES)" deps
	@$(MAKE) --no-print-directory $(BUILD)/game $(NPM_DIR)/node_modules/playwright-core/package.json
	@$(MAKE) --no-print-directory web-pinned
	node --no-warnings web/test/node_check.mjs $(WEB)/physics.wasm $(BUILD)/game
	node web/test/chromium_check.mjs $(WEB) $(BUILD)/game build/web-test

-include $(shell find $(WEB)/obj -name '*.d' 2>/dev/null)
