#!/usr/bin/env python3
"""The figures of a checks.sh folder, one line each: per binary its light field (first evaluation, setup, error) and
its hectare (wall, the seconds outside every stage, peak memory, the stages), then each binary's hectare and light
over main's. Standard library only: the GPU machine has Python but not the project's packages.

    validation/bench/gpu/summary.py OUT_DIR
"""
import glob
import json
import os
import re
import sys
from statistics import median


def light_rows(folder):
    """{binary: {balls: [first-evaluation seconds, ...]}} and the rows' setup and error, from light_NAME_N.json."""
    seconds, details = {}, []
    for path in sorted(glob.glob(os.path.join(folder, "light_*.json"))):
        name = re.match(r"light_(.+)_\d+\.json$", os.path.basename(path)).group(1)
        for row in json.load(open(path))["stands"]:
            solve = row["opencl_culled_far_field"]
            seconds.setdefault(name, {}).setdefault(row["balls"], []).append(solve["seconds"])
            details.append("light %s %s: %d balls %.3f s (setup %.3f, search %.3f, far field %.3f), "
                           "mean |dlight| %.8f"
                           % (name, os.path.basename(path), row["balls"], solve["seconds"], solve["setup_seconds"],
                              solve["search_seconds"], solve["far_field_seconds"],
                              solve["error_vs_reference_exact"]["mean_abs_light"]))
    return seconds, details


def hectare_rows(folder):
    """{binary: total seconds} and one line per hectare_NAME.json."""
    totals, details = {}, []
    for path in sorted(glob.glob(os.path.join(folder, "hectare_*.json"))):
        name = re.match(r"hectare_(.+)\.json$", os.path.basename(path)).group(1)
        run = json.load(open(path))
        stages = run["stage_seconds"]
        totals[name] = run["total_seconds"]
        details.append("hectare %s: %.1f s (%.1f s outside the stages), peak %.0f MiB, %d alive, %d dead; %s"
                       % (name, run["total_seconds"], run["total_seconds"] - sum(stages.values()),
                          run["peak_memory_mib"], run["trees_alive_at_end"], run["trees_dead"],
                          ", ".join("%s %.1f" % item for item in sorted(stages.items()))))
    return totals, details


def ratios(light, hectare):
    """Each other binary's figures over main's (the medians of its runs)."""
    lines = []
    for name in sorted(set(light) | set(hectare)):
        if name == "main":
            continue
        if name in hectare and "main" in hectare:
            lines.append("main / %s, hectare: %.3f" % (name, hectare["main"] / hectare[name]))
        for balls in sorted(light.get(name, {})):
            if balls in light.get("main", {}):
                lines.append("main / %s, light of %d balls (medians): %.3f"
                             % (name, balls, median(light["main"][balls]) / median(light[name][balls])))
    return lines


def main(argv):
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        sys.stderr.write("usage: summary.py OUT_DIR (a folder checks.sh wrote)\n")
        return 2
    light, light_lines = light_rows(argv[1])
    hectare, hectare_lines = hectare_rows(argv[1])
    for line in light_lines + hectare_lines + ratios(light, hectare):
        print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
