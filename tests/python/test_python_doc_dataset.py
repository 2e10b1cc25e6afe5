"""docs/python.md's dataset block (```python dataset), run as written on a dataset this test
writes: twelve linear 16-bit PNGs of random surfaces under random lights and their truth table.
The block's one input, the folder, is substituted; then every method must report every image,
with finite errors >= 0, fold by fold as the block's 3 folds put them, and the tables it prints
must name every method. The page's other blocks are run by tests/docs/run_python_doc.py, whose
python_blocks() reads the page here too."""

import ast
import re
import sys

import numpy as np
import pytest

from conftest import REPO

sys.path.insert(0, str(REPO / "tests" / "docs"))
sys.path.insert(0, str(REPO / "tests" / "support"))
from png16 import write_png16  # noqa: E402
from run_python_doc import python_blocks  # noqa: E402

pandas = pytest.importorskip("pandas")  # the block reads its results as DataFrames

PAGE = REPO / "docs" / "python.md"
IMAGES = 12


def dataset_block():
    blocks = [code for info, code in python_blocks(PAGE.read_text(encoding="utf-8")) if info == "dataset"]
    assert len(blocks) == 1, "docs/python.md should hold one ```python dataset block"
    return blocks[0]


def write_dataset(folder):
    """IMAGES images of 8×10 pixels, each of 20 surfaces of a world of 200 under its own light
    (so that no image's surfaces are all in the other folds' gamuts); truths.csv."""
    rng = np.random.default_rng(31)
    world = rng.integers(50, 900, size=(200, 3))
    lines = ["image,r,g,b"]
    for i in range(IMAGES):
        e = rng.integers(3, 60, size=3)
        surfaces = world[rng.choice(200, size=20, replace=False)]
        img = surfaces[rng.integers(0, 20, size=(8, 10))] * e
        write_png16(folder / f"img{i:02d}.png", [[tuple(int(x) for x in px) for px in row] for row in img])
        lines.append(f"img{i:02d}.png,{e[0]},{e[1]},{e[2]}")
    (folder / "truths.csv").write_text("\n".join(lines) + "\n")


def test_the_block_takes_only_the_dataset_folder():
    code = dataset_block()
    tree = ast.parse(code)
    assigned = [t.id for node in ast.walk(tree) if isinstance(node, ast.Assign) for t in node.targets
                if isinstance(t, ast.Name)]
    assert assigned.count("dataset") == 1
    # Its only literal path is the dataset's; everything else it reads is derived from it.
    strings = [n.value for n in ast.walk(tree) if isinstance(n, ast.Constant) and isinstance(n.value, str)]
    assert not [s for s in strings if s.endswith((".png", ".csv")) and s != "truths.csv"]


def test_the_dataset_block_runs(tmp_path, capsys):
    write_dataset(tmp_path)
    code, n = re.subn(r'^dataset = "[^"\n]*"', lambda _: f"dataset = {str(tmp_path)!r}", dataset_block(),
                      flags=re.M)
    assert n == 1, "the block should set its input as: dataset = \"...\""
    namespace = {"__name__": "__doc_example__"}
    exec(compile(code, f"{PAGE} (python dataset block)", "exec"), namespace)
    summary, records = namespace["summary"], namespace["records"]
    printed = capsys.readouterr().out

    methods = list(summary["method"])
    assert len(methods) == len(set(methods)) >= 11  # every gamut method and baseline
    assert set(records["method"]) == set(methods)
    assert (summary["images"] == IMAGES).all()
    for method in methods:
        mine = records[records["method"] == method]
        assert sorted(mine["image"]) == [f"img{i:02d}.png" for i in range(IMAGES)]
        errors = mine["error_deg"].to_numpy(dtype=float)
        assert np.all(np.isfinite(errors)) and np.all(errors >= 0) and np.all(errors <= 180), method
        # --folds 3: the image on data line i is in fold i mod 3.
        assert all(row.fold == int(row.image[3:5]) % 3 for row in mine.itertuples())
        # The summary is over the same records: an image answered by the method, or (a gamut
        # method with an empty F) by grey world's fallback, counted as empty.
        s = summary[summary["method"] == method].iloc[0]
        assert s["answered"] == int(mine["answered"].sum())
        if pandas.notna(s["empty"]):
            assert s["answered"] + s["empty"] == IMAGES
        else:
            assert s["answered"] == IMAGES  # a baseline always answers
        assert s["median_deg"] == pytest.approx(float(np.median(errors)), abs=1e-9)
    for method in methods:
        assert method in printed
    # The gamut methods' table: the share of images with the true light in F is a share.
    gamut = namespace["gamut"]
    assert len(gamut) >= 6 and gamut["truth_in_feasible"].between(0, 1).all()
