"""One heliostand run folder, read for the report: the stand over age, the thinnings and the diameters.

Reads what `heliostand grow SCENARIO --out DIR` writes (docs/formats.md "CSV tables" and "run.json"):

- stand_table.csv in both layouts: without a `species` column every row is the whole stand; with one, the
  rows whose species is `all` are the whole stand and the others are per species. Rows may be one per output
  year or one per simulated year; the removed_* and dead_* flows are "since the previous row" in both.
- hg_m, total_production_m3_per_ha, cai_m3_per_ha and mai_m3_per_ha are optional: when a column is absent its
  series is computed here (see `production_series`) and the run remembers which ones were, so the summary can
  say so.
- trees.csv (per output year) and events.csv (every removal and death) give the diameter distributions before
  and after each thinning (see `thinning_distributions` for the rule).

Every problem is raised as RunInputError with the file, and the line and column where it applies.
"""
import csv
import json
import math
import os
import re
from dataclasses import dataclass, field


class RunInputError(Exception):
    """Bad input: the message names the file, and the line and column where it applies."""


# Columns the report cannot do without; every other stand_table column is optional.
STAND_TABLE_COLUMNS = (
    "stand_age", "stems_per_ha", "basal_area_m2_per_ha", "qmd_cm", "top_height_m", "volume_m3_per_ha",
    "removed_stems_per_ha", "removed_volume_m3_per_ha", "dead_stems_per_ha", "dead_volume_m3_per_ha")
TREES_COLUMNS = ("stand_age", "tree_id", "status", "dbh_cm")
EVENTS_COLUMNS = ("stand_age", "tree_id", "event", "reason")

# stand_table.csv columns that hold text; every other one is a number (empty = not defined).
STAND_TABLE_TEXT_COLUMNS = {"species"}
WHOLE_STAND = "all"
DEATH_CAUSE_COLUMN = re.compile(r"^dead_(.+)_stems_per_ha$")


@dataclass
class Thinning:
    """One thinning: every removal in one stand age (several rules in one year are joined)."""
    age: float
    reason: str
    removed_tree_ids: set


@dataclass
class DiameterDistribution:
    """DBH (cm) of the trees standing just before and just after a thinning, from trees.csv."""
    thinning: Thinning
    snapshot_age: float  # the output year the diameters come from (at or before the thinning)
    before_cm: list
    after_cm: list


@dataclass
class Run:
    folder: str
    label: str
    stand: dict            # column → list of values over stand_age (the whole stand)
    species: dict          # species → {column → list}, empty in the layout without a species column
    death_causes: list     # causes with a dead_<cause>_stems_per_ha column, in table order
    computed: list         # the optional series computed here because their column was absent
    thinnings: list
    distributions: list    # one DiameterDistribution per thinning that has trees.csv data
    final_diameters_cm: list
    final_output_age: float
    plot_area_ha: float    # derived from trees.csv and stand_table.csv; None when they give no way to tell
    manifest: dict = field(default_factory=dict)  # run.json, empty when the run has none
    notes: list = field(default_factory=list)

    @property
    def ages(self):
        return self.stand["stand_age"]


# --- CSV reading --------------------------------------------------------------------------------------------

def parse_number(text, path, line, column_index, name):
    if text.strip() == "":
        return math.nan  # an empty field means "not defined" (docs/formats.md)
    try:
        return float(text)
    except ValueError:
        raise RunInputError("%s:%d:%d: column %s: '%s' is not a number" % (path, line, column_index + 1, name, text))


def open_table(path):
    try:
        return open(path, newline="", encoding="utf-8")
    except FileNotFoundError:
        raise RunInputError("%s: no such file (a run folder holds the tables `heliostand grow SCENARIO --out DIR` "
                            "writes)" % path)
    except OSError as e:
        raise RunInputError("%s: cannot read: %s" % (path, e.strerror))


def read_table(path, required, is_numeric):
    """Rows of one CSV table as dicts; `is_numeric(column)` says which columns are parsed as numbers."""
    with open_table(path) as f:
        reader = csv.reader(f)
        try:
            header = next(reader, None)
            if header is None:
                raise RunInputError("%s: empty file, no header row" % path)
            missing = [name for name in required if name not in header]
            if missing:
                raise RunInputError("%s:1: missing column%s %s" % (path, "s" if len(missing) > 1 else "",
                                                                   ", ".join(missing)))
            rows = [parse_record(record, header, path, reader.line_num, is_numeric)
                    for record in reader if record]
        except csv.Error as e:
            raise RunInputError("%s:%d: not a readable CSV row: %s" % (path, reader.line_num, e))
        except UnicodeDecodeError as e:
            raise RunInputError("%s: not UTF-8 text (byte %d)" % (path, e.start))
    return header, rows


def parse_record(record, header, path, line, is_numeric):
    if len(record) != len(header):
        raise RunInputError("%s:%d: %d fields, the header has %d" % (path, line, len(record), len(header)))
    row = {"_line": line}
    for index, (name, text) in enumerate(zip(header, record)):
        row[name] = parse_number(text, path, line, index, name) if is_numeric(name) else text
    return row


# --- stand_table.csv ----------------------------------------------------------------------------------------

def read_stand_table(path):
    """(whole-stand columns, per-species columns, header) with rows in stand-age order."""
    header, rows = read_table(path, STAND_TABLE_COLUMNS, lambda name: name not in STAND_TABLE_TEXT_COLUMNS)
    if "species" in header:
        whole = [row for row in rows if row["species"] == WHOLE_STAND]
        if rows and not whole:
            raise RunInputError("%s: a species column but no row with species '%s' (the whole stand)"
                                % (path, WHOLE_STAND))
        by_species = {}
        for row in rows:
            if row["species"] != WHOLE_STAND:
                by_species.setdefault(row["species"], []).append(row)
    else:
        whole, by_species = rows, {}
    if not whole:
        raise RunInputError("%s: no rows (the run wrote no year)" % path)
    check_one_row_per_age(whole, path)
    numeric = [name for name in header if name not in STAND_TABLE_TEXT_COLUMNS]
    return (as_columns(whole, numeric),
            {name: as_columns(species_rows, numeric) for name, species_rows in by_species.items()},
            header)


def check_one_row_per_age(rows, path):
    seen = {}
    for row in rows:
        age = row["stand_age"]
        if math.isnan(age):
            raise RunInputError("%s:%d: column stand_age is empty" % (path, row["_line"]))
        if age in seen:
            raise RunInputError("%s:%d: stand age %g again (first on line %d)" % (path, row["_line"], age, seen[age]))
        seen[age] = row["_line"]


def as_columns(rows, names):
    rows = sorted(rows, key=lambda row: row["stand_age"])
    return {name: [row[name] for row in rows] for name in names}


def death_causes(header):
    causes = []
    for name in header:
        match = DEATH_CAUSE_COLUMN.match(name)
        if match and match.group(1) not in causes:
            causes.append(match.group(1))
    return causes


# --- production and increments --------------------------------------------------------------------------------

def running_total(values):
    total, totals = 0.0, []
    for value in values:
        total += 0.0 if math.isnan(value) else value  # an undefined flow is no flow
        totals.append(total)
    return totals


def production_series(stand):
    """Fill total production, CAI and MAI (m³/ha, m³/ha/yr) where the table lacks them; return what was computed.

    Total production = standing volume + everything removed or dead since the first row. What left the stand
    before the run began is unknown, so it counts from the standing volume of the first simulated year.
    CAI = the change of total production between consecutive rows per year between them (with one row per
    output year this is the periodic annual increment of the interval); MAI = total production / stand age.
    """
    computed = []
    if "total_production_m3_per_ha" not in stand:
        removed = running_total(stand["removed_volume_m3_per_ha"])
        dead = running_total(stand["dead_volume_m3_per_ha"])
        stand["total_production_m3_per_ha"] = [v + r + d for v, r, d in
                                               zip(stand["volume_m3_per_ha"], removed, dead)]
        computed.append("total_production_m3_per_ha")
    production, ages = stand["total_production_m3_per_ha"], stand["stand_age"]
    if "cai_m3_per_ha" not in stand:
        stand["cai_m3_per_ha"] = [math.nan] + [
            (production[i] - production[i - 1]) / (ages[i] - ages[i - 1]) for i in range(1, len(ages))]
        computed.append("cai_m3_per_ha")
    if "mai_m3_per_ha" not in stand:
        stand["mai_m3_per_ha"] = [p / a if a > 0 else math.nan for p, a in zip(production, ages)]
        computed.append("mai_m3_per_ha")
    return computed


# --- events.csv and trees.csv ----------------------------------------------------------------------------------

def read_thinnings(path):
    _, rows = read_table(path, EVENTS_COLUMNS, lambda name: name == "stand_age")
    by_age = {}
    for row in rows:
        if row["event"] != "removed":
            continue
        if math.isnan(row["stand_age"]):
            raise RunInputError("%s:%d: column stand_age is empty" % (path, row["_line"]))
        thinning = by_age.setdefault(row["stand_age"], Thinning(row["stand_age"], "", set()))
        thinning.removed_tree_ids.add(row["tree_id"])
        reasons = thinning.reason.split(" + ") if thinning.reason else []
        if row["reason"] not in reasons:
            thinning.reason = " + ".join(reasons + [row["reason"]])
    return [by_age[age] for age in sorted(by_age)]


def read_trees(path):
    """Output age → list of (tree_id, status, dbh_cm)."""
    _, rows = read_table(path, TREES_COLUMNS, lambda name: name in ("stand_age", "dbh_cm"))
    years = {}
    for row in rows:
        if math.isnan(row["stand_age"]):
            raise RunInputError("%s:%d: column stand_age is empty" % (path, row["_line"]))
        years.setdefault(row["stand_age"], []).append((row["tree_id"], row["status"], row["dbh_cm"]))
    return years


def thinning_distributions(thinnings, tree_years):
    """Diameters before and after each thinning.

    trees.csv has output years only, so the diameters come from the last output year at or before the thinning
    age A. Before = the trees alive in that year; when that year is A itself the thinned trees are listed there
    with status `removed`, and they count as standing before. After = before minus the trees events.csv lists
    as removed at A. Trees that died between that output year and A are not taken out (with the usual one output
    per year there are none). A thinning before the first output year has no distribution.
    """
    distributions = []
    for thinning in thinnings:
        earlier = [age for age in tree_years if age <= thinning.age]
        if not earlier:
            continue
        snapshot = max(earlier)
        standing = [(tree_id, dbh) for tree_id, status, dbh in tree_years[snapshot]
                    if status == "alive" or (snapshot == thinning.age and status == "removed"
                                             and tree_id in thinning.removed_tree_ids)]
        distributions.append(DiameterDistribution(
            thinning, snapshot,
            before_cm=[dbh for _, dbh in standing if not math.isnan(dbh)],
            after_cm=[dbh for tree_id, dbh in standing
                      if tree_id not in thinning.removed_tree_ids and not math.isnan(dbh)]))
    return distributions


def plot_area_ha(tree_years, stand):
    """The plot area, from the first output year whose living trees and stems/ha are both known (else None)."""
    stems_at = dict(zip(stand["stand_age"], stand["stems_per_ha"]))
    for age in sorted(tree_years):
        alive = sum(1 for _, status, _ in tree_years[age] if status == "alive")
        stems = stems_at.get(age, math.nan)
        if alive > 0 and stems > 0:
            return alive / stems
    return None


# --- run.json and the whole folder ------------------------------------------------------------------------------

def read_manifest(path):
    """run.json as a dict; {} when the folder has none (an unfinished or failed run, docs/formats.md)."""
    if not os.path.exists(path):
        return {}
    try:
        with open(path, encoding="utf-8") as f:
            manifest = json.load(f)
    except json.JSONDecodeError as e:
        raise RunInputError("%s:%d:%d: not valid JSON: %s" % (path, e.lineno, e.colno, e.msg))
    except (OSError, UnicodeDecodeError) as e:
        raise RunInputError("%s: cannot read: %s" % (path, e))
    if not isinstance(manifest, dict):
        raise RunInputError("%s: not a JSON object" % path)
    return manifest


def read_run(folder, label):
    if not os.path.isdir(folder):
        raise RunInputError("%s: no such folder" % folder)
    stand, species, header = read_stand_table(os.path.join(folder, "stand_table.csv"))
    computed = production_series(stand)
    for species_stand in species.values():
        production_series(species_stand)
    thinnings = read_thinnings(os.path.join(folder, "events.csv"))
    tree_years = read_trees(os.path.join(folder, "trees.csv"))
    if not tree_years:
        raise RunInputError("%s: no rows (the run wrote no output year)" % os.path.join(folder, "trees.csv"))
    final_age = max(tree_years)
    run = Run(folder=folder, label=label, stand=stand, species=species, death_causes=death_causes(header),
              computed=computed, thinnings=thinnings,
              distributions=thinning_distributions(thinnings, tree_years),
              final_diameters_cm=[dbh for _, status, dbh in tree_years[final_age]
                                  if status == "alive" and not math.isnan(dbh)],
              final_output_age=final_age, plot_area_ha=plot_area_ha(tree_years, stand),
              manifest=read_manifest(os.path.join(folder, "run.json")))
    if not run.manifest:
        run.notes.append("%s has no run.json: an unfinished or failed run (its tables stop at the last finished "
                         "year)." % label)
    if "hg_m" not in stand:
        run.notes.append("%s: stand_table.csv has no hg_m column, so the charts show no Hg." % label)
    return run
