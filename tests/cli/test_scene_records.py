#!/usr/bin/env python3
"""`gmcc reproduce --scenes-out`, the statistics and `--shard` + `gmcc merge` end to end.

1. The scene generator, regenerated in Python from docs/reproduction.md "Scene generator"
   alone (seed words, std::seed_seq, MT19937-64, Lemire's sampler, the partial Fisher-Yates
   draw), must give every scene's `drawn` surfaces, scene by scene, for the synthetic and the
   camera experiment, with a seed above 2^32.
2. Every CSV statistic of a run, recomputed in Python (statistics, exact sums) from its per-scene records following
   docs/reproduction.md "Statistics", must match the CSV's 6 decimals.
3. A reduced run whole and in 3 shards merged by `gmcc merge` must give the same bytes: records,
   CSV, JSON, table and plot data; and the records must not depend on --threads.
4. Bad shards and merges: exit 2, a message, nothing written.

usage: test_scene_records.py GMCC_BINARY     (ends with a line 'N passed, N failed')
"""
import csv
import io
import json
import os
import sys
import tempfile

import math
import statistics

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_harness import Runner, expect  # noqa: E402

M32, M64 = (1 << 32) - 1, (1 << 64) - 1


# --- docs/reproduction.md "Scene generator", step by step -----------------------------------

def seed_words(S, light, n, s):  # step 1
    return [S & M32, S >> 32, light, n, s & M32, s >> 32]


def seed_sequence(v, N=624):  # step 2
    a = [0x8B8B8B8B] * N
    L, t = len(v), 11
    p = (N - t) // 2
    q = p + t
    M = max(L + 1, N)

    def T(x):
        return x ^ (x >> 27)

    for k in range(M):
        r1 = (1664525 * T(a[k % N] ^ a[(k + p) % N] ^ a[(k - 1) % N])) & M32
        if k == 0:
            r2 = r1 + L
        elif k <= L:
            r2 = r1 + (k % N) + v[k - 1]
        else:
            r2 = r1 + (k % N)
        r2 &= M32
        a[(k + p) % N] = (a[(k + p) % N] + r1) & M32
        a[(k + q) % N] = (a[(k + q) % N] + r2) & M32
        a[k % N] = r2
    for k in range(M, M + N):
        r3 = (1566083941 * T((a[k % N] + a[(k + p) % N] + a[(k - 1) % N]) & M32)) & M32
        r4 = (r3 - (k % N)) & M32
        a[(k + p) % N] ^= r3
        a[(k + q) % N] ^= r4
        a[k % N] = r4
    return a


class MT19937_64:  # step 3
    def __init__(self, a):
        self.x = [a[2 * i] | (a[2 * i + 1] << 32) for i in range(312)]
        if (self.x[0] & 0xFFFFFFFF80000000) == 0 and not any(self.x[1:]):
            self.x[0] = 1 << 63
        self.j = 312  # a twist before the first output

    def twist(self):
        x = self.x
        for i in range(312):
            y = (x[i] & 0xFFFFFFFF80000000) | (x[(i + 1) % 312] & 0x7FFFFFFF)
            x[i] = x[(i + 156) % 312] ^ (y >> 1) ^ (0xB5026F5AA96619E9 if y & 1 else 0)
        self.j = 0

    def __call__(self):
        if self.j == 312:
            self.twist()
        z = self.x[self.j]
        self.j += 1
        z ^= (z >> 29) & 0x5555555555555555
        z ^= (z << 17) & 0x71D67FFFEDA60000 & M64
        z ^= (z << 37) & 0xFFF7EEE000000000 & M64
        z ^= z >> 43
        return z


def below(g, m):  # step 4
    P = g() * m
    if P & M64 < m:
        u = ((1 << 64) - m) % m
        while P & M64 < u:
            P = g() * m
    return P >> 64


def draw(S, light, n, s, K):  # step 5
    g = MT19937_64(seed_sequence(seed_words(S, light, n, s)))
    pool = list(range(K))
    for i in range(n):
        j = i + below(g, K - i)
        pool[i], pool[j] = pool[j], pool[i]
    return pool[:n]


# --- docs/reproduction.md "Statistics" --------------------------------------------------------

def quantile(x, p):
    h = (len(x) - 1) * p
    i = math.floor(h)
    f = h - i
    return x[i] if f == 0 or i + 1 >= len(x) else (1 - f) * x[i] + f * x[i + 1]


def stats(values):
    if not values:
        return dict.fromkeys(("mean", "se", "median", "trimean", "best25", "worst25", "p95", "max"), 0.0)
    x = sorted(values)
    q = -(-len(x) // 4)
    # statistics.fmean and stdev sum exactly (another route than gmcc's double sums)
    return {"mean": statistics.fmean(values),
            "se": statistics.stdev(values) / math.sqrt(len(values)) if len(values) > 1 else float("nan"),
            "median": quantile(x, 0.5), "trimean": (quantile(x, 0.25) + 2 * quantile(x, 0.5) + quantile(x, 0.75)) / 4,
            "best25": statistics.fmean(x[:q]), "worst25": statistics.fmean(x[-q:]),
            "p95": quantile(x, 0.95), "max": x[-1]}


def lines(path):
    """The records of a --scenes-out file, after its provenance line (checked here)."""
    with open(path) as f:
        records = [json.loads(line) for line in f]
    expect(list(records[0]) == ["provenance"], f"{path}: the first line is not the provenance")
    check_provenance(records[0]["provenance"])
    return records[1:]


def check_provenance(p):
    expect(p["software"] == "gmcc" and p["command"].startswith("reproduce ") and "--seed" in p["options"],
           f"provenance {p}")
    for name in ("--threads", "--shard", "--scenes-out", "--csv", "--json", "--plot"):
        expect(name not in p["options"], f"{name} is recorded in the provenance")


def read_csv(path):
    with open(path) as f:
        first = f.readline()
        expect(first.startswith("# gmcc-provenance: "), f"{path}: no provenance line")
        check_provenance(json.loads(first[len("# gmcc-provenance: "):]))
        return list(csv.DictReader(f))


def main():
    gmcc = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(gmcc, tmp, prefix=("reproduce",), timeout=600)
        merge = Runner(gmcc, tmp, prefix=("merge",), timeout=600)
        p = lambda name: os.path.join(tmp, name)  # noqa: E731

        seed = 12345678901  # above 2^32: both seed words matter
        run_args = ["--scenes", "4", "--surfaces", "6", "--seed", str(seed)]

        def regenerate(experiment, K, extra):
            rc, out, err = r.run(experiment, *run_args, *extra, "--scenes-out", p(experiment + ".jsonl"))
            expect(rc == 0, f"{experiment}: exit {rc}: {err}")
            records = lines(p(experiment + ".jsonl"))
            setup, scenes = records[0], records[1:]
            expect(setup["surface_indices"] == "0-based" and setup["seed"] == seed, "the setup line")
            expect(len(scenes) == len(setup["lights"]) * 6 * 4, "one record per scene")
            order = [(x["light_index"], x["surfaces"], x["scene"]) for x in scenes]
            expect(order == sorted(order), "records in canonical order")
            for x in scenes:
                mine = draw(seed, x["light_index"], x["surfaces"], x["scene"], K)
                where = (x["light_index"], x["surfaces"], x["scene"])
                expect(mine == x["drawn"], f"{experiment} scene {where}: Python {mine}, gmcc {x['drawn']}")
                expect(len(set(x["drawn"])) == x["surfaces"] and max(x["drawn"]) < K, "n distinct surfaces")

        r.check("synthetic scenes regenerated from the docs",
                lambda: regenerate("synthetic", 1269, ["--lights", "D75,P2856,P15000"]))
        r.check("camera scenes regenerated from the docs", lambda: regenerate("camera", 24, []))
        r.check("a known draw (seed 1, D75, n = 3, scene 0) by the generator alone",
                lambda: expect(draw(1, 0, 3, 0, 1269) == draw(1, 0, 3, 0, 1269) and
                               draw(1, 0, 1, 0, 1269) == [452], draw(1, 0, 1, 0, 1269)))

        def statistics_from_records():
            rc, _, err = r.run("camera", "--scenes", "9", "--surfaces", "4", "--noise", "0.05",
                               "--scenes-out", p("st.jsonl"), "--csv", p("st.csv"))
            expect(rc == 0, err)
            recs = lines(p("st.jsonl"))
            setup, scenes = recs[0], recs[1:]
            rows = read_csv(p("st.csv"))
            expect(len(rows) == len(setup["lights"]) * 4 * len(setup["rules"]), "one row per cell and rule")
            names = {"error": "error_deg", "worst_case": "worst_case_deg",
                     "illuminant_error": "illuminant_error_deg", "reproduction_error": "reproduction_error_deg"}
            checked = 0
            for row in rows:
                cell = [x for x in scenes if x["light"] == row["illuminant"] and x["surfaces"] == int(row["surfaces"])]
                scored = [x["rules"][row["rule"]] for x in cell if x["rules"] and x["rules"][row["rule"]]]
                expect(int(row["empty_scenes"]) == sum(1 for x in cell if x["rules"] is None), "empty scenes")
                expect(int(row["positive_map_scenes"]) == sum(1 for y in scored if y["illuminant_error_deg"] is not None),
                       "positive maps")
                for q, member in names.items():
                    values = [y[member] for y in scored if y[member] is not None]
                    st = stats(values)
                    for k, v in st.items():
                        col = f"{k}_{q}_deg"
                        if col not in row:
                            continue
                        got = row[col]
                        if math.isnan(v):
                            expect(got == "", f"{col}: {got!r}, expected an empty field")
                        else:
                            expect(abs(float(got) - v) <= 1.5e-6, f"{row['illuminant']} n={row['surfaces']} "
                                   f"{row['rule']} {col}: CSV {got}, records {v:.9f}")
                        checked += 1
            expect(checked == len(rows) * 32, f"every statistic column checked ({checked})")
        r.check("every CSV statistic recomputed from the records", statistics_from_records)

        def shards_merge_to_the_whole():
            base = ["synthetic", "--scenes", "5", "--surfaces", "4", "--seed", "3", "--lights", "D75,P2856"]
            rc, whole_out, err = r.run(*base, "--threads", "2", "--scenes-out", p("w.jsonl"), "--csv", p("w.csv"),
                                       "--json", p("w.json"), "--plot", p("wplot"))
            expect(rc == 0, err)
            for k in (1, 2, 3):
                rc, out, err = r.run(*base, "--threads", "1", "--shard", f"{k}/3", "--scenes-out", p(f"s{k}.jsonl"))
                expect(rc == 0 and f"shard {k}/3" in out, err)
            counts = [len(lines(p(f"s{k}.jsonl"))) - 1 for k in (1, 2, 3)]
            expect(counts == [13, 13, 14], f"40 scenes in parts of 13, 13, 14: {counts}")
            rc, merged_out, err = merge.run(p("s3.jsonl"), p("s1.jsonl"), p("s2.jsonl"), "--scenes-out", p("m.jsonl"),
                                            "--csv", p("m.csv"), "--json", p("m.json"), "--plot", p("mplot"))
            expect(rc == 0, err)
            expect(merged_out == whole_out, "the table on stdout")
            for a, b in (("w.jsonl", "m.jsonl"), ("w.csv", "m.csv"), ("w.json", "m.json"),
                         ("wplot/synthetic.dat", "mplot/synthetic.dat"), ("wplot/synthetic.gp", "mplot/synthetic.gp")):
                expect(open(p(a), "rb").read() == open(p(b), "rb").read(), f"{b} differs from {a}")
            json.load(open(p("w.json")))  # one JSON document
        r.check("3 shards merged = the whole run, byte for byte", shards_merge_to_the_whole)

        def seed_claim_options_merge():
            # The seed-claim conditions (docs/reproduction.md §5b) round-trip through the setup line:
            # 2 shards merged give the whole run's bytes, and the members are there.
            base = ["synthetic", "--scenes", "1", "--surfaces", "2", "--lights", "D75", "--crule",
                    "--crule-extended", "--crule-black", "exclude", "--specular", "0.3", "--intensity", "2"]
            rc, whole_out, err = r.run(*base, "--scenes-out", p("cw.jsonl"), "--csv", p("cw.csv"))
            expect(rc == 0, err)
            for k in (1, 2):
                rc, out, err = r.run(*base, "--shard", f"{k}/2", "--scenes-out", p(f"cs{k}.jsonl"))
                expect(rc == 0, err)
            rc, merged_out, err = merge.run(p("cs2.jsonl"), p("cs1.jsonl"), "--scenes-out", p("cm.jsonl"),
                                            "--csv", p("cm.csv"))
            expect(rc == 0, err)
            expect(merged_out == whole_out, "the table on stdout")
            for a, b in (("cw.jsonl", "cm.jsonl"), ("cw.csv", "cm.csv")):
                expect(open(p(a), "rb").read() == open(p(b), "rb").read(), f"{b} differs from {a}")
            setup = lines(p("cw.jsonl"))[0]
            expect(setup["crule_black"] == "exclude" and setup["crule_extended"] is True and
                   setup["specular"] == 0.3 and setup["intensity"] == 2, f"the setup line: {setup}")
            expect(setup["rules"][-2:] == ["crule_max_trace", "crule_cone_mean"], "the extended rules")
        r.check("seed-claim options survive shards and merge", seed_claim_options_merge)

        def threads_do_not_matter():
            for t in ("1", "2"):
                rc, _, err = r.run("synthetic", "--scenes", "3", "--surfaces", "5", "--threads", t,
                                   "--scenes-out", p(f"t{t}.jsonl"))
                expect(rc == 0, err)
            expect(open(p("t1.jsonl"), "rb").read() == open(p("t2.jsonl"), "rb").read(), "records differ by --threads")
        r.check("records identical for 1 and 2 threads", threads_do_not_matter)

        def expansion_outputs():
            rc, _, err = r.run("expansion", "--scenes", "2", "--surfaces", "3", "--csv", p("e.csv"),
                               "--scenes-out", p("e.jsonl"))
            expect(rc == 0, err)
            rows = read_csv(p("e.csv"))
            expect(len(rows) == 3 * 4 * 3 * 3, f"rows per (expansion, light, n, rule): {len(rows)}")
            expect({(x["expansion_policy"], x["expansion_factor"]) for x in rows} ==
                   {("none", "0"), ("centroid-clip", "1/10"), ("multiplicative", "1/10")}, "the three expansions")
            recs = lines(p("e.jsonl"))
            setups = [i for i, x in enumerate(recs) if "format" in x]
            expect(setups == [0, 25, 50], f"a setup line per run: {setups}")
            # The scenes do not depend on the expansion (docs: Scene generator).
            expect([x["drawn"] for x in recs[1:25]] == [x["drawn"] for x in recs[26:50]] ==
                   [x["drawn"] for x in recs[51:75]], "same scenes under every expansion")
        r.check("expansion --csv and --scenes-out", expansion_outputs)

        def json_aggregates():
            doc = json.load(open(p("w.json")))
            expect(list(doc)[:2] == ["provenance", "setup"], list(doc)[:3])
            check_provenance(doc["provenance"])
            rows = read_csv(p("w.csv"))
            expect(doc["setup"]["experiment"] == "synthetic" and len(doc["cells"]) == 2 * 4, "setup and cells")
            for row in rows:
                cell = [c for c in doc["cells"] if c["light"] == row["illuminant"] and c["surfaces"] == int(row["surfaces"])]
                st = cell[0]["rules"][row["rule"]]
                for q in ("error", "worst_case", "illuminant_error", "reproduction_error"):
                    for k in ("mean", "se", "median", "trimean", "best25", "worst25", "p95", "max"):
                        col = f"{k}_{q}_deg"
                        expect(f"{float(st[q + '_deg'][k]):.6f}" == row[col], f"JSON {q}.{k} vs CSV {col}")
        r.check("JSON aggregates agree with the CSV", json_aggregates)

        def one_scene():
            rc, out, err = r.run("synthetic", "--scenes", "1", "--surfaces", "2", "--csv", p("one.csv"))
            expect(rc == 0 and "nan" not in out, err)
            for row in read_csv(p("one.csv")):
                expect(row["se_error_deg"] == "" and row["mean_error_deg"] == row["median_error_deg"] ==
                       row["trimean_error_deg"] == row["best25_error_deg"] == row["p95_error_deg"], row)
        r.check("one scene per cell: no standard error, every quantile the value", one_scene)

        def bad(runner, args, words):
            before = set(os.listdir(tmp))
            rc, out, err = runner.run(*args)
            expect(rc == 2 and out == "" and "gmcc: error:" in err and all(w in err for w in words),
                   f"{args}: exit {rc}, stderr {err!r}")
            expect(set(os.listdir(tmp)) == before, f"{args}: something was written")

        small = ["synthetic", "--scenes", "2", "--surfaces", "2"]
        for args, words in [(small + ["--shard", "2/3"], ["--scenes-out"]),
                            (small + ["--shard", "0/3", "--scenes-out", p("x")], ["--shard"]),
                            (small + ["--shard", "4/3", "--scenes-out", p("x")], ["--shard"]),
                            (small + ["--shard", "a/b", "--scenes-out", p("x")], ["--shard"]),
                            (small + ["--shard", "1/2", "--scenes-out", p("x"), "--csv", p("y")], ["--csv", "merge"])]:
            r.check(f"rejected: {' '.join(args[5:])}", lambda a=args, w=words: bad(r, a, w))

        def merge_errors():
            rc, _, err = r.run(*small, "--seed", "5", "--shard", "1/2", "--scenes-out", p("other.jsonl"))
            expect(rc == 0, err)
            bad(merge, [p("s1.jsonl"), p("s2.jsonl"), "--csv", p("out.csv")], ["none of the files", "missing"])
            bad(merge, [p("s1.jsonl"), p("s2.jsonl"), p("s3.jsonl"), p("s2.jsonl"), "--csv", p("out.csv")],
                ["already in"])
            bad(merge, [p("s1.jsonl"), p("other.jsonl"), "--csv", p("out.csv")], ["another run"])
            with open(p("broken.jsonl"), "w") as f:
                f.write(open(p("s1.jsonl")).read().replace('"drawn":[', '"drawn":[1,', 1))
            bad(merge, [p("broken.jsonl"), p("s2.jsonl"), p("s3.jsonl")], ["broken.jsonl:3:"])
            bad(merge, [p("no-such-file.jsonl")], ["no-such-file"])
            # reproduce expansion's file holds three runs: refused at the second setup line, not
            # with a missing member of a scene record.
            rc, _, err = r.run("expansion", "--scenes", "1", "--surfaces", "2", "--scenes-out", p("expansion.jsonl"))
            expect(rc == 0, err)
            bad(merge, [p("expansion.jsonl"), "--csv", p("out.csv")], ["a second setup line", "one run"])
            # A part whose provenance names another build or other data is refused; another path
            # to the same data is not.
            for text, ok in (('"commit":"', False), ('"sha256":"', False), ('"path":"', True)):
                with open(p("s2.jsonl")) as f:
                    lines = f.read().split("\n")
                lines[0] = lines[0].replace(text, text + "0", 1)
                with open(p("foreign.jsonl"), "w") as f:
                    f.write("\n".join(lines))
                if ok:
                    rc, _, err = merge.run(p("s1.jsonl"), p("foreign.jsonl"), p("s3.jsonl"), "--csv", p("ok.csv"))
                    expect(rc == 0, err)
                    os.remove(p("ok.csv"))
                else:
                    bad(merge, [p("s1.jsonl"), p("foreign.jsonl"), p("s3.jsonl"), "--csv", p("out.csv")],
                        ["foreign.jsonl:1:", "provenance"])
        r.check("merge refuses missing, repeated, foreign and broken parts", merge_errors)

        print(f"{r.passed + merge.passed} passed, {r.failed + merge.failed} failed")
        return 1 if r.failed + merge.failed else 0


if __name__ == "__main__":
    sys.exit(main())
