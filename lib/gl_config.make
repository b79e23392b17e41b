# GL build settings shared by lib/sbrt_gl, r3.sbrt.render and the unit
# tests. OSMesa is built in only where its header exists (Mesa < 25.1).
SBRT_OSMESA_HEADER := $(wildcard /usr/include/GL/osmesa.h)
SBRT_GL_CXXFLAGS = $(if $(SBRT_OSMESA_HEADER),-DSBRT_HAVE_OSMESA)
# libOSMesa is loaded at run time (osmesa_context.cpp), never linked
SBRT_GL_LIBS = -lEGL -ldl
