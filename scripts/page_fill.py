#!/usr/bin/env python3
"""How full each page of a PDF is: the last row with ink, as a fraction of the page's height.

    scripts/page_fill.py FILE.pdf    prints one percentage per page, e.g. "95% 78% 40%"

Renders the pages with poppler's pdftoppm (grey, 40 dpi) and finds, on each, the lowest pixel
row darker than 200 of 255 (text, rules and figure lines all count; the page's white bottom
margin does not). An A4 page with 10 mm margins is at most 96% full by this measure.
Standard library only.
"""
import glob
import os
import subprocess
import sys
import tempfile


def fills(pdf):
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run(["pdftoppm", "-r", "40", "-gray", pdf, os.path.join(tmp, "p")], check=True)
        out = []
        # pdftoppm numbers the pages with leading zeros as needed, so a sort keeps their order
        for name in sorted(glob.glob(os.path.join(tmp, "p*.pgm"))):
            data = open(name, "rb").read()
            magic, w, h, _maxval, pix = data.split(maxsplit=4)
            assert magic == b"P5", name
            w, h = int(w), int(h)
            last = 0
            for y in range(h):
                if min(pix[y * w:(y + 1) * w]) < 200:
                    last = y + 1
            out.append(last / h)
        return out


if __name__ == "__main__":
    print(" ".join(f"{round(100 * f)}%" for f in fills(sys.argv[1])))
