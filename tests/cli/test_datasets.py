#!/usr/bin/env python3
"""`gmcc benchmark --layout nus|cube+`: datasets read as they ship (tests/support/make_datasets.cpp
writes a NUS camera folder with its MATLAB ground truth, by libmatio's writer, and a Cube+ folder),
against the same datasets written as plain truth tables from what the tool drew: the same records,
image by image. Also: the chart box, the black level and the saturation level reach the pixels, and
a broken layout exits 2 naming the file, and the binary does not link libmatio (it is opened on the
first MATLAB file).

    test_datasets.py GMCC_BINARY MAKE_DATASETS
"""

import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_harness import Runner, expect  # noqa: E402


HERE = os.path.dirname(os.path.abspath(__file__))


def png_of_size(width, height):
    """An 8-bit RGB PNG of mid grey."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    body = zlib.compress(b"".join(b"\0" + b"\x80" * (3 * width) for _ in range(height)))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", body) + chunk(b"IEND", b""))


def records(path):
    return [json.loads(x) for x in open(path).read().splitlines()[2:]]


def main():
    binary, maker = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([maker, tmp], check=True, timeout=300)
        r = Runner(binary, tmp, prefix=["benchmark"])

        def two_runs(name, first, second, common, quiet=False):
            """Both runs' records: benchmark with the arguments `first` and `second` (each followed
            by `common` and --records to a file of its own), each expected to succeed and, when
            quiet, to write nothing on stderr."""
            out = []
            for k, args in enumerate((first, second)):
                path = os.path.join(tmp, f"{name}_{k}.jsonl")
                rc, _, err = r.run(*args, *common, "--records", path)
                expect(rc == 0 and (not quiet or err == ""), err)
                out.append(records(path))
            return out

        def nus_equals_its_table():
            common = ["--folds", "3", "--pixel-rule", "gijsenij", "--no-progress"]
            ra, rb = two_runs("nus", ["--layout", "nus", "--images", os.path.join(tmp, "nus")],
                              ["--images", os.path.join(tmp, "nus"), "--truths", os.path.join(tmp, "nus_table.csv")],
                              common)
            expect(len(ra) == 6 * 11 and len(ra) == len(rb), len(ra))
            # The provenance states the levels the images were read with: the MAT file's, not the
            # options' defaults (--black-level 0 --saturation max).
            levels = json.loads(open(os.path.join(tmp, "nus_0.jsonl")).readline())["provenance"]["image_levels"]
            expect(len(levels) == 6 and all(x["black_level"] == 512 and x["saturation"] == 15000 and
                                            x["black_from"] == x["saturation_from"] == "given" for x in levels), levels)
            for x, y in zip(ra, rb):
                x.pop("image"), y.pop("image")
                expect(x == y, (x, y))

        def nus_mat73_equals_mat5():
            # The same ground truth as MATLAB 7.3 (HDF5, read through libmatio): the same records,
            # and nothing on stderr (HDF5's and libmatio's own messages are kept off it).
            common = ["--folds", "3", "--methods", "grey-world,gm3d-max-trace", "--no-progress"]
            ra, rb = two_runs("mat", ["--layout", "nus", "--images", os.path.join(tmp, "nus")],
                              ["--layout", "nus", "--images", os.path.join(tmp, "nus73")], common, quiet=True)
            expect(len(ra) == 12 and ra == rb, (ra[:1], rb[:1]))

        def cube_equals_its_table():
            common = ["--folds", "2", "--methods", "gm3d-max-trace,grey-world", "--no-progress"]
            ra, rb = two_runs("cube", ["--layout", "cube+", "--images", os.path.join(tmp, "cube")],
                              ["--images", os.path.join(tmp, "cube"), "--truths", os.path.join(tmp, "cube_table.csv")],
                              common)
            expect(len(ra) == 8 and [x["error_deg"] for x in ra] == [x["error_deg"] for x in rb], (ra, rb))
            # The masked corner is bright: had it been kept, grey world would move; with it masked,
            # grey world of images of random surfaces under a light is within a few degrees.
            for x in ra:
                if x["method"] == "grey-world":
                    expect(x["error_deg"] < 5, x)

        def broken_layouts():
            empty = os.path.join(tmp, "empty")
            os.makedirs(empty)
            rc, out, err = r.run("--layout", "nus", "--images", empty, "--folds", "2")
            expect(rc == 2 and "_gt.mat" in err, err)
            rc, out, err = r.run("--layout", "cube+", "--images", empty, "--folds", "2")
            expect(rc == 2 and "cube+_gt.txt" in err, err)
            rc, out, err = r.run("--layout", "nus", "--images", os.path.join(tmp, "nus"), "--truths",
                                 os.path.join(tmp, "nus_table.csv"), "--folds", "2")
            expect(rc == 2 and "--truths" in err, err)
            with open(os.path.join(empty, "cube+_gt.txt"), "w") as f:
                f.write("1 2\n")
            rc, out, err = r.run("--layout", "cube+", "--images", empty, "--folds", "2")
            expect(rc == 2 and "cube+_gt.txt:1:" in err, err)

        def gehler_shi_equals_its_table():
            # The split shipped in threefoldCVsplit.mat, against the same folds in a folds file.
            ra, rb = two_runs("gehler", ["--layout", "gehler-shi", "--images", os.path.join(tmp, "gehler")],
                              ["--images", os.path.join(tmp, "gehler"), "--truths", os.path.join(tmp, "gehler_table.csv"),
                               "--folds-file", os.path.join(tmp, "gehler_folds.csv")],
                              ["--pixel-rule", "gijsenij", "--no-progress"])
            expect(len(ra) == 6 * 11 and ra == rb, (len(ra), ra[:1], rb[:1]))
            expect([x["fold"] for x in ra[::11]] == [0, 1, 2, 0, 1, 2], [x["fold"] for x in ra[::11]])

        def dataset_table_equals_the_layout():
            # `gmcc dataset` writes what the layout read as a truth table; benchmark on that table
            # gives the layout run's records, and its folds file is the shipped split.
            for layout, folder, extra in (("nus", "nus", ["--folds", "3"]), ("cube+", "cube", ["--folds", "2"]),
                                          ("gehler-shi", "gehler", [])):
                d = os.path.join(tmp, folder)
                table, folds = os.path.join(tmp, folder + "_read.csv"), os.path.join(tmp, folder + "_folds_read.csv")
                p = subprocess.run([binary, "dataset", "--layout", layout, "--images", d] +
                                   (["--folds-out", folds] if layout == "gehler-shi" else []),
                                   capture_output=True, text=True, timeout=120)
                expect(p.returncode == 0 and p.stdout.startswith("# gmcc-provenance: "), p.stderr)
                with open(table, "w") as f:
                    f.write(p.stdout)
                ra, rb = two_runs(folder + "_read", ["--layout", layout, "--images", d, *extra],
                                  ["--images", d, "--truths", table, *extra,
                                   *(["--folds-file", folds] if layout == "gehler-shi" else [])],
                                  ["--methods", "gm3d-max-trace,grey-world", "--no-progress"])
                expect(ra == rb, (layout, ra[:1], rb[:1]))
            rows = [line.split(",") for line in open(os.path.join(tmp, "gehler_read.csv")).read().splitlines()[2:]]
            expect([x[4] for x in rows] == ["0", "0", "129", "129", "129", "129"], rows)  # Shi's description.txt
            expect(open(os.path.join(tmp, "gehler_folds_read.csv")).read().splitlines()[1:] ==
                   open(os.path.join(tmp, "gehler_folds.csv")).read().splitlines(), "folds")
            p = subprocess.run([binary, "dataset", "--layout", "nus", "--images", os.path.join(tmp, "nus"),
                                "--folds-out", os.path.join(tmp, "x.csv")], capture_output=True, text=True)
            expect(p.returncode == 2 and "--folds-out" in p.stderr and not os.path.exists(os.path.join(tmp, "x.csv")),
                   p.stderr)

        def gehler_shi_shapes_and_frames_checked():
            # A copy of the folder with one PNG rotated (portrait against its landscape frame), then
            # one coordinate file without its frame line (the first line a corner, as 22 real ones).
            src = os.path.join(tmp, "gehler")
            for case in ("rotated", "frameless", "half"):
                d = os.path.join(tmp, "gehler_" + case)
                shutil.copytree(src, d)
                png = os.path.join(d, "png", "IMG_0302.png")
                coords = os.path.join(d, "coordinates", "IMG_0302_macbeth.txt")
                if case == "rotated":
                    with open(png, "wb") as f:
                        f.write(png_of_size(32, 48))
                elif case == "frameless":
                    with open(coords, "w") as f:
                        f.write("15.5 10.25\n22 10\n15 15\n22 15\n1 1\n")
                else:  # a 25 x 17 copy of the 24 x 16 frame's image: the frame scaled, rounded: accepted
                    with open(png, "wb") as f:
                        f.write(png_of_size(49, 33))
                p = subprocess.run([binary, "dataset", "--layout", "gehler-shi", "--images", d],
                                   capture_output=True, text=True, timeout=120)
                if case == "half":
                    expect(p.returncode == 0, p.stderr)
                    continue
                expect(p.returncode == 2 and p.stdout == "" and p.stderr.count("\n") == 1, (case, p.stderr))
                if case == "rotated":
                    expect(png in p.stderr and "32x48" in p.stderr and "24x16" in p.stderr, p.stderr)
                else:
                    expect(coords + ":1:" in p.stderr and "no frame line" in p.stderr, p.stderr)
                rc, out, err = r.run("--layout", "gehler-shi", "--images", d, "--no-progress", "--methods",
                                     "grey-world", "--records", os.path.join(d, "r.jsonl"))
                expect(rc == 2 and not os.path.exists(os.path.join(d, "r.jsonl")), err)

        def verify_script_on_written_datasets():
            # scripts/verify-datasets on the NUS and Cube+ folders the tool wrote (their MAT and
            # text files; the script makes its own stand-in images).
            script = os.path.join(os.path.dirname(os.path.dirname(HERE)), "scripts", "verify-datasets")
            p = subprocess.run([sys.executable, script, "--gmcc", binary, os.path.join(tmp, "nus"),
                                os.path.join(tmp, "cube")], capture_output=True, text=True, timeout=600)
            expect(p.returncode == 0 and p.stdout.count("ok    ") == 4, (p.stdout, p.stderr))

        def matio_loaded_on_demand():
            # libmatio (and HDF5, libcurl, GnuTLS behind it) is opened on the first MATLAB file, not
            # linked: every other command starts without loading it (docs/performance-history.md "Start-up").
            # MATLAB 7.3 files (nus73 above) are read through it; MATLAB 5 files by gmcc itself.
            dynamic = subprocess.run(["readelf", "-d", binary], capture_output=True, text=True, check=True).stdout
            needed = [line for line in dynamic.splitlines() if "(NEEDED)" in line]
            expect(needed and not any("matio" in line or "hdf5" in line for line in needed), needed)

        r.check_all(nus_equals_its_table, nus_mat73_equals_mat5, cube_equals_its_table, gehler_shi_equals_its_table,
                    broken_layouts, dataset_table_equals_the_layout, gehler_shi_shapes_and_frames_checked,
                    verify_script_on_written_datasets, matio_loaded_on_demand)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
