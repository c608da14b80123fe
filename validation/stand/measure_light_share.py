#!/usr/bin/env python3
"""The pipe-model light share of the example survey's trees in their closed stand: how diameter_light_saturation
is set (docs/model.md "Growth rules", Diameter).

  measure_light_share.py HELIOSTAND OUT_DIR [--light "KEY = VALUE" ...]

Grows stands/sobetsu as its scenario says (periodic plot, default light numerics, roots on) for one year with
the thinnings left out (they come later) and trees.csv written every year, then prints the median and quartiles
over the living trees of
  at the survey (age 35):   s0 = relative_light, i.e. absorbed light / the same crown's absorbed light alone: the
                            share ConiferTree::pipe_model_share gives the first year's diameter growth;
  one year on (age 36):     s1 = light_budget_36 / (light_budget_35 / relative_light_35 * (DBH_36 / DBH_35)^2):
                            the share the second year's growth reads (the reference light scaled by basal area).
The saturation is the median of s0. Nothing in the run depends on a growth parameter before s0 is solved (year 0
is the surveyed stand's light), so the measurement is one of the light field alone. `--light` adds or replaces a
key of [light], e.g. --light "far_field_bias_correction = false".
"""
import csv
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "stands", "sobetsu")


def scenario_text(light_keys):
    with open(os.path.join(EXAMPLE, "scenario.toml")) as f:
        text = f.read()
    survey = os.path.abspath(os.path.join(EXAMPLE, "survey.csv"))
    text = re.sub(r'^survey = "[^"]*"', f'survey = "{survey}"', text, flags=re.M)
    text = re.sub(r"^output_interval = \d+", "output_interval = 1", text, flags=re.M)
    text = re.sub(r"^years = \d+", "years = 1", text, flags=re.M)
    # Drop every [[thinning]] table (they fall after the one simulated year and would be refused).
    text = re.sub(r"^\[\[thinning\]\]\n(?:(?!\[).*\n)*", "", text, flags=re.M)
    for item in light_keys:
        key = item.split("=")[0].strip()
        text, n = re.subn(rf"^{re.escape(key)} *=.*$", item, text, flags=re.M)
        if n == 0:
            text = text.replace("[light]\n", f"[light]\n{item}\n", 1)
    return text


def rows_by_age(path):
    by_age = {}
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            if r["status"] == "alive":
                by_age.setdefault(int(r["stand_age"]), {})[r["tree_id"]] = r
    return by_age


def summary(name, values):
    q1, median, q3 = statistics.quantiles(values, n=4, method="inclusive")
    print(f"{name}: median {median:.3f}, quartiles {q1:.3f}-{q3:.3f}, {len(values)} trees")


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    heliostand, out = argv[0], argv[1]
    light_keys = [argv[i + 1] for i in range(2, len(argv) - 1, 2) if argv[i] == "--light"]
    os.makedirs(out, exist_ok=True)
    scenario = os.path.join(out, "scenario.toml")
    with open(scenario, "w") as f:
        f.write(scenario_text(light_keys))
    subprocess.run([heliostand, "grow", scenario, "--out", os.path.join(out, "out"), "--force", "--no-vtk", "-q"],
                   check=True)
    by_age = rows_by_age(os.path.join(out, "out", "trees.csv"))
    survey, next_year = by_age[35], by_age[36]
    s0 = [float(r["relative_light"]) for r in survey.values()]
    s1 = []
    for tree, r in next_year.items():
        r0 = survey[tree]
        reference = float(r0["light_budget"]) / float(r0["relative_light"])
        basal_area_ratio = (float(r["dbh_cm"]) / float(r0["dbh_cm"])) ** 2
        s1.append(float(r["light_budget"]) / (reference * basal_area_ratio))
    summary("share at the survey (age 35)", s0)
    summary("share one year on (age 36)", s1)


if __name__ == "__main__":
    main(sys.argv[1:])
