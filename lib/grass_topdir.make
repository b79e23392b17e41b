# The GRASS installation the addon builds against (MODULE_TOPDIR, GRASS's
# own name for it): the one `grass --config path` names (GRASS 8.2 on
# Debian 12, 8.4 on Debian 13), /usr/lib/grass82 where no grass is on the
# PATH. A command line's MODULE_TOPDIR= (g.extension gives one) wins.
# (:=, once: a ?= of $(shell) would run grass at every use)
ifndef MODULE_TOPDIR
MODULE_TOPDIR := $(shell grass --config path 2>/dev/null || echo /usr/lib/grass82)
endif
