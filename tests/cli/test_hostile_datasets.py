#!/usr/bin/env python3
"""Issue 42's reproducers for the dataset layouts, `benchmark` and `merge`: each ends with an answer
or with exit 2 and one line on stderr naming the file, within the documented resources. The MATLAB
files are written here, byte by byte (a MATLAB 5 writer of the few types the datasets use), so
that each can lie in one place; the images come from tests/support/make_datasets.cpp.

    test_hostile_datasets.py GMCC_BINARY MAKE_DATASETS

Every run has a subprocess timeout: a hang is a failure here, not a wait. No time is asserted.
"""

import json
import os
import random
import shutil
import stat
import struct
import subprocess
import sys
import tempfile
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_harness import Runner, expect, memory_limit  # noqa: E402

# MATLAB 5 data types and array classes (MAT-File Format, tables 1-1 and 1-3).
miINT8, miUINT8, miINT32, miUINT32, miDOUBLE, miMATRIX, miCOMPRESSED = 1, 2, 5, 6, 9, 14, 15
mxCELL, mxCHAR, mxDOUBLE = 1, 4, 6


def element(kind, data):
    return struct.pack("<II", kind, len(data)) + data + b"\0" * (-len(data) % 8)


def matrix(name, cls, dims, *data):
    body = element(miUINT32, struct.pack("<II", cls, 0)) + element(miINT32, struct.pack("<%di" % len(dims), *dims))
    return element(miMATRIX, body + element(miINT8, name.encode()) + b"".join(data))


def doubles(name, rows):
    """A real double matrix from its rows (stored column-major)."""
    r, c = len(rows), len(rows[0])
    values = [rows[i][j] for j in range(c) for i in range(r)]
    return matrix(name, mxDOUBLE, [r, c], element(miDOUBLE, struct.pack("<%dd" % len(values), *values)))


def chars(text, dims=None):
    return matrix("", mxCHAR, dims or [1, len(text)], element(miUINT8, text.encode()))


def cell(name, items, dims=None):
    return matrix(name, mxCELL, dims or [len(items), 1], *items)


def mat_file(variables, compress=False):
    header = b"MATLAB 5.0 MAT-file, written by gmcc's tests".ljust(116, b" ") + b"\0" * 8 + struct.pack("<H", 0x0100) + b"IM"
    body = b""
    for v in variables:
        if compress:
            z = zlib.compress(v)
            body += struct.pack("<II", miCOMPRESSED, len(z)) + z
        else:
            body += v
    return header + body


def nus_variables(names, darkness=0, saturation=65535, name_cells=None):
    n = len(names)
    return [
        doubles("groundtruth_illuminants", [[1 + i, 2, 3] for i in range(n)]),
        doubles("CC_coords", [[1, 2, 1, 2] for _ in range(n)]),
        doubles("darkness_level", [[darkness]]),
        doubles("saturation_level", [[saturation]]),
        cell("all_image_names", name_cells if name_cells is not None else [chars(x) for x in names]),
    ]


def main():
    binary, maker = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([maker, tmp], check=True, timeout=300)
        r = Runner(binary, tmp, prefix=["benchmark"])
        png_dir = os.path.join(tmp, "nus", "PNG")
        names = sorted(f[:-4] for f in os.listdir(png_dir))
        counter = [0]

        def nus_folder(content, name="Cam_gt.mat"):
            """A NUS camera folder: the generated images and `content` as its ground truth."""
            counter[0] += 1
            d = os.path.join(tmp, "nus%d" % counter[0])
            shutil.copytree(png_dir, os.path.join(d, "PNG"))
            if content is not None:
                with open(os.path.join(d, name), "wb") as f:
                    f.write(content)
            return d

        fast = ["--folds", "2", "--methods", "grey-world", "--no-progress"]

        def refused(d, *words, layout="nus", extra=(), prefix=()):
            rc, out, err = r.run(*prefix, "--layout", layout, "--images", d, *fast, *extra, timeout=60)
            lines = err.strip().split("\n")
            expect(rc == 2 and out == "" and len(lines) == 1 and lines[0].startswith("gmcc: error: "), (d, rc, err))
            for w in words:
                expect(w in err, (w, err))
            return err

        def written_file_is_read():
            # The writer here and gmcc's reader agree, uncompressed and compressed.
            for compress in (False, True):
                d = nus_folder(mat_file(nus_variables(names), compress))
                rc, out, err = r.run("--layout", "nus", "--images", d, *fast)
                expect(rc == 0 and "grey-world" in out and err == "", (compress, rc, err))

        def name_longer_than_stored():
            # A name claiming 100000 characters where 16 are stored: refused before any is read
            # (a heap over-read, SIGSEGV before); a smaller lie too.
            for claimed, word in ((100000, "claim"), (40, "character array")):
                cells = [chars(x) for x in names]
                cells[2] = chars(names[2], dims=[1, claimed])
                d = nus_folder(mat_file(nus_variables(names, name_cells=cells)))
                refused(d, "Cam_gt.mat", word)

        def dimensions_beyond_the_file():
            # 20000 x 20000 doubles declared in a file of about 1 KB: refused before allocation,
            # within a memory limit far below the 3.2 GB it declares.
            big = matrix("groundtruth_illuminants", mxDOUBLE, [20000, 20000], element(miDOUBLE, struct.pack("<3d", 1, 2, 3)))
            v = nus_variables(names)
            v[0] = big
            d = nus_folder(mat_file(v))
            refused(d, "Cam_gt.mat", "claim", prefix=memory_limit(binary, 400))
            # A cell array declaring 10^8 cells.
            v = nus_variables(names)
            v[4] = matrix("all_image_names", mxCELL, [10000, 10000], chars("x"))
            refused(nus_folder(mat_file(v)), "Cam_gt.mat", "claim", prefix=memory_limit(binary, 400))

        def compressed_zeros():
            # 64 MB of zeros (about 64 KB compressed) declared as a uint8 matrix: refused at the
            # 16 MiB a MATLAB file may inflate to, under a memory limit it would exceed as doubles.
            n = 64 << 20
            body = element(miUINT32, struct.pack("<II", 9, 0)) + element(miINT32, struct.pack("<2i", n, 1))
            body += element(miINT8, b"CC_coords") + struct.pack("<II", miUINT8, n)
            z = zlib.compressobj(9)
            inner = struct.pack("<II", miMATRIX, len(body) + n) + body
            packed = z.compress(inner) + z.compress(b"\0" * n) + z.flush()
            v = nus_variables(names)
            content = mat_file(v[:1]) + struct.pack("<II", miCOMPRESSED, len(packed)) + packed
            refused(nus_folder(content), "Cam_gt.mat", "16 MiB", prefix=memory_limit(binary, 400))

        def byte_flips():
            # 80 copies of a valid file with 1 to 8 random bytes changed (seeded): each ends with an
            # answer or exit 2 and one line, never a signal.
            good = mat_file(nus_variables(names))
            rng = random.Random(42)
            d = nus_folder(None)
            outcomes = {0: 0, 2: 0}
            for trial in range(80):
                b = bytearray(good)
                for _ in range(rng.randint(1, 8)):
                    b[rng.randrange(128, len(b))] = rng.randrange(256)
                with open(os.path.join(d, "Cam_gt.mat"), "wb") as f:
                    f.write(b)
                rc, out, err = r.run("--layout", "nus", "--images", d, *fast, timeout=60)
                expect(rc in outcomes, (trial, rc, err))
                if rc == 2:
                    expect(len(err.strip().split("\n")) == 1 and err.startswith("gmcc: error: "), (trial, err))
                outcomes[rc] += 1
            expect(outcomes[2] > 0, outcomes)

        def fifo_ground_truth():
            # A FIFO as *_gt.mat (libmatio would open it again after gmcc read it, for ever):
            # refused before it is opened.
            d = nus_folder(None)
            os.mkfifo(os.path.join(d, "Cam_gt.mat"))
            refused(d, "Cam_gt.mat", "FIFO")
            # A FIFO among a Gehler-Shi folder's images.
            g = os.path.join(tmp, "gehler_fifo")
            shutil.copytree(os.path.join(tmp, "gehler"), g)
            first = sorted(os.listdir(os.path.join(g, "png")))[0]
            os.remove(os.path.join(g, "png", first))
            os.mkfifo(os.path.join(g, "png", first))
            refused(g, first, "FIFO", layout="gehler-shi", extra=())

        def truncated_mat73():
            # A MATLAB 7.3 (HDF5) file cut short: one gmcc line, no HDF5 diagnostics.
            content = b"MATLAB 7.3 MAT-file, Platform: GLNXA64".ljust(512, b" ") + b"\x89HDF\r\n\x1a\n" + b"\0" * 40
            refused(nus_folder(content), "Cam_gt.mat")

        def names_under_the_folder():
            for bad, word in (("../PNG/" + names[0], "not a file name"), ("/etc/" + names[0], "not a file name")):
                cells = [chars(x) for x in names]
                cells[1] = chars(bad)
                refused(nus_folder(mat_file(nus_variables(names, name_cells=cells))), "Cam_gt.mat", word)
            twice = list(names)
            twice[3] = twice[0]
            refused(nus_folder(mat_file(nus_variables(twice))), "Cam_gt.mat", "twice")

        def no_training_colour():
            # darkness_level 65535: every pixel is black; no gamut can be learned.
            d = nus_folder(mat_file(nus_variables(names, darkness=65535)))
            rc, out, err = r.run("--layout", "nus", "--images", d, "--folds", "2", "--methods", "gm3d-max-trace",
                                 "--no-progress", timeout=60)
            expect(rc == 2 and len(err.strip().split("\n")) == 1 and "internal" not in err, (rc, err))

        def cube_plus_bom():
            c = os.path.join(tmp, "cube_bom")
            shutil.copytree(os.path.join(tmp, "cube"), c)
            p = os.path.join(c, "cube+_gt.txt")
            with open(p, "rb") as f:
                text = f.read()
            with open(p, "wb") as f:
                f.write(b"\xef\xbb\xbf" + text)
            rc, out, err = r.run("--layout", "cube+", "--images", c, "--folds", "2", "--methods", "grey-world",
                                 "--no-progress")
            expect(rc == 0 and err == "", err)

        def gehler_split_of_one_fold():
            g = os.path.join(tmp, "gehler_one")
            shutil.copytree(os.path.join(tmp, "gehler"), g)
            n = len([x for x in os.listdir(os.path.join(g, "png")) if x.lower().endswith(".png")])
            split = cell("te_split", [doubles("", [[float(i + 1) for i in range(n)]])], dims=[1, 1])
            with open(os.path.join(g, "threefoldCVsplit.mat"), "wb") as f:
                f.write(mat_file([split]))
            rc, out, err = r.run("--layout", "gehler-shi", "--images", g, "--methods", "grey-world", "--no-progress")
            expect(rc == 2 and "threefoldCVsplit.mat" in err and "2 folds" in err, (rc, err))


        nus = os.path.join(tmp, "nus")
        table = os.path.join(tmp, "nus_table.csv")
        with open(table) as f:
            table_lines = f.read().splitlines()

        def table_file(lines):
            path = r.file("\n".join(lines) + "\n")
            return path

        def run_table(*args, truths=table, timeout=120):
            return r.run("--images", nus, "--truths", truths, "--no-progress", *args, timeout=timeout)

        def one_line(rc, out, err, *words):
            lines = err.strip().split("\n")
            expect(rc == 2 and out == "" and len(lines) == 1 and lines[0].startswith("gmcc: error: "), (rc, err))
            for w in words:
                expect(w in err, (w, err))

        def table_paths_under_images():
            # An image path that is absolute or climbs out of --images is refused, naming the line.
            first = table_lines[1].split(",")
            for bad, word in (("../nus/" + first[0], "leaves"), (os.path.join(nus, first[0]), "outside")):
                lines = list(table_lines)
                lines[1] = ",".join([bad] + first[1:])
                path = table_file(lines)
                one_line(*run_table("--folds", "2", "--methods", "grey-world", truths=path), path + ":2:", word)

        def folds_checked_against_the_dataset():
            images = [x.split(",")[0] for x in table_lines[1:]]
            extra = r.file("image,fold\n" + "".join(f"{x},{i % 2}\n" for i, x in enumerate(images)) + "PNG/nothere.PNG,0\n")
            one_line(*run_table("--folds-file", extra, "--methods", "grey-world"), extra, "nothere", "not in the dataset")
            single = r.file("image,fold\n" + "".join(f"{x},0\n" for x in images))
            one_line(*run_table("--folds-file", single, "--methods", "grey-world"), single, "2 folds")

        def tiny_edge_sigma_answers():
            # Sigmas whose Gaussian tails underflow (below about 0.026) and whose square underflows
            # (1e-300): an answer, the derivatives' limit (central differences), not an internal error.
            for sigma in ("0.01", "1e-300"):
                rc, out, err = run_table("--folds", "2", "--methods", "gm3d-edge1-max-trace,gm3d-edge2-max-trace",
                                         "--edge-sigma", sigma)
                expect(rc == 0 and err == "" and "gm3d-edge1-max-trace" in out, (sigma, rc, err))

        def tiny_prefilter_answers():
            rc, out, err = run_table("--folds", "2", "--methods", "gm2d-max-area,gm3d-max-trace", "--prefilter", "1e-300")
            expect(rc == 0 and err == "" and "gm2d-max-area" in out, (rc, err))

        def saturation_one_refused():
            # --saturation 1 on images without a saturation column: nothing or only black is left.
            cube = os.path.join(tmp, "cube")
            rc, out, err = r.run("--layout", "cube+", "--images", cube, "--folds", "2", "--methods", "gm3d-max-trace",
                                 "--saturation", "1", "--no-progress")
            one_line(rc, out, err, cube)
            expect("internal" not in err, err)

        def unwritable_plot_before_work():
            blocker = r.file("a file, not a folder\n")
            csv = os.path.join(tmp, "plot_refused.csv")
            rc, out, err = run_table("--folds", "2", "--methods", "grey-world", "--csv", csv, "--plot",
                                     os.path.join(blocker, "plots"))
            one_line(rc, out, err, blocker)
            expect(not os.path.exists(csv), "the CSV was written before the plot folder was refused")

        def shards():
            parts = []
            for k in (1, 2):
                p = os.path.join(tmp, f"part{k}.jsonl")
                rc, out, err = run_table("--folds", "2", "--methods", "grey-world,white-patch", "--shard", f"{k}/2",
                                         "--records", p)
                expect(rc == 0, err)
                with open(p) as f:
                    parts.append(f.read().splitlines())
            return parts

        def merge_checks_values():
            parts = shards()

            def merge(part0, *extra, limit=(), part1=None):
                p, q = os.path.join(tmp, "forged.jsonl"), os.path.join(tmp, "forged2.jsonl")
                for path, lines in ((p, part0), (q, part1 or parts[1])):
                    with open(path, "w") as f:
                        f.write("\n".join(lines) + "\n")
                return r.run(*limit, "merge", p, q, *extra, prefix=[]), p

            (rc, out, err), _ = merge(parts[0])
            expect(rc == 0 and "grey-world" in out, err)
            # A header claiming 10^8 images: refused from the records, not allocated from the header.
            forged = [list(parts[0]), list(parts[1])]
            for part in forged:
                h = json.loads(part[1])
                h["benchmark"]["images"] = 10 ** 8
                part[1] = json.dumps(h)
            (rc, out, err), p = merge(forged[0], part1=forged[1], limit=memory_limit(binary, 400))
            one_line(rc, out, err, "shard is missing")
            # A negative error, an image renamed in one of its records, a negative fold.
            for field, value, word in (("error_deg", -3.0, "angle"), ("image", "PNG/renamed.PNG", "earlier record"),
                                       ("fold", -1, "negative")):
                forged = list(parts[0])
                k = next(i for i in range(2, len(forged)) if json.loads(forged[i])["method"] == "white-patch")
                rec = json.loads(forged[k])
                rec[field] = value
                forged[k] = json.dumps(rec)
                (rc, out, err), p = merge(forged)
                one_line(rc, out, err, p, word)
            # --plot into a folder that cannot be made: refused before anything is written.
            blocker = r.file("a file, not a folder\n")
            csv = os.path.join(tmp, "merge_refused.csv")
            (rc, out, err), _ = merge(parts[0], "--csv", csv, "--plot", os.path.join(blocker, "plots"))
            one_line(rc, out, err, blocker)
            expect(not os.path.exists(csv), "merge wrote the CSV before refusing the plot folder")

        def error_after_progress_starts_a_line():
            # An error found after the progress line has been drawn (no colour above black, found
            # when the gamuts are learned, after every image is read): it starts a line of its
            # own. The progress line appears after 2 s only, so the slow edge path is used on the
            # Cube+ images with a black level of 65535.
            with open(os.path.join(tmp, "cube_table.csv")) as f:
                rows = f.read().splitlines()
            header = rows[0].split(",")
            k = header.index("black_level")
            black = [rows[0]] + [",".join(x.split(",")[:k] + ["65535"] + x.split(",")[k + 1:]) for x in rows[1:]]
            truths = table_file(black)
            rc, out, err = r.run("--images", os.path.join(tmp, "cube"), "--truths", truths, "--folds", "2",
                                 "--methods", "gm3d-edge2-max-trace", "--edge-sigma", "12", "--threads", "1",
                                 timeout=600)
            expect(rc == 2 and "no colour above black" in err, (rc, err))
            at = err.find("gmcc: error: ")
            expect(at == 0 or err[at - 1] == "\n", repr(err[-300:]))

        r.check_all(written_file_is_read, name_longer_than_stored, dimensions_beyond_the_file, compressed_zeros,
                    byte_flips, fifo_ground_truth, truncated_mat73, names_under_the_folder, no_training_colour,
                    cube_plus_bom, gehler_split_of_one_fold, table_paths_under_images,
                    folds_checked_against_the_dataset, tiny_edge_sigma_answers, tiny_prefilter_answers,
                    saturation_one_refused, unwritable_plot_before_work, merge_checks_values,
                    error_after_progress_starts_a_line)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
