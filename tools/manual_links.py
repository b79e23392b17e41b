#!/usr/bin/env python3
"""
MODULE:    tools/manual_links.py (r3.sbrt addon)
PURPOSE:   Points the relative links of installed manual pages to GRASS's
           own pages (core modules in SEE ALSO, the index pages of the
           footer, the style sheet and logo) at the manuals of the GRASS
           the addon was built against, as g.extension's
           update_manual_page() does for an installed addon: the installed
           GRASS's page (file://GISBASE/docs/html/NAME) where it exists,
           else https://grass.osgeo.org/grassXY/manuals/NAME of that GRASS
           version. Links to the addon's own pages and images stay
           relative. Run again on a page it changed, it changes nothing.
           (docs/BUILD-NOTES.md 4)
USAGE:     tools/manual_links.py GISBASE VERSION PAGE.html...
           e.g. tools/manual_links.py /usr/lib/grass82 8.2.1 dist/docs/html/r3.sbrt.what.html
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import re
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
# href="..." of <a> and <link>, src="..." of <img>
LINK = re.compile(r'(<(?:a|link)\b[^>]*?\bhref="|<img\b[^>]*?\bsrc=")([^"]*)(")')


def own_pages():
    """The addon's manual pages: every top-level folder NAME holding NAME.html."""
    return {name + ".html" for name in os.listdir(ROOT)
            if os.path.isfile(os.path.join(ROOT, name, name + ".html"))}


def manuals_url(version):
    """https://grass.osgeo.org/grassXY/manuals/ of GRASS X.Y.*"""
    major, minor = version.split(".")[:2]
    return "https://grass.osgeo.org/grass%s%s/manuals/" % (major, re.sub(r"\D.*", "", minor))


def target(link, page_dir, gisbase, url, ours):
    """Where a link of an installed page should point (itself if it stays)."""
    if not link or link.startswith(("#", "/")) or re.match(r"[A-Za-z][A-Za-z0-9+.-]*:", link):
        return link  # an anchor, an absolute path or a URL
    name = link.split("#", 1)[0].split("?", 1)[0]
    if "/" in name or name in ours or os.path.exists(os.path.join(page_dir, name)):
        return link  # the addon's own page or a file installed beside it
    core = os.path.join(gisbase, "docs", "html", name)
    if os.path.exists(core):
        return "file://" + os.path.abspath(core) + link[len(name):]
    return url + link


def fix_page(path, gisbase, version):
    """Rewrites the page in place; gives the number of links changed."""
    with open(path, encoding="utf-8") as page:
        text = page.read()
    page_dir = os.path.dirname(os.path.abspath(path))
    url, ours = manuals_url(version), own_pages()
    changed = 0

    def replace(match):
        nonlocal changed
        new = target(match.group(2), page_dir, gisbase, url, ours)
        changed += new != match.group(2)
        return match.group(1) + new + match.group(3)

    text = LINK.sub(replace, text)
    if changed:
        with open(path, "w", encoding="utf-8") as page:
            page.write(text)
    return changed


def main(argv):
    if len(argv) < 4:
        sys.exit("usage: tools/manual_links.py GISBASE VERSION PAGE.html...")
    gisbase, version = argv[1], argv[2]
    if not re.match(r"\d+\.\d+", version):
        sys.exit("manual_links: version %r is not X.Y[.Z] (GRASS_VERSION_NUMBER)" % version)
    for path in argv[3:]:
        fix_page(path, gisbase, version)


if __name__ == "__main__":
    main(sys.argv)
