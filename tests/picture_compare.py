#!/usr/bin/env python3
"""Compares two pictures the way a reader sees them (docs/design.md, "Published pictures").

  picture_compare.py same A B [--bound F]   exit 1 unless A and B look alike
  picture_compare.py count FILE.svg         prints the SVG's fills, strokes and layers
  picture_compare.py colours FILE           prints how many pixels are coloured (neither white,
                                            grey nor black) and how many are dark

SVG files are compared by their elements (fills with their colours, strokes, layers: the same
counts) and by their pixels as rsvg-convert draws them; PNG and PDF files by their pixels (PDF:
poppler's pdftoppm). Pixels are compared in blocks of 4 x 4 (antialiasing moves edges by a
pixel): the pictures differ when more than F (default 0.005) of the blocks differ by more than
48 levels of 255 in some channel, or when the sizes differ by more than a pixel.
"""
import os
import re
import subprocess
import sys
import tempfile


def svg_elements(path):
    text = open(path, encoding="utf-8").read()
    fills = re.findall(r'<path d="[^"]*" fill="(#[0-9a-fA-F]{6})"', text)
    # Strokes: paths without a fill of their own (the layers' groups give fill="none"), lines.
    strokes = len(re.findall(r'<path d="[^"]*"(?! fill=)', text)) + len(re.findall(r"<(?:line|polyline) ", text))
    layers = re.findall(r'inkscape:label="([^"]*)"', text)
    colours = {}
    for f in fills:
        colours[f] = colours.get(f, 0) + 1
    return {"fills": len(fills), "fill_colours": colours, "strokes": strokes, "layers": layers}


def to_ppm(path, work):
    out = os.path.join(work, os.path.basename(path) + ".ppm")
    ext = path.lower().rsplit(".", 1)[-1]
    if ext == "svg":
        png = out + ".png"
        subprocess.run(["rsvg-convert", "-b", "white", path, "-o", png], check=True)
        path, ext = png, "png"
    if ext == "pdf":
        base = out + ".pdf"
        subprocess.run(["pdftoppm", "-r", "96", "-singlefile", path, base], check=True)
        return base + ".ppm"
    if ext == "png":
        # Transparent pixels over white (cairo writes RGBA).
        with open(out, "wb") as f:
            subprocess.run(["pngtopnm", "-mix", "-background", "white", path], stdout=f, stderr=subprocess.DEVNULL, check=True)
        return out
    raise SystemExit(f"picture_compare: cannot read {path}")


def read_ppm(path):
    data = open(path, "rb").read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    pos += 1
    kind, w, h, maxval = fields[0], int(fields[1]), int(fields[2]), int(fields[3])
    px = data[pos:]
    if kind == b"P5":  # grey
        px = bytes(b for v in px for b in (v, v, v))
    elif kind != b"P6" or maxval != 255:
        raise SystemExit(f"picture_compare: {path}: not an 8-bit PPM")
    return w, h, px


def blocks(w, h, px, size=4):
    bw, bh = (w + size - 1) // size, (h + size - 1) // size
    sums = [[0, 0, 0, 0] for _ in range(bw * bh)]
    for y in range(h):
        row = px[y * w * 3:(y + 1) * w * 3]
        base = (y // size) * bw
        for x in range(w):
            s = sums[base + x // size]
            i = 3 * x
            s[0] += row[i]
            s[1] += row[i + 1]
            s[2] += row[i + 2]
            s[3] += 1
    return bw, bh, [(s[0] / s[3], s[1] / s[3], s[2] / s[3]) for s in sums]


def pixels(path, work):
    return read_ppm(to_ppm(path, work))


def same(a, b, bound):
    problems = []
    if a.lower().endswith(".svg") and b.lower().endswith(".svg"):
        ea, eb = svg_elements(a), svg_elements(b)
        for k in ("fills", "fill_colours", "strokes", "layers"):
            if ea[k] != eb[k]:
                problems.append(f"{k}: {summary(ea[k])} vs {summary(eb[k])}")
    with tempfile.TemporaryDirectory() as work:
        os.makedirs(os.path.join(work, "a"))
        os.makedirs(os.path.join(work, "b"))
        wa, ha, pa = pixels(a, os.path.join(work, "a"))
        wb, hb, pb = pixels(b, os.path.join(work, "b"))
    if abs(wa - wb) > 1 or abs(ha - hb) > 1:
        problems.append(f"size {wa}x{ha} vs {wb}x{hb}")
        return problems, 1.0
    w, h = min(wa, wb), min(ha, hb)
    pa = b"".join(pa[y * wa * 3:(y * wa + w) * 3] for y in range(h))
    pb = b"".join(pb[y * wb * 3:(y * wb + w) * 3] for y in range(h))
    _, _, ba = blocks(w, h, pa)
    _, _, bb = blocks(w, h, pb)
    differ = sum(1 for x, y in zip(ba, bb) if max(abs(x[k] - y[k]) for k in range(3)) > 48)
    frac = differ / max(1, len(ba))
    if frac > bound:
        problems.append(f"{differ} of {len(ba)} blocks of 4x4 pixels differ ({frac:.4f} > {bound})")
    return problems, frac


def summary(v):
    if isinstance(v, list) and len(v) > 6:
        return f"{len(v)} layers {v[:3]}..."
    return str(v)


def colours(path):
    with tempfile.TemporaryDirectory() as work:
        w, h, px = pixels(path, work)
    coloured = dark = 0
    for i in range(0, len(px), 3):
        r, g, b = px[i], px[i + 1], px[i + 2]
        if max(r, g, b) - min(r, g, b) > 24 or 40 < (r + g + b) / 3 < 215:
            coloured += 1
        if (r + g + b) / 3 < 100:
            dark += 1
    return coloured, dark, w * h


def main(argv):
    if len(argv) >= 4 and argv[1] == "same":
        bound = float(argv[argv.index("--bound") + 1]) if "--bound" in argv else 0.005
        problems, frac = same(argv[2], argv[3], bound)
        if problems:
            print(f"{argv[2]} vs {argv[3]}: " + "; ".join(problems))
            return 1
        print(f"{os.path.basename(argv[2])}: same picture ({frac:.4f} of the blocks differ)")
        return 0
    if len(argv) == 3 and argv[1] == "count":
        e = svg_elements(argv[2])
        print(f"fills {e['fills']} colours {len(e['fill_colours'])} strokes {e['strokes']} layers {len(e['layers'])}")
        return 0
    if len(argv) == 3 and argv[1] == "colours":
        c, d, n = colours(argv[2])
        print(f"coloured {c} dark {d} pixels {n}")
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
