# Shared rules of the r3.sbrt modules, included by each module Makefile after it names its program.
# Links the static libraries lib/grass_sbrt and lib/sbrt (docs/BUILD-NOTES.md 2),
# lib/sbrt_gl with EGL (and OSMesa) when the module sets SBRT_USES_GL, and
# GRASS's vector and database libraries when it sets SBRT_USES_VECTOR, and
# what it names in SBRT_EXTRA_LIBES.
# MODULE_TOPDIR: set by the module Makefile (../lib/grass_topdir.make)

SBRT_DIR = ../lib/sbrt
GRASS_SBRT_DIR = ../lib/grass_sbrt

# recursive (=): Grass.make defines the library variables later
LIBES = $(SBRT_EXTRA_LIBES) $(SBRT_VECTOR_LIBES) $(RASTER3DLIB) $(RASTERLIB) $(GISLIB)
DEPENDENCIES = $(RASTER3DDEP) $(RASTERDEP) $(GISDEP)
EXTRA_INC = -I$(SBRT_DIR) -I$(GRASS_SBRT_DIR)
ifdef SBRT_USES_VECTOR
SBRT_VECTOR_LIBES = $(VECTORLIB) $(DBMILIB)
DEPENDENCIES += $(VECTORDEP) $(DBMIDEP)
EXTRA_INC += $(VECT_INC)
EXTRA_CFLAGS += $(VECT_CFLAGS)
endif
EXTRA_HEADERS = $(wildcard $(SBRT_DIR)/*.hpp $(SBRT_DIR)/*/*.hpp $(GRASS_SBRT_DIR)/*.hpp *.hpp)
# the static libraries: lib/sbrt and lib/sbrt_gl in their default folder
# (../lib/static_lib.make, the same archives the unit tests link),
# lib/grass_sbrt in GRASS's OBJ.* (recursive: OBJDIR comes from Grass.make);
# the GL library (lib/sbrt_gl) comes before the core library it uses
SBRT_STLIBS = $(GRASS_SBRT_DIR)/$(OBJDIR)/libgrass_sbrt.a $(SBRT_DIR)/build/libsbrt.a
ifdef SBRT_USES_GL
include ../lib/gl_config.make
SBRT_GL_DIR = ../lib/sbrt_gl
EXTRA_INC += -I$(SBRT_GL_DIR)
EXTRA_HEADERS += $(wildcard $(SBRT_GL_DIR)/*.hpp)
SBRT_STLIBS = $(SBRT_GL_DIR)/build/libsbrt_gl.a \
              $(GRASS_SBRT_DIR)/$(OBJDIR)/libgrass_sbrt.a $(SBRT_DIR)/build/libsbrt.a
endif
# a changed library relinks the module
DEPENDENCIES += $(SBRT_STLIBS)

# before the include: the compile and link rules take their prerequisites
# from EXTRA_HEADERS and DEPENDENCIES when they are defined
include $(MODULE_TOPDIR)/include/Make/Module.make

# After the include: Vars.make/Compile.make reset LINK = $(CC).
LINK = $(CXX)
CXXFLAGS += -std=c++17 -Wall -Wextra -O2 -pthread
LIBES := $(SBRT_STLIBS) $(LIBES) $(SBRT_GL_LIBS) -lpng $(ZSTDLIB) $(ZLIB) -pthread
include ../lib/manual_links.make

default: cmd
