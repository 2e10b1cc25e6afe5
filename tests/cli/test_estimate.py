#!/usr/bin/env python3
"""`gmcc estimate` on images the project renders itself (tests/support/make_mondrian_images.cpp):
the shipped sample's 8 Munsell chips under D75 (narrow-band sensors) as a 16-bit Mondrian above a
black level of 256, with saturated pixels, written as PNG and TIFF.

What is checked, each by a route independent of the image code where one exists:
- the PNG and the TIFF give the same answer;
- pixel counts: total = masked + saturated + kept, an exclusion polygon over the left half masks
  exactly 60 x 90 pixels, and the saturated ones are between 1 and the 20 drawn;
- the estimate agrees with `gmcc select` on the exact colours of the chips shown: the
  image's quantisation to 16 bits moves the maps by little, and the recovery errors against the
  true light D75 differ by little;
- bad files and options exit 2 naming the file, with no corrected image written.

    test_estimate.py GMCC_BINARY MAKE_MONDRIAN_IMAGES
"""

import json
from fractions import Fraction
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_harness import Runner, expect  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(ROOT, "data")
CANONICAL = os.path.join(DATA, "samples", "canonical_munsell_D55.csv")
# The lights at the narrow-band sensors' wavelengths 610, 540, 450 nm (data/cie_illuminants_*).
D55 = "95.14,102.102,97.993"
D75 = "86.14,106.289,133.01"
RULES = ("max_area", "mean_2d", "mean_3d")


def main():
    binary, maker = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([maker, DATA, tmp], check=True, timeout=120)
        png, tif = os.path.join(tmp, "mondrian.png"), os.path.join(tmp, "mondrian.tif")
        r = Runner(binary, tmp, prefix=["estimate"])
        base = ["--canonical", CANONICAL, "--black-level", "256", "--canonical-illuminant", D55]

        def estimate(*args):
            rc, out, err = r.run(*base, *args, "--json")
            expect(rc == 0, f"exit {rc}: {err}")
            return json.loads(out)

        def png_equals_tiff():
            a, b = estimate(png), estimate(tif)
            ia, ib = a["images"][0], b["images"][0]
            ia.pop("file"), ib.pop("file")
            expect(ia == ib, "PNG and TIFF differ")
            expect(ia["width"] == 120 and ia["height"] == 90 and ia["bits"] == 16, ia)

        def pixel_counts():
            p = estimate(png)["images"][0]["pixels"]
            expect(p["total"] == 120 * 90, p)
            expect(p["masked"] + p["saturated"] + p["kept"] == p["total"], p)
            expect(p["masked"] == 0 and 1 <= p["saturated"] <= 20, p)
            with open(os.path.join(tmp, "shown.csv")) as f:
                chips = len(f.readlines())
            expect(p["colours"] == chips, f"one colour per chip shown ({chips}): {p}")
            q = estimate(png, "--exclude-polygon", "0,0,60,0,60,90,0,90")["images"][0]["pixels"]
            expect(q["masked"] == 60 * 90, q)
            n = estimate(png, "--saturation", "none")["images"][0]["pixels"]
            expect(n["saturated"] == 0 and n["colours"] == p["colours"] + 1, (n, p))

        def agrees_with_select_on_exact_colours():
            img = estimate(png, "--truth", D75)["images"][0]
            shown = os.path.join(tmp, "shown.csv")  # the chips the cells show, exactly
            p = subprocess.run([binary, "select", "--canonical", CANONICAL, "--image", shown,
                                "--canonical-illuminant", D55, "--truth", D75, "--json"],
                               capture_output=True, text=True, timeout=120)
            expect(p.returncode == 0, p.stderr)
            exact = json.loads(p.stdout)
            for rule in RULES:
                m_img = img["estimates"][rule]["map"]
                m_exact = exact["selections"][rule]["map"]
                for a, b in zip(m_img, m_exact):
                    expect(abs(a - b) <= 5e-4 * b, f"{rule}: map {m_img} vs exact {m_exact}")
                e_img = img["truth"]["errors"][rule]["illuminant_error_deg"]
                e_exact = exact["truth"]["errors"][rule]["illuminant_error_deg"]
                expect(abs(e_img - e_exact) <= 0.01, f"{rule}: recovery error {e_img} vs {e_exact}")
                light = img["estimates"][rule]["light"]
                expect(abs(sum(x * x for x in light) - 1) < 1e-12, f"unit light {light}")

        def hull_equals_distinct():
            # The hull's few colours give the same feasible set and selections as every distinct
            # colour (the 2-D feasible set depends on the chromaticity hull only).
            a = estimate(png)["images"][0]
            b = estimate(png, "--colour-set", "distinct")["images"][0]
            expect(a["pixels"]["hull_vertices"] < b["pixels"]["colours"], (a["pixels"], b["pixels"]))
            for key in ("feasible_set", "selections", "estimates"):
                expect(a[key] == b[key], f"{key} differs between --colour-set hull and distinct")

        def learned_canonical():
            # gmcc canonical --from-images: the image's pixels divided by its light. Then the
            # true map takes the image's colours exactly onto the learned ones: truth in F.
            truths = os.path.join(tmp, "truths.csv")
            with open(truths, "w") as f:
                f.write("image,r,g,b\nmondrian.png," + D75 + "\n")
            learned = os.path.join(tmp, "learned.csv")
            rc, out, err = r.run("--from-images", "--truths", truths, "--black-level", "256",
                                 "--out", learned, png, prefix=["canonical"])
            expect(rc == 0 and out == "", f"exit {rc}: {err}")
            with open(learned) as f:
                lines = [x for x in f.read().splitlines() if not x.startswith("#")]
            expect(lines[0] == "r/b,g/b,1", lines[:1])  # chromaticity lifts, marked as such
            got = [tuple(Fraction(v) for v in x.split(",")) for x in lines[1:]]
            # Independently: the hull of the shown chips' chromaticities under a white light.
            e = [Fraction(v) for v in D75.split(",")]
            with open(os.path.join(tmp, "shown.csv")) as f:
                chips = [[Fraction(v) for v in x.split(",")] for x in f.read().split()]
            pts = sorted({(c[0] / e[0] / (c[2] / e[2]), c[1] / e[1] / (c[2] / e[2])) for c in chips})
            def half(points):
                h = []
                for p in points:
                    while len(h) >= 2 and ((h[-1][0] - h[-2][0]) * (p[1] - h[-2][1])
                                           - (h[-1][1] - h[-2][1]) * (p[0] - h[-2][0])) <= 0:
                        h.pop()
                    h.append(p)
                return h[:-1]
            hull = half(pts) + half(pts[::-1])
            expect(len(got) == len(hull), f"{len(got)} learned vertices, {len(hull)} expected")
            for v in hull:
                expect(any(abs(g[0] - v[0]) <= v[0] / 1000 and abs(g[1] - v[1]) <= v[1] / 1000
                           and g[2] == 1 for g in got), f"vertex {v} not learned: {got}")
            doc = json.loads(r.run("--canonical", learned, "--black-level", "256", "--truth", D75,
                                   "--json", png)[1])
            expect(doc["images"][0]["truth"]["in_feasible_set"] is True, "truth in F exactly")
            rc, _, err = r.run("--from-images", "--truths", truths, tif, prefix=["canonical"])
            expect(rc == 2 and "no light for image" in err, err)

        def truths_file():
            # --truths gives each image its light; the same errors as --truth for one image.
            truths = os.path.join(tmp, "truths2.csv")
            with open(truths, "w") as f:
                f.write("image,r,g,b\n# the same light for both files\n")
                f.write(f"mondrian.png,{D75}\n{tif},{D75}\n")
            both = estimate("--truths", truths, png, tif)["images"]
            one = estimate("--truth", D75, png)["images"][0]
            expect(len(both) == 2 and all(x["truth"] == one["truth"] for x in both),
                   "--truths gives each image the errors --truth gives")
            rc, _, err = r.run(*base, "--truths", truths, "--truth", D75, png)
            expect(rc == 2 and "--truths" in err, err)
            with open(truths, "w") as f:
                f.write(f"image,r,g,b\nother.png,{D75}\n")
            rc, _, err = r.run(*base, "--truths", truths, png)
            expect(rc == 2 and "no light for image" in err and truths in err, err)

        def corrected_images():
            out = os.path.join(tmp, "corrected")
            rc, _, err = r.run(*base, "--corrected", out, png)
            expect(rc == 0, err)
            names = sorted(os.listdir(out))
            expect(names == [f"mondrian_{k}.png" for k in sorted(RULES)], names)
            for n in names:
                with open(os.path.join(out, n), "rb") as f:
                    head = f.read(32)
                expect(head[:8] == b"\x89PNG\r\n\x1a\n" and head[24] == 16, f"{n}: 16-bit PNG")

        def bad_inputs():
            not_image = r.file("1,2,3\n")
            rc, out, err = r.run(*base, not_image)
            expect(rc == 2 and out == "" and not_image in err and "not a PNG or TIFF" in err, err)
            with open(png, "rb") as f:
                data = f.read()
            cut = os.path.join(tmp, "cut.png")
            with open(cut, "wb") as f:
                f.write(data[: len(data) // 2])
            out_dir = os.path.join(tmp, "never")
            rc, out, err = r.run(*base, "--corrected", out_dir, png, cut)
            expect(rc == 2 and "cut.png" in err, err)
            expect(not os.path.exists(out_dir) or os.listdir(out_dir) == [],
                   "no corrected image when an image fails")
            rc, _, err = r.run(*base, "--mask", tif, "--exclude-polygon", "1,2,3", png)
            expect(rc == 2 and "--exclude-polygon" in err, err)
            rc, _, err = r.run(*base, "--truth", D75, png, tif)
            expect(rc == 2 and "--truth" in err, err)
            # A mask of another size: the 6x4 noise-free Mondrian made by the test tool.
            small_dir = os.path.join(tmp, "small")
            os.makedirs(small_dir)
            subprocess.run([maker, DATA, small_dir, "6", "4"], check=True, timeout=60)
            small = os.path.join(small_dir, "mondrian.png")
            rc, out, err = r.run(*base, "--mask", small, png)
            expect(rc == 2 and out == "" and "the mask is 6x4" in err and png in err, err)
            rc, _, err = r.run(*base, "--bin", "0", png)
            expect(rc == 2 and "--bin" in err, err)

        def no_light_names_its_cause():
            # One dark pixel (0, 0, 50) among chips: in 3-D it forces the map's red and green to 0
            # (the canonical gamut holds no colour (0, 0, t > 0) but black), so no rule has a
            # light; the summary names the cause and the option, and with it every rule answers.
            sys.path.insert(0, os.path.join(ROOT, "tests", "support"))
            from png16 import write_png16
            chips = [(17394, 17749, 19888), (7837, 1283, 1247), (15210, 5548, 2182), (16582, 19653, 14942),
                     (14677, 17525, 2742), (5356, 7027, 6373), (3571, 7938, 6236), (12385, 20001, 20108)]
            path = os.path.join(tmp, "dark_pixel.png")
            write_png16(path, [chips[:4], chips[4:], [(0, 0, 50)] + chips[1:4]])
            rc, out, err = r.run("--space", "3d", "--canonical", CANONICAL, path)
            expect(rc == 0 and out.count("no light (a map component is 0: likely dark pixels with a zero channel")
                   == 3 and out.count("--dark 1 or --pixel-rule gijsenij") == 3, out)
            rc, out, err = r.run("--space", "3d", "--canonical", CANONICAL, "--dark", "1", path)
            expect(rc == 0 and "no light" not in out and out.count("  light (") == 3, out)

        r.check_all(png_equals_tiff, pixel_counts, agrees_with_select_on_exact_colours, hull_equals_distinct,
                    learned_canonical, truths_file, corrected_images, bad_inputs, no_light_names_its_cause)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
