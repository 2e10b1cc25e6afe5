#!/usr/bin/env python3
"""Check the built HTML manual as a reader would: open pages in headless Chromium (Debian's).

    check_manual.py --html DIR [--chromium PATH] [--screenshots DIR]
    check_manual.py --self-test [--chromium PATH]

For the front page (index.html), one API page (feasible_set.h's) and one docs page (the
reproduction page, with its figures), each loaded by Chromium from file:// with the network
off:
  - the page renders: its title and phrases of its body are in the DOM Chromium built (the
    front page's version and commit line among them);
  - no missing image: every <img> the page shows has loaded in the browser (naturalWidth > 0,
    read by a script added to a scratch copy of the page), and every <img>'s file exists (the
    search box's and tree's icons stay hidden until used: their files are checked);
  - no dead internal link: every href and src that is not an external URL names a file of the
    manual, and an anchor `#a` names an id or name in that file;
  - nothing is loaded from outside the manual: no <img>, <script> or stylesheet from a URL;
  - no markup shows as text (`<tt>`, `@ref`, a `{#label}`);
  - a screenshot, SCREENSHOTS/manual-<page>.png (1280×1400), is written and is a PNG of that
    size that is not blank (a rendered page compresses to more than a blank one).
Then every HTML file of the manual is read (without the browser) for dead internal links,
missing images and markup shown as text, so no page of the manual links nowhere.

--self-test builds a scratch manual with a missing image, an image file the browser cannot
decode, a dead link, a dead anchor and an external image, and fails unless each is reported
(and a good image, link and anchor are not).

Exit status 0 when everything holds; 1 with one line per problem.
"""

import argparse
import html.parser
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import urllib.parse

PAGES = [
    # (file, expected in <title>, expected in the body text)
    ("index.html", "gmcc", ["A map of the library", "This manual documents gmcc ",
                            "How to cite this version", "@software{gmcc,"]),
    ("feasible__set_8h.html", "feasible_set.h", ["File Reference", "Function Documentation",
                                                 "feasible_set()"]),
    ("docs_reproduction.html", "Reproducing", ["Synthetic experiment", "Sharding"]),
]
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                  "--no-first-run", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync", "--hide-scrollbars",
                  "--disable-dev-shm-usage", "--disable-extensions",
                  "--virtual-time-budget=10000"]
# Added at the end of a scratch copy of a page: once everything has loaded, record in the DOM
# what the browser made of each image.
PROBE = """<script>
window.addEventListener('load', function () {
  var imgs = document.getElementsByTagName('img');
  for (var i = 0; i < imgs.length; i++) {
    imgs[i].setAttribute('data-gmcc-loaded',
        imgs[i].complete && imgs[i].naturalWidth > 0 ? 'yes' : 'no');
    imgs[i].setAttribute('data-gmcc-shown', imgs[i].getClientRects().length > 0 ? 'yes' : 'no');
  }
  document.body.setAttribute('data-gmcc-probe', 'done');
});
</script>
"""
# Markup a reader must never see as text: Doxygen's escaped tags, unresolved commands, labels.
LEFTOVERS = ["<tt>", "</tt>", "@ref ", "\\ref ", "{#docs_", "<!-- gmcc:"]
EXTERNAL = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")


class Elements(html.parser.HTMLParser):
    """The links, images, scripts and stylesheets of a page, its ids, title and text."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.refs = []      # (tag, attribute, value, attrs)
        self.ids = set()
        self.title = ""
        self.text = []
        self._in_title = False
        self._skip = 0
        self.probe_done = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        for key in ("id", "name"):
            if a.get(key):
                self.ids.add(a[key])
        if tag == "a" and a.get("href") is not None:
            self.refs.append(("a", "href", a["href"], a))
        elif tag in ("img", "script", "iframe") and a.get("src"):
            self.refs.append((tag, "src", a["src"], a))
        elif tag == "link" and a.get("href"):
            self.refs.append(("link", "href", a["href"], a))
        if tag == "img" and not a.get("src"):
            self.refs.append(("img", "src", "", a))
        if tag == "body" and a.get("data-gmcc-probe") == "done":
            self.probe_done = True
        if tag == "title":
            self._in_title = True
        if tag in ("script", "style"):
            self._skip += 1

    def handle_startendtag(self, tag, attrs):
        self.handle_starttag(tag, attrs)
        if tag in ("script", "style"):
            self._skip -= 1

    def handle_endtag(self, tag):
        if tag == "title":
            self._in_title = False
        if tag in ("script", "style") and self._skip:
            self._skip -= 1

    def handle_data(self, data):
        if self._in_title:
            self.title += data
        elif not self._skip:
            self.text.append(data)


def parse(text):
    p = Elements()
    p.feed(text)
    return p


class Checker:
    def __init__(self, html_dir):
        self.html = os.path.abspath(html_dir)
        self.problems = []
        self._ids = {}

    def problem(self, where, what):
        self.problems.append("%s: %s" % (where, what))

    def ids_of(self, path):
        if path not in self._ids:
            with open(path, encoding="utf-8", errors="replace") as f:
                self._ids[path] = parse(f.read()).ids
        return self._ids[path]

    def check_refs(self, where, page_path, elements, loaded_probe):
        """Every non-external href/src names an existing file (and anchor) of the manual."""
        base = os.path.dirname(page_path)
        for tag, attr, value, attrs in elements.refs:
            if tag == "img" and not value:
                self.problem(where, "<img> without src")
                continue
            if value.startswith("javascript:") or value in ("#", ""):
                continue
            if EXTERNAL.match(value):
                scheme = value.split(":", 1)[0].lower()
                if tag != "a" and scheme != "file":
                    self.problem(where, "<%s %s=%s> loads from outside the manual"
                                 % (tag, attr, value))
                if scheme != "file":
                    continue
                target = urllib.parse.urlparse(value)
                path, fragment = urllib.parse.unquote(target.path), target.fragment
            else:
                url = urllib.parse.urlparse(value)
                path = urllib.parse.unquote(url.path)
                fragment = url.fragment
                path = os.path.normpath(os.path.join(base, path)) if path else page_path
            if not os.path.abspath(path).startswith(self.html + os.sep):
                self.problem(where, "<%s %s=%s> points outside the manual" % (tag, attr, value))
                continue
            if not os.path.isfile(path):
                self.problem(where, "<%s %s=%s>: no such file %s"
                             % (tag, attr, value, os.path.relpath(path, self.html)))
                continue
            if fragment and path.endswith(".html"):
                ids = elements.ids if path == page_path else self.ids_of(path)
                if fragment not in ids:
                    self.problem(where, "<%s %s=%s>: no anchor #%s in %s" % (
                        tag, attr, value, fragment, os.path.relpath(path, self.html)))
            if tag == "img":
                if os.path.getsize(path) == 0:
                    self.problem(where, "<img src=%s>: empty file" % value)
                if loaded_probe and attrs.get("data-gmcc-shown") == "yes" and \
                        attrs.get("data-gmcc-loaded") != "yes":
                    self.problem(where, "<img src=%s> did not load in the browser" % value)

    def static_pass(self):
        """Every HTML file of the manual, read as text."""
        count = 0
        for root, _, files in os.walk(self.html):
            for name in files:
                if not name.endswith(".html"):
                    continue
                path = os.path.join(root, name)
                with open(path, encoding="utf-8", errors="replace") as f:
                    elements = parse(f.read())
                where = os.path.relpath(path, self.html)
                self.check_refs(where, path, elements, False)
                if not name.endswith("_source.html"):   # a header's verbatim text may hold them
                    body = " ".join(" ".join(elements.text).split())
                    for leftover in LEFTOVERS:
                        if leftover in body:
                            self.problem(where, "shows markup as text: %r" % leftover)
                count += 1
        return count


def chromium_run(chromium, args, timeout=180):
    profile = tempfile.mkdtemp(prefix="gmcc-chromium-")
    try:
        return subprocess.run([chromium] + CHROMIUM_FLAGS + ["--user-data-dir=" + profile] + args,
                              capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return subprocess.CompletedProcess(args, -1, "", "chromium ran over %d s" % timeout)
    finally:
        shutil.rmtree(profile, ignore_errors=True)


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    return struct.unpack(">II", head[16:24])


def check_page(checker, chromium, name, title_part, body_part, screenshots):
    path = os.path.join(checker.html, name)
    if not os.path.isfile(path):
        checker.problem(name, "the page was not built")
        return
    with open(path, encoding="utf-8") as f:
        text = f.read()
    scratch = os.path.join(checker.html, ".gmcc-check-" + name)
    with open(scratch, "w", encoding="utf-8") as f:
        f.write(text.replace("</body>", PROBE + "</body>") if "</body>" in text else text + PROBE)
    try:
        run = chromium_run(chromium, ["--dump-dom", "file://" + scratch])
    finally:
        os.remove(scratch)
    if run.returncode or "<html" not in run.stdout:
        checker.problem(name, "chromium --dump-dom failed (%d): %s"
                        % (run.returncode, run.stderr.strip()[-300:]))
        return
    dom = parse(run.stdout)
    if not dom.probe_done:
        checker.problem(name, "the page did not finish loading in the browser")
    if title_part not in dom.title:
        checker.problem(name, "title %r does not hold %r" % (dom.title.strip(), title_part))
    body = " ".join(" ".join(dom.text).split())
    for part in body_part:
        if part not in body:
            checker.problem(name, "the rendered page does not show %r" % part)
    for leftover in LEFTOVERS:
        if leftover in body:
            checker.problem(name, "the rendered page shows markup as text: %r" % leftover)
    # The probe's page is the scratch copy, beside the real one: links resolve the same.
    checker.check_refs(name + " (in Chromium)", path, dom, True)
    if screenshots:
        shot = os.path.join(os.path.abspath(screenshots),
                            "manual-" + os.path.splitext(name)[0] + ".png")
        if os.path.exists(shot):
            os.remove(shot)
        run = chromium_run(chromium, ["--window-size=1280,1400", "--screenshot=" + shot,
                                      "file://" + path])
        size = png_size(shot) if os.path.exists(shot) else None
        if size is None:
            checker.problem(name, "no screenshot (chromium %d: %s)"
                            % (run.returncode, run.stderr.strip()[-300:]))
        elif size != (1280, 1400):
            checker.problem(name, "screenshot is %dx%d, not 1280x1400" % size)
        elif os.path.getsize(shot) < 30000:
            checker.problem(name, "screenshot %s is nearly blank (%d bytes)"
                            % (shot, os.path.getsize(shot)))
        else:
            print("screenshot: %s" % shot)


def check(html_dir, chromium, screenshots, pages=PAGES):
    checker = Checker(html_dir)
    for name, title_part, body_part in pages:
        check_page(checker, chromium, name, title_part, body_part, screenshots)
    n = checker.static_pass()
    return checker, n


def self_test(chromium):
    """A scratch manual with one of each fault: every one must be reported."""
    d = tempfile.mkdtemp(prefix="gmcc-manual-self-test-")
    try:
        with open(os.path.join(d, "good.png"), "wb") as f:
            # A valid 1x1 PNG.
            f.write(bytes.fromhex(
                "89504e470d0a1a0a0000000d4948445200000001000000010806000000"
                "1f15c4890000000d49444154789c6360f8cfc0f01f0005000201e2d5"
                "b7a10000000049454e44ae426082"))
        with open(os.path.join(d, "broken.png"), "wb") as f:
            f.write(b"not a PNG at all")
        with open(os.path.join(d, "other.html"), "w") as f:
            f.write('<html><head><title>other</title></head><body><p id="here">x</p>'
                    '</body></html>')
        with open(os.path.join(d, "index.html"), "w") as f:
            f.write('<html><head><title>gmcc self test</title></head><body>'
                    '<p>A map of the library</p><p>see &lt;tt&gt;x&lt;/tt&gt;</p>'
                    '<img src="good.png"><img src="missing.png"><img src="broken.png">'
                    '<img src="https://example.invalid/x.png">'
                    '<a href="other.html#here">ok</a><a href="nowhere.html">dead</a>'
                    '<a href="other.html#gone">dead anchor</a>'
                    '<a href="https://doi.org/10.1016/S0262-8856(98)00179-6">external</a>'
                    '</body></html>')
        checker, _ = check(d, chromium, None, [("index.html", "gmcc", ["A map of the library"])])
        expected = ["broken.png> did not load in the browser", "no such file missing.png",
                    "x.png> loads from outside the manual", "no such file nowhere.html",
                    "no anchor #gone", "shows markup as text: '<tt>'"]
        text = "\n".join(checker.problems)
        failed = [e for e in expected if e not in text]
        wrong = [p for p in checker.problems
                 if "good.png" in p or "#here" in p or "doi.org" in p]
        for e in failed:
            print("self-test: not reported: %s" % e)
        for w in wrong:
            print("self-test: reported a good reference: %s" % w)
        if failed or wrong:
            print("self-test: the reports were:\n  " + "\n  ".join(checker.problems))
            return 1
        print("self-test: all %d planted faults reported, no good reference reported"
              % len(expected))
        return 0
    finally:
        shutil.rmtree(d, ignore_errors=True)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--html")
    ap.add_argument("--chromium", default=shutil.which("chromium") or "chromium")
    ap.add_argument("--screenshots")
    ap.add_argument("--self-test", action="store_true")
    args = ap.parse_args(argv)
    if args.self_test:
        return self_test(args.chromium)
    if not args.html:
        ap.error("--html is required")
    checker, n = check(args.html, args.chromium, args.screenshots)
    for p in checker.problems:
        print(p)
    if checker.problems:
        print("check_manual.py: %d problems" % len(checker.problems))
        return 1
    print("check_manual.py: %d pages rendered in Chromium and %d HTML files read: no missing "
          "image, no dead internal link" % (len(PAGES), n))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
