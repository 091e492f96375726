"""tools/report/compare.py (gdnav compare): paired statistics, pairing rules, NaN metrics and bad input, on synthetic
batch folders. Run by CTest (Tools.Compare) with PYTHONPATH=tools/report."""
import contextlib
import io
import math
import os
import tempfile
import unittest
import warnings

import yaml

import compare


def metrics(index, seed, rot_mean_rad, hor_final_m, short=False, steps=6000):
    """A minimal complete metrics.yaml record; SHORT: a run that ended before the GNSS loss (no finals' %)."""
    nan = float("nan")
    sig = {k: {"mean": 0.01, "std": 0.005, "max": -0.02, "final": 1.5} for k in
           ("yaw_rad", "pitch_rad", "bank_rad", "h_m", "vn_mps", "ve_mps", "cross_m", "along_m")}
    sig["rot_rad"] = {"mean": rot_mean_rad, "std": 0.001, "max": 0.05, "final": 0.01}
    sig["hor_m"] = {"mean": 1.0, "std": 1.0, "max": 2.0, "final": hor_final_m}
    pct = nan if short else 100.0 * hor_final_m / 1000.0
    return {"complete": True, "seed": seed, "run_index": index, "steps": steps, "distance_since_gnss_m": 0.0 if short else 1000.0,
            "final_percent": {"hor": pct, "cross": pct, "along": pct}, "signals": sig}


def make_batch(root, name, seed, values, drawn=None, short=False, steps=6000, first=0):
    """A batch folder: batch.yaml and runs/run_NNNN/metrics.yaml per (rot mean, hor final) of VALUES; DRAWN: the text
    of each run's drawn_scenario.yaml (None: not recorded, as batches of an older gdnav)."""
    path = os.path.join(root, name)
    os.makedirs(os.path.join(path, "runs"), exist_ok=True)
    with open(os.path.join(path, "batch.yaml"), "w") as fh:
        yaml.safe_dump({"scenario": "2", "generator": "paper_scenario2", "seed": seed}, fh)
    for i, (rot, hor) in enumerate(values, start=first):
        d = os.path.join(path, "runs", f"run_{i:04d}")
        os.makedirs(d)
        with open(os.path.join(d, "metrics.yaml"), "w") as fh:
            yaml.safe_dump(metrics(i, seed, rot, hor, short, steps), fh)
        if drawn is not None:
            with open(os.path.join(d, "drawn_scenario.yaml"), "w") as fh:
                fh.write(drawn(i))
    return path


def run(*args):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = compare.main(list(args))
    return code, out.getvalue(), err.getvalue()


class PairedStats(unittest.TestCase):
    def test_wilcoxon_matches_scipy_docs_example(self):
        # scipy.stats.wilcoxon's documentation: Fisher's 15 height differences, two-sided exact p = 0.04126.
        d = [6, 8, 14, 16, 23, 24, 28, 29, 41, -48, 49, 56, 60, -67, 75]
        s = compare.paired_stats([0.0] * len(d), [float(x) for x in d])
        self.assertAlmostEqual(s["p"], 0.041259765625, places=12)
        self.assertEqual(s["n"], 15)
        self.assertEqual(s["better"], 2)  # the two negative differences
        self.assertAlmostEqual(s["mean"], sum(d) / 15.0, places=12)

    def test_mean_and_standard_error_by_hand(self):
        # differences 1, 2, 3: mean 2, sample std 1, s.e. 1/sqrt(3); all positive: exact two-sided p = 2/2^3.
        s = compare.paired_stats([1.0, 1.0, 1.0], [2.0, 3.0, 4.0])
        self.assertAlmostEqual(s["mean"], 2.0)
        self.assertAlmostEqual(s["se"], 1.0 / math.sqrt(3.0))
        self.assertEqual(s["better"], 0)
        self.assertAlmostEqual(s["p"], 0.25)

    def test_zero_differences_take_the_normal_approximation_silently(self):
        # differences 0, 1, 2, 3: zeros dropped ('wilcox'), r+ = 6 of 3 pairs: z = (6 - 3) / sqrt(3.5) -> p = 0.1088.
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            s = compare.paired_stats([1.0] * 4, [1.0, 2.0, 3.0, 4.0])
        self.assertEqual(caught, [])
        self.assertAlmostEqual(s["p"], 2.0 * (1.0 - 0.5 * (1.0 + math.erf(3.0 / math.sqrt(3.5) / math.sqrt(2.0)))),
                               places=12)

    def test_nan_pairs_are_left_out_and_nothing_left_is_nan(self):
        s = compare.paired_stats([1.0, float("nan"), 1.0], [2.0, 5.0, float("nan")])
        self.assertEqual(s["n"], 1)
        self.assertTrue(math.isnan(s["se"]) and math.isnan(s["p"]))
        s = compare.paired_stats([float("nan")] * 3, [1.0, 2.0, 3.0])
        self.assertEqual(s["n"], 0)
        self.assertTrue(math.isnan(s["mean"]))


class Command(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        self.same = lambda i: f"mission: run {i}\n"

    def tearDown(self):
        self.tmp.cleanup()

    def test_tables_and_paired_differences(self):
        base = make_batch(self.root, "base", 4, [(0.002, 10.0), (0.003, 20.0), (0.004, 30.0)], self.same)
        cand = make_batch(self.root, "cand", 4, [(0.001, 11.0), (0.002, 21.0), (0.003, 29.0)], self.same)
        code, out, err = run(base, cand)
        self.assertEqual(code, 0, err)
        self.assertEqual(err, "")
        self.assertIn("| base | mean |", out)  # the paper's tables, labelled by folder
        self.assertIn("## cand against base: paired over 3 runs (runs 0-2)", out)
        # ‖Δr̂‖ run mean: every run 0.001 rad = 0.0573 deg better; exact p of 3 same-sign pairs = 0.25.
        row = next(line for line in out.splitlines() if line.startswith("| ‖Δr̂‖ run mean"))
        self.assertIn("| −0.0573 ± 0.0000 | 3 of 3 | 0.25 |", row)
        row = next(line for line in out.splitlines() if line.startswith("| Δx_hor final [m]"))
        self.assertIn("| 1 of 3 |", row)

    def test_short_runs_give_na(self):
        base = make_batch(self.root, "base", 4, [(0.002, 10.0), (0.003, 20.0)], self.same, short=True)
        cand = make_batch(self.root, "cand", 4, [(0.001, 11.0), (0.002, 21.0)], self.same, short=True)
        code, out, err = run(base, cand, "--labels", "paper,mine")
        self.assertEqual(code, 0, err)
        row = next(line for line in out.splitlines() if line.startswith("| Δx_hor final [%]"))
        self.assertEqual(row, "| Δx_hor final [%] | n/a | n/a | n/a | n/a | n/a |")
        self.assertIn("## mine against paper", out)

    def test_refuses_different_seeds_drawn_scenarios_lengths_and_runs(self):
        base = make_batch(self.root, "base", 4, [(0.002, 10.0)] * 2, self.same)
        for name, seed, drawn, steps, first, words in [
                ("seed5", 5, self.same, 6000, 0, "different seeds (4 and 5, run 0)"),
                ("other", 4, lambda i: f"mission: other {i}\n", 6000, 0, "run 0 drew different scenarios"),
                ("long", 4, self.same, 9000, 0, "different run lengths (steps) (6000 and 9000, run 0)"),
                ("later", 4, self.same, 6000, 5, "no run index in common (runs 0-1 and 5-6)")]:
            cand = make_batch(self.root, name, seed, [(0.002, 10.0)] * 2, drawn, steps=steps, first=first)
            code, out, err = run(base, cand)
            self.assertEqual(code, 2, name)
            self.assertEqual(out, "")
            self.assertEqual(len(err.splitlines()), 1, err)
            self.assertIn("did not fly the same missions: " + words, err)

    def test_older_batches_pair_with_one_warning(self):
        base = make_batch(self.root, "base", 4, [(0.002, 10.0)] * 2, None)
        cand = make_batch(self.root, "cand", 4, [(0.001, 10.0)] * 2, self.same)
        code, out, err = run(base, cand)
        self.assertEqual(code, 0, err)
        self.assertEqual(len(err.splitlines()), 1, err)
        self.assertIn("drawn scenarios could not be checked", err)

    def test_bad_input_is_one_line_and_exit_2(self):
        base = make_batch(self.root, "base", 4, [(0.002, 10.0)], self.same)
        empty = os.path.join(self.root, "empty")
        os.makedirs(os.path.join(empty, "runs"))
        for args, words in [((base, self.root), "is not a gdnav montecarlo batch"),
                            ((base, empty), "no complete run"),
                            ((base, base, "--labels", "a,b,c"), "--labels gives 3 label(s) for 2 batches"),
                            ((base,), "at least one candidate")]:
            code, out, err = run(*args)
            self.assertEqual(code, 2, args)
            self.assertEqual(len(err.splitlines()), 1, err)
            self.assertIn(words, err)

    def test_a_damaged_run_is_named_in_one_line(self):
        # files.yaml (written by gdnav montecarlo when a run ends) records each file's size; a file that has changed
        # since makes the batch refused, the run named.
        base = make_batch(self.root, "base", 4, [(0.002, 10.0), (0.003, 20.0)], self.same)
        cand = make_batch(self.root, "cand", 4, [(0.001, 11.0), (0.002, 21.0)], self.same)
        run1 = os.path.join(cand, "runs", "run_0001")
        with open(os.path.join(run1, "run.h5"), "wb") as fh:
            fh.write(b"x" * 1000)
        with open(os.path.join(run1, "files.yaml"), "w") as fh:
            fh.write('files:\n  "run.h5": {size: 4096, digest: "0"}\n')
        code, out, err = run(base, cand)
        self.assertEqual(code, 2)
        self.assertEqual(err.splitlines(), [f"compare: run 1 ({run1}) is damaged: run.h5 has 1000 bytes, 4096 when "
                                            "the run ended; run the batch's gdnav montecarlo command again to rerun "
                                            "it"])


if __name__ == "__main__":
    unittest.main()
