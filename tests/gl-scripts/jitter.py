#!/usr/bin/env python3
"""How many pixels of each multi-pass picture depend on sub-pixel rasterisation.

usage: jitter.py PX [PX ...]

For each PX, writes the multi-pass scripts with every projection moved by PX pixels
(make_scripts.py --jitter), runs them in Chromium and counts, against the committed pictures in
chromium/, the pixels that differ by more than 3/255 on some channel (docs/gl-scripts.md, "How
robust the pictures are"). Standard library only.
"""
import os, struct, subprocess, sys, tempfile, zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def read_png(path):
    """Rows of an 8-bit RGBA PNG with filter 0 on every row (what run-chromium.py writes)."""
    with open(path, "rb") as fh:
        data = fh.read()
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height = struct.unpack(">II", body[:8])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride = zlib.decompress(idat), width * 4 + 1
    if any(raw[y * stride] for y in range(height)):
        raise ValueError(f"{path}: a row with a PNG filter other than 0")
    return [raw[y * stride + 1:(y + 1) * stride] for y in range(height)]


def pixels_off(a, b, tolerance=3):
    return sum(1 for ra, rb in zip(a, b) for x in range(0, len(ra), 4)
               if max(abs(ra[x + c] - rb[x + c]) for c in range(4)) > tolerance)


def main(argv):
    if not argv:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    names = sorted(f[:-5] for f in os.listdir(os.path.join(HERE, "chromium")) if f.endswith(".json"))
    print("script".ljust(16) + "".join(f"{'jitter ' + px:>18}" for px in argv))
    with tempfile.TemporaryDirectory() as tmp:
        counts = {name: [] for name in names}
        for px in argv:
            out = os.path.join(tmp, px)
            subprocess.run([sys.executable, os.path.join(HERE, "make_scripts.py"), "--out", out, "--jitter", px],
                           check=True)
            for name in names:
                png = os.path.join(out, name + ".png")
                script = os.path.join(out, name + ".json")
                results = os.path.join(out, name + ".results.json")
                subprocess.run([sys.executable, os.path.join(HERE, "run-chromium.py"), script, "-o", png,
                                "--results", results], check=True, stdout=subprocess.DEVNULL)
                committed = read_png(os.path.join(HERE, "chromium", name + ".png"))
                counts[name].append(pixels_off(committed, read_png(png)))
        for name in names:
            print(name.ljust(16) + "".join(f"{n:>18}" for n in counts[name]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
