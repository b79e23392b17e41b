# r3.sbrt addon: builds the static libraries lib/sbrt, lib/grass_sbrt and
# lib/sbrt_gl, then the modules, into ./dist. Not Dir.make: its "pre" target writes into the
# system GISBASE on Debian and its subdirs loop swallows failures
# (docs/BUILD-NOTES.md 5).
include lib/grass_topdir.make

# lib/sbrt and lib/sbrt_gl: GRASS-free, one rule for every consumer
# (lib/static_lib.make); lib/grass_sbrt and the modules: GRASS make
LIBDIRS = \
	lib/sbrt \
	lib/grass_sbrt \
	lib/sbrt_gl
# every r3.sbrt.* folder with a Makefile is a module (no list to keep)
MODULEDIRS = $(patsubst %/Makefile,%,$(wildcard r3.sbrt.*/Makefile)) g.gui.sbrt
SUBDIRS = $(LIBDIRS) $(MODULEDIRS)

# Plain "make" never installs into the system GISBASE: local builds land in
# ./dist. g.extension passes BIN=, HTMLDIR=, ... and ARCH_DISTDIR= itself.
ifeq ($(origin ARCH_DISTDIR),undefined)
SUBMAKE_ARGS = ARCH_DISTDIR=$(CURDIR)/dist GISBASE=$(MODULE_TOPDIR) \
	STRINGDIR=$(CURDIR)/dist/locale/scriptstrings
endif

# one target a folder, so that make -j builds the libraries side by side and
# then the modules side by side; the C++ modules link the libraries
default: $(SUBDIRS)

$(SUBDIRS):
	@$(MAKE) -C $@ MODULE_TOPDIR=$(MODULE_TOPDIR) $(SUBMAKE_ARGS)

$(filter r3.%,$(MODULEDIRS)): $(LIBDIRS)

install:
	@for d in $(SUBDIRS); do $(MAKE) -C $$d MODULE_TOPDIR=$(MODULE_TOPDIR) $(SUBMAKE_ARGS) install || exit 1; done

# Set-up of a fresh Debian machine, the demo and the tests: `make test` the
# tests for people (unit tests, short fuzzing, the stage order, the
# gunittest files, the notebook), `make check` the deep ones (the unit tests
# under ASan+UBSan, longer fuzzing, valgrind of the modules, the gunittest
# files on GRASS 8.4 in a Debian 13 root). CI runs both.
setup:
	@tools/setup.sh

# demo, test and check build on every core (make -j, whatever they were
# called with): the libraries side by side, then the modules
BUILD_JOBS := $(shell nproc)

demo: setup
	@$(MAKE) --no-print-directory -j$(BUILD_JOBS) default
	@tools/demo.sh

test: setup
	@$(MAKE) --no-print-directory -j$(BUILD_JOBS) default
	@tools/run_tests.sh test

check: setup
	@$(MAKE) --no-print-directory -j$(BUILD_JOBS) default
	@tools/run_tests.sh check

clean:
	@for d in $(SUBDIRS); do $(MAKE) -C $$d MODULE_TOPDIR=$(MODULE_TOPDIR) $(SUBMAKE_ARGS) clean; done
	$(MAKE) -C testsuite/unit clean
	$(MAKE) -C testsuite/fuzz clean
	$(MAKE) -C benchmarks/trace_bench clean
	$(MAKE) -C benchmarks/geotop_like clean
	rm -rf dist testreport

.PHONY: default install setup demo test check clean $(SUBDIRS)
