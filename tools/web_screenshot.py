#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""make web-screenshot: the page (build/web) in headless Chromium, the
seed rendered at its default settings, saved as docs/img/web.png.

    tools/web_screenshot.py [WEB_DIR [OUT.png]]
"""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from cdp import Browser, find_chromium  # noqa: E402


def main():
    web = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT,
                                                             "build/web")
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(
        ROOT, "docs/img/web.png")
    if not find_chromium():
        sys.exit("web_screenshot: chromium not found (apt-get install "
                 "--no-install-recommends chromium)")
    with Browser(web, width=1400, height=1150) as b:
        b.open("index.html")
        state = b.eval("await fixtrace.ready; await fixtrace.render(); "
                       "return document.body.dataset.state")
        if state != "done":
            sys.exit("web_screenshot: the page did not render (%s)" % state)
        b.screenshot(out + ".tmp")
    os.replace(out + ".tmp", out)
    print("wrote %s" % os.path.relpath(out, ROOT))


if __name__ == "__main__":
    main()
