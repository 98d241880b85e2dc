#!/usr/bin/env python3
"""Generates src/glut/bitmap_fonts.rs and src/glut/stroke_fonts.rs (GLUT's font data) from the
GL calls the system's freeglut issues for each glyph, as dumped by tools/freeglut_fonts_dump.c:

    cc -O2 -rdynamic -o /tmp/fgdump tools/freeglut_fonts_dump.c -lglut
    xvfb-run -a /tmp/fgdump > /tmp/freeglut_fonts.txt
    python3 tools/gen_glut_fonts.py /tmp/freeglut_fonts.txt src/glut

The outputs are formatted with rustfmt (as `cargo fmt` leaves them) when rustfmt is on PATH.

Why from freeglut itself: GLUT programs expect freeglut's glyphs, and no public source gives them
exactly. The bitmap fonts were first generated here from the X11 BDF fonts Debian ships
(xfonts-base, xfonts-75dpi), but those are the 1999 ISO 10646 revision of the fonts, and 64 of
the 1,785 glyphs differ from freeglut's (misc-fixed glyphs redrawn, ASCII quotes and hyphen in
the Adobe fonts). Older revisions do not match either (rendered cells compared, padding bits
ignored): the final X11R6 BDFs of the X Consortium tree (github.com/alanc/xc-historical,
xc/fonts/bdf) differ in 142 glyphs (the misc-fixed control glyphs 1..31 above all), XFree86
4.0's (github.com/th-otto/GEM-xfree86, misc/*-ISO8859-1.bdf and 75dpi) in 59; freeglut's
fg_font_data.c names XFree86 4.3.0, of which no public copy of the fonts was found. freeglut's stroke fonts are the Hershey Roman simplex shapes with metrics from
the X PEX Roman fonts, scaled by freeglut's genstroke utility; no other source has its numbers.
The dump is of the data freeglut ships (fg_font_data.c, fg_stroke_roman.c,
fg_stroke_mono_roman.c), whose licence notice the generated files carry.

Bitmap glyph layout (as freeglut draws it): glBitmap(width, height, 0, yorig, width, 0, bits),
a cell as wide as its advance, `height` rows tall (the font's height), rows bottom to top,
ceil(width / 8) bytes a row, most significant bit first. freeglut draws codes 1..=255.

Stroke glyphs: codes 32..=127 (freeglut's fonts hold 128 codes, 0..=31 empty); each is a list
of GL_LINE_STRIP vertex lists in font units and an advance (the glTranslatef after it).
"""
import os
import shutil
import struct
import subprocess
import sys

BITMAP = [
    "BITMAP_8_BY_13",
    "BITMAP_9_BY_15",
    "BITMAP_TIMES_ROMAN_10",
    "BITMAP_TIMES_ROMAN_24",
    "BITMAP_HELVETICA_10",
    "BITMAP_HELVETICA_12",
    "BITMAP_HELVETICA_18",
]
STROKE = ["STROKE_ROMAN", "STROKE_MONO_ROMAN"]

NOTICE = """\
// The font data of freeglut 3.x (fg_font_data.c, fg_stroke_roman.c, fg_stroke_mono_roman.c), as
// the system's libglut issues it to GL. Its notice:
//
// Copyright (c) 1999-2000 Pawel W. Olszta. All Rights Reserved.
// Written by Pawel W. Olszta, <olszta@sourceforge.net>
// Portions copyright (c) 2004, the OpenGLUT project contributors.
//
// Permission is hereby granted, free of charge, to any person obtaining a
// copy of this software and associated documentation files (the "Software"),
// to deal in the Software without restriction, including without limitation
// the rights to use, copy, modify, merge, publish, distribute, sublicense,
// and/or sell copies of the Software, and to permit persons to whom the
// Software is furnished to do so, subject to the following conditions:
//
// The above copyright notice and this permission notice shall be included
// in all copies or substantial portions of the Software.
//
// THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS
// OR IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
// FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT.  IN NO EVENT SHALL
// PAWEL W. OLSZTA BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER LIABILITY, WHETHER
// IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM, OUT OF OR IN
// CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE.
"""


def f32(text):
    """The shortest decimal that reads back as the f32 `text` (C's %a) names, as Rust source."""
    v = float.fromhex(text)
    assert struct.unpack("f", struct.pack("f", v))[0] == v, text
    for p in range(1, 10):
        s = "%.*g" % (p, v)
        if struct.unpack("f", struct.pack("f", float(s)))[0] == v:
            break
    if "e" in s:
        s = repr(float(s))
    if "." not in s and "e" not in s:
        s += ".0"
    return s


def parse(path):
    bitmap = {}
    stroke = {}
    glyph = None
    with open(path) as f:
        for line in f.read().splitlines():
            t = line.split()
            if t[0] == "BF":
                bitmap[int(t[1])] = {"height": int(t[2]), "name": t[3], "glyphs": {}}
            elif t[0] == "B":
                i, code, w, h = int(t[1]), int(t[2]), int(t[3]), int(t[4])
                xo, yo, xm, ym = (float.fromhex(v) for v in t[5:9])
                font = bitmap[i]
                assert h == font["height"] and xo == 0 and ym == 0 and xm == w, line
                assert yo == int(yo)
                font.setdefault("yorig", int(yo))
                assert font["yorig"] == int(yo), line
                bits = b"" if t[9] == "-" else bytes.fromhex(t[9])
                assert len(bits) == (w + 7) // 8 * h, line
                font["glyphs"][code] = (w, bits)
            elif t[0] == "SF":
                stroke[int(t[1])] = {"height": t[2], "name": t[3], "glyphs": {}}
            elif t[0] == "S":
                glyph = {"font": int(t[1]), "code": int(t[2]), "width": t[3], "strips": []}
                glyph["advance"] = None
            elif t[0] == "L":
                xs = t[1:]
                glyph["strips"].append([(xs[k], xs[k + 1]) for k in range(0, len(xs), 2)])
            elif t[0] == "T":
                assert glyph["advance"] is None and t[2] == "0x0p+0" and t[3] == "0x0p+0", line
                glyph["advance"] = t[1]
            elif t[0] == "E":
                if glyph["advance"] is not None:
                    assert float.fromhex(glyph["advance"]) == float.fromhex(glyph["width"])
                    assert glyph["code"] < 128
                    stroke[glyph["font"]]["glyphs"][glyph["code"]] = glyph
                else:
                    assert not glyph["strips"] and float.fromhex(glyph["width"]) == 0, glyph
                glyph = None
            else:
                raise SystemExit(f"unexpected line {line!r}")
    assert sorted(bitmap) == list(range(7)) and sorted(stroke) == [0, 1]
    return bitmap, stroke


def rustfmt(text):
    if shutil.which("rustfmt"):
        text = subprocess.run(
            ["rustfmt", "--edition", "2021", "--emit", "stdout"],
            input=text,
            capture_output=True,
            text=True,
            check=True,
        ).stdout
    return text


def bitmap_rs(bitmap):
    out = ["// @generated by tools/gen_glut_fonts.py from freeglut's glyphs; do not edit."]
    out += NOTICE.splitlines()
    out += ["", "use super::text::BitmapFontData;", ""]
    for i, const in enumerate(BITMAP):
        font = bitmap[i]
        assert sorted(font["glyphs"]) == list(range(1, 256))
        widths, offsets, blob = [0], [0], bytearray()
        for code in range(1, 256):
            w, bits = font["glyphs"][code]
            widths.append(w)
            offsets.append(len(blob))
            blob += bits
        out.append(f"/// `{font['name']}`")
        out.append(f"pub(super) static {const}: BitmapFontData = BitmapFontData {{")
        out.append(f'    name: "{font["name"]}",')
        out.append(f"    height: {font['height']},")
        out.append(f"    yorig: {font['yorig']},")
        out.append(f"    widths: {widths!r},")
        out.append(f"    offsets: {offsets!r},")
        out.append("    bits: &[")
        for k in range(0, len(blob), 24):
            out.append("        " + ", ".join(str(v) for v in blob[k : k + 24]) + ",")
        out.append("    ],")
        out.append("};")
        out.append("")
    return rustfmt("\n".join(out) + "\n")


def stroke_rs(stroke):
    out = ["// @generated by tools/gen_glut_fonts.py from freeglut's glyphs; do not edit."]
    out += NOTICE.splitlines()
    out += ["", "use super::text::{StrokeFontData, StrokeGlyph};", ""]
    for i, const in enumerate(STROKE):
        font = stroke[i]
        assert sorted(font["glyphs"]) == list(range(32, 128)), sorted(font["glyphs"])
        out.append(f"/// freeglut's `{font['name']}` stroke font.")
        out.append(f"pub(super) static {const}: StrokeFontData = StrokeFontData {{")
        out.append(f'    name: "{font["name"]}",')
        out.append(f"    height: {f32(font['height'])},")
        out.append("    glyphs: [")
        for code in range(128):
            g = font["glyphs"].get(code)
            if g is None:
                out.append("        None,")
                continue
            strips = ", ".join(
                "&[" + ", ".join(f"[{f32(x)}, {f32(y)}]" for x, y in s) + "]" for s in g["strips"]
            )
            out.append(f"        // {code}: {chr(code)!r}")
            out.append(
                f"        Some(StrokeGlyph {{ advance: {f32(g['advance'])}, strips: &[{strips}] }}),"
            )
        out.append("    ],")
        out.append("};")
        out.append("")
    return rustfmt("\n".join(out) + "\n")


def main():
    bitmap, stroke = parse(sys.argv[1])
    with open(os.path.join(sys.argv[2], "bitmap_fonts.rs"), "w") as f:
        f.write(bitmap_rs(bitmap))
    with open(os.path.join(sys.argv[2], "stroke_fonts.rs"), "w") as f:
        f.write(stroke_rs(stroke))


if __name__ == "__main__":
    main()
