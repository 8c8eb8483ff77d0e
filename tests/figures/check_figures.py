"""The figures' rendered geometry, measured in a headless Chromium: every figure kind frictionlab
draws (make_figures.py: the command line's gnuplot SVGs, frictionlab.plot's matplotlib SVGs) is
loaded into one page; a script in the page takes getBoundingClientRect() of every text element
(gnuplot's SVG text carries no boxes of its own: the browser lays it out) and of the elements
matplotlib names by id; the checks here then fail naming the figure and the elements when

  - a legend overlaps an axis label or a tick label (legend: the union of the key's entries and,
    by the sample's length, the line beside each; matplotlib: the legend's own box),
  - an axis label carries no unit: "(UNIT)" or "[UNIT]"; a unitless quantity says "(-)" or
    "(count)" (the explicit list UNITLESS),
  - a text is smaller than MIN_FONT_PX when the figure is shown 800 px wide (a report column, a
    laptop window's half),
  - a label the script sets is missing from the rendered figure,
  - a text (a title, a label) runs past the figure's left or right edge, where it is clipped.

A deliberately bad figure (a legend over the x label, a label without a unit, a title past the
edge) is checked first and
must fail, so the test can fail.

Usage: check_figures.py FRICTIONLAB_EXE SOURCE_DIR [--python-path DIR] [--keep DIR]
Exit 0 all good, 1 a figure failed, 77 chromium missing (ctest SKIP_RETURN_CODE).
"""
import argparse
import html
import json
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import make_figures  # noqa: E402

SHOWN_WIDTH_PX = 800   # the width a figure is shown at for the font check
MIN_FONT_PX = 11       # smallest text a reader reads comfortably at that width (CSS px)
UNITLESS = ("(-)", "(count)", "[-]", "[count]")  # how a unitless axis says so
TOUCH_PX = 0.5         # boxes closer than this do not count as overlapping (anti-aliasing, rounding)

# A gnuplot-shaped SVG whose legend sits on its x label, and whose y label has no unit: the test
# must report both (a check that cannot fail is no check).
BAD_SVG = """<svg width="600" height="300" viewBox="0 0 600 300" xmlns="http://www.w3.org/2000/svg">
<g font-family="Sans" font-size="16"><g transform="translate(300,290)" text-anchor="middle"><text>velocity (m/s)</text></g>
<g transform="translate(20,150) rotate(270)" text-anchor="middle"><text>friction</text></g>
<g transform="translate(60,270)" text-anchor="end"><text>0.5</text></g>
<g id="gnuplot_plot_1"><title>measured</title><g transform="translate(320,288)" text-anchor="start"><text>measured</text></g>
<path d="M260,283 L310,283" stroke="black"/></g>
<g transform="translate(560,20)" text-anchor="start"><text>a title past the edge</text></g></g></svg>"""
BAD_LABELS = ["velocity (m/s)", "friction"]

PAGE_SCRIPT = r"""
const out = [];
for (const div of document.querySelectorAll('div.fig')) {
  const svg = div.querySelector('svg');
  const vb = svg.viewBox && svg.viewBox.baseVal && svg.viewBox.baseVal.width ? svg.viewBox.baseVal.width
           : parseFloat(svg.getAttribute('width'));
  const box = svg.getBoundingClientRect();
  const scale = box.width / vb;
  const rect = (e) => { const r = e.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; };
  const texts = [];
  for (const t of svg.querySelectorAll('text')) {
    const r = t.getBoundingClientRect();
    if (r.width === 0 || !t.textContent.trim()) continue;
    const plot = t.closest('g[id^="gnuplot_plot"]');
    const named = t.closest('[id^="fl-"]');
    texts.push({s: t.textContent, r: rect(t), key: !!plot, id: named ? named.id : '',
                font: parseFloat(getComputedStyle(t).fontSize) * scale});
  }
  const ids = {};
  for (const e of svg.querySelectorAll('[id^="fl-"]')) ids[e.id] = rect(e);
  out.push({name: div.dataset.name, width: box.width, box: [box.left, box.top, box.right, box.bottom], texts: texts,
            ids: ids});
}
document.getElementById('result').textContent = 'RESULT' + JSON.stringify(out) + 'END';
"""


# What some figures' gnuplot scripts must say (the issue's fixes, which the geometry cannot see):
# a log-spaced map key on a true logarithmic axis with its unit, the polar plot's dashed rings,
# the drift figure counting its 8 logs (not its 16 rows).
EXPECT_IN_SCRIPT = {
    "analyze-map-2d": ["set logscale x 10", "set xlabel 'plant.V0 (m/s)'", "set ylabel 'plant.c (N s/m)'"],
    "analyze-map-1d": ["set xlabel 'friction.Fs (N)'", "unset logscale x"],
    "simulate-xy-circle": ["dashed rings", "dt (8,6)"],
    "analyze-contour": ["dashed rings", "dt (8,6)"],
    "identify-drift": ["over 8 logs"],
}


def find_browser():
    for b in ("chromium", "chromium-browser"):
        if shutil.which(b):
            return shutil.which(b)
    return None


def svg_body(path_or_text):
    text = path_or_text if path_or_text.lstrip().startswith("<svg") else pathlib.Path(path_or_text).read_text()
    text = re.sub(r"<\?xml[^>]*\?>", "", text)
    text = re.sub(r"<!DOCTYPE[^>]*>", "", text, flags=re.S)
    # Data lines (paths of thousands of points) are not measured: dropped, the page renders in a
    # fraction of the time. Legend samples, ticks and frames are short paths and stay.
    text = re.sub(r"<path\b[^>]{4000,}>", "", text)
    return text


def measure(browser, figures, scratch):
    """figures: [(name, svg text or path)]; returns {name: measurements} from one browser run."""
    parts = ["<!DOCTYPE html><html><head><meta charset='utf-8'><style>body{margin:0}"
             f"div.fig{{width:{SHOWN_WIDTH_PX}px}} div.fig svg{{width:{SHOWN_WIDTH_PX}px;height:auto;display:block}}"
             "</style></head><body>"]
    for name, svg in figures:
        parts.append(f"<div class='fig' data-name='{html.escape(name)}'>{svg_body(str(svg))}</div>")
    parts.append(f"<pre id='result'></pre><script>{PAGE_SCRIPT}</script></body></html>")
    page = pathlib.Path(scratch) / "figures.html"
    page.write_text("".join(parts), encoding="utf-8")
    profile = tempfile.mkdtemp(dir=scratch, prefix="profile.")
    done = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                           "--disable-background-networking", "--disable-component-update", "--disable-sync",
                           "--disable-dev-shm-usage", f"--user-data-dir={profile}", "--dump-dom", f"file://{page}"],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
    m = re.search(r"RESULT(.*?)END", done.stdout, re.S)
    if not m:
        raise RuntimeError("chromium gave no measurements (exit %d): %s" % (done.returncode, done.stderr[-1500:]))
    return {f["name"]: f for f in json.loads(html.unescape(m.group(1)))}


def squash(s):
    """A label as gnuplot's enhanced text renders it (markup gone), spaces dropped: to match."""
    return re.sub(r"[\s{}^_\\@&~]", "", s)


def overlaps(a, b):
    return a[0] < b[2] - TOUCH_PX and b[0] < a[2] - TOUCH_PX and a[1] < b[3] - TOUCH_PX and b[1] < a[3] - TOUCH_PX


def union(rects):
    return [min(r[0] for r in rects), min(r[1] for r in rects), max(r[2] for r in rects), max(r[3] for r in rects)]


NUMBER = re.compile(r"^[\s\-\u2212+0-9.,eE\u00d7^]+$")


def has_unit(label):
    return bool(re.search(r"\([^()]+\)\s*$|\[[^\[\]]+\]\s*$", label)) or label.strip().endswith(UNITLESS)


def check(name, kind, labels, m):
    """The problems of one figure, as lines naming it and the elements."""
    problems = []
    for label in dict.fromkeys(labels):
        if not has_unit(label):
            problems.append(f"{name}: axis label '{label}' carries no unit (write '(UNIT)'; unitless: "
                            + " or ".join(f"'{u}'" for u in UNITLESS) + ")")
    texts = m["texts"]
    left, right = m["box"][0], m["box"][2]
    for t in texts:
        if t["r"][0] < left - TOUCH_PX or t["r"][2] > right + TOUCH_PX:
            problems.append(f"{name}: text '{t['s'][:60]}' runs past the figure's edge (clipped)")
            break
    for t in texts:
        if t["font"] < MIN_FONT_PX:
            problems.append(f"{name}: text '{t['s'][:40]}' is {t['font']:.1f} px at {SHOWN_WIDTH_PX} px wide "
                            f"(smallest allowed {MIN_FONT_PX} px)")
            break
    if kind == "gnuplot":
        wanted = {squash(l) for l in labels}
        label_boxes = [(t["s"], t["r"]) for t in texts if not t["key"] and squash(t["s"]) in wanted]
        for label in labels:
            if not any(squash(s) == squash(label) for s, _ in label_boxes):
                problems.append(f"{name}: axis label '{label}' set by the script is not in the rendered figure")
        ticks = [(t["s"], t["r"]) for t in texts if not t["key"] and NUMBER.match(t["s"])]
        entries = [t for t in texts if t["key"]]
        legends = []
        if entries:
            # One legend per panel: entries grouped by nearness (a panel's key is one block).
            entries.sort(key=lambda t: (t["r"][1], t["r"][0]))
            groups = []
            for t in entries:
                h = t["r"][3] - t["r"][1]
                for g in groups:
                    u = union([e["r"] for e in g])
                    if t["r"][1] <= u[3] + 1.5 * h and t["r"][3] >= u[1] - 1.5 * h:
                        g.append(t)
                        break
                else:
                    groups.append([t])
            for g in groups:
                u = union([e["r"] for e in g])
                h = max(e["r"][3] - e["r"][1] for e in g)
                # the sample line beside each entry: samplen 2 (two character widths) and a gap
                legends.append(("legend [" + ", ".join(e["s"] for e in g) + "]", [u[0] - 2.5 * h, u[1], u[2], u[3]]))
    else:
        ids = m["ids"]
        label_boxes = [(k, r) for k, r in ids.items() if re.match(r"fl-[xy]label-", k) and r[2] > r[0]]
        ticks = [(k, r) for k, r in ids.items() if k.startswith("fl-tick-") and r[2] > r[0]]
        legends = [(k, r) for k, r in ids.items() if k.startswith("fl-legend-")]
        if not label_boxes or not ticks:  # nothing measured: the check would pass vacuously
            problems.append(f"{name}: no axis labels or tick labels measured (ids fl-xlabel-*, fl-tick-*)")
        label_boxes = [(next((t["s"] for t in texts if t["id"] == k), k), r) for k, r in label_boxes]
        ticks = [(next((t["s"] for t in texts if t["id"] == k), k), r) for k, r in ticks]
    for lname, lr in legends:
        for what, boxes in (("axis label", label_boxes), ("tick label", ticks)):
            for s, r in boxes:
                if overlaps(lr, r):
                    problems.append(f"{name}: {lname} overlaps the {what} '{s}'")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("exe")
    ap.add_argument("src")
    ap.add_argument("--keep", help="make the figures here (kept) instead of a temporary directory")
    ap.add_argument("--no-python", action="store_true", help="the command line's figures only")
    a = ap.parse_args()
    browser = find_browser()
    if not browser:
        print("SKIP: chromium not installed (Debian package chromium; scripts/setup.sh installs it)")
        return 77
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="fl-figures.") as scratch:
        out = pathlib.Path(a.keep) if a.keep else pathlib.Path(scratch) / "figures"
        figures = make_figures.make_all(a.exe, a.src, out, python=not a.no_python)
        made = time.monotonic()
        m = measure(browser, [("bad", BAD_SVG)] + [(f.name, f.svg) for f in figures], scratch)
        # The bad figure first: its overlap and its missing unit must be found.
        bad = check("bad", "gnuplot", BAD_LABELS, m["bad"])
        if not any("overlaps the axis label 'velocity (m/s)'" in p for p in bad) or \
           not any("'friction' carries no unit" in p for p in bad) or \
           not any("'a title past the edge' runs past the figure's edge" in p for p in bad):
            print("FAIL: the deliberately bad figure was not caught:\n  " + "\n  ".join(bad or ["(no problem found)"]))
            return 1
        problems = []
        for f in figures:
            if f.name not in m:
                problems.append(f"{f.name}: not rendered")
                continue
            problems += check(f.name, f.kind, f.labels, m[f.name])
            if f.name in EXPECT_IN_SCRIPT:
                script = pathlib.Path(f"{f.svg}.gp").read_text()
                problems += [f"{f.name}: the script lacks {w!r}" for w in EXPECT_IN_SCRIPT[f.name] if w not in script]
    print(f"figures: {len(figures)} drawn in {made - start:.1f} s, measured in {time.monotonic() - made:.1f} s; "
          f"the bad figure caught ({len(bad)} problems)")
    if problems:
        print("FAIL:\n  " + "\n  ".join(problems))
        return 1
    print("figures: ok (" + ", ".join(f.name for f in figures) + ")")
    return 0


if __name__ == "__main__":
    sys.exit(main())
