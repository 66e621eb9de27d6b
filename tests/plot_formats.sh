#!/usr/bin/env bash
# Output formats of `hlr render` read back by real readers: the PDF by pdfinfo and
# pdftoppm, the DXF's layers and linetypes, the PNG preview against rsvg-convert's rendering of
# the SVG (pixel agreement within antialiasing), extensions case-insensitive, a sheet of views.
#   tests/plot_formats.sh HLR DATA_DIR
set -euo pipefail
HLR="$(realpath "$1")" D="$(realpath "$2")"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
fail=0
"$HLR" render "$D/demo.yaml" --hidden dashed --page A4 --landscape -o "$W/a.PDF"
pdfinfo "$W/a.PDF" > "$W/info.txt"
grep -q "Page size:.*841.89 x 595.276 pts (A4)" "$W/info.txt" || { echo "PDF: not an A4 landscape page"; cat "$W/info.txt"; fail=1; }
pdftoppm -r 30 -png "$W/a.PDF" "$W/page" || { echo "PDF: pdftoppm cannot read it"; fail=1; }
"$HLR" render "$D/demo.yaml" --hidden dashed -o "$W/a.dxf"
for want in "visible-silhouette" "hidden-crease" "DASHED" "AC1015" "POLYLINE"; do
  grep -q "$want" "$W/a.dxf" || { echo "DXF: no $want"; fail=1; }
done
# The same bytes on every run, in every format (a DXF once carried an uninitialised handle:
# dxflib's text style must be named "Standard" for its dimension style to refer to it; a PDF
# carried the clock's creation date: none now, or SOURCE_DATE_EPOCH's). A second apart.
for f in svg pdf png dxf json; do
  "$HLR" render "$D/demo.yaml" --hidden dashed --page A4 -o "$W/r1.$f"
  [ "$f" = pdf ] && sleep 1.1
  "$HLR" render "$D/demo.yaml" --hidden dashed --page A4 -o "$W/r2.$f"
  cmp -s "$W/r1.$f" "$W/r2.$f" || { echo "$f: two runs differ"; fail=1; }
done
SOURCE_DATE_EPOCH=1700000000 "$HLR" render "$D/demo.yaml" --page A4 -o "$W/dated.pdf"
pdfinfo "$W/dated.pdf" | grep -q "CreationDate:.*2023" || { echo "PDF: SOURCE_DATE_EPOCH not its creation date"; pdfinfo "$W/dated.pdf"; fail=1; }
"$HLR" render "$D/demo.yaml" --hidden dashed -o "$W/a.JSON"
head -c 1 "$W/a.JSON" | grep -q '{' || { echo "JSON by upper-case extension: not JSON"; fail=1; }
"$HLR" render "$D/demo.yaml" --hidden dashed --dpi 96 -o "$W/a.png"
"$HLR" render "$D/demo.yaml" --hidden dashed -o "$W/a.svg"
rsvg-convert "$W/a.svg" -o "$W/b.png"
# An image against rsvg-convert's rendering of the SVG: sizes, dark pixels, each dark pixel near a
# dark-ish one of the other.
cat > "$W/same_picture.py" <<'PY'
import struct, sys, zlib
def read(path):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n'
    pos, idat, w = 8, b'', 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            w, h, depth, ctype = struct.unpack('>IIBB', body[:10])
            assert depth == 8
            bpp = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    raw, rows, prev, stride, i = zlib.decompress(idat), [], None, w * bpp, 0
    for y in range(h):
        f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x] if prev else 0
            c = prev[x - bpp] if prev and x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        prev = line
        # grey, with transparency over white
        g = []
        for x in range(w):
            px = line[x * bpp:(x + 1) * bpp]
            v = sum(px[:3]) / 3 if bpp >= 3 else px[0]
            alpha = px[3] if bpp == 4 else px[1] if bpp == 2 else 255
            g.append(255 - (255 - v) * alpha / 255)
        rows.append(g)
    return w, h, rows
what = sys.argv[3]
wa, ha, A = read(sys.argv[1])
wb, hb, B = read(sys.argv[2])
if abs(wa - wb) > 1 or abs(ha - hb) > 1:
    sys.exit(f"{what} {wa}x{ha} vs rsvg-convert {wb}x{hb}")
w, h = min(wa, wb), min(ha, hb)
dark_a = sum(1 for y in range(h) for x in range(w) if A[y][x] < 128)
dark_b = sum(1 for y in range(h) for x in range(w) if B[y][x] < 128)
# A dark pixel of one image must be near a dark-ish pixel of the other (antialiasing moves edges by a pixel).
def near(I, x, y):
    return any(I[yy][xx] < 200 for yy in range(max(0, y - 1), min(h, y + 2)) for xx in range(max(0, x - 1), min(w, x + 2)))
miss = sum(1 for y in range(h) for x in range(w) if (A[y][x] < 100 and not near(B, x, y)) or (B[y][x] < 100 and not near(A, x, y)))
if dark_a == 0 or abs(dark_a - dark_b) > 0.15 * max(dark_a, dark_b) or miss > 0.01 * max(dark_a, dark_b):
    sys.exit(f"{what} differs from rsvg-convert: dark pixels {dark_a} vs {dark_b}, unmatched {miss}")
print(f"{what}: {w}x{h}, dark pixels {dark_a} vs {dark_b}, unmatched {miss}")
PY
python3 "$W/same_picture.py" "$W/a.png" "$W/b.png" "PNG preview" || fail=1
# The PDF (written by plot_pdf.cpp) as poppler draws it, against the SVG, without a word from
# poppler on stderr; a sheet of views with labels (glyph outlines) and hidden dashes too.
"$HLR" render "$D/demo.yaml" --hidden dashed -o "$W/p.pdf"
pdftoppm -r 96 -png -singlefile "$W/p.pdf" "$W/p" 2>"$W/poppler.txt" || { echo "PDF: pdftoppm cannot read it"; fail=1; }
python3 "$W/same_picture.py" "$W/p.png" "$W/b.png" "PDF" || fail=1
"$HLR" render "$D/demo.yaml" --views front,top,right,iso --page 200x150mm --scale 1:1 --hidden dashed -o "$W/views.pdf"
"$HLR" render "$D/demo.yaml" --views front,top,right,iso --page 200x150mm --scale 1:1 --hidden dashed -o "$W/views.svg"
pdftoppm -r 96 -png -singlefile "$W/views.pdf" "$W/views" 2>>"$W/poppler.txt" || { echo "PDF: pdftoppm cannot read the sheet"; fail=1; }
pdfinfo "$W/views.pdf" >/dev/null 2>>"$W/poppler.txt"
rsvg-convert "$W/views.svg" -o "$W/views_svg.png"
python3 "$W/same_picture.py" "$W/views.png" "$W/views_svg.png" "PDF sheet with labels" || fail=1
[ ! -s "$W/poppler.txt" ] || { echo "PDF: poppler complains:"; cat "$W/poppler.txt"; fail=1; }
"$HLR" render "$D/demo.yaml" --views front,top,right,iso --page A3 --landscape --scale 1:1 --hidden dashed --dashes geometry -o "$W/sheet.svg"
grep -q ">FRONT</text>" "$W/sheet.svg" && grep -q ">ISO</text>" "$W/sheet.svg" && grep -q "scale 1:1" "$W/sheet.svg" || { echo "sheet: labels missing"; fail=1; }
if grep -q "stroke-dasharray" "$W/sheet.svg"; then echo "sheet: --dashes geometry left a dasharray"; fail=1; fi
if [ "$fail" = 0 ]; then echo "plot formats: all read back"; fi
exit "$fail"
