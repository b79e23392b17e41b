"""
MODULE:    testsuite/test_manual_links.py (r3.sbrt addon)
PURPOSE:   The manuals link GRASS's own pages as GRASS's addons do
           (relative, href="r.what.html", never a fixed grass-stable URL),
           and tools/manual_links.py points them at the GRASS the addon is
           built against: the installed GRASS's page where it exists, else
           https://grass.osgeo.org/grassXY/manuals/ of that version; the
           addon's own pages and images stay relative (issue 52, item 4)
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import os
import re
import shutil
import subprocess
import tempfile

from grass.gunittest.case import TestCase
from grass.gunittest.main import test

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
SCRIPT = os.path.join(ROOT, "tools", "manual_links.py")
MANUALS = ["r3.sbrt.convert", "r3.sbrt.manage", "r3.sbrt.support", "r3.sbrt.render",
           "r3.sbrt.what", "r3.sbrt.surface", "r3.sbrt.volume", "r3.sbrt.profile",
           "g.gui.sbrt"]


def links(text):
    return re.findall(r'<a\b[^>]*?\bhref="([^"]*)"', text)


class TestManualLinks(TestCase):

    def test_no_fixed_version_in_sources(self):
        """No manual names a GRASS version of its own in a link."""
        for module in MANUALS:
            with open(os.path.join(ROOT, module, module + ".html"), encoding="utf-8") as page:
                for link in links(page.read()):
                    self.assertNotIn("grass.osgeo.org/grass", link,
                                     "%s.html links %s" % (module, link))

    def rewritten(self, gisbase, version):
        """r3.sbrt.what's page rewritten in a folder of its own beside its image."""
        work = tempfile.mkdtemp(prefix="r3sbrt_links_")
        self.addCleanup(shutil.rmtree, work, ignore_errors=True)
        page = os.path.join(work, "r3.sbrt.what.html")
        shutil.copy(os.path.join(ROOT, "r3.sbrt.what", "r3.sbrt.what.html"), page)
        shutil.copy(os.path.join(ROOT, "r3.sbrt.what", "r3_sbrt_what_logs.png"), work)
        subprocess.run([SCRIPT, gisbase, version, page], check=True, timeout=60)
        with open(page, encoding="utf-8") as text:
            return text.read()

    def test_links_to_the_installed_grass(self):
        gisbase = os.environ["GISBASE"]
        text = self.rewritten(gisbase, "8.2.1")
        core = os.path.join(os.path.realpath(gisbase), "docs", "html", "r.what.html")
        expected = ("file://" + os.path.join(gisbase, "docs", "html", "r.what.html")
                    if os.path.exists(core) else
                    "https://grass.osgeo.org/grass82/manuals/r.what.html")
        self.assertIn('href="%s"' % expected, text)
        self.assertIn('href="r3.sbrt.render.html"', text)  # the addon's own page
        self.assertIn('src="r3_sbrt_what_logs.png"', text)  # its own image

    def test_links_to_the_version_built_against(self):
        """Without GRASS's pages installed: the manuals of that version online."""
        text = self.rewritten("/nonexistent", "8.4.1")
        self.assertIn('href="https://grass.osgeo.org/grass84/manuals/r.what.html"', text)
        self.assertIn('href="https://grass.osgeo.org/grass84/manuals/v.what.rast.html"', text)
        for link in links(text):
            if not link.startswith(("#", "https://", "file://")):
                self.assertTrue(re.match(r"(r3\.sbrt\.|g\.gui\.sbrt)", link), link)


if __name__ == "__main__":
    test()
