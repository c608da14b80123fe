#!/usr/bin/env python3
"""Judge three runs of a stand drawn from a yield table against the table and against forestry's rules.

  check_stand_growth.py TABLE.csv THINNED_OUT UNTHINNED_OUT HEAVY_OUT HEAVY_AGE REPORT.md

THINNED_OUT   thinned to the table's stems/ha every 5 years (make_yield_stand.py): its basal area and quadratic-mean
              DBH must stay within 20 % of the table's (remaining stand) at every table age over at least 40 years.
UNTHINNED_OUT never thinned: it must lose stems by suppression, its basal area must stay at or below 80 m²/ha, and
              log N against log Dq (least squares over the rows from 10 years after the start on: the first decade is
              the crowns' adjustment from their alone-grown establishment) must run with a slope in [-2.0, -1.3]
              (Reineke 1933: -1.605).
HEAVY_OUT     the unthinned stand thinned once from below at HEAVY_AGE: the residual trees' mean DBH increment over
              the next 15 years must be at least 15 % above the same trees' increment unthinned, and their mean crown
              radius at the end larger.
Every figure goes to REPORT.md; the exit status is the number of failed checks (0: all hold).
"""
import csv
import math
import sys


def table_rows(path):
    with open(path, newline="") as f:
        return {int(r["age_years"]): r for r in csv.DictReader(line for line in f if not line.startswith("#"))}


def stand_rows(out):
    """The whole stand's rows of stand_table.csv (species "all"), one per simulated year, by stand age."""
    with open(f"{out}/stand_table.csv", newline="") as f:
        return {int(r["stand_age"]): r for r in csv.DictReader(f) if r["species"] == "all"}


def output_ages(out):
    """The stand ages written to trees.csv (every output_interval years, 5 here): the ages the slope is fitted on."""
    with open(f"{out}/trees.csv", newline="") as f:
        return sorted({int(r["stand_age"]) for r in csv.DictReader(f)})


def trees(out):
    with open(f"{out}/trees.csv", newline="") as f:
        return {(r["tree_id"], int(r["stand_age"])): r for r in csv.DictReader(f)}


def slope(xs, ys):
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main(table_path, thinned, unthinned, heavy, heavy_age, report_path):
    heavy_age = int(heavy_age)
    table = table_rows(table_path)
    lines, failures = [], []

    def check(ok, what):
        lines.append(f"- {'PASS' if ok else 'FAIL'}: {what}")
        if not ok:
            failures.append(what)

    # 1. The yield table, thinned stand.
    run = stand_rows(thinned)
    ages = sorted(a for a in run if a in table)
    lines.append("## Thinned to the table's stems/ha\n")
    lines.append("| age | N table | N run | G table | G run | dev G | Dg table | Dg run | dev Dg | h_q table | mean h run |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|")
    worst = 0.0
    for a in ages:
        t, r = table[a], run[a]
        dg = (float(r["basal_area_m2_per_ha"]) / float(t["basal_area_m2_per_ha"]) - 1.0,
              float(r["qmd_cm"]) / float(t["dg_cm"]) - 1.0)
        if a > ages[0]:
            worst = max(worst, abs(dg[0]), abs(dg[1]))
        lines.append(f"| {a} | {float(t['stems_per_ha']):.0f} | {float(r['stems_per_ha']):.0f} | {t['basal_area_m2_per_ha']} | "
                     f"{float(r['basal_area_m2_per_ha']):.1f} | {100 * dg[0]:+.1f} % | {t['dg_cm']} | {float(r['qmd_cm']):.1f} | "
                     f"{100 * dg[1]:+.1f} % | {t['mean_height_m']} | {float(r['mean_height_m']):.1f} |")
    lines.append("")
    check(ages[-1] - ages[0] >= 40, f"the run covers {ages[-1] - ages[0]} years of the table (at least 40)")
    check(worst <= 0.20, f"basal area and Dg within 20 % of the table at every age after the start (worst {100 * worst:.1f} %)")

    # 2. Self-thinning, unthinned stand. The table has a row every year; the report lists the output years, each with
    # the deaths of the period since the one before, and the slope is fitted on them.
    run = stand_rows(unthinned)
    ages = sorted(run)
    written = output_ages(unthinned)
    dead_in = lambda first, last: sum(float(run[a]["dead_suppression_stems_per_ha"]) for a in ages if first < a <= last)
    lines.append("\n## Unthinned\n")
    lines.append("| age | N | G | Dq | dead by suppression (in the period) |")
    lines.append("|---|---|---|---|---|")
    for previous, a in zip([ages[0] - 1] + written, written):
        r = run[a]
        lines.append(f"| {a} | {float(r['stems_per_ha']):.0f} | {float(r['basal_area_m2_per_ha']):.1f} | {float(r['qmd_cm']):.2f} | "
                     f"{dead_in(previous, a):.0f} |")
    lines.append("")
    dead = dead_in(ages[0] - 1, ages[-1])
    check(dead > 0, f"stems die of suppression ({dead:.0f} stems/ha in all)")
    top = max(float(run[a]["basal_area_m2_per_ha"]) for a in ages)
    check(top <= 80.0, f"basal area never above 80 m²/ha in any year (highest {top:.1f})")
    fit = [a for a in written if a >= ages[0] + 10]
    s = slope([math.log(float(run[a]["qmd_cm"])) for a in fit], [math.log(float(run[a]["stems_per_ha"])) for a in fit])
    check(-2.0 <= s <= -1.3, f"log N vs log Dq slope {s:.2f} over ages {fit[0]}-{fit[-1]} in [-2.0, -1.3] (Reineke: -1.605)")

    # 3. Release after a heavy thinning from below.
    a, b = trees(heavy), trees(unthinned)
    end = heavy_age + 15
    ids = [i for (i, age), r in a.items() if age == end and r["status"] == "alive" and b.get((i, end), {}).get("status") == "alive"]
    grow = lambda t: sum(float(t[(i, end)]["dbh_cm"]) - float(t[(i, heavy_age)]["dbh_cm"]) for i in ids) / len(ids)
    crown = lambda t: sum(float(t[(i, end)]["crown_radius_m"]) for i in ids) / len(ids)
    lines.append(f"\n## Release: thinned from below at {heavy_age}, the {len(ids)} trees alive at {end} in both runs\n")
    lines.append(f"| | thinned | unthinned |\n|---|---|---|")
    lines.append(f"| mean DBH increment {heavy_age}-{end}, cm | {grow(a):.2f} | {grow(b):.2f} |")
    lines.append(f"| mean crown radius at {end}, m | {crown(a):.2f} | {crown(b):.2f} |\n")
    gain = grow(a) / grow(b) - 1.0
    check(gain >= 0.15, f"released trees thicken at least 15 % faster ({100 * gain:+.1f} %)")
    check(crown(a) > crown(b), f"released crowns are wider ({crown(a):.2f} m against {crown(b):.2f} m)")

    with open(report_path, "w") as f:
        f.write("# Stand growth against a yield table and forestry's rules\n\n")
        f.write("\n".join(l for l in lines if l.startswith("- ")) + "\n\n")
        f.write("\n".join(l for l in lines if not l.startswith("- ")) + "\n")
    print("\n".join(lines))
    return len(failures)


if __name__ == "__main__":
    if len(sys.argv) != 7:
        sys.exit(__doc__)
    sys.exit(main(*sys.argv[1:]))
