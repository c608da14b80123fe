#!/usr/bin/env python3
"""How a stand run scales with its number of trees (issue 16): grows the planted benchmark stands
(validation/bench/stands/planted_{100,400,1600,2500}.toml) a few years each with `heliostand bench stand` and
writes a Markdown table of time and peak memory per tree and per tree-year against trees.

    validation/bench/scaling.py --heliostand build/heliostand --years 3 --out out/bench

Give --heliostand twice (e.g. build-old/heliostand and build/heliostand) to compare two builds side by side:
every stand is run by each binary in turn, so both see the same machine load, and the table gets a column of
ratios (second / first). Each run's JSON is kept in --out; the table goes to stdout and to OUT/scaling.md.
"""
import argparse
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
PLANTED = [HERE / "stands" / f"planted_{trees}.toml" for trees in (100, 400, 1600, 2500)]
MIB = 1024.0 * 1024.0


def whole_years(text):
    """--years: a whole number of at least 1, as heliostand's own --years."""
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"a whole number >= 1 is expected, got {text}")
    return int(text)


def program(text):
    """--heliostand: a program that can be run, found now rather than after the first stand's minutes."""
    path = Path(text)
    if not path.is_file() or not os.access(path, os.X_OK):
        raise argparse.ArgumentTypeError(f"{text} is not a program that can be run")
    return path


def scenario_file(text):
    """--stand: a file that exists (heliostand itself then checks what is in it)."""
    path = Path(text)
    if not path.is_file():
        raise argparse.ArgumentTypeError(f"{text}: no such file")
    return path


def output_folder(text):
    """--out: a folder to write into, not an empty name (that would be the current folder) nor an existing file."""
    if not text:
        raise argparse.ArgumentTypeError("a folder name is expected, got an empty one")
    path = Path(text)
    if path.exists() and not path.is_dir():
        raise argparse.ArgumentTypeError(f"{text} exists and is not a folder")
    return path


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--heliostand", action="append", type=program,
                        help="heliostand binary (default build/heliostand); twice to compare two builds")
    parser.add_argument("--years", type=whole_years, default=3, help="years each stand is grown (default 3)")
    parser.add_argument("--device", help="passed to bench stand (default: the scenarios' device, auto)")
    parser.add_argument("--stand", action="append", type=scenario_file,
                        help="scenario to run instead of the four planted stands (repeatable)")
    parser.add_argument("--out", type=output_folder, default=Path("out/bench"),
                        help="folder for the JSON and scaling.md")
    arguments = parser.parse_args()
    if not arguments.heliostand:
        try:
            arguments.heliostand = [program("build/heliostand")]
        except argparse.ArgumentTypeError as error:
            parser.error(f"argument --heliostand: {error} (the default; build first, or name one)")
    if len(arguments.heliostand) > 2:
        parser.error("at most two --heliostand binaries")
    try:  # made now, so that a folder that cannot be made is found before the first stand's minutes
        arguments.out.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        parser.error(f"argument --out: cannot create {arguments.out}: {error.strerror}")
    return arguments


def machine_line(processor):
    """The machine, with the processor as `bench stand` describes it: lscpu's model name alone ("AMD EPYC") does not
    tell apart machines whose speed differs by up to 1.9x (the CPU family and AVX-512 do)."""
    def known(value):
        return "unknown" if value is None else value
    if processor:
        extensions = " ".join(processor["vector_extensions"]) or "no vector extensions"
        cpu = (f"{known(processor['model_name'])}; CPU family {known(processor['cpu_family'])}, "
               f"model {known(processor['model'])}; {extensions}")
    else:  # a binary older than the field
        cpu = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                    if line.startswith("model name")), platform.processor())
    memory_kb = next(int(line.split()[1]) for line in Path("/proc/meminfo").read_text().splitlines()
                     if line.startswith("MemTotal"))
    return f"{os.cpu_count()} CPUs ({cpu}), {memory_kb / 1024 / 1024:.0f} GiB RAM, {platform.platform()}"


def load_average():
    return "{:.1f} {:.1f} {:.1f}".format(*os.getloadavg())


def bench(binary, scenario, years, device, json_path):
    command = [str(binary), "bench", "stand", str(scenario), "--years", str(years), "-o", str(json_path), "-q"]
    if device:
        command += ["--device", device]
    print("$ " + " ".join(command), file=sys.stderr, flush=True)
    status = subprocess.run(command, stdout=subprocess.DEVNULL).returncode
    if status != 0:  # heliostand has said why on stderr, just above: no Python traceback after it
        sys.exit(f"scaling.py: the run above failed (exit status {status}); no table written")
    return json.loads(json_path.read_text())


def row(run):
    """The quantities of one run that the table shows, per tree and per tree-year."""
    tree_years = max(1, run["tree_years"])
    peak_mib = run["peak_memory_bytes"] / MIB
    # the stand's light field and the open-grown one (a separate stage since 2026-11-25; older JSON has only "light")
    light = run["stage_seconds"].get("light", 0.0) + run["stage_seconds"].get("light (open grown)", 0.0)
    return {
        "trees": run["trees"],
        "tree_years": run["tree_years"],
        "leaf_balls": run["leaf_balls_at_end"],
        "root_segments": run["root_segments_at_end"],
        "seconds": run["total_seconds"],
        "light_seconds": light,
        "roots_seconds": run["stage_seconds"].get("roots", 0.0),
        "light_share": light / run["total_seconds"] if run["total_seconds"] > 0 else 0.0,
        "ms_per_tree_year": 1000.0 * run["total_seconds"] / tree_years,
        "peak_mib": peak_mib,
        "held_mib": run["heap_in_use_at_end_bytes"] / MIB,
        "mib_per_tree": peak_mib / max(1, run["trees"]),
        "kib_per_tree_year": 1024.0 * peak_mib / tree_years,
    }


def table(label, rows):
    lines = [f"**{label}**", "",
             "| trees | tree-years | leaf balls (end) | root segments (end) | wall s | light s | roots s | light share "
             "| ms / tree-year | peak MiB | MiB / tree | KiB / tree-year | held at end MiB | KiB held / tree |",
             "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['trees']:,} | {r['tree_years']:,} | {r['leaf_balls']:,} | {r['root_segments']:,} "
                     f"| {r['seconds']:.1f} | {r['light_seconds']:.1f} | {r['roots_seconds']:.1f} "
                     f"| {100 * r['light_share']:.0f} % | {r['ms_per_tree_year']:.0f} "
                     f"| {r['peak_mib']:.0f} | {r['mib_per_tree']:.2f} | {r['kib_per_tree_year']:.0f} "
                     f"| {r['held_mib']:.0f} | {1024 * r['held_mib'] / max(1, r['trees']):.0f} |")
    lines += ["", marginal_memory(rows), ""]
    return lines


def slope(xs, ys):
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")


def marginal_memory(rows):
    """Least-squares slopes against trees and leaf balls: what one more tree (or ball) costs, without the fixed part
    (program, OpenCL runtime, kernels). Peak = the whole run's high-water mark; held = the heap after the last year."""
    if len(rows) < 2:
        return "(one stand: no slope)"
    trees = [r["trees"] for r in rows]
    balls = [r["leaf_balls"] for r in rows]
    peaks = [r["peak_mib"] * MIB for r in rows]
    held = [r["held_mib"] * MIB for r in rows]
    return (f"Least squares over the stands: peak memory grows by {slope(trees, peaks) / 1024:.0f} KiB per tree "
            f"({slope(balls, peaks):.0f} bytes per leaf ball at the end); the heap held after the last year by "
            f"{slope(trees, held) / 1024:.0f} KiB per tree.")


def ratio(b, a):
    """b / a to two places, or a dash where a is zero (a stage the first binary did not time, or skipped)."""
    return f"{b / a:.2f}" if a > 0 else "–"


def ratio_table(labels, rows_a, rows_b):
    lines = [f"**{labels[1]} / {labels[0]}** (same stands, run alternately)", "",
             "| trees | wall time | light | roots | light share | peak memory | held at end |",
             "|---:|---:|---:|---:|---:|---:|---:|"]
    for a, b in zip(rows_a, rows_b):
        wall, light, roots, peak, held = (ratio(b[key], a[key]) for key in
                                          ("seconds", "light_seconds", "roots_seconds", "peak_mib", "held_mib"))
        lines.append(f"| {a['trees']:,} | {wall} | {light} | {roots} | "
                     f"{100 * a['light_share']:.0f} % → {100 * b['light_share']:.0f} % | {peak} | {held} |")
    return lines + [""]


def main():
    arguments = parse_arguments()
    binaries = arguments.heliostand
    stands = arguments.stand or PLANTED
    started = time.strftime("%Y-%m-%d %H:%M %Z")
    loads = [load_average()]
    # By position, not by path: the same binary given twice (to see the machine's noise) keeps two sets of runs.
    runs = [[] for _ in binaries]
    for scenario in stands:
        for number, binary in enumerate(binaries):
            json_path = arguments.out / f"{scenario.stem}.{number}.json"
            runs[number].append(bench(binary, scenario, arguments.years, arguments.device, json_path))
            loads.append(load_average())
    rows = [[row(run) for run in binary_runs] for binary_runs in runs]

    device = runs[0][0]["device"]
    processor = next((run["processor"] for binary_runs in runs for run in binary_runs if "processor" in run), None)
    lines = [f"Stand scaling, {arguments.years} years per stand, started {started}.", "",
             f"Machine: {machine_line(processor)}; device {device}.",
             f"Load average (1, 5, 15 min) before and after each run: {'; '.join(loads)}.", "",
             "Command: `" + " ".join([sys.argv[0]] + sys.argv[1:]) + "`", ""]
    for binary, binary_rows in zip(binaries, rows):
        lines += table(str(binary), binary_rows)
    if len(binaries) == 2:
        lines += ratio_table([str(b) for b in binaries], rows[0], rows[1])
    text = "\n".join(lines)
    (arguments.out / "scaling.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
