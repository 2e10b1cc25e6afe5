#!/usr/bin/env python3
"""A real camera raw file through gmcc (data/raw/colorchart.dng, data/SOURCES.md: a Canon 550D's
14-bit DNG of a ColorChecker Passport), against an independent decode of its TIFF tags in Python
(scripts/verify-datasets' decode_dng: TIFF 6.0 and DNG 1.6, numpy for the 14-bit unpacking).

- `gmcc estimate --json` and its text report the camera, RGGB, the black level 2056 at every quad
  position, the white level 15000 and the saturated quads the Python decode counts; an independent
  dcraw decode (issue 43) gave the same pattern and levels;
- provenance records the levels the image was read with (the file's, or the ones given);
- the same file named .tif goes to LibRaw by its content (CFA data), named .crw or .raw by its
  extension, and gives the same report;
- a truncated copy is refused: exit 2, one line naming the file with LibRaw's reason (its data
  error), nothing else on stderr, nothing on stdout;
- the file with its raw data marked VC-5 (compression 9, GoPro's GPR) is refused naming VC-5 and
  the decoder Debian's LibRaw lacks;
- scripts/verify-datasets run on a folder holding the file passes.

    test_real_files.py GMCC_BINARY DATA_DIR SCRIPTS_DIR
"""

import importlib.machinery
import importlib.util
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from cli_harness import Runner, expect  # noqa: E402


def load_script(path):
    loader = importlib.machinery.SourceFileLoader("verify_datasets", path)
    spec = importlib.util.spec_from_loader("verify_datasets", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def main():
    binary, data, scripts = sys.argv[1], sys.argv[2], sys.argv[3]
    dng = os.path.join(data, "raw", "colorchart.dng")
    canonical = os.path.join(data, "samples", "canonical_munsell_D55.csv")
    verify = load_script(os.path.join(scripts, "verify-datasets"))
    raw_bytes = open(dng, "rb").read()
    decoded = verify.decode_dng(raw_bytes)
    m = decoded["mosaic"]
    quads = m.reshape(m.shape[0] // 2, 2, m.shape[1] // 2, 2)
    saturated = int((quads >= decoded["white"]).any(axis=(1, 3)).sum())

    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(binary, tmp, prefix=["estimate", "--canonical", canonical])

        def estimate_json(path, *extra):
            rc, out, err = r.run("--json", *extra, path)
            expect(rc == 0 and err == "", (rc, err))
            return json.loads(out)

        def independent_facts():
            expect(decoded["pattern"] == "RGGB" and decoded["black"] == [2056] and decoded["white"] == 15000
                   and decoded["bits"] == 14 and m.shape == (1156, 1734), decoded)
            expect(decoded["make"] == "Canon" and decoded["model"] == "Canon EOS Kiss X4", decoded)

        def json_reports_the_levels():
            doc = estimate_json(dng)
            image = doc["images"][0]
            expect(image["raw"] == {"camera": "Canon EOS Kiss X4", "pattern": "RGGB", "black": [2056] * 4,
                                    "black_from": "file", "white": 15000, "white_from": "file",
                                    "saturated_quads": saturated}, image["raw"])
            expect(image["pixels"]["saturated"] == saturated, (saturated, image["pixels"]))  # 0: its largest code is 12128
            expect(image["pixels"]["total"] == 867 * 578 and (image["width"], image["height"]) == (867, 578), image)
            levels = doc["provenance"]["image_levels"]
            expect(levels == [{"path": dng, "black_level": [2056] * 4, "black_from": "file", "saturation": 15000,
                               "saturation_from": "file"}], levels)

        def given_levels_are_reported_as_given():
            doc = estimate_json(dng, "--black-level", "2048", "--saturation", "8000")
            raw = doc["images"][0]["raw"]
            expect(raw["black"] == [2048] * 4 and raw["black_from"] == "given" and raw["white"] == 8000
                   and raw["white_from"] == "given", raw)
            expect(raw["saturated_quads"] == int((quads >= 8000).any(axis=(1, 3)).sum()) > 0, raw)

        def text_reports_the_levels():
            rc, out, err = r.run(dng)
            expect(rc == 0, err)
            line = (f"  raw: Canon EOS Kiss X4, RGGB, black 2056 2056 2056 2056 (the file's), white 15000 "
                    f"(the file's), {saturated} quads saturated\n")
            expect(line in out, out)

        def routed_by_content_and_extension():
            want = estimate_json(dng)["images"][0]["raw"]
            for name in ("chart.tif", "chart.TIFF", "chart.crw", "chart.raw", "chart.fff", "chart"):
                path = os.path.join(tmp, name)
                shutil.copy(dng, path)
                got = estimate_json(path)["images"][0].get("raw")
                expect(got == want, (name, got))

        def truncated_file_refused():
            path = os.path.join(tmp, "truncated.dng")
            with open(path, "wb") as f:
                f.write(raw_bytes[:2000000])
            rc, out, err = r.run(path)
            expect(rc == 2 and out == "" and err.count("\n") == 1, (rc, out, err))
            expect(path in err and "LibRaw" in err, err)
            expect("unexpected end of file" in err or "data corrupted" in err, err)

        def vc5_named():
            # The raw IFD's Compression entry set to 9, as GoPro's GPR files have it.
            b = bytearray(raw_bytes)
            ifds_seen = 0
            order = "<" if b[:2] == b"II" else ">"
            todo = [struct.unpack(order + "I", b[4:8])[0]]
            while todo:
                at = todo.pop()
                if at == 0:
                    continue
                n = struct.unpack(order + "H", b[at:at + 2])[0]
                entries = {}
                for k in range(n):
                    e = at + 2 + 12 * k
                    tag, typ, count = struct.unpack(order + "HHI", b[e:e + 8])
                    entries[tag] = e
                    if tag == 330:
                        todo += list(struct.unpack(order + "I" * count, b[e + 8:e + 12])) if count == 1 else []
                e262 = entries.get(262)
                if e262 and struct.unpack(order + "H", b[e262 + 8:e262 + 10])[0] == 32803:
                    b[entries[259] + 8:entries[259] + 10] = struct.pack(order + "H", 9)
                    ifds_seen += 1
                todo.append(struct.unpack(order + "I", b[at + 2 + 12 * n:at + 6 + 12 * n])[0])
            expect(ifds_seen == 1, ifds_seen)
            path = os.path.join(tmp, "GOPR0001.GPR")
            with open(path, "wb") as f:
                f.write(bytes(b))
            rc, out, err = r.run(path)
            expect(rc == 2 and out == "" and err.count("\n") == 1 and path in err, (rc, err))
            expect("VC-5" in err and "GPR" in err, err)

        def verify_script_passes():
            folder = os.path.join(tmp, "real")
            os.makedirs(folder)
            shutil.copy(dng, folder)
            p = subprocess.run([sys.executable, os.path.join(scripts, "verify-datasets"), "--gmcc", binary, folder],
                               capture_output=True, text=True, timeout=600)
            expect(p.returncode == 0 and "ok    " in p.stdout and "every check held" in p.stdout,
                   (p.returncode, p.stdout, p.stderr))

        r.check_all(independent_facts, json_reports_the_levels, given_levels_are_reported_as_given,
                    text_reports_the_levels, routed_by_content_and_extension, truncated_file_refused, vc5_named,
                    verify_script_passes)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
