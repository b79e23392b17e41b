# The one rule that builds a static library of this addon (lib/sbrt,
# lib/sbrt_gl) from its sources, included by that library's Makefile. Every
# consumer (the modules through the top Makefile, the unit tests, the fuzz
# target, trace_bench) runs that Makefile:
#
#   make -C lib/sbrt [BUILD=dir CXX=c++ FLAGS="..."]  ->  dir/libsbrt.a
#
# The default flavour (BUILD=build, g++, FLAGS below) is built once and
# linked by the modules, the unit tests and trace_bench. A flavour that
# needs other compile flags (ASan+UBSan for the unit tests, clang with
# libFuzzer's coverage for the fuzz target) is the same rule with other
# CXX/FLAGS into another folder, which the consumer names (its own build
# folder). A change of CXX or FLAGS for a folder rebuilds it (BUILD/flags).
#
# Set by the including Makefile: LIB (name), SOURCES (*.cpp relative to the
# library's folder), INCLUDES (-I/-D of its own), optionally EXTRA_OBJECTS
# (made by rules of its own, compiled with $(compile_cxx)).
#
# No GRASS make fragments here: the libraries are GRASS-free, and the unit
# tests, fuzz target and trace_bench build without GRASS.

BUILD ?= build
FLAGS ?= -std=c++17 -O2 -g -Wall -Wextra -pthread

# absolute, so that the objects' dependency files (*.d) name the same
# targets however the folder was given (build, ../../lib/sbrt/build)
OUT := $(abspath $(BUILD))
STLIB := $(OUT)/lib$(LIB).a
OBJECTS = $(patsubst %.cpp,$(OUT)/%.o,$(SOURCES))

# -MMD -MP: each object lists the headers it read (BUILD/**/*.d), so a
# changed header recompiles exactly the objects that include it
compile_cxx = $(CXX) $(FLAGS) $(INCLUDES) -MMD -MP -c -o $@ $<

default: $(STLIB)

$(STLIB): $(OBJECTS) $(EXTRA_OBJECTS) $(OUT)/sources
	rm -f $@ && $(AR) crs $@ $(OBJECTS) $(EXTRA_OBJECTS)

# objects keep their stage folder (format/reader.o), so equal file names in
# two folders do not collide; a file moved between folders simply builds in
# its new place (the archive is made afresh from the current list)
$(OUT)/%.o: %.cpp $(OUT)/flags
	@mkdir -p $(@D)
	$(compile_cxx)

# the compiler and flags this folder was built with, rewritten (and so
# rebuilding everything) only when they change. Written when the Makefile
# is read, not by a rule that always runs, so that `make -n` lists only what
# a changed header would rebuild; a dry run (-n) writes nothing.
build_cmd = $(subst ','\'',$(CXX) $(FLAGS) $(INCLUDES))
ifeq ($(findstring n,$(firstword -$(MAKEFLAGS))),)
$(shell mkdir -p $(OUT) && { echo '$(build_cmd)' | cmp -s - $(OUT)/flags || \
                             echo '$(build_cmd)' >$(OUT)/flags; })
endif
$(OUT)/flags: ;

# the list of sources, rewritten when it changes (a file added or removed,
# another STAGES=): the archive is made again, nothing is recompiled
sources_list = $(sort $(SOURCES))
ifeq ($(findstring n,$(firstword -$(MAKEFLAGS))),)
$(shell mkdir -p $(OUT) && { echo '$(sources_list)' | cmp -s - $(OUT)/sources || \
                             echo '$(sources_list)' >$(OUT)/sources; })
endif
$(OUT)/sources: ;

-include $(OBJECTS:.o=.d) $(EXTRA_OBJECTS:.o=.d)

# the default folder, any other in here, and the OBJ.* folders of the
# GRASS make system that built these libraries before
clean:
	rm -rf build build-* OBJ.*

# no PGM here (g.extension would list it as a module); nothing to install
install:

.PHONY: default clean install
