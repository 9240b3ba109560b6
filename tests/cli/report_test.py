#!/usr/bin/env python3
"""envdesign report: the page is self-contained, carries the recommendation and three plots,
and headless Chromium renders it to a screenshot that is not blank.

Usage: report_test.py BUILD_DIR SPEC [--keep DIR]
The PNG is decoded here (zlib and the PNG filters) so that no imaging package is needed."""

import os
import struct
import subprocess
import sys
import tempfile
import zlib


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def decode_png(data):
    """(width, height, channels, rows) of an 8-bit, non-interlaced RGB or RGBA PNG."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail("the screenshot is not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, color, _, _, interlace = header
    if depth != 8 or color not in (2, 6) or interlace:
        fail("unexpected PNG format: depth %d color %d interlace %d" % (depth, color, interlace))
    channels = 3 if color == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            corner = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                line[i] = (line[i] + paeth(left, up, corner)) & 255
        rows.append(line)
        previous = line
    return width, height, channels, rows


def pixel_counts(width, height, channels, rows):
    """Pixels that are not the white background, and strongly coloured ones (the plots)."""
    ink = coloured = 0
    for line in rows:
        for x in range(0, width * channels, channels):
            r, g, b = line[x], line[x + 1], line[x + 2]
            if min(r, g, b) < 235:
                ink += 1
            if max(r, g, b) - min(r, g, b) > 80:
                coloured += 1
    return ink, coloured


def main():
    build, spec = sys.argv[1], sys.argv[2]
    keep = sys.argv[4] if len(sys.argv) > 4 and sys.argv[3] == "--keep" else None
    with tempfile.TemporaryDirectory() as tmp:
        out = keep or tmp
        page = os.path.join(out, "report.html")
        run = subprocess.run([os.path.join(build, "bin", "envdesign"), "report", spec, "-o", page,
                              "--ranking", "5"], capture_output=True, text=True, timeout=60)
        if run.returncode != 0:
            fail("envdesign report exited %d: %s" % (run.returncode, run.stderr))
        html = open(page, encoding="utf-8").read()
        for needed in ("Recommendation:", "barrier-00-01, barrier-10-11", "What each modification",
                       "When would the answer change?", "Task serve-g2"):
            if needed not in html:
                fail("the page lacks %r" % needed)
        if html.count("<svg") != 3:
            fail("expected 3 inline plots, found %d" % html.count("<svg"))
        for external in ("<script", "<link", "<img", "src=", "url("):
            if external in html:
                fail("the page is not self-contained: %r" % external)
        chromium = "/usr/bin/chromium"
        if not os.path.exists(chromium):
            fail("chromium is not installed (deploy/install-deps.sh installs it)")
        shot = os.path.join(out, "report.png")
        profile = os.path.join(tmp, "profile")
        subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu",
                        "--hide-scrollbars", "--user-data-dir=" + profile, "--force-device-scale-factor=0.5",
                        "--window-size=1100,3000", "--screenshot=" + shot, "file://" + page],
                       capture_output=True, timeout=90)
        if not os.path.exists(shot):
            fail("chromium wrote no screenshot")
        width, height, channels, rows = decode_png(open(shot, "rb").read())
        ink, coloured = pixel_counts(width, height, channels, rows)
        total = width * height
        print("screenshot %dx%d: %.1f%% ink, %.2f%% coloured" %
              (width, height, 100.0 * ink / total, 100.0 * coloured / total))
        # Half scale (--force-device-scale-factor) keeps the decoding here quick.
        # A blank page has no ink; text and tables alone stay under 1% coloured pixels,
        # the plots' bars and lines make more.
        if ink < 0.03 * total:
            fail("the screenshot is (nearly) blank")
        if coloured < 0.005 * total:
            fail("no plot colours in the screenshot")
    print("ok")


if __name__ == "__main__":
    main()
