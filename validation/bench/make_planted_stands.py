#!/usr/bin/env python3
"""Writes the benchmark surveys: SYNTHETIC 20-year Todomatsu plantations planted on a 2 m x 2 m grid
(2500 stems/ha, every planting position still stocked), each tree jittered off its grid point, on square
plots of 20, 40, 80 and 100 m = 100, 400, 1,600 and 2,500 trees (the last one hectare). The sizes follow
stands/tiny (age 20, 7-10 m tall, DBH 10-14 cm). And old_100.csv: 100 SYNTHETIC 60-year trees on a 3 m grid
(1,111 stems/ha, as a thinned plantation), to time establishing old trees. No tree in them was measured.
Deterministic: one fixed seed, the same files every run.

    python3 validation/bench/make_planted_stands.py validation/bench/stands
"""
import argparse
import csv
import random
from pathlib import Path

SEED = 16          # issue 16; any fixed number keeps the files reproducible
SPACING = 2.0      # m between rows and between plants in a row
JITTER = 0.3       # m; planters do not hit the grid exactly
PLOTS = {100: 20.0, 400: 40.0, 1600: 80.0, 2500: 100.0}  # trees: plot edge, m


# Sizes of a stand's trees: each (mean, change per unit of the tree's vigour, noise sd, lowest, highest); the crown
# radius is (intercept, change per cm of DBH, noise sd, lowest, highest).
YOUNG = {  # age 20, as stands/tiny: 7-10 m tall, DBH 10-14 cm
    "height": (8.8, 0.8, 0.25, 7.0, 10.5),         # m
    "dbh": (12.0, 1.4, 0.7, 9.0, 15.0),            # cm
    "crown_radius": (0.2, 0.07, 0.06, 0.8, 1.3),   # m
    "crown_base": (4.0, -0.25, 0.2, 3.3, 4.6),     # m
}
# Age 60, a plantation thinned to ~1,100 stems/ha: 17-23 m tall, DBH 18-30 cm (basal area 49 m2/ha, a little above
# the silver-fir yield table's class I.0 at 60, 44.8: validation/stand/sources.md), crown base 8-12 m.
OLD = {
    "height": (20.0, 1.2, 0.4, 17.0, 23.0),
    "dbh": (23.5, 2.5, 1.2, 18.0, 30.0),
    "crown_radius": (0.4, 0.06, 0.12, 1.4, 2.5),
    "crown_base": (10.0, -0.5, 0.5, 8.0, 12.0),
}


def clip(value, low, high):
    return max(low, min(high, value))


def size(rng, rule, driver):
    mean, slope, noise, low, high = rule
    return clip(mean + slope * driver + rng.gauss(0.0, noise), low, high)


def tree_row(rng, number, grid_x, grid_y, edge, sizes):
    x = clip(grid_x + rng.uniform(-JITTER, JITTER), 0.0, edge)
    y = clip(grid_y + rng.uniform(-JITTER, JITTER), 0.0, edge)
    # One vigour score per tree drives all its sizes, so they are correlated as in a real stand.
    vigour = rng.gauss(0.0, 1.0)
    height = size(rng, sizes["height"], vigour)
    dbh = size(rng, sizes["dbh"], vigour)
    crown_radius = size(rng, sizes["crown_radius"], dbh)
    crown_base = size(rng, sizes["crown_base"], vigour)
    return [f"P{number:04d}", f"{x:.2f}", f"{y:.2f}", f"{height:.1f}", f"{dbh:.1f}",
            f"{crown_radius:.2f}", f"{crown_base:.1f}"]


def write_stand(path, rng, spacing, edge, sizes):
    cells = int(edge / spacing)
    with open(path, "w", newline="") as out:
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(["id", "x", "y", "height", "dbh", "crown_radius", "crown_base"])
        for j in range(cells):
            for i in range(cells):
                number = j * cells + i + 1
                writer.writerow(tree_row(rng, number, spacing / 2 + i * spacing, spacing / 2 + j * spacing, edge,
                                         sizes))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder", nargs="?", type=Path, default=Path(__file__).parent / "stands",
                        help="where the surveys are written (default: the stands folder beside this script)")
    folder = parser.parse_args().folder  # (before: any first argument was the folder, `--help` one named so)
    folder.mkdir(parents=True, exist_ok=True)
    for trees, edge in PLOTS.items():
        write_stand(folder / f"planted_{trees}.csv", random.Random(SEED * 10_000 + trees), SPACING, edge, YOUNG)
    write_stand(folder / "old_100.csv", random.Random(SEED * 10_000 + 60), 3.0, 30.0, OLD)


if __name__ == "__main__":
    main()
