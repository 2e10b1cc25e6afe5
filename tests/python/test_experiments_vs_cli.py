"""gmcc.reproduce_synthetic / reproduce_camera against `gmcc reproduce ... --scenes-out`: the
same seeded scenes, record by record (surfaces drawn, F's kind and area, every rule's map and
errors, bit for bit)."""

import json

import numpy as np
import pytest

import gmcc

FIELDS = ("map", "error_deg", "worst_case_deg", "illuminant_error_deg", "reproduction_error_deg")


def cli_records(cli, tmp_path, *args):
    out = tmp_path / "scenes.jsonl"
    cli("reproduce", *args, "--scenes-out", out)
    lines = [json.loads(line) for line in out.read_text().splitlines()]
    return lines[1], lines[2:]


def compare(records, setup, scenes):
    assert len(records) == len(scenes)
    for rec, s in zip(records, scenes):
        assert rec["light"] == s["light"] and rec["surfaces"] == s["surfaces"] and rec["scene"] == s["scene"]
        assert rec["drawn"] == " ".join(map(str, s["drawn"]))
        assert rec["kind"] == s["feasible_set"]["kind"]
        assert rec["area"] == s["feasible_set"]["area"]
        for rule in setup["rules"]:
            theirs = (s["rules"] or {}).get(rule)
            if theirs is None:
                assert np.isnan(rec[rule + "_error_deg"])
                continue
            assert [rec[rule + "_map_x"], rec[rule + "_map_y"]] == theirs["map"]
            for f in FIELDS[1:]:
                want = theirs[f]
                got = rec[rule + "_" + f]
                assert (np.isnan(got) if want is None else got == want), (rule, f)


def test_synthetic_records_match_cli(cli, tmp_path):
    setup, scenes = cli_records(cli, tmp_path, "synthetic", "--scenes", "6", "--surfaces", "4", "--seed", "5",
                                "--lights", "D75", "P2856", "--expand", "0.1", "--expand-policy", "multiplicative")
    records = gmcc.reproduce_synthetic(lights=("D75", "P2856"), max_surfaces=4, scenes=6, seed=5,
                                       expand="0.1", expand_policy="multiplicative", frame=False)
    compare(records, setup, scenes)


def test_camera_records_match_cli(cli, tmp_path):
    setup, scenes = cli_records(cli, tmp_path, "camera", "--scenes", "5", "--surfaces", "3", "--seed", "2")
    records = gmcc.reproduce_camera(max_surfaces=3, scenes=5, seed=2, frame=False)
    compare(records, setup, scenes)
    assert set(records["light"]) == set(setup["lights"])


def test_bad_experiment_options():
    with pytest.raises(ValueError, match="unknown|light"):
        gmcc.reproduce_synthetic(lights=("D5000000",), scenes=1, max_surfaces=1)
    with pytest.raises(ValueError, match="canonical_surfaces"):
        gmcc.reproduce_camera(canonical_surfaces="paint", scenes=1, max_surfaces=1)
    with pytest.raises(ValueError, match="surfaces"):
        gmcc.reproduce_synthetic(min_surfaces=3, max_surfaces=2, scenes=1)


@pytest.mark.parametrize("kw, exc, word", [
    ({"scenes": -1}, ValueError, "scenes"), ({"scenes": 0}, ValueError, "scenes"),
    ({"scenes": 10**7}, ValueError, "scenes"), ({"seed": -1}, ValueError, "seed"),
    ({"threads": -2}, ValueError, "threads"), ({"scenes": 1.5}, TypeError, "scenes"),
    ({"max_surfaces": True}, TypeError, "max_surfaces"),
    # 2 lights x 11 surface counts x 200,000 scenes = 4.4e6 records: more than Python keeps.
    ({"lights": ("D75", "D100"), "scenes": 200000}, ValueError, "4400000 scene records")])
def test_counts_out_of_range_name_the_argument(kw, exc, word):
    # Issue 30: a negative count got pybind's signature dump; now the argument and its range.
    for run in (gmcc.reproduce_synthetic, gmcc.reproduce_camera):
        with pytest.raises(exc, match=word) as info:
            run(**kw)
        assert "incompatible function arguments" not in str(info.value)
