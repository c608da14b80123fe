#!/usr/bin/env python3
"""Draw a stand from a yield table at a young age and write its survey and scenario.

The stand is a planted square grid (the table's stems/ha at the start age, with a small jitter) on a
periodic plot; heights and DBHs scatter around the table's h_q and Dg so that the drawn stand's
quadratic-mean DBH is the table's Dg exactly. Crown base and crown diameter are left to the survey's
imputation. Every later row of the table becomes a thinning from below to the table's stems/ha
(German yield tables list the remaining stand after thinning), unless --unthinned.

usage: make_yield_stand.py TABLE.csv OUT_DIR [--start-age 30] [--years 40] [--trees 49]
                           [--unthinned | --heavy-thinning AGE N] [--seed 1] [--device auto] [--species FILE.toml] [--light 'key = value']
"""
import argparse
import csv
import math
import os
import random
import sys


def read_table(path, site_class=None):
    """The table's rows by age; a table of several site classes needs the class (its `site_class` column)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if rows and "site_class" in rows[0]:
        if site_class is None:
            sys.exit(f"{path}: the table has several site classes; choose one with --site-class")
        rows = [r for r in rows if float(r["site_class"]) == float(site_class)]
    return {int(r["age_years"]): r for r in rows}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("table")
    p.add_argument("out")
    p.add_argument("--start-age", type=int, default=30)
    p.add_argument("--site-class", default=None, help="for a table of several site classes (column site_class)")
    p.add_argument("--years", type=int, default=40)
    p.add_argument("--trees", type=int, default=49, help="trees on the plot (a square number keeps the grid even)")
    p.add_argument("--unthinned", action="store_true")
    p.add_argument("--heavy-thinning", nargs=2, type=float, metavar=("AGE", "STEMS_PER_HA"),
                   help="instead of the table's thinnings, one heavy thinning from below at AGE down to STEMS_PER_HA")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--device", default="auto")
    p.add_argument("--species", default="", help="a TOML file whose [species.NAME] table the stand grows as")
    p.add_argument("--species-set", default=[], action="append",
                   help="a 'key = value' line added to the species table (to break one rule and see the checks fail)")
    p.add_argument("--light", default=[], help="extra [light] keys, e.g. 'sky_bands = 8' (numerics of a small run)",
                   action="append")
    a = p.parse_args()

    table = read_table(a.table, a.site_class)
    if a.start_age not in table:
        sys.exit(f"{a.table}: no row for age {a.start_age}")
    start = table[a.start_age]
    density = float(start["stems_per_ha"])
    h_q = float(start["mean_height_m"])
    d_g = float(start["dg_cm"])

    side = math.sqrt(a.trees * 10000.0 / density)  # m, square plot holding a.trees at the table's density
    per_row = max(1, round(math.sqrt(a.trees)))
    spacing = side / per_row
    rng = random.Random(a.seed)

    # Relative size of each tree: one lognormal draw shared by height and DBH (a big tree is big in both).
    sizes = [rng.lognormvariate(0.0, 0.25) for _ in range(per_row * per_row)]
    dbh = [d_g * s for s in sizes]
    scale = d_g / math.sqrt(sum(d * d for d in dbh) / len(dbh))  # the drawn stand's Dg is the table's
    dbh = [d * scale for d in dbh]
    # Height follows DBH loosely: h = h_q * (d / Dg)^0.35 (flat height-diameter curve of a young dense stand).
    height = [h_q * (d / d_g) ** 0.35 for d in dbh]

    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "survey.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["id", "x", "y", "height", "dbh", "crown_diameter"])
        k = 0
        for i in range(per_row):
            for j in range(per_row):
                x = (i + 0.5) * spacing + rng.uniform(-0.15, 0.15) * spacing
                y = (j + 0.5) * spacing + rng.uniform(-0.15, 0.15) * spacing
                # Crowns of a closed young stand just touch: diameter = the spacing, larger for larger trees.
                crown = spacing * (dbh[k] / d_g) ** 0.5
                w.writerow([f"T{k + 1:03d}", f"{x:.2f}", f"{y:.2f}", f"{height[k]:.2f}", f"{dbh[k]:.2f}", f"{crown:.2f}"])
                k += 1

    last_age = a.start_age + a.years
    with open(os.path.join(a.out, "scenario.toml"), "w") as f:
        f.write(f"# Drawn by validation/stand/make_yield_stand.py from {os.path.basename(a.table)}, age {a.start_age}\n")
        f.write(f"[stand]\nsurvey = \"survey.csv\"\nage_at_survey = {a.start_age}\n")
        f.write(f"x_min = 0.0\ny_min = 0.0\nx_max = {side:.4f}\ny_max = {side:.4f}\n\n")
        f.write(f"[run]\nyears = {a.years}\nseed = {a.seed}\noutput_interval = 5\ndevice = \"{a.device}\"\n\n")
        if a.species:
            with open(a.species) as species:
                f.write(species.read() + "".join(k + "\n" for k in a.species_set) + "\n")
        f.write("[light]\nperiodic = true\n" + "".join(k + "\n" for k in a.light if k) + "\n[roots]\nenabled = false\n")
        if a.heavy_thinning:
            f.write(f"\n[[thinning]]\nage = {int(a.heavy_thinning[0])}\nmethod = \"from_below\"\n"
                    f"target_stems_per_ha = {a.heavy_thinning[1]:.0f}\nreason = \"heavy thinning from below\"\n")
        elif not a.unthinned:
            for age in sorted(table):
                if a.start_age < age <= last_age:
                    f.write(f"\n[[thinning]]\nage = {age}\nmethod = \"from_below\"\n"
                            f"target_stems_per_ha = {float(table[age]['stems_per_ha']):.0f}\n"
                            f"reason = \"yield table, age {age}\"\n")


if __name__ == "__main__":
    main()
