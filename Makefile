# ricochet build. `make demo` and `make check` install missing Debian packages
# first (scripts/install-deps.sh), then build.
CC      ?= cc
OPT     ?= -O2
CSTD    := -std=c11 -D_POSIX_C_SOURCE=200809L
WARN    := -Wall -Wextra -pedantic -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
           -Wno-unused-parameter
# complex-step differentiation uses C99 complex arithmetic; the limited-range
# rule is exact for the finite values the kernels see (docs/design.md).
CFLAGS  ?= $(OPT) -g
CXFLAGS ?= -fcx-limited-range
# the git commit of the sources, in the results files (docs/output-format.md)
RC_COMMIT := $(shell c=$$(git rev-parse --short=12 HEAD 2>/dev/null) && { git diff --quiet HEAD 2>/dev/null && echo $$c || echo $$c-modified; } || echo unknown)
# the library's objects are position-independent: one set of objects makes
# both build/libricochet.a and build/libricochet.so
ALLCFLAGS = $(CSTD) $(WARN) $(CXFLAGS) -fPIC -pthread -Iinclude -Isrc -I/usr/include/suitesparse \
            -DRC_COMMIT='"$(RC_COMMIT)"' $(CFLAGS)
# what the library links against; also written into ricochet.pc (Libs.private)
LIBS_PRIVATE := -lsundials_cvodes -lsundials_arkode -lsundials_ida -lsundials_kinsol -lsundials_nvecserial -lsundials_sunmatrixsparse \
           -lsundials_sunlinsolklu -lklu -lgsl -lgslcblas -lnetcdf -lm -pthread
LDLIBS  := $(LIBS_PRIVATE)
BUILD   ?= build
PREFIX  ?= /usr/local
LIBDIR  ?= $(PREFIX)/lib
# the Python module (python/ricochet) goes where Debian's python3 looks for
# a prefix: $(PREFIX)/lib/python3.N/dist-packages (/usr/local/lib/python3.11/
# dist-packages on Debian 12)
PYVER   := $(shell /usr/bin/python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null || echo 3)
PYDIR   ?= $(PREFIX)/lib/python$(PYVER)/dist-packages

# The git commit of the sources, baked in as RC_COMMIT (`ricochet --version`,
# rc_build_commit()); "unknown" outside a git checkout. Defined here only.
RC_COMMIT := $(shell git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)
# Library version from the public header; the soname carries the major number.
VERSION := $(shell sed -n 's/^\#define RICOCHET_VERSION "\(.*\)"/\1/p' include/ricochet/ricochet.h)
SOMAJOR := $(firstword $(subst ., ,$(VERSION)))
SONAME  := libricochet.so.$(SOMAJOR)

# Sources are discovered stage by stage and room by room (src/README.md): a
# stage's files and its rooms' (src/<stage>/<room>/); src/cli holds the
# command-line program, everything else goes into the library.
STAGES  := base case model engine solver output
LIB_SRC := $(foreach d,$(STAGES),$(wildcard src/$(d)/*.c src/$(d)/*/*.c))
LIB_OBJ := $(patsubst src/%.c,$(BUILD)/obj/%.o,$(LIB_SRC))
SRC_HDR := $(wildcard src/*/*.h src/*/*/*.h src/*/*/*.inc include/ricochet/*.h)
TEST_SRC := $(wildcard tests/*.c)
TEST_OBJ := $(patsubst tests/%.c,$(BUILD)/tobj/%.o,$(TEST_SRC))
LIB     := $(BUILD)/libricochet.a
SHLIB   := $(BUILD)/libricochet.so.$(VERSION)
BIN     := $(BUILD)/ricochet
TESTBIN := $(BUILD)/run_tests
REPLAY  := $(BUILD)/fuzz_replay
FUZZ_SECONDS ?= 60
# the physics scene fuzzer (fuzz/physics/README.md): scenes, first seed, jobs;
# PHYSFUZZ_STRICT=1 makes its make-check sample count failures (0: XFAIL)
SCENES  ?= 200
SEED    ?= 1
JOBS    ?= 2
PHYSFUZZ_OUT ?= $(BUILD)/physfuzz
PHYSFUZZ_STRICT ?= 0
export PHYSFUZZ_STRICT

.PHONY: all lib demo gallery check validate asan tsan valgrind bench install uninstall clean deps deps-test test fuzz physics-fuzz FORCE

all: $(BIN) $(TESTBIN) $(SHLIB) $(REPLAY)

# the static and the shared library only
lib: $(LIB) $(SHLIB)

deps:
	@bash scripts/install-deps.sh

# what the tests need besides (scripts/install-deps.sh test)
deps-test:
	@bash scripts/install-deps.sh test

$(BUILD)/obj/%.o: src/%.c $(SRC_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(ALLCFLAGS) -c $< -o $@

# The vector operations of the integrator (nvfast.c) at -O3: their
# element-wise loops vectorised (the same operations per element, so the
# same results; the sums are not reassociated without -ffast-math).
$(BUILD)/obj/solver/nvfast.o: ALLCFLAGS += -O3

# netcdf.c alone carries the commit; rebuilt when it changes
$(BUILD)/obj/output/netcdf.o: src/output/netcdf.c $(SRC_HDR) $(BUILD)/commit
	@mkdir -p $(dir $@)
	$(CC) $(ALLCFLAGS) -DRC_COMMIT='"$(RC_COMMIT)"' -c $< -o $@

$(BUILD)/commit: FORCE
	@mkdir -p $(BUILD)
	@echo '$(RC_COMMIT)' | cmp -s - $@ || echo '$(RC_COMMIT)' > $@

FORCE:

$(BUILD)/tobj/%.o: tests/%.c $(wildcard tests/*.h tests/*.def) $(SRC_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(ALLCFLAGS) -c $< -o $@

$(LIB): $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

# the shared library exports the functions of include/ricochet/ricochet.h only
$(SHLIB): $(LIB_OBJ) src/libricochet.map
	$(CC) $(ALLCFLAGS) -shared -Wl,-soname,$(SONAME) -Wl,--version-script=src/libricochet.map \
	    -o $@ $(LIB_OBJ) $(LDLIBS)
	ln -sf $(notdir $@) $(BUILD)/$(SONAME)
	ln -sf $(SONAME) $(BUILD)/libricochet.so

# the commit is rebuilt into base/commit.o (rc_build_commit) whenever it changes
$(BUILD)/commit.stamp: FORCE
	@mkdir -p $(BUILD)
	@echo '$(RC_COMMIT)' | cmp -s - $@ || echo '$(RC_COMMIT)' > $@
$(BUILD)/obj/base/commit.o: $(BUILD)/commit.stamp

CLI_OBJ := $(patsubst src/%.c,$(BUILD)/obj/%.o,$(wildcard src/cli/*.c))
$(BIN): $(CLI_OBJ) $(LIB)
	$(CC) $(ALLCFLAGS) -o $@ $^ $(LDLIBS)

$(TESTBIN): $(TEST_OBJ) $(LIB)
	$(CC) $(ALLCFLAGS) -o $@ $^ $(LDLIBS)

# The fuzz target without libFuzzer: replays fuzz/regressions/ and the seeds
# under make check (fuzz/README.md).
$(REPLAY): fuzz/replay.c fuzz/fuzz_deck.c $(LIB)
	$(CC) $(ALLCFLAGS) -o $@ fuzz/replay.c fuzz/fuzz_deck.c $(LIB) $(LDLIBS)

# Unit tests, then the fast validation problems; one closing tally line.
check: deps-test
	@$(MAKE) --no-print-directory all
	@bash scripts/check.sh $(BUILD) fast

test: all
	@$(BUILD)/run_tests

# Every validation problem, including the convergence studies.
validate: deps-test
	@$(MAKE) --no-print-directory all
	@bash scripts/check.sh $(BUILD) all

# Default case end to end: netCDF results and PNG plots in out/. Builds the
# program only (not the tests).
demo: deps
	@$(MAKE) --no-print-directory $(BIN)
	@mkdir -p out
	$(BIN) run cases/demo_sphere_drop.rad -o out/demo.nc
	/usr/bin/python3 scripts/plot.py out/demo.nc out/demo
	@echo "results: out/demo.nc, plots: out/demo_*.png"

# The example gallery (cases/README.md): every cases/*.rad but the demo run
# into out/gallery/NAME.nc (summary in NAME.log), then one picture
# out/gallery/NAME.png by scripts/plot.py with the options of the deck's
# "# plot:" line. Needs the ricochet binary only; stops at the first case
# that fails (exit code != 0) or whose physics checks do not pass (a static
# analysis, /SOLVER Method 3, runs none: its summary line "physics checks:
# not run (static analysis ..." is accepted instead).
GALLERY := $(filter-out cases/demo_sphere_drop.rad,$(wildcard cases/*.rad))
gallery: deps $(BIN)
	@mkdir -p out/gallery
	@set -e; for f in $(GALLERY); do n=$$(basename $$f .rad); \
	    $(BIN) run $$f -o out/gallery/$$n.nc > out/gallery/$$n.log 2>&1 || \
	        { cat out/gallery/$$n.log; echo "gallery: $$f failed"; exit 1; }; \
	    grep -Eq '^physics checks: (passed|not run \(static analysis)' out/gallery/$$n.log || \
	        { cat out/gallery/$$n.log; echo "gallery: $$f: physics checks did not pass"; exit 1; }; \
	    /usr/bin/python3 scripts/plot.py out/gallery/$$n.nc $$(sed -n 's/^# plot: //p' $$f) \
	        --png out/gallery/$$n.png > /dev/null; \
	    echo "$$f: $$(grep -o 'simulated .* wall' out/gallery/$$n.log), $$(grep -Eo '^physics checks: (passed|not run)' out/gallery/$$n.log) -> out/gallery/$$n.png"; \
	done

# AddressSanitizer + UndefinedBehaviorSanitizer build: unit tests, the malformed
# decks, the fuzz regressions and seeds, the demo case.
asan: deps-test
	@$(MAKE) --no-print-directory BUILD=build-asan OPT=-O1 \
	    CFLAGS="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all" all
	ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 build-asan/run_tests
	@# every error path of the catalogue and the fuzz inputs, leaks included
	ASAN_OPTIONS=detect_leaks=1 bash tests/malformed_test.sh build-asan/ricochet > build-asan/malformed.log; \
	    grep '^FAIL ' build-asan/malformed.log; \
	    echo "malformed decks under ASan: $$(grep -c '^PASS ' build-asan/malformed.log) passed"; \
	    ! grep -q '^FAIL ' build-asan/malformed.log
	ASAN_OPTIONS=detect_leaks=1 build-asan/fuzz_replay fuzz/regressions/*
	ASAN_OPTIONS=detect_leaks=1 build-asan/fuzz_replay -q fuzz/corpus/*
	@mkdir -p out
	ASAN_OPTIONS=detect_leaks=1 build-asan/ricochet run cases/demo_sphere_drop.rad -o out/asan_demo.nc
	@# every command-line path, failures included (a leak or error exits 9)
	ASAN_OPTIONS=detect_leaks=1:exitcode=9 UBSAN_OPTIONS=print_stacktrace=1 \
	    bash tests/cli_test.sh build-asan/ricochet > out/asan_cli.log 2>&1; \
	    cat out/asan_cli.log; ! grep -q '^FAIL ' out/asan_cli.log

# ThreadSanitizer: the library and tests/tsan/threads.c (two simulations in
# two threads writing two files, a session stepped from a third thread) built
# with -fsanitize=thread in build-tsan (the library only: about a minute on
# two cores); fails on any ThreadSanitizer report (scripts/tsan.sh).
TSAN_CFLAGS := -O1 -g -fsanitize=thread -fno-omit-frame-pointer
# Every netCDF function the library calls is wrapped (-Wl,--wrap) to make
# HDF5's library-wide state visible to ThreadSanitizer (tests/tsan/threads.c).
TSAN_WRAP = $(shell sed -n 's/^WRAP[^,]*, *\(nc_[a-z_]*\),.*/\1/p' tests/tsan/threads.c)
tsan: deps-test
	@$(MAKE) --no-print-directory BUILD=build-tsan CFLAGS="$(TSAN_CFLAGS)" build-tsan/libricochet.a
	$(CC) $(CSTD) $(WARN) -pthread -Iinclude $(TSAN_CFLAGS) -o build-tsan/tsan_threads tests/tsan/threads.c \
	    build-tsan/libricochet.a $(LDLIBS) $(foreach f,$(TSAN_WRAP),-Wl,--wrap=$(f))
	@bash scripts/tsan.sh build-tsan/tsan_threads build-tsan/libricochet.a

valgrind: all
	@mkdir -p out
	valgrind --error-exitcode=9 --leak-check=full --errors-for-leak-kinds=definite \
	    $(BIN) run cases/demo_sphere_drop.rad -o out/valgrind_demo.nc
	@# every command-line path, failures included (a leak or error exits 9)
	RICOCHET_DELAY=15 RICOCHET_WRAP="valgrind -q --error-exitcode=9 --leak-check=full --errors-for-leak-kinds=definite" \
	    bash tests/cli_test.sh $(BIN) > out/valgrind_cli.log 2>&1; \
	    cat out/valgrind_cli.log; ! grep -q '^FAIL ' out/valgrind_cli.log

# libFuzzer on the reader and compiler for FUZZ_SECONDS (default 60) with
# clang, ASan and UBSan, in build-fuzz; fails when it finds a crash, leak or
# hang (fuzz/README.md). clang 14 has no -fcx-limited-range: full-range
# complex arithmetic there.
FUZZ_CFLAGS := -O1 -g -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer \
               -fno-sanitize-recover=all
fuzz:
	@bash scripts/install-deps.sh fuzz
	@$(MAKE) --no-print-directory BUILD=build-fuzz CC=clang CXFLAGS= CFLAGS="$(FUZZ_CFLAGS)" \
	    build-fuzz/libricochet.a
	clang $(CSTD) $(WARN) -Iinclude $(FUZZ_CFLAGS) -fsanitize=fuzzer -o build-fuzz/fuzz_deck \
	    fuzz/fuzz_deck.c build-fuzz/libricochet.a $(LDLIBS)
	@bash fuzz/run.sh build-fuzz $(FUZZ_SECONDS)

# Random physics scenes run and checked against physical invariants
# (energy, dissipation, penetration, momentum, frame/unit invariance,
# backends, rtol convergence): a tally line and $(PHYSFUZZ_OUT)/report.json,
# the decks and results of every violating scene kept there.
physics-fuzz: all
	/usr/bin/python3 fuzz/physics/scenefuzz.py run --scenes $(SCENES) --seed $(SEED) --jobs $(JOBS) \
	    --out $(PHYSFUZZ_OUT) --ricochet $(BIN) $(if $(filter 1,$(PHYSFUZZ_STRICT)),--strict)

bench: deps
	@$(MAKE) --no-print-directory all
	@bash bench/run.sh $(BUILD)

# PREFIX (default /usr/local), LIBDIR, PYDIR and DESTDIR (a staging root)
# are honoured: bin/ricochet, the static and shared libraries, the header,
# lib/pkgconfig/ricochet.pc and the Python module.
install: $(BIN) $(LIB) $(SHLIB)
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(LIBDIR)/pkgconfig $(DESTDIR)$(PREFIX)/include/ricochet \
	    $(DESTDIR)$(PYDIR)/ricochet
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/ricochet
	install -m 644 $(LIB) $(DESTDIR)$(LIBDIR)/libricochet.a
	install -m 755 $(SHLIB) $(DESTDIR)$(LIBDIR)/
	ln -sf $(notdir $(SHLIB)) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/libricochet.so
	install -m 644 include/ricochet/*.h $(DESTDIR)$(PREFIX)/include/ricochet/
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@LIBDIR@|$(LIBDIR)|' -e 's|@VERSION@|$(VERSION)|' \
	    -e 's|@LIBS_PRIVATE@|$(LIBS_PRIVATE)|' ricochet.pc.in > $(DESTDIR)$(LIBDIR)/pkgconfig/ricochet.pc
	install -m 644 python/ricochet/*.py $(DESTDIR)$(PYDIR)/ricochet/

# what install wrote (same PREFIX, LIBDIR, PYDIR, DESTDIR)
uninstall:
	rm -f $(DESTDIR)$(PREFIX)/bin/ricochet $(DESTDIR)$(LIBDIR)/libricochet.a $(DESTDIR)$(LIBDIR)/libricochet.so \
	    $(DESTDIR)$(LIBDIR)/$(SONAME) $(DESTDIR)$(LIBDIR)/libricochet.so.$(VERSION) \
	    $(DESTDIR)$(LIBDIR)/pkgconfig/ricochet.pc $(DESTDIR)$(PREFIX)/include/ricochet/ricochet.h
	rm -rf $(DESTDIR)$(PYDIR)/ricochet
	-rmdir $(DESTDIR)$(PREFIX)/include/ricochet

clean:
	rm -rf build build-asan build-tsan build-fuzz out
