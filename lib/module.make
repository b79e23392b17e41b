# Shared rules of the r3.sbrt modules, included by each module Makefile after it names its program.
# Links the static libraries lib/grass_sbrt and lib/sbrt (GRASS-NOTES 1.3).
MODULE_TOPDIR ?= /usr/lib/grass82

SBRT_DIR = ../lib/sbrt
GRASS_SBRT_DIR = ../lib/grass_sbrt

LIBES = $(RASTER3DLIB) $(RASTERLIB) $(GISLIB)
DEPENDENCIES = $(RASTER3DDEP) $(RASTERDEP) $(GISDEP)
EXTRA_INC = -I$(SBRT_DIR) -I$(GRASS_SBRT_DIR)
EXTRA_HEADERS = $(wildcard $(SBRT_DIR)/*.hpp $(GRASS_SBRT_DIR)/*.hpp *.hpp)

include $(MODULE_TOPDIR)/include/Make/Module.make

# After the include: Vars.make/Compile.make reset LINK = $(CC).
LINK = $(CXX)
CXXFLAGS += -std=c++17 -Wall -Wextra -O2 -pthread
SBRT_STLIBS = $(GRASS_SBRT_DIR)/$(OBJDIR)/libgrass_sbrt.a $(SBRT_DIR)/$(OBJDIR)/libsbrt.a
LIBES := $(SBRT_STLIBS) $(LIBES) $(ZLIB) -pthread
DEPENDENCIES += $(SBRT_STLIBS)

default: cmd
