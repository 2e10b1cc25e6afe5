"""gmcc.reproduce_gehler_shi: the same scenes, record by record and bit for bit, as `gmcc reproduce
gehler-shi --scenes-out` with the same options, and the same cell statistics as its --json (via
gmcc.summarise); and, without the command line, the records against the shipped data read here
independently: which images are tested, how many scenes each draws at each patch count, which
patches a scene may draw, and the baselines' maps and errors recomputed from the drawn patches."""

import json
import math
from collections import Counter, defaultdict
from fractions import Fraction

import numpy as np
import pytest

import gmcc
from conftest import DATA

RULES = ("max_area", "mean_2d", "mean_3d")
BASELINES = ("grey_world", "max_rgb")
STATISTICS = ("mean", "median", "trimean", "best25", "worst25", "p95", "max")


def read_data():
    """(images in file order as (name, camera, truth r,g,b as floats, tau), patches
    {name: {patch: (r, g, b) as Fractions}}) from the shipped CSV files."""
    images = []
    for line in (DATA / "gehler_shi_568_groundtruth.csv").read_text().splitlines()[1:]:
        f = line.split(",")
        e = tuple(float(x) for x in f[6:9])
        images.append((f[1], f[2], e, math.log2(e[2] / e[0])))
    patches = defaultdict(dict)
    for line in (DATA / "gehler_shi_568_colorchecker_patch_rgb_rec2018.csv").read_text().splitlines()[1:]:
        f = line.split(",")
        if f[3].lower() == "nan":
            continue
        patches[f[1]][int(f[2])] = tuple(Fraction(x) for x in f[3:6])
    return images, patches


IMAGES, PATCHES = read_data()


def usable(name, dark=Fraction(1, 500), clip=Fraction(19, 20), exclude=()):
    """The patch numbers of an image whose every channel lies strictly between dark and clip."""
    return [k for k, c in sorted(PATCHES[name].items()) if k not in exclude and all(dark < x < clip for x in c)]


def angle_deg(u, v):
    u, v = np.asarray(u, float), np.asarray(v, float)
    return float(np.degrees(np.arctan2(np.linalg.norm(np.cross(u, v)), u @ v)))


def test_records_match_the_command_line(cli, tmp_path):
    args = ["--cameras", "Canon1D", "--scenes", "2", "--surfaces", "4", "--seed", "7", "--protocol", "paper",
            "--expand", "0.05", "--expand-policy", "multiplicative"]
    out, js = tmp_path / "scenes.jsonl", tmp_path / "cells.json"
    cli("reproduce", "gehler-shi", *args, "--scenes-out", out, f"--json={js}")  # the fixture parses stdout after "--json"
    lines = [json.loads(line) for line in out.read_text().splitlines()]
    setup, scenes = lines[1], lines[2:]
    records = gmcc.reproduce_gehler_shi(cameras=("Canon1D",), scenes=2, max_surfaces=4, seed=7, protocol="paper",
                                        expand="0.05", expand_policy="multiplicative", frame=False)
    assert setup["experiment"] == "gehler-shi"
    assert len(records) == len(scenes) > 100
    for rec, s in zip(records, scenes):
        assert (rec["light"], rec["surfaces"], rec["scene"]) == (s["light"], s["surfaces"], s["scene"])
        assert rec["drawn"] == " ".join(map(str, s["drawn"]))
        assert rec["kind"] == s["feasible_set"]["kind"] and rec["area"] == s["feasible_set"]["area"]
        for rule in RULES:
            theirs = (s["rules"] or {}).get(rule)
            if theirs is None:
                assert np.isnan(rec[rule + "_error_deg"]) and not rec[rule + "_truth_in_feasible_set"]
                continue
            assert [rec[rule + "_map_x"], rec[rule + "_map_y"]] == theirs["map"]
            assert rec[rule + "_truth_in_feasible_set"] == theirs["truth_in_feasible_set"]
            for f in ("error_deg", "worst_case_deg", "illuminant_error_deg", "reproduction_error_deg"):
                want, got = theirs[f], rec[rule + "_" + f]
                assert (np.isnan(got) if want is None else got == want), (rule, f)
        for b in BASELINES:
            theirs = s["baselines"][b]
            assert [rec[b + "_map_x"], rec[b + "_map_y"]] == theirs["map"]
            for f in ("error_deg", "illuminant_error_deg", "reproduction_error_deg"):
                assert rec[b + "_" + f] == theirs[f], (b, f)
    # The table's cells are summarise over the records, to the bit: the same values in the same
    # order through the same statistics.
    cells = json.loads(js.read_text())["cells"]
    assert {(c["light"], c["surfaces"]) for c in cells} == {(g, n) for g in ("Canon1D yellowish", "Canon1D bluish")
                                                              for n in range(1, 5)}
    for rule in RULES:
        for error in ("error_deg", "illuminant_error_deg"):
            stats = gmcc.summarise(records, rule, error=error, by=("group", "surfaces"))
            for c in cells:
                mine, theirs = stats[(c["light"], c["surfaces"])], c["rules"][rule][error]
                assert mine.n == theirs["n"]
                for st in STATISTICS:
                    got, want = getattr(mine, st), theirs[st]  # an undefined statistic: NaN, JSON null
                    assert (np.isnan(got) if want is None else got == want), (rule, error, c["light"], c["surfaces"], st)
    for b in BASELINES:
        stats = gmcc.summarise(records, b, error="illuminant_error_deg", by=("group", "surfaces"))
        for c in cells:
            assert stats[(c["light"], c["surfaces"])].median == c["baselines_all"][b]["illuminant_error_deg"]["median"]
    sel = records["group"] == "Canon1D bluish"
    for c in cells:
        here = records[(records["group"] == c["light"]) & (records["surfaces"] == c["surfaces"])]
        assert len(here) == c["scenes"] and int(np.sum(here["kind"] == "empty")) == c["empty_scenes"]
    assert sel.any() and (~sel).any()


def test_leave_one_out_follows_the_data():
    scenes, top = 2, 4
    records = gmcc.reproduce_gehler_shi(cameras="Canon1D", scenes=scenes, max_surfaces=top, seed=3, frame=False)
    canon1d = [im for im in IMAGES if im[1] == "Canon1D"]
    assert len(canon1d) == 86
    # Every image is a test light, in file order, and draws `scenes` scenes at each k it has
    # enough usable patches for.
    assert list(dict.fromkeys(records["light"])) == [im[0] for im in canon1d if usable(im[0])]
    count = Counter(zip(records["light"], records["surfaces"]))
    for name, *_ in canon1d:
        for k in range(1, top + 1):
            assert count[(name, k)] == (scenes if len(usable(name)) >= k else 0), (name, k)
    assert set(records["group"]) == {"Canon1D"}
    truth = {name: e for name, _, e, _ in canon1d}
    for rec in records:
        drawn = [int(x) for x in rec["drawn"].split()]
        assert len(drawn) == len(set(drawn)) == rec["surfaces"]
        assert set(drawn) <= set(usable(rec["light"]))
        # The baselines from the drawn patches, computed here: grey world the mean, max-RGB the
        # per-channel maximum; a light e gives the map (e_b/e_r, e_b/e_g) for the white canonical
        # light, scored against the ground truth's map.
        colours = np.array([[float(x) for x in PATCHES[rec["light"]][k]] for k in drawn])
        e = truth[rec["light"]]
        true_map = (e[2] / e[0], e[2] / e[1], 1)
        for b, est in (("grey_world", colours.mean(axis=0)), ("max_rgb", colours.max(axis=0))):
            m = (est[2] / est[0], est[2] / est[1], 1)
            assert rec[b + "_map_x"] == pytest.approx(m[0], rel=1e-12)
            assert rec[b + "_map_y"] == pytest.approx(m[1], rel=1e-12)
            assert rec[b + "_error_deg"] == pytest.approx(angle_deg(m, true_map), abs=1e-9)
            assert rec[b + "_illuminant_error_deg"] == pytest.approx(angle_deg(est, e), abs=1e-9)
    for rule in RULES:
        err, worst = records[rule + "_error_deg"], records[rule + "_worst_case_deg"]
        answered = records["kind"] != "empty"
        assert np.all(np.isfinite(err[answered])) and np.all(np.isnan(err[~answered]))
        assert np.all(err[answered] >= 0) and np.all(err[answered] <= 180)
        # Where the true map lies in F, no map of F is farther from the rule's map than the
        # worst case: the true map's error is bounded by it.
        inside = records[rule + "_truth_in_feasible_set"]
        assert inside.sum() > 0.9 * answered.sum()
        assert np.all(err[inside] <= worst[inside] * (1 + 1e-12) + 1e-12)


def test_paper_protocol_groups_and_excluded_patches():
    grey_row = (19, 20, 21, 22, 23, 24)
    records = gmcc.reproduce_gehler_shi(cameras=["Canon1D"], protocol="paper", scenes=1, max_surfaces=2,
                                        exclude_patches=grey_row, frame=False)
    assert not {int(x) for d in records["drawn"] for x in d.split()} & set(grey_row)
    # The groups from the ground truth, computed here as docs/reproduction.md §6 defines them:
    # daylight tau >= 0 (with a usable patch), the 3 daylight images nearest its lower median make
    # the canonical chart, yellowish tau < -1/2, bluish tau above that median.
    canon1d = [im for im in IMAGES if im[1] == "Canon1D"]
    daylight = [i for i, im in enumerate(canon1d) if im[3] >= 0 and usable(im[0], exclude=grey_row)]
    taus = sorted(canon1d[i][3] for i in daylight)
    median = taus[(len(taus) - 1) // 2]
    chart = sorted(sorted(daylight, key=lambda i: abs(canon1d[i][3] - median))[:3])
    yellowish = [im[0] for i, im in enumerate(canon1d) if i not in chart and im[3] < -0.5]
    bluish = [im[0] for i, im in enumerate(canon1d) if i not in chart and im[3] > median]
    tested = lambda names: [n for n in names if usable(n, exclude=grey_row)]  # noqa: E731
    assert list(dict.fromkeys(records["light"][records["group"] == "Canon1D yellowish"])) == tested(yellowish)
    assert list(dict.fromkeys(records["light"][records["group"] == "Canon1D bluish"])) == tested(bluish)
    assert len(yellowish) > 10 and len(bluish) > 10


def test_frame_and_options():
    a = gmcc.reproduce_gehler_shi(cameras="Canon1D", scenes=1, max_surfaces=2, frame=False)
    df = gmcc.reproduce_gehler_shi(cameras="Canon1D", scenes=1, max_surfaces=2, frame=True)
    assert list(df.columns) == list(a.dtype.names)
    assert a.dtype.names[:7] == ("light", "group", "surfaces", "scene", "kind", "area", "drawn")
    assert np.array_equal(df["mean_3d_error_deg"].to_numpy(), a["mean_3d_error_deg"], equal_nan=True)
    # The same seed, any thread count: the same records; another seed: other scenes.
    b = gmcc.reproduce_gehler_shi(cameras="Canon1D", scenes=1, max_surfaces=2, threads=1, frame=False)
    c = gmcc.reproduce_gehler_shi(cameras="Canon1D", scenes=1, max_surfaces=2, seed=2, frame=False)
    assert a.tobytes() == b.tobytes()
    assert len(c) == len(a) and list(c["drawn"]) != list(a["drawn"])


@pytest.mark.parametrize("options, message", [
    ({"protocol": "cross"}, "protocol"),
    ({"cameras": ["Canon7D"]}, "unknown camera"),
    ({"cameras": []}, "cameras"),
    ({"dark": "0.5", "clip": "0.4"}, "dark: must be below clip"),
    ({"dark": "-1"}, "dark: must be >= 0"),
    ({"exclude_patches": [25]}, "exclude_patches"),
    ({"max_surfaces": 25}, "max_surfaces"),
    ({"min_surfaces": 3, "max_surfaces": 2}, "surfaces"),
    ({"scenes": 0}, "scenes"),
    ({"expand": "0.1"}, "expand"),
    ({"mean3d": "guess"}, "mean3d"),
])
def test_bad_options_name_the_argument(options, message):
    with pytest.raises(ValueError, match=message):
        gmcc.reproduce_gehler_shi(**{"cameras": ("Canon1D",), "scenes": 1, "max_surfaces": 1, **options})


def test_bad_types_and_data(tmp_path):
    with pytest.raises(TypeError, match="exclude_patches"):
        gmcc.reproduce_gehler_shi(cameras="Canon1D", scenes=1, max_surfaces=1, exclude_patches=["19"])
    with pytest.raises(TypeError, match="scenes"):
        gmcc.reproduce_gehler_shi(cameras="Canon1D", scenes=1.5, max_surfaces=1)
    with pytest.raises(ValueError, match="gehler_shi_568"):
        gmcc.reproduce_gehler_shi(cameras="Canon1D", scenes=1, max_surfaces=1, data=str(tmp_path))
