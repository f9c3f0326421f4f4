#!/usr/bin/env python3
"""Draws the shipped decals (presets/decals/*.png): the project's own artwork, no
third-party marks. Python 3's standard library only: shapes are signed distance fields
(anti-aliased by their distance to the edge), composited "over" in sRGB, written as
8-bit RGBA PNGs through zlib.

  scripts/make-decals.py [OUT_DIR]      (default: presets/decals)

- wordmark.png: "DRAUGHT" over "BREWING CO." with "EST. 2026", in white (a decal's
  colour parameter tints it: white enamel on a stout, red or black on a lager);
- crest.png: a shield in navy, gold and cream with a monogram, a chevron and a hop cone;
- gold-band.png: a band with two fine lines, white (a metallic decal's colour makes it
  gold), the same in every column so that copies join into a ring.
"""
import math
import os
import struct
import sys
import zlib


# ---- canvas and compositing ----

class Canvas:
    def __init__(self, w, h):
        self.w, self.h = w, h
        self.px = [[0.0, 0.0, 0.0, 0.0] for _ in range(w * h)]  # premultiplied sRGB, 0..1

    def fill(self, sdf, bbox, colour, alpha=1.0):
        """Composites colour over the canvas where sdf(x, y) < 0 (distance in pixels)."""
        x0, y0, x1, y1 = bbox
        x0, y0 = max(0, int(x0) - 2), max(0, int(y0) - 2)
        x1, y1 = min(self.w, int(x1) + 3), min(self.h, int(y1) + 3)
        r, g, b = (c / 255.0 for c in colour)
        for y in range(y0, y1):
            row = y * self.w
            for x in range(x0, x1):
                d = sdf(x + 0.5, y + 0.5)
                cov = 0.5 - d
                if cov <= 0.0:
                    continue
                a = alpha * (1.0 if cov >= 1.0 else cov)
                p = self.px[row + x]
                k = 1.0 - a
                p[0] = r * a + p[0] * k
                p[1] = g * a + p[1] * k
                p[2] = b * a + p[2] * k
                p[3] = a + p[3] * k

    def png(self):
        raw = bytearray()
        for y in range(self.h):
            raw.append(0)
            for x in range(self.w):
                r, g, b, a = self.px[y * self.w + x]
                if a > 1e-6:
                    r, g, b = r / a, g / a, b / a
                raw += bytes(max(0, min(255, round(c * 255))) for c in (r, g, b, a))

        def chunk(kind, data):
            body = kind + data
            return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

        header = struct.pack(">IIBBBBB", self.w, self.h, 8, 6, 0, 0, 0)
        return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) +
                chunk(b"IEND", b""))


# ---- shapes: (sdf, bbox) ----

def seg_dist(px, py, ax, ay, bx, by):
    dx, dy = bx - ax, by - ay
    l2 = dx * dx + dy * dy
    t = 0.0 if l2 == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / l2))
    qx, qy = ax + t * dx - px, ay + t * dy - py
    return math.sqrt(qx * qx + qy * qy)


def strokes(polylines, width):
    """Round-capped strokes along polylines (lists of points), one shape."""
    segs = [(p[i][0], p[i][1], p[i + 1][0], p[i + 1][1]) for p in polylines for i in range(len(p) - 1)]
    segs += [(p[0][0], p[0][1], p[0][0], p[0][1]) for p in polylines if len(p) == 1]
    half = width / 2.0
    xs = [c for s in segs for c in (s[0], s[2])]
    ys = [c for s in segs for c in (s[1], s[3])]
    bbox = (min(xs) - half, min(ys) - half, max(xs) + half, max(ys) + half)

    def sdf(x, y):
        best = 1e9
        for ax, ay, bx, by in segs:
            # cheap reject by the segment's box
            if x < min(ax, bx) - half - best or x > max(ax, bx) + half + best:
                continue
            d = seg_dist(x, y, ax, ay, bx, by)
            if d < best:
                best = d
        return best - half
    return sdf, bbox


def polygon(points):
    """A filled polygon (even-odd), any shape."""
    n = len(points)
    xs, ys = [p[0] for p in points], [p[1] for p in points]

    def sdf(x, y):
        d = 1e9
        inside = False
        for i in range(n):
            ax, ay = points[i]
            bx, by = points[(i + 1) % n]
            d = min(d, seg_dist(x, y, ax, ay, bx, by))
            if (ay > y) != (by > y) and x < (bx - ax) * (y - ay) / (by - ay) + ax:
                inside = not inside
        return -d if inside else d
    return sdf, (min(xs), min(ys), max(xs), max(ys))


def ellipse_arc(cx, cy, rx, ry, a0, a1, steps=None):
    """Points along an ellipse from angle a0 to a1 (degrees, counter-clockwise, y up)."""
    steps = steps or max(6, int(abs(a1 - a0) / 6))
    return [(cx + rx * math.cos(math.radians(a0 + (a1 - a0) * i / steps)),
             cy - ry * math.sin(math.radians(a0 + (a1 - a0) * i / steps))) for i in range(steps + 1)]


def star(cx, cy, r_out, r_in, points=5, turn=90.0):
    pts = []
    for i in range(2 * points):
        r = r_out if i % 2 == 0 else r_in
        a = math.radians(turn + 180.0 * i / points)
        pts.append((cx + r * math.cos(a), cy - r * math.sin(a)))
    return polygon(pts)


# ---- a geometric stroke alphabet: cap height 1, y down from the cap line (0) to the baseline (1) ----

def glyph(ch):
    """(polylines, advance width) of a capital, digit or mark."""
    E = ellipse_arc
    g = {
        "A": ([[(0, 1), (0.36, 0), (0.72, 1)], [(0.15, 0.64), (0.57, 0.64)]], 0.72),
        "B": ([[(0.3, 0.5), (0, 0.5), (0, 0), (0.28, 0)] + E(0.28, 0.25, 0.27, 0.25, 90, -90)[1:],
               [(0, 0.5), (0.3, 0.5)] + E(0.3, 0.75, 0.3, 0.25, 90, -90)[1:] + [(0, 1), (0, 0.5)]], 0.6),
        "C": ([E(0.37, 0.5, 0.37, 0.5, 48, 312)], 0.68),
        "D": ([[(0.26, 1), (0, 1), (0, 0), (0.26, 0)] + E(0.26, 0.5, 0.4, 0.5, 90, -90)[1:]], 0.66),
        "E": ([[(0.56, 0), (0, 0), (0, 1), (0.56, 1)], [(0, 0.5), (0.46, 0.5)]], 0.56),
        "G": ([E(0.37, 0.5, 0.37, 0.5, 45, 360) + [(0.74, 0.56), (0.42, 0.56)]], 0.74),
        "H": ([[(0, 0), (0, 1)], [(0.62, 0), (0.62, 1)], [(0, 0.5), (0.62, 0.5)]], 0.62),
        "I": ([[(0, 0), (0, 1)]], 0.0),
        "N": ([[(0, 1), (0, 0), (0.64, 1), (0.64, 0)]], 0.64),
        "O": ([E(0.4, 0.5, 0.4, 0.5, 0, 360, 64)], 0.8),
        "R": ([[(0, 1), (0, 0), (0.32, 0)] + E(0.32, 0.26, 0.28, 0.26, 90, -90)[1:] + [(0, 0.52)],
               [(0.3, 0.52), (0.62, 1)]], 0.62),
        "S": ([E(0.3, 0.26, 0.28, 0.26, 30, 270) + E(0.3, 0.76, 0.3, 0.24, 90, -150)[1:]], 0.6),
        "T": ([[(0, 0), (0.66, 0)], [(0.33, 0), (0.33, 1)]], 0.66),
        "U": ([[(0, 0), (0, 0.64)] + E(0.32, 0.64, 0.32, 0.36, 180, 360)[1:] + [(0.64, 0)]], 0.64),
        "W": ([[(0, 0), (0.21, 1), (0.43, 0.28), (0.65, 1), (0.86, 0)]], 0.86),
        ".": ([[(0.0, 1.0)]], 0.0),
        "0": ([E(0.3, 0.5, 0.3, 0.5, 0, 360, 48)], 0.6),
        "2": ([E(0.3, 0.3, 0.3, 0.3, 160, -40) + [(0, 1), (0.62, 1)]], 0.62),
        "6": ([E(0.31, 0.69, 0.31, 0.31, 0, 360, 40), E(0.56, 0.69, 0.56, 0.69, 180, 108)], 0.62),
        " ": ([], 0.3),
    }
    return g[ch]


def text(canvas, s, x, y, cap, weight, colour, tracking=0.28):
    """Draws s with its cap line at y, starting at x; returns the end x."""
    for ch in s:
        lines, adv = glyph(ch)
        if lines:
            pts = [[(x + px * cap, y + py * cap) for px, py in line] for line in lines]
            canvas.fill(*strokes(pts, weight * cap), colour)
        x += (adv + tracking) * cap + (weight * cap if ch != " " else 0)
    return x


def text_width(s, cap, weight, tracking=0.28):
    w = 0.0
    for ch in s:
        _, adv = glyph(ch)
        w += (adv + tracking) * cap + (weight * cap if ch != " " else 0)
    return w - tracking * cap  # no space after the last


def centred_text(canvas, s, cx, y, cap, weight, colour, tracking=0.28):
    w = text_width(s, cap, weight, tracking)
    text(canvas, s, cx - w / 2 + weight * cap / 2, y, cap, weight, colour, tracking)
    return w


# ---- the decals ----

WHITE = (255, 255, 255)
NAVY = (27, 41, 72)
GOLD = (214, 170, 70)
CREAM = (246, 237, 214)
HOP = (150, 168, 62)
HOP_DARK = (84, 104, 34)


def wordmark():
    c = Canvas(1024, 400)
    cx = 512
    # EST. 2026 between two rules
    w = centred_text(c, "EST. 2026", cx, 22, 40, 0.14, WHITE, 0.36)
    for side in (-1, 1):
        x_in, x_out = cx + side * (w / 2 + 26), cx + side * (w / 2 + 200)
        c.fill(*strokes([[(x_in, 42), (x_out, 42)]], 5), WHITE)
    # DRAUGHT, bold, with tight tracking, as large as fits between the margins
    cap = min(186.0, 960.0 / text_width("DRAUGHT", 1.0, 0.17, 0.16))
    centred_text(c, "DRAUGHT", cx, 96 + (186 - cap) / 2, cap, 0.17, WHITE, 0.16)
    # a rule with a star in its middle
    c.fill(*strokes([[(cx - 430, 314), (cx - 34, 314)], [(cx + 34, 314), (cx + 430, 314)]], 6), WHITE)
    c.fill(*star(cx, 314, 22, 9), WHITE)
    centred_text(c, "BREWING CO.", cx, 346, 40, 0.14, WHITE, 0.36)
    return c


def shield_outline(x0, y0, x1, y1, shoulder):
    """Points round a shield: a straight top, straight sides down to `shoulder`, curved
    flanks meeting at a point at the bottom middle."""
    mx = (x0 + x1) / 2
    pts = [(x0, y0), (x1, y0), (x1, shoulder)]
    steps = 24
    for i in range(1, steps + 1):  # right flank: a quadratic curve to the point
        t = i / steps
        px = (1 - t) ** 2 * x1 + 2 * (1 - t) * t * x1 + t * t * mx
        py = (1 - t) ** 2 * shoulder + 2 * (1 - t) * t * (y1 - (y1 - shoulder) * 0.25) + t * t * y1
        pts.append((px, py))
    for i in range(1, steps):  # left flank, mirrored
        t = 1 - i / steps
        px = (1 - t) ** 2 * x0 + 2 * (1 - t) * t * x0 + t * t * mx
        py = (1 - t) ** 2 * shoulder + 2 * (1 - t) * t * (y1 - (y1 - shoulder) * 0.25) + t * t * y1
        pts.append((px, py))
    pts.append((x0, shoulder))
    return pts


def crest():
    c = Canvas(512, 640)
    outer = shield_outline(40, 40, 472, 612, 330)
    c.fill(*polygon(outer), GOLD)
    c.fill(*polygon(shield_outline(56, 56, 456, 588, 326)), NAVY)
    inner = shield_outline(72, 72, 440, 566, 322)
    c.fill(*strokes([inner + [inner[0]]], 5), CREAM)
    # The monogram in the upper field, between two stars.
    centred_text(c, "D", 256, 112, 150, 0.2, CREAM)
    for x in (140, 372):
        c.fill(*star(x, 186, 26, 11), GOLD)
    # A chevron across the middle.
    c.fill(*polygon([(92, 392), (256, 296), (420, 392), (420, 440), (256, 344), (92, 440)]), GOLD)
    # A hop cone below it: rows of pointed bracts, each overlapping the row above, on a
    # stem with a leaf.
    c.fill(*strokes([[(256, 398), (258, 372), (272, 356)]], 7), HOP_DARK)
    leaf = ellipse_arc(316, 346, 44, 16, 180, 360, 20)[:-1] + [(362, 336)] + ellipse_arc(316, 346, 44, 16, 0, 180, 20)[1:]
    leaf = [(x, y + (x - 272) * -0.35) for x, y in leaf]  # tilted up to the right
    c.fill(*polygon(leaf), HOP)
    c.fill(*strokes([[(276, 356), (356, 326)]], 3), HOP_DARK)

    def bract(x, y, w, h):
        return [(x - w, y)] + ellipse_arc(x, y, w, h, 180, 270, 10)[1:] + ellipse_arc(x, y, w, h, 270, 360, 10)[1:] + \
            [(x + w * 0.55, y - h * 0.7), (x, y - h * 0.45), (x - w * 0.55, y - h * 0.7)]
    rows = [(410, [256], 20), (434, [238, 274], 22), (460, [224, 256, 288], 22), (488, [228, 256, 284], 22),
            (516, [240, 272], 21), (542, [256], 18)]
    for y, xs, w in rows:
        for x in xs:
            c.fill(*polygon(bract(x, y, w + 3, w * 1.25 + 3)), HOP_DARK)
            c.fill(*polygon(bract(x, y - 2, w, w * 1.25)), HOP)
    return c


def gold_band():
    c = Canvas(1024, 56)
    box = lambda y0, y1: polygon([(-4, y0), (1028, y0), (1028, y1), (-4, y1)])
    c.fill(*box(4, 9), WHITE)
    c.fill(*box(15, 41), WHITE)
    c.fill(*box(47, 52), WHITE)
    return c


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "presets", "decals")
    os.makedirs(out, exist_ok=True)
    for name, draw in (("wordmark", wordmark), ("crest", crest), ("gold-band", gold_band)):
        path = os.path.join(out, name + ".png")
        data = draw().png()  # drawn first: the file is never left empty
        with open(path, "wb") as f:
            f.write(data)
        print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
