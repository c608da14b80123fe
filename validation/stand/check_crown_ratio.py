#!/usr/bin/env python3
"""The live-crown ratio of a run's dominant trees stays in the published range at every written age.

  check_crown_ratio.py TREES.csv [LOW HIGH]

Dominants: the tallest fifth of the living trees (at least one). Their mean live-crown ratio
(1 - crown base / height) must lie in [LOW, HIGH], by default [0.56, 0.85]:
  0.56  relative crown length of the best-growing silver firs (Abies alba) in Poland, >= 56 %; a young dense
        Todomatsu stand at canopy closure had 69 % (validation/stand/sources.md, section 2);
  0.85  our bound, not published: an open-grown conifer's crown reaches nearly to the ground, a dominant in a
        closed or thinned stand keeps a shorter one.
Prints one line per age; the exit status is the number of ages outside the range.
"""
import collections
import csv
import sys


def main(path, low=0.56, high=0.85):
    low, high = float(low), float(high)
    living = collections.defaultdict(list)
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            if r["status"] == "alive" and float(r["height_m"]) > 0:
                living[int(r["stand_age"])].append(r)
    if not living:
        sys.exit(f"{path}: no living trees")
    outside = 0
    for age in sorted(living):
        trees = sorted(living[age], key=lambda r: -float(r["height_m"]))
        dominants = trees[: max(1, len(trees) // 5)]
        ratio = sum(1 - float(r["crown_base_m"]) / float(r["height_m"]) for r in dominants) / len(dominants)
        ok = low <= ratio <= high
        outside += not ok
        print(f"age {age}: {len(dominants)} dominants of {len(trees)} trees, mean live-crown ratio {ratio:.3f} "
              f"{'in' if ok else 'OUTSIDE'} [{low}, {high}]")
    return outside


if __name__ == "__main__":
    if len(sys.argv) not in (2, 4):
        sys.exit(__doc__)
    sys.exit(main(*sys.argv[1:]))
