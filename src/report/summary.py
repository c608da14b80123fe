"""The one-page report.md: which runs, a summary table, the charts embedded, and what was computed here.

One run: the stand at the first and the last row of stand_table.csv side by side. Several runs: one column per
run, "first → last". Removals and deaths are totals of the table's flow columns over the whole run.
"""
import math

from charts import DIAMETER_CLASS_CM

DISTRIBUTION_RULE = (
    "Diameters come from trees.csv, which has output years only: those of the last output year at or before "
    "the thinning. *Before* = the trees alive in that year (plus, when it is the thinning year itself, the trees "
    "trees.csv lists there as `removed`); *after* = before minus the trees events.csv lists as removed at that "
    "age. Trees that died between that output year and the thinning are not taken out. Classes are %g cm wide; "
    "the grey left showing above a green bar is what the thinning took from that class."
    % DIAMETER_CLASS_CM)

COMPUTED_NOTE = {
    "total_production_m3_per_ha": "total production = standing volume + cumulative removed and dead volume "
                                  "since the first row (what left the stand before the run is unknown)",
    "cai_m3_per_ha": "CAI = change of total production between consecutive rows per year (with one row per "
                     "output year: the periodic annual increment of each interval)",
    "mai_m3_per_ha": "MAI = total production / stand age",
}


def number(value, decimals):
    return "–" if value is None or math.isnan(value) else "%.*f" % (decimals, value)


def first_last(run, column, decimals):
    values = run.stand.get(column)
    if values is None:
        return "–", "–"
    return number(values[0], decimals), number(values[-1], decimals)


def flow_total(run, column, decimals):
    values = run.stand.get(column)
    if values is None:
        return "–"
    return number(sum(0.0 if math.isnan(v) else v for v in values), decimals)


# (row name, stand_table column, decimals) for the state of the stand at the first and last row.
STATE_ROWS = (
    ("stand age (years)", "stand_age", 0),
    ("stems/ha", "stems_per_ha", 0),
    ("basal area (m²/ha)", "basal_area_m2_per_ha", 1),
    ("Dg (cm)", "qmd_cm", 1),
    ("Hg (m)", "hg_m", 1),
    ("top height (m)", "top_height_m", 1),
    ("standing volume (m³/ha)", "volume_m3_per_ha", 0),
    ("total production (m³/ha)", "total_production_m3_per_ha", 0),
    ("MAI (m³/ha/year)", "mai_m3_per_ha", 1),
)


def flow_rows(runs):
    """(row name, stand_table column, decimals) of the totals over the run: removals, then deaths by cause."""
    rows = [("removed by thinning (stems/ha)", "removed_stems_per_ha", 0),
            ("removed volume (m³/ha)", "removed_volume_m3_per_ha", 0),
            ("died, all causes (stems/ha)", "dead_stems_per_ha", 0)]
    causes = []
    for run in runs:
        causes += [cause for cause in run.death_causes if cause not in causes]
    rows += [("died of %s (stems/ha)" % cause, "dead_%s_stems_per_ha" % cause, 0) for cause in causes]
    return rows + [("died volume (m³/ha)", "dead_volume_m3_per_ha", 0)]


def has_column(runs, column):
    return any(column in run.stand for run in runs)


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    return lines + ["| " + " | ".join(row) + " |" for row in rows]


def single_run_table(run):
    state = [[name, *first_last(run, column, decimals)]
             for name, column, decimals in STATE_ROWS if column in run.stand]
    totals = [[name, "", flow_total(run, column, decimals)] for name, column, decimals in flow_rows([run])]
    thinnings = [["thinnings", "", "%d (%s)" % (len(run.thinnings), ", ".join(
        "age %g: %s" % (t.age, t.reason) for t in run.thinnings)) if run.thinnings else "none"]]
    return table(["", "first year", "last year (totals over the run)"], state + thinnings + totals)


def comparison_table(runs):
    state = [[name] + [" → ".join(first_last(run, column, decimals)) if column in run.stand else "–" for run in runs]
             for name, column, decimals in STATE_ROWS if has_column(runs, column)]
    thinnings = [["thinnings"] + [", ".join("age %g" % t.age for t in run.thinnings) or "none" for run in runs]]
    totals = [[name] + [flow_total(run, column, decimals) for run in runs]
              for name, column, decimals in flow_rows(runs)]
    return table([""] + [run.label for run in runs], state + thinnings + totals)


def run_lines(runs):
    lines = []
    for run in runs:
        manifest = run.manifest
        details = ["folder `%s`" % run.folder]
        for key, name in (("scenario", "scenario"), ("seed", "seed"), ("heliostand_version", "heliostand"),
                          ("finished_utc", "finished")):
            if key in manifest:
                details.append("%s `%s`" % (name, manifest[key]))
        lines.append("- **%s**: %s" % (run.label, ", ".join(details)))
    return lines


def notes(runs):
    lines = []
    for column, text in COMPUTED_NOTE.items():
        labels = [run.label for run in runs if column in run.computed]
        if labels:
            lines.append("- Computed here, stand_table.csv has no `%s` (%s): %s." % (column, ", ".join(labels), text))
    for run in runs:
        lines += ["- %s" % note for note in run.notes]
    return lines


def chart_lines(over_age, final_chart, thinning_charts):
    lines = ["## Over stand age", "",
             "Dashed vertical lines: thinnings (events.csv), labelled with their reason.", ""]
    for title, name in over_age:
        lines += ["### %s" % title, "", "![%s](%s)" % (title, name), ""]
    lines += ["## Diameter distributions", "", "![Diameter distribution in the last output year](%s)" % final_chart,
              ""]
    if thinning_charts:
        lines += ["### Before and after each thinning", "", DISTRIBUTION_RULE, ""]
    for run, distribution, name in thinning_charts:
        title = "%s, thinning at age %g" % (run.label, distribution.thinning.age)
        lines += ["![%s](%s)" % (title, name), ""]
    return lines


def write_report(path, runs, over_age, final_chart, thinning_charts):
    if len(runs) == 1:
        title, summary = "heliostand report: %s" % runs[0].label, single_run_table(runs[0])
    else:
        title = "heliostand report: %s" % " vs ".join(run.label for run in runs)
        summary = comparison_table(runs)
    lines = ["# %s" % title, ""] + run_lines(runs) + ["", "## Summary", ""] + summary + [""]
    run_notes = notes(runs)
    if run_notes:
        lines += ["Notes:", ""] + run_notes + [""]
    lines += chart_lines(over_age, final_chart, thinning_charts)
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))
