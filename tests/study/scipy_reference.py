#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference values for vv::study's statistics from an independent
implementation (Debian's python3-scipy), on random data from SEED.

    scipy_reference.py SEED OUT.txt

One case per line, space-separated (tests/study/StatisticsTest.cpp reads
them):
    friedman N K <N*K values, row by row> CHI2 P
    binom_greater CORRECT ANSWERS P            (one-sided, chance 1/2)
    mean_ci N <N values> LOW HIGH              (95 %, Student's t)
    median_ci N L COVERAGE                     ([x(L), x(N+1-L)], 95 %)
    norm_two_sided Z P
tests/study/data/scipy_reference.txt was made with SEED 1; the test runs
this script with SEED 2 when python3 with scipy is there.
"""
import sys

import numpy as np
from scipy import stats


def main():
    seed, out = int(sys.argv[1]), sys.argv[2]
    rng = np.random.default_rng(seed)
    lines = [f"# scipy {__import__('scipy').__version__}, seed {seed}"]
    for n, k, ties in [(5, 3, False), (12, 5, False), (20, 5, True), (8, 2, True),
                       (30, 4, True), (3, 6, False), (40, 5, False)]:
        data = rng.normal(size=(n, k)) + np.linspace(0.0, 0.6, k)
        if ties:
            data = np.round(data * 2.0) / 2.0
        chi2, p = stats.friedmanchisquare(*data.T) if k > 2 else friedman_two(data)
        values = " ".join(repr(float(v)) for v in data.ravel())
        lines.append(f"friedman {n} {k} {values} {chi2!r} {p!r}")
    for answers in [10, 40, 150]:
        for correct in sorted({answers // 2, int(answers * 0.6), int(answers * 0.75), answers}):
            p = stats.binomtest(correct, answers, 0.5, alternative="greater").pvalue
            lines.append(f"binom_greater {correct} {answers} {p!r}")
    for n in [2, 5, 20]:
        values = rng.normal(loc=1.5, scale=0.4, size=n)
        low, high = stats.t.interval(0.95, n - 1, loc=values.mean(), scale=stats.sem(values))
        text = " ".join(repr(float(v)) for v in values)
        lines.append(f"mean_ci {n} {text} {low!r} {high!r}")
    for n in [6, 9, 20, 50, 150]:
        best = 1
        for l in range(1, (n + 1) // 2 + 1):
            if 1.0 - 2.0 * stats.binom.cdf(l - 1, n, 0.5) >= 0.95:
                best = l
        coverage = 1.0 - 2.0 * stats.binom.cdf(best - 1, n, 0.5)
        lines.append(f"median_ci {n} {best} {coverage!r}")
    for z in [0.0, 1.0, 1.959963984540054, 2.807033768343811, 4.5]:
        lines.append(f"norm_two_sided {z!r} {2.0 * stats.norm.sf(z)!r}")
    with open(out, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def friedman_two(data):
    """scipy's friedmanchisquare needs three groups; the same statistic for two."""
    ranks = np.apply_along_axis(stats.rankdata, 1, data)
    n, k = data.shape
    sums = ranks.sum(axis=0)
    ties = 0.0
    for row in data:
        _, counts = np.unique(row, return_counts=True)
        ties += float((counts ** 3 - counts).sum())
    spread = float(((sums - n * (k + 1) / 2.0) ** 2).sum())
    denominator = n * k * (k + 1) - ties / (k - 1)
    chi2 = 12.0 * spread / denominator if denominator > 0 and spread > 0 else 0.0
    return chi2, float(stats.chi2.sf(chi2, k - 1)) if chi2 > 0 else 1.0


if __name__ == "__main__":
    main()
