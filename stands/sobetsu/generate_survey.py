#!/usr/bin/env python3
"""Generates survey.csv: a SYNTHETIC 35-year Todomatsu (Abies sachalinensis) plantation of 62 trees,
in the style of the Sobetsu (Hokkaido) survey of seed 001 (planting position, height, live-crown base
height, DBH, projected crown diameter). No tree in it was measured. Deterministic: same file every run.

    python3 stands/sobetsu/generate_survey.py > stands/sobetsu/survey.csv
"""
import csv
import random
import sys

SEED = 1991  # year of the seed papers; any fixed number keeps the file reproducible
PLOT_X, PLOT_Y = 24.0, 20.0  # m; 0.048 ha
SPACING = 2.0  # m between planting rows and between plants in a row: 2500 stems/ha planted
TREES_LEFT = 62  # of the 12 x 10 = 120 planting positions, after 35 years of mortality
JITTER = 0.3  # m; planters do not hit the grid exactly


def clip(value, low, high):
    return max(low, min(high, value))


def main():
    rng = random.Random(SEED)
    grid = [(SPACING / 2 + i * SPACING, SPACING / 2 + j * SPACING)
            for j in range(int(PLOT_Y / SPACING)) for i in range(int(PLOT_X / SPACING))]
    survivors = sorted(rng.sample(range(len(grid)), TREES_LEFT))

    writer = csv.writer(sys.stdout, lineterminator="\n")
    writer.writerow(["id", "x", "y", "height", "dbh", "crown_base", "crown_diameter"])
    for number, cell in enumerate(survivors, start=1):
        gx, gy = grid[cell]
        x = clip(gx + rng.uniform(-JITTER, JITTER), 0.0, PLOT_X)
        y = clip(gy + rng.uniform(-JITTER, JITTER), 0.0, PLOT_Y)
        # One "vigour" score per tree drives all its sizes, so they are correlated as in a real stand:
        # dominant trees are taller, thicker, wider and keep their crown a little lower.
        vigour = rng.gauss(0.0, 1.0)
        height = clip(16.0 + 1.0 * vigour + rng.gauss(0.0, 0.3), 14.0, 18.0)               # m
        dbh = clip(21.0 + 2.4 * vigour + rng.gauss(0.0, 1.2), 16.0, 26.0)                 # cm
        crown_radius = clip(0.25 + 0.068 * dbh + rng.gauss(0.0, 0.08), 1.2, 2.2)           # m
        crown_base = clip(7.5 - 0.35 * vigour + rng.gauss(0.0, 0.4), 6.0, 9.0)             # m
        writer.writerow([f"S{number:02d}", f"{x:.2f}", f"{y:.2f}", f"{height:.1f}", f"{dbh:.1f}",
                         f"{crown_base:.1f}", f"{2 * crown_radius:.2f}"])


if __name__ == "__main__":
    main()
