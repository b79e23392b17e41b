# Included by every module Makefile after GRASS's Module.make or
# Script.make. A plain `make` (into ./dist): the installed manual page's
# links to GRASS's own pages (SEE ALSO, the footer's index pages) point at
# the manuals of the GRASS built against (../tools/manual_links.py,
# docs/BUILD-NOTES.md 4). g.extension passes SOURCE_URL and rewrites them
# itself.
ifndef SOURCE_URL
html:
	@$(PYTHON) ../tools/manual_links.py $(GISBASE) $(GRASS_VERSION_NUMBER) $(HTMLDIR)/$(PGM).html
endif
