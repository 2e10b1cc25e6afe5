#!/usr/bin/env python3
"""Camera raw files from the command line (input/raw_file.h, docs/conventions.md §8): DNGs this
test writes itself (tests/support/dng.py), whose every photosite it knows, against the same
pixels written as a linear 16-bit PNG.

The scene: integer surfaces under an integer light; each quad of the Bayer mosaic holds a pixel
(r, g, b) as R = r + k, G1 = g + d + k, G2 = g - d + k, B = b + k (black level k, a random split
d of green between the two green photosites), so the quad read linearly is 2·(r, g, b) exactly.
Then:
- `gmcc estimate` on the DNG gives the light the PNG of (r, g, b) gives, for every 2×2 pattern
  (RGGB, BGGR, GRBG, GBRG), for per-photosite black levels (BlackLevelRepeatDim), in 2-D and 3-D,
  with the same pixel counts; quads with one photosite at the white level are dropped as
  saturated, as the PNG's pixels at --saturation are;
- --black-level and --saturation replace the file's metadata (a DNG whose metadata is wrong,
  corrected on the command line, equals the PNG);
- `gmcc canonical --from-images` learns the same canonical gamut from DNGs as from the PNGs;
- `gmcc benchmark` on a table of DNGs gives every method's light and error of the table of PNGs;
- files LibRaw does not read, and mosaics gmcc does not read, exit 2 naming the file.

    test_raw_files.py GMCC_BINARY
"""

import json
import math
import os
import random
import struct
import sys
import tempfile

from cli_harness import Runner, expect, memory_limit, random_triples  # noqa: E402
from dng import write_dng  # noqa: E402
from png16 import write_png16  # noqa: E402

WHITE = 16383  # a 14-bit sensor


def angle(u, v):
    dot = sum(a * b for a, b in zip(u, v))
    cross = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return math.degrees(math.atan2(math.sqrt(sum(c * c for c in cross)), dot))


def mosaic(quads, pattern, blacks, rng, saturate=()):
    """The CFA rows of `quads` (rows of (r, g, b)) in `pattern`, with black level blacks[p] at
    pattern position p; quads listed in `saturate` get one green photosite at WHITE."""
    h, w = len(quads), len(quads[0])
    rows = [[0] * (2 * w) for _ in range(2 * h)]
    for y in range(h):
        for x in range(w):
            r, g, b = quads[y][x]
            d = rng.randint(-min(g, 3), min(g, 3))
            greens = [g + d, g - d]
            for p, c in enumerate(pattern):
                v = r if c == "R" else b if c == "B" else greens.pop()
                rows[2 * y + p // 2][2 * x + p % 2] = v + blacks[p]
            if (y, x) in saturate:
                p = pattern.index("G")
                rows[2 * y + p // 2][2 * x + p % 2] = WHITE
    return rows


def main():
    binary = sys.argv[1]
    rng = random.Random(31)
    surfaces = random_triples(rng, 12, 20, 900)
    lights = random_triples(rng, 6, 3, 15)
    w, h = 16, 12  # quads: a 32×24 mosaic (LibRaw reads no raw file under 22 photosites a side)
    saturate = {(1, 1), (5, 7), (10, 3)}
    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(binary, tmp)
        canonical = os.path.join(tmp, "canonical.csv")
        with open(canonical, "w") as f:
            f.write("".join(f"{s[0]},{s[1]},{s[2]}\n" for s in surfaces))
        images = []  # (png path, dng path, light) with one pattern each
        patterns = ["RGGB", "BGGR", "GRBG", "GBRG", "RGGB", "GBRG"]
        for i, e in enumerate(lights):
            quads = [[tuple(surfaces[(3 * x + y + i) % 12][k] * e[k] for k in range(3)) for x in range(w)]
                     for y in range(h)]
            png_rows = [[(65535,) * 3 if (y, x) in saturate else quads[y][x] for x in range(w)] for y in range(h)]
            png = os.path.join(tmp, f"im{i}.png")
            write_png16(png, png_rows)
            dng = os.path.join(tmp, f"im{i}.dng")
            if i % 2:
                blacks = [rng.randint(60, 70) for _ in range(4)]
                write_dng(dng, mosaic(quads, patterns[i], blacks, rng, saturate), pattern=patterns[i],
                          black_per_channel=blacks, white=WHITE)
            else:
                write_dng(dng, mosaic(quads, patterns[i], [128] * 4, rng, saturate), pattern=patterns[i],
                          black=128, white=WHITE)
            images.append((png, dng, e))

        def estimates(*args):
            rc, out, err = r.run("estimate", "--canonical", canonical, "--json", *args, prefix=[])
            expect(rc == 0, err)
            return json.loads(out)["images"]

        def same_estimates(a, b, what):
            expect(len(a) == len(b), what)
            for x, y in zip(a, b):
                expect(x["pixels"] == y["pixels"], (what, x["pixels"], y["pixels"]))
                expect(x["pixels"]["saturated"] == len(saturate), (what, x["pixels"]))
                expect(x["estimates"].keys() == y["estimates"].keys(), what)
                for rule, est in x["estimates"].items():
                    if "light" in est:
                        expect(angle(est["light"], y["estimates"][rule]["light"]) < 1e-9, (what, rule, est))

        def dng_equals_png():
            for space in ("2d", "3d"):
                a = estimates("--space", space, "--saturation", "65535", *[p for p, _, _ in images])
                b = estimates("--space", space, *[d for _, d, _ in images])
                same_estimates(a, b, space)
                if space == "3d":
                    # Every surface is seen, so F3 is the segment to the true map: each rule
                    # recovers the light (a check that the DNG's colours are the scene's).
                    for x, (_, _, e) in zip(b, images):
                        for rule, est in x["estimates"].items():
                            expect(angle(est["light"], e) < 1e-9, (x["file"], rule, est["light"], e))

        def levels_override_metadata():
            png, _, e = images[0]
            quads = [[tuple(surfaces[(3 * x + y) % 12][k] * e[k] for k in range(3)) for x in range(w)] for y in range(h)]
            wrong = os.path.join(tmp, "wrong.dng")
            # Metadata says black 0 and white 60000; the truth is black 128, white 16383.
            write_dng(wrong, mosaic(quads, "RGGB", [128] * 4, rng, saturate), black=0, white=60000)
            rc, out, err = r.run("estimate", "--canonical", canonical, wrong, prefix=[])
            expect(rc == 2 and "white level 60000 above 32768" in err and err.startswith(f"gmcc: error: {wrong}:"), err)
            a = estimates("--saturation", "65535", png)
            b = estimates("--black-level", "128", "--saturation", str(WHITE), wrong)
            same_estimates(a, b, "override")

        def canonical_from_dngs():
            truths_png, truths_dng = os.path.join(tmp, "tp.csv"), os.path.join(tmp, "td.csv")
            with open(truths_png, "w") as f, open(truths_dng, "w") as g:
                f.write("image,r,g,b\n")
                g.write("image,r,g,b\n")
                for png, dng, e in images:
                    f.write(f"{os.path.basename(png)},{e[0]},{e[1]},{e[2]}\n")
                    g.write(f"{os.path.basename(dng)},{e[0]},{e[1]},{e[2]}\n")
            for space in ("2d", "3d"):
                outs = []
                for truths, files, sat in ((truths_png, [p for p, _, _ in images], ["--saturation", "65535"]),
                                           (truths_dng, [d for _, d, _ in images], [])):
                    out = os.path.join(tmp, f"learned-{space}-{len(outs)}.csv")
                    rc, _, err = r.run("canonical", "--from-images", "--space", space, "--truths", truths, *sat,
                                       "--out", out, *files, prefix=[])
                    expect(rc == 0, err)
                    outs.append([x for x in open(out).read().splitlines() if not x.startswith("#")])
                expect(outs[0] == outs[1] and len(outs[0]) > 3, (space, outs))
            return truths_png, truths_dng

        def benchmark_on_dngs():
            canonical_from_dngs()
            # Without saturated quads: the derivative methods smooth across them, and a saturated
            # pixel's value (65535 in both files) is not twice the PNG's.
            bench = os.path.join(tmp, "bench")
            os.mkdir(bench)
            truths = {ext: os.path.join(tmp, f"bench-{ext}.csv") for ext in ("png", "dng")}
            for ext in truths:
                with open(truths[ext], "w") as f:
                    f.write("image,r,g,b\n")
                    f.write("".join(f"im{i}.{ext},{e[0]},{e[1]},{e[2]}\n" for i, (_, _, e) in enumerate(images)))
            for i, (_, _, e) in enumerate(images):
                quads = [[tuple(surfaces[(3 * x + y + i) % 12][k] * e[k] + rng.randint(0, 40) for k in range(3))
                          for x in range(w)] for y in range(h)]
                write_png16(os.path.join(bench, f"im{i}.png"), quads)
                write_dng(os.path.join(bench, f"im{i}.dng"), mosaic(quads, patterns[i], [100] * 4, rng),
                          pattern=patterns[i], black=100, white=WHITE)
            records = []
            for ext, sat in (("png", ["--saturation", "none"]), ("dng", [])):
                path = os.path.join(tmp, f"bench-{ext}.jsonl")
                rc, _, err = r.run("benchmark", "--images", bench, "--truths", truths[ext], "--folds", "3", *sat,
                                   "--no-progress", "--records", path, prefix=[])
                expect(rc == 0, err)
                records.append([json.loads(x) for x in open(path)][2:])
            expect(len(records[0]) == len(records[1]) == 6 * 11, [len(x) for x in records])
            for a, b in zip(*records):
                expect(a["method"] == b["method"] and a["image"][:-4] == b["image"][:-4], (a, b))
                expect(angle(a["light"], b["light"]) < 1e-9 and abs(a["error_deg"] - b["error_deg"]) < 1e-9, (a, b))

        def unreadable_files():
            cases = {"garbage.dng": b"II*\0" + bytes(range(200)), "notraw.cr2": b"hello, not a raw file\n"}
            for name, content in cases.items():
                path = os.path.join(tmp, name)
                with open(path, "wb") as f:
                    f.write(content)
                rc, out, err = r.run("estimate", "--canonical", canonical, path, prefix=[])
                expect(rc == 2 and err.startswith(f"gmcc: error: {path}:") and "LibRaw" in err, (name, err))
            # A mosaic that is not red, two greens and blue.
            odd = os.path.join(tmp, "odd.dng")
            write_dng(odd, [[100] * 32 for _ in range(24)], pattern="RGGR", white=WHITE)
            rc, out, err = r.run("estimate", "--canonical", canonical, odd, prefix=[])
            expect(rc == 2 and "RGGR" in err and "only red, two greens and blue" in err, err)

        def header_bound():
            # A small DNG whose header declares 16384 x 16384 lossless-JPEG photosites (issue 42):
            # refused from the header, before LibRaw decodes it, as images are (4096:1), and
            # within a memory limit far below the gigabyte the decode took.
            small = os.path.join(tmp, "small.dng")
            write_dng(small, [[100] * 32 for _ in range(24)], white=WHITE)
            with open(small, "rb") as f:
                b = bytearray(f.read())
            (ifd,) = struct.unpack_from("<I", b, 4)
            (count,) = struct.unpack_from("<H", b, ifd)
            for k in range(count):
                at = ifd + 2 + 12 * k
                tag, kind = struct.unpack_from("<HH", b, at)
                if tag in (256, 257, 278):  # ImageWidth, ImageLength, RowsPerStrip
                    struct.pack_into("<I", b, at + 8, 16384)
                if tag == 259:  # Compression: lossless JPEG
                    struct.pack_into("<H", b, at + 8, 7)
            big = os.path.join(tmp, "declares_big.dng")
            with open(big, "wb") as f:
                f.write(b)
            rc, out, err = r.run(*memory_limit(binary, 400), "estimate", "--canonical", canonical, big, prefix=[])
            expect(rc == 2 and err.count("\n") == 1 and "4096:1" in err and big in err, (rc, err))

        r.check_all(dng_equals_png, levels_override_metadata, benchmark_on_dngs, unreadable_files, header_bound)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
