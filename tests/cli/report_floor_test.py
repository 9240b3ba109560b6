#!/usr/bin/env python3
"""envdesign report on an imported floor (examples/floor) and on a spec whose empty design
dwarfs the rest (issue 25): the floor is drawn (lanes, sight lines, the chosen zones, the
paths of the most probable tasks before and after), and on every plot the chosen design is
visible, apart from the empty design, at the value `envdesign design --json` gives.

The plots are read from the SVG gnuplot wrote: each panel's frame, its axis ticks (pixel ->
value) and the chosen design's series. Headless Chromium renders the page: a DOM measure of
the drawn elements (a copy of the page with a script added) and a screenshot whose pixels
show the floor's colours.

Usage: report_floor_test.py BUILD_DIR EXAMPLES_DIR [--keep DIR]"""

import json
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_test import decode_png, fail  # noqa: E402  (one PNG decoder for both tests)

NUMBER = r"(-?[0-9.]+(?:e[-+]?[0-9]+)?)"
CHROMIUM = "/usr/bin/chromium"


def run(build, *args):
    done = subprocess.run([os.path.join(build, "bin", "envdesign")] + list(args),
                          capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        fail("envdesign %s exited %d: %s" % (" ".join(args), done.returncode, done.stderr))
    return done.stdout


# ---- the plots, from gnuplot's SVG ---------------------------------------------------------

def frames(svg):
    """The panels' frames: gnuplot draws each as a closed rectangle from its top left corner
    down (bars and key boxes start at a bottom corner), with labelled ticks on its left."""
    out = []
    for d in re.findall(r"d='(M[^']*Z)\s*'", svg):
        xy = [tuple(map(float, p)) for p in re.findall(NUMBER + "," + NUMBER, d)]
        xs, ys = sorted({x for x, _ in xy}), sorted({y for _, y in xy})
        if len(xy) != 5 or len(xs) != 2 or len(ys) != 2:
            continue
        frame = (xs[0], ys[0], xs[1], ys[1])  # left, top, right, bottom
        if xy[0] == (xs[0], ys[0]) and xy[1] == (xs[0], ys[1]) and len(ticks(svg, frame, "y")) > 1:
            out.append(frame)
    return sorted(set(out))


def ticks(svg, frame, axis):
    """(pixel, value) of the labelled ticks on a frame's left (y) or bottom (x) edge."""
    left, top, right, bottom = frame
    out = []
    pattern = (r"<path stroke='black'\s+d='M" + NUMBER + "," + NUMBER + " L" + NUMBER + "," +
               NUMBER + r"[^']*'/>\s*<g transform=\"translate\([^)]*\)\"[^>]*>\s*"
               r"<text><tspan[^>]*>([^<]*)</tspan>")
    for x1, y1, x2, y2, label in re.findall(pattern, svg):
        x1, y1, x2, y2 = map(float, (x1, y1, x2, y2))
        try:
            value = float(label)
        except ValueError:
            continue
        if axis == "y" and y1 == y2 and abs(x1 - left) < 0.5 and top - 1 <= y1 <= bottom + 1:
            out.append((y1, value))
        if axis == "x" and x1 == x2 and abs(y1 - bottom) < 0.5 and left - 1 <= x1 <= right + 1:
            out.append((x1, value))
    return sorted(set(out))


def scale(tick_list):
    """pixel -> value through the ticks: linear, or logarithmic when that fits them better."""
    if len(tick_list) < 2:
        fail("an axis has fewer than two labelled ticks: %r" % tick_list)
    (p0, v0), (p1, v1) = tick_list[0], tick_list[-1]

    def linear(p):
        return v0 + (p - p0) * (v1 - v0) / (p1 - p0)

    def log(p):
        return math.exp(math.log(v0) + (p - p0) * (math.log(v1) - math.log(v0)) / (p1 - p0))

    def misfit(f):
        return max(abs(f(p) - v) / max(abs(v), 1e-9) for p, v in tick_list)

    if all(v > 0 for _, v in tick_list) and misfit(log) < misfit(linear):
        return log, "log"
    return linear, "linear"


def series_points(svg, title_start):
    """Pixel points of the series whose <title> starts with `title_start`: line vertices and
    point markers (the key's sample included: it lies outside every frame)."""
    at = svg.find("<title>" + title_start)
    if at < 0:
        return None
    start = svg.rfind("<g id=", 0, at)
    depth, end = 0, start
    for m in re.finditer(r"<g[ >]|</g>", svg[start:]):  # to the series group's own </g>
        depth += -1 if m.group(0) == "</g>" else 1
        if depth == 0:
            end = start + m.end()
            break
    group = svg[start:end]
    points = [tuple(map(float, p)) for p in re.findall(r"translate\(" + NUMBER + "," + NUMBER +
                                                       r"\) scale", group)]
    for d in re.findall(r"d='([^']*)'", group):
        points += [tuple(map(float, p)) for p in re.findall(NUMBER + "," + NUMBER, d)]
    return points


def inside(point, frame):
    left, top, right, bottom = frame
    return left - 0.5 <= point[0] <= right + 0.5 and top - 0.5 <= point[1] <= bottom + 0.5


def check_plot(name, svg, chosen_title, objective, spec_x):
    """The chosen series lies in one panel, clear of the bottom (3% of the panel at least), no
    empty design in that panel, and its value at the spec's x (bars: its marker) is the
    objective. Returns what was measured, for the log."""
    points = series_points(svg, chosen_title)
    if not points:
        fail("%s: no series titled %r" % (name, chosen_title))
    panels = frames(svg)
    home = [f for f in panels if sum(inside(p, f) for p in points) > 0]
    if len(home) != 1:
        fail("%s: the chosen design is in %d panels, not one" % (name, len(home)))
    frame = home[0]
    drawn = [p for p in points if inside(p, frame)]
    left, top, right, bottom = frame
    heights = sorted((bottom - y) / (bottom - top) for _, y in drawn)
    lowest = heights[0]
    if lowest < 0.03:
        fail("%s: the chosen design lies on the axis (%.1f%% of the panel's height)" %
             (name, 100 * lowest))
    empty = series_points(svg, "{} (the empty design")
    if empty and any(inside(p, frame) for p in empty):
        fail("%s: the empty design shares the chosen design's panel" % name)
    to_y, kind = scale(ticks(svg, frame, "y"))
    if spec_x is None:  # bars: the marker on the chosen bar's top
        at = min(drawn, key=lambda p: p[1])
    else:
        to_x, _ = scale(ticks(svg, frame, "x"))
        at = min(drawn, key=lambda p: abs(to_x(p[0]) - spec_x))
        if abs(to_x(at[0]) - spec_x) > 0.02 * max(1.0, spec_x):
            fail("%s: no point of the chosen design at x = %g" % (name, spec_x))
    value = to_y(at[1])
    span = to_y(top) - to_y(bottom)
    tolerance = 0.03 * value if kind == "log" else 0.01 * span
    if abs(value - objective) > tolerance:
        fail("%s: the chosen design is plotted at %.4g, its objective is %.4g" %
             (name, value, objective))
    return "%s: %s axis, chosen at %.4g (objective %.4g), %.0f%% above the axis" % (
        name, kind, value, objective, 100 * lowest)


def check_plots(html, result):
    svgs = re.findall(r"<svg.*?</svg>", html, re.S)
    plots = [s for s in svgs if "gnuplot_canvas" in s]
    if len(plots) != 3:
        fail("expected 3 plots, found %d" % len(plots))
    design = result["design"]
    chosen = ("{" + ", ".join(design) + "}" if design else "{}") + " (chosen)"
    weights = result["weights"]
    names = ("terms", "objective against T", "objective against alpha")
    xs = (None, weights["horizon"], weights["alpha"])
    by_name = dict(zip(("terms", "T", "alpha"), plots))  # in page order
    out = []
    for name, key, x in zip(names, ("terms", "T", "alpha"), xs):
        out.append(check_plot(name, by_name[key], chosen, result["objective"], x))
    # The empty design's own bar carries its objective.
    baseline = result["baseline"]["objective"]
    if ">%s<" % shown(baseline) not in by_name["terms"]:
        fail("the empty design's bar is not labelled %s" % shown(baseline))
    return out


def shown(value):
    """As the CLI prints a number (number_format.cc): whole, one decimal from 1000, else four
    significant digits."""
    if value == int(value) and abs(value) < 1e15:
        return "%d" % value
    if 1000 <= abs(value) < 1e9:
        return "%.1f" % value
    return "%.4g" % value


# ---- the floor ----------------------------------------------------------------------------

def check_floor_html(html):
    start = html.find("<h2>The floor</h2>")
    if start < 0:
        fail("the page has no floor section")
    svgs = re.findall(r"<svg.*?</svg>", html[start:html.find("<h2>Where the objective")], re.S)
    if len(svgs) != 7:  # the floor, and three tasks before and after
        fail("expected 7 floor pictures, found %d" % len(svgs))
    overview = svgs[0]
    counts = {c: overview.count('class="%s"' % c)
              for c in ("robot-edge", "human-edge", "wall", "zone", "tape", "lane", "place")}
    expected = {"robot-edge": 18, "human-edge": 4, "wall": 16, "zone": 2, "tape": 0, "lane": 0,
                "place": 9}
    if counts != expected:
        fail("the floor drawing: %r, expected %r" % (counts, expected))
    for name in ("gap-barrier", "top-aisle-marking"):
        if "<title>%s</title></polygon>" % name not in overview:
            fail("the chosen zone %s is not drawn" % name)
    # The first task drawn is v19-v16 (all tasks equally probable, the largest IE first):
    # before, the robot drives round the racks (v19 v20 v21 v22 v17 v16, 40 m) where people
    # expect it back along the aisle (v19 v18 v17 v16, 20 m).
    if "<h3>Task v19-v16: v19 (pick_a) to v16 (dock)" not in html:
        fail("the first task drawn is not v19-v16")
    before, after = svgs[1], svgs[2]
    robot = polyline(before, "robot-path")
    expected_path = polyline(before, "expected-path")
    if len(robot) != 6 or len(expected_path) != 4:
        fail("v19-v16 before: robot path of %d places (6 expected), people's of %d (4)" %
             (len(robot), len(expected_path)))
    if polyline(after, "robot-path") != polyline(after, "expected-path"):
        fail("v19-v16 after: people should expect the robot's path (IE 0)")
    if 'class="zone"' in before or after.count('class="zone"') != 2:
        fail("the before picture must show no modification, the after one both zones")
    return counts


def polyline(svg, kind):
    m = re.search(r'<g class="%s">.*?<polyline points="([^"]*)"' % kind, svg)
    if not m:
        fail("no %s in a task's picture" % kind)
    return m.group(1).split()


# ---- Chromium -----------------------------------------------------------------------------

MEASURE = """<script>
window.addEventListener('load', () => {
  const seen = el => { const r = el.getBoundingClientRect(); return r.width > 0 || r.height > 0; };
  const box = el => { const r = el.getBoundingClientRect();
    return [r.left + scrollX, r.top + scrollY, r.width, r.height]; };
  const out = {floors: [], plots: []};
  document.querySelectorAll('svg').forEach(svg => {
    if (svg.querySelector('#gnuplot_canvas')) {
      const g = [...svg.querySelectorAll('g[id^=gnuplot_plot]')].find(
        g => (g.querySelector('title') || {}).textContent.includes('(chosen)'));
      out.plots.push({chosen_drawn: !!g && seen(g), box: box(svg)});
    } else {
      const count = {};
      for (const c of ['robot-edge', 'human-edge', 'zone', 'robot-path', 'expected-path'])
        count[c] = [...svg.querySelectorAll('.' + c)].filter(seen).length;
      out.floors.push({count, box: box(svg)});
    }
  });
  out.height = document.documentElement.scrollHeight;
  const pre = document.createElement('pre'); pre.id = 'measure';
  pre.textContent = JSON.stringify(out); document.body.appendChild(pre);
});
</script>"""


def chromium(args, tmp):
    return subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu",
                           "--hide-scrollbars", "--user-data-dir=" + os.path.join(tmp, "profile")]
                          + args, capture_output=True, text=True, timeout=90)


def measure_in_chromium(page, tmp):
    copy = os.path.join(tmp, "measured.html")
    with open(page, encoding="utf-8") as f:
        html = f.read()
    with open(copy, "w", encoding="utf-8") as f:
        f.write(html.replace("</body>", MEASURE + "</body>"))
    dom = chromium(["--virtual-time-budget=5000", "--dump-dom", "file://" + copy], tmp).stdout
    m = re.search(r'<pre id="measure">(.*?)</pre>', dom, re.S)
    if not m:
        fail("Chromium ran no measure: %s" % dom[:300])
    return json.loads(m.group(1).replace("&quot;", '"').replace("&amp;", "&"))


def colour_pixels(rows, channels, box, scale_factor, test):
    left, top, width, height = [int(v * scale_factor) for v in box]
    n = 0
    for y in range(max(top, 0), min(top + height, len(rows))):
        line = rows[y]
        for x in range(left, left + width):
            i = x * channels
            if i + 2 < len(line) and test(line[i], line[i + 1], line[i + 2]):
                n += 1
    return n


def check_in_chromium(page, tmp, keep):
    if not os.path.exists(CHROMIUM):
        fail("chromium is not installed (deploy/install-deps.sh installs it)")
    m = measure_in_chromium(page, tmp)
    floors, plots = m["floors"], m["plots"]
    if len(floors) != 7 or floors[0]["count"]["robot-edge"] != 18 or \
            floors[0]["count"]["zone"] != 2:
        fail("Chromium draws the floor otherwise: %r" % floors[:1])
    for f in floors[1:]:
        if f["count"]["robot-path"] != 1 or f["count"]["expected-path"] != 1:
            fail("a task's picture lacks a drawn path: %r" % f["count"])
    if len(plots) != 3 or not all(p["chosen_drawn"] for p in plots):
        fail("Chromium does not draw the chosen design on every plot: %r" % plots)
    # A screenshot of the top of the page (the floor) at half scale.
    shot = os.path.join(keep or tmp, "report-floor.png")
    bottom = int(floors[-1]["box"][1] + floors[-1]["box"][3]) + 40
    chromium(["--force-device-scale-factor=0.5", "--window-size=1100,%d" % bottom,
              "--screenshot=" + shot, "file://" + page], tmp)
    if not os.path.exists(shot):
        fail("chromium wrote no screenshot")
    with open(shot, "rb") as f:
        width, height, channels, rows = decode_png(f.read())
    red = colour_pixels(rows, channels, floors[0]["box"], 0.5,
                        lambda r, g, b: r > 200 and 110 < g < 190 and 110 < b < 190)
    purple = sum(colour_pixels(rows, channels, f["box"], 0.5,
                               lambda r, g, b: b - g > 35 and r - g > 25)  # #8e44ad, 55%
                 for f in floors[1:])
    print("screenshot %dx%d: %d barrier pixels on the floor, %d path pixels in the tasks" %
          (width, height, red, purple))
    if red < 50:
        fail("the chosen barrier is not visible in the screenshot")
    if purple < 300:
        fail("the robot's paths are not visible in the screenshot")


def main():
    build, examples = sys.argv[1], sys.argv[2]
    keep = sys.argv[4] if len(sys.argv) > 4 and sys.argv[3] == "--keep" else None
    with tempfile.TemporaryDirectory() as tmp:
        floor = os.path.join(tmp, "floor")
        ex = os.path.join(examples, "floor")
        run(build, "floor", "import", os.path.join(ex, "warehouse.building.yaml"), "--zones",
            os.path.join(ex, "zones.json"), "-o", floor)
        spec = os.path.join(floor, "design.textproto")
        result = json.loads(run(build, "design", spec, "--json"))
        if result["design"] != ["gap-barrier", "top-aisle-marking"]:
            fail("unexpected design %r" % result["design"])
        page = os.path.join(keep or tmp, "report-floor.html")
        run(build, "report", spec, "-o", page)
        with open(page, encoding="utf-8") as f:
            html = f.read()
        print("floor drawing:", check_floor_html(html))
        for line in check_plots(html, result):
            print(line)
        # The case of issue 25: an empty design two orders above the rest.
        wide = os.path.join(examples, "restaurant", "c-two-tasks-t10.textproto")
        wide_result = json.loads(run(build, "design", wide, "--json"))
        wide_page = os.path.join(keep or tmp, "report-restaurant.html")
        run(build, "report", wide, "-o", wide_page)
        with open(wide_page, encoding="utf-8") as f:
            wide_html = f.read()
        if "<h2>The floor</h2>" in wide_html:
            fail("a spec without floor.json has a floor section")
        for line in check_plots(wide_html, wide_result):
            print("restaurant", line)
        check_in_chromium(page, tmp, keep)
    print("ok")


if __name__ == "__main__":
    main()
