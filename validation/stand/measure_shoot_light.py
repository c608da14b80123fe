#!/usr/bin/env python3
"""How the shoot rules' relative-light thresholds carry over from one light field to another (docs/light.md,
"The corrected far field by default").

  measure_shoot_light.py HELIOSTAND OUT_DIR [--light "KEY = VALUE" ...]

Solves the light of the example survey (stands/sobetsu as its scenario says: periodic plot, default numerics) at the
survey twice, with the far field uncorrected and corrected (`far_field_bias_correction`), and reads every leaf ball's
relative light (its light in the stand / its light with its own tree alone: the value the shoot rules read) from the
`relative_light` array of the age-35 `leaf_balls` block. Both runs hold the same balls in the same order (the surveyed
stand before any simulated year), so the balls pair one to one. It prints

  - the paired ratio corrected / uncorrected (median, quartiles): whether the correction scales relative light by
    one factor;
  - for every relative-light threshold of the shoot rules as judged on the uncorrected light (the Todomatsu defaults
    until 2026-11-24), the share of balls below it under the uncorrected light and the value with the same share
    below it under the corrected light (quantile mapping): the threshold that means, on the corrected light, what
    the old value meant on the uncorrected one.

Nothing before the first solve depends on a growth or shoot parameter, so this measures the light field alone.
`--light` adds or replaces a key of [light] in both runs, e.g. --light "cutoff_m = 2.0".
"""
import os
import re
import statistics
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
import zlib

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import measure_light_share  # noqa: E402  (the scenario text: one simulated year, thinnings dropped)

# The thresholds on relative light as judged on the uncorrected far field: the Todomatsu defaults until 2026-11-24.
# The growth thresholds' defaults are now the values this script maps them to; death_threshold was set halfway
# between its value here and the mapped one (src/architecture/species.hpp, docs/light.md).
THRESHOLDS = [
    ("death_threshold - dither", 0.05),
    ("death_threshold", 0.15),
    ("death_threshold + dither", 0.25),
    ("elongation_light_zero", 0.03),
    ("elongation_light_saturation", 0.4),
    ("height_light_zero", 0.05),
    ("height_light_saturation", 0.5),
]


def read_point_array(vtp_path, name):
    """A point-data array of a VTK XML PolyData file with appended, zlib-compressed raw data (what heliostand
    writes: header_type UInt32, vtkZLibDataCompressor)."""
    with open(vtp_path, "rb") as f:
        content = f.read()
    marker = content.index(b"<AppendedData")
    start = content.index(b"_", marker) + 1
    header = content[:marker].decode()
    if 'header_type="UInt32"' not in header or 'compressor="vtkZLibDataCompressor"' not in header:
        sys.exit(f"{vtp_path}: expected UInt32 headers and zlib compression")
    for tag in re.findall(r"<DataArray [^>]*>", header):
        array = ET.fromstring(tag.rstrip("/>") + "/>")
        if array.get("Name") == name and array.get("type") == "Float64":
            offset = start + int(array.get("offset"))
            blocks = struct.unpack_from("<I", content, offset)[0]
            sizes = struct.unpack_from(f"<{3 + blocks}I", content, offset)[3:]
            data, position = b"", offset + 4 * (3 + blocks)
            for size in sizes:
                data += zlib.decompress(content[position:position + size])
                position += size
            return list(struct.unpack(f"<{len(data) // 8}d", data))
    sys.exit(f"{vtp_path}: no Float64 point array '{name}'")


def leaf_ball_block(out):
    folder = os.path.join(out, "stand", "stand_age_0035")
    for vtp in sorted(os.listdir(folder)):
        with open(os.path.join(folder, vtp), "rb") as f:
            head = f.read(4096)
        if b'Name="relative_light"' in head and b'Name="radius"' in head:
            return os.path.join(folder, vtp)
    sys.exit(f"{folder}: no leaf_balls block with relative_light")


def relative_light(heliostand, out, correction, light_keys):
    os.makedirs(out, exist_ok=True)
    scenario = os.path.join(out, "scenario.toml")
    with open(scenario, "w") as f:
        f.write(measure_light_share.scenario_text(light_keys + [f"far_field_bias_correction = {correction}"]))
    subprocess.run([heliostand, "grow", scenario, "--out", os.path.join(out, "out"), "--force", "-q"], check=True)
    return read_point_array(leaf_ball_block(os.path.join(out, "out")), "relative_light")


def share_below(values, threshold):
    return sum(v < threshold for v in values) / len(values)


def value_at_share(sorted_values, share):
    index = min(len(sorted_values) - 1, max(0, round(share * len(sorted_values))))
    return sorted_values[index]


def main(argv):
    if len(argv) < 2 or len(argv) % 2 != 0 or any(argv[i] != "--light" for i in range(2, len(argv), 2)):
        sys.exit(__doc__)
    heliostand, out = argv[0], argv[1]
    light_keys = [argv[i + 1] for i in range(2, len(argv), 2)]
    off = relative_light(heliostand, os.path.join(out, "uncorrected"), "false", light_keys)
    on = relative_light(heliostand, os.path.join(out, "corrected"), "true", light_keys)
    if len(off) != len(on):
        sys.exit(f"the two runs hold {len(off)} and {len(on)} leaf balls: they should be the same stand")
    ratios = [b / a for a, b in zip(off, on) if a > 0]
    q1, median, q3 = statistics.quantiles(ratios, n=4, method="inclusive")
    print(f"{len(off)} leaf balls; relative light uncorrected median {statistics.median(off):.4f}, "
          f"corrected {statistics.median(on):.4f}")
    print(f"paired ratio corrected / uncorrected: median {median:.3f}, quartiles {q1:.3f}-{q3:.3f}")
    on_sorted = sorted(on)
    print("| threshold | judged on uncorrected | share of balls below it, uncorrected | same share, corrected |")
    print("|---|---:|---:|---:|")
    for name, value in THRESHOLDS:
        share = share_below(off, value)
        print(f"| {name} | {value:.2f} | {share:.3f} | {value_at_share(on_sorted, share):.3f} |")


if __name__ == "__main__":
    main(sys.argv[1:])
