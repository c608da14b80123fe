"""The report's charts: one PNG per chart, every run on the same axes.

With one run the quantities sharing a chart get their own colours; with several runs each run keeps one colour
on every chart and the quantities are told apart by line style. Thinnings are dashed vertical lines on every
chart over stand age, labelled with their reason (events.csv).

matplotlib must be imported through `load_pyplot`, which selects the Agg backend (no display needed).
"""
import math
import re

from run_data import running_total

RUN_COLOURS = ("#1b6ca8", "#d1495b", "#2e933c", "#edae49", "#6a4c93", "#00798c", "#8d6a9f", "#5c5c5c")
QUANTITY_COLOURS = ("#2e6f40", "#b5651d", "#1b6ca8", "#8d6a9f")
LINE_STYLES = ("-", "--", ":", "-.")
CAUSE_COLOURS = ("#7f7f7f", "#b5651d", "#1b6ca8", "#d1495b", "#6a4c93", "#2e933c")
FIGURE_SIZE_IN = (8.0, 4.5)
DPI = 100
DIAMETER_CLASS_CM = 2.0

plt = None


def load_pyplot():
    """Import matplotlib with the Agg backend; raises ImportError when python3-matplotlib is missing."""
    global plt
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot
    plt = matplotlib.pyplot


# --- shared drawing ------------------------------------------------------------------------------------------

def new_chart(title, ylabel, xlabel="stand age (years)"):
    figure, axes = plt.subplots(figsize=FIGURE_SIZE_IN, dpi=DPI)
    axes.set_title(title)
    axes.set_xlabel(xlabel)
    axes.set_ylabel(ylabel)
    axes.grid(True, color="#dddddd", linewidth=0.6)
    axes.set_axisbelow(True)  # grid lines behind the bars, not across them
    return figure, axes


def save(figure, folder, name):
    figure.tight_layout()
    figure.savefig("%s/%s" % (folder, name))
    plt.close(figure)
    return name


def finite(xs, ys):
    """The points where both coordinates are defined (an empty stand has no mean height, for instance)."""
    pairs = [(x, y) for x, y in zip(xs, ys) if not (math.isnan(x) or math.isnan(y))]
    return [x for x, _ in pairs], [y for _, y in pairs]


def line_look(runs, run_index, quantity_index):
    """Colour and line style: by quantity for one run, by run (colour) and quantity (style) when comparing."""
    if len(runs) == 1:
        return QUANTITY_COLOURS[quantity_index % len(QUANTITY_COLOURS)], "-"
    return RUN_COLOURS[run_index % len(RUN_COLOURS)], LINE_STYLES[quantity_index % len(LINE_STYLES)]


def line_label(runs, run, quantity):
    if len(runs) == 1:
        return quantity
    return "%s, %s" % (quantity, run.label) if quantity else run.label


def mark_thinnings(axes, runs):
    """A dashed vertical line at every thinning, labelled once per age and reason."""
    labelled = set()
    for index, run in enumerate(runs):
        colour = "#555555" if len(runs) == 1 else RUN_COLOURS[index % len(RUN_COLOURS)]
        for thinning in run.thinnings:
            axes.axvline(thinning.age, color=colour, linestyle=(0, (4, 3)), linewidth=1.0, alpha=0.8)
            if (thinning.age, thinning.reason) in labelled:
                continue
            labelled.add((thinning.age, thinning.reason))
            axes.text(thinning.age, 0.98, " %s " % thinning.reason, transform=axes.get_xaxis_transform(),
                      rotation=90, ha="right", va="top", fontsize=7, color=colour)


def draw_quantity(axes, runs, run_index, quantity_index, quantity, column):
    """One stand_table column over age; a column the table lacks (Hg in the older layout) is left out."""
    run = runs[run_index]
    if column not in run.stand:
        return
    colour, style = line_look(runs, run_index, quantity_index)
    xs, ys = finite(run.ages, run.stand[column])
    axes.plot(xs, ys, color=colour, linestyle=style, marker="." if len(xs) < 40 else None,
              label=line_label(runs, run, quantity))


def over_age_chart(runs, folder, name, title, ylabel, quantities, species_lines=False):
    """Lines over stand age; `quantities` = [(legend name, stand_table column)], absent columns are skipped."""
    figure, axes = new_chart(title, ylabel)
    for run_index, run in enumerate(runs):
        for quantity_index, (quantity, column) in enumerate(quantities):
            draw_quantity(axes, runs, run_index, quantity_index, quantity, column)
        if species_lines and len(runs) == 1:
            draw_species(axes, run, quantities[0][1])
    mark_thinnings(axes, runs)
    axes.set_ylim(bottom=0)
    if axes.get_legend_handles_labels()[0]:  # a lone unnamed line (one run, one quantity) needs no legend
        axes.legend(fontsize=8)
    return save(figure, folder, name)


def draw_species(axes, run, column):
    """Thin dashed lines per species, where the table has more than one (with one they repeat the total)."""
    if len(run.species) < 2:
        return
    for index, (species, stand) in enumerate(sorted(run.species.items())):
        xs, ys = finite(stand["stand_age"], stand[column])
        axes.plot(xs, ys, color=RUN_COLOURS[index % len(RUN_COLOURS)], linestyle="--", linewidth=1,
                  label=species)


# --- the charts over stand age ------------------------------------------------------------------------------------

def stems_chart(runs, folder):
    return over_age_chart(runs, folder, "stems_per_ha.png", "Living stems per hectare", "stems/ha",
                          [("all species" if has_species(runs) else "", "stems_per_ha")], species_lines=True)


def basal_area_chart(runs, folder):
    return over_age_chart(runs, folder, "basal_area.png", "Basal area", "basal area (m²/ha)",
                          [("all species" if has_species(runs) else "", "basal_area_m2_per_ha")], species_lines=True)


def has_species(runs):
    return len(runs) == 1 and len(runs[0].species) > 1


def diameter_height_chart(runs, folder):
    """Dg above, Hg and top height below: centimetres and metres do not share an axis."""
    figure, (upper, lower) = plt.subplots(2, 1, figsize=(FIGURE_SIZE_IN[0], FIGURE_SIZE_IN[1] * 1.5), dpi=DPI,
                                          sharex=True)
    upper.set_title("Quadratic mean diameter (Dg) and heights")
    upper.set_ylabel("Dg (cm)")
    lower.set_ylabel("height (m)")
    lower.set_xlabel("stand age (years)")
    for run_index, run in enumerate(runs):
        draw_quantity(upper, runs, run_index, 0, "Dg", "qmd_cm")
        draw_quantity(lower, runs, run_index, 1, "Hg", "hg_m")
        draw_quantity(lower, runs, run_index, 2, "top height", "top_height_m")
    for axes in (upper, lower):
        axes.grid(True, color="#dddddd", linewidth=0.6)
        mark_thinnings(axes, runs)
        axes.set_ylim(bottom=0)
        if axes.get_legend_handles_labels()[0]:
            axes.legend(fontsize=8)
    return save(figure, folder, "diameter_and_height.png")


def volume_chart(runs, folder):
    return over_age_chart(runs, folder, "volume_and_production.png", "Standing volume and total production",
                          "m³/ha", [("standing volume", "volume_m3_per_ha"),
                                    ("total production", "total_production_m3_per_ha")])


def increments_chart(runs, folder):
    return over_age_chart(runs, folder, "increments.png", "Current and mean annual volume increment",
                          "m³/ha/year", [(increment_name(runs), "cai_m3_per_ha"), ("MAI", "mai_m3_per_ha")])


def increment_name(runs):
    """CAI computed from rows several years apart is a periodic annual increment, and says so."""
    periodic = any("cai_m3_per_ha" in run.computed and row_period(run) != "year" for run in runs)
    return "periodic annual increment (CAI over each output interval)" if periodic else "CAI"


# --- mortality ---------------------------------------------------------------------------------------------------

def mortality_chart(runs, folder):
    """One run: stems/ha that died per table row, stacked by cause. Several: cumulative deaths per cause."""
    if len(runs) == 1:
        figure, axes = new_chart("Mortality by cause (stems/ha per %s)" % row_period(runs[0]), "stems/ha died")
        any_death = stacked_deaths(axes, runs[0])
    else:
        figure, axes = new_chart("Cumulative mortality by cause", "stems/ha died since the start")
        any_death = cumulative_deaths(axes, runs)
    if not any_death:
        axes.text(0.5, 0.5, "no tree died in %s" % ("this run" if len(runs) == 1 else "these runs"),
                  transform=axes.transAxes, ha="center", va="center", color="#555555")
        axes.set_ylim(0, 1)
    else:
        axes.set_ylim(0, axes.get_ylim()[1] * 1.15)  # room above the tallest bar for the thinning labels
    mark_thinnings(axes, runs)
    if axes.get_legend_handles_labels()[0]:
        axes.legend(fontsize=8)
    return save(figure, folder, "mortality_by_cause.png")


def row_period(run):
    steps = {b - a for a, b in zip(run.ages, run.ages[1:])}
    return "year" if steps <= {1.0} else "output interval"


def row_intervals(ages):
    """(start, length) of the years each row's flows cover: since the previous row; the first row its own year."""
    starts = [ages[0] - 1.0] + list(ages[:-1])
    return starts, [age - start for age, start in zip(ages, starts)]


def stacked_deaths(axes, run):
    """Each bar spans the years its row's deaths happened in, so a death in year 49 shows between 45 and 50."""
    bottom = [0.0] * len(run.ages)
    starts, lengths = row_intervals(run.ages)
    any_death = False
    for index, cause in enumerate(run.death_causes):
        heights = [0.0 if math.isnan(v) else v for v in run.stand["dead_%s_stems_per_ha" % cause]]
        axes.bar(starts, heights, width=[0.9 * length for length in lengths], bottom=bottom, align="edge",
                 color=CAUSE_COLOURS[index % len(CAUSE_COLOURS)], label=cause)
        bottom = [b + h for b, h in zip(bottom, heights)]
        any_death = any_death or any(h > 0 for h in heights)
    return any_death


def cumulative_deaths(axes, runs):
    any_death = False
    for run_index, run in enumerate(runs):
        for cause_index, cause in enumerate(run.death_causes):
            totals = running_total(run.stand["dead_%s_stems_per_ha" % cause])
            if totals[-1] <= 0:
                continue  # lines along zero would hide each other and crowd the legend
            axes.plot(run.ages, totals, color=RUN_COLOURS[run_index % len(RUN_COLOURS)],
                      linestyle=LINE_STYLES[cause_index % len(LINE_STYLES)], label="%s, %s" % (cause, run.label))
            any_death = True
    return any_death


# --- diameter distributions ---------------------------------------------------------------------------------------

def diameter_classes(*samples):
    """Class edges every DIAMETER_CLASS_CM from below the thinnest to above the thickest stem."""
    values = [v for sample in samples for v in sample]
    if not values:
        return [0.0, DIAMETER_CLASS_CM]
    low = math.floor(min(values) / DIAMETER_CLASS_CM) * DIAMETER_CLASS_CM
    high = (math.floor(max(values) / DIAMETER_CLASS_CM) + 1) * DIAMETER_CLASS_CM
    count = int(round((high - low) / DIAMETER_CLASS_CM))
    return [low + i * DIAMETER_CLASS_CM for i in range(count + 1)]


def per_ha(run, sample):
    """Histogram weights: stems/ha when the plot area is known, else trees on the plot."""
    weight = 1.0 / run.plot_area_ha if run.plot_area_ha else 1.0
    return [weight] * len(sample)


def stems_axis_label(runs):
    return "stems/ha" if all(run.plot_area_ha for run in runs) else "trees on the plot"


def thinning_chart(run, distribution, folder, name):
    """Before in grey, after in colour on top of it: the grey that shows is what the thinning took."""
    figure, axes = new_chart("%s: diameters before and after the thinning at age %g (%s)"
                             % (run.label, distribution.thinning.age, distribution.thinning.reason),
                             stems_axis_label([run]), xlabel="DBH class (cm, %g-cm classes)" % DIAMETER_CLASS_CM)
    edges = diameter_classes(distribution.before_cm)
    axes.hist(distribution.before_cm, bins=edges, weights=per_ha(run, distribution.before_cm), color="#bbbbbb",
              edgecolor="#777777", label="before (%d trees)" % len(distribution.before_cm))
    axes.hist(distribution.after_cm, bins=edges, weights=per_ha(run, distribution.after_cm), color="#2e6f40",
              edgecolor="#1d4529", rwidth=0.6, label="after (%d trees)" % len(distribution.after_cm))
    if distribution.snapshot_age != distribution.thinning.age:
        axes.text(0.01, 0.97, "diameters of the output year %g" % distribution.snapshot_age,
                  transform=axes.transAxes, va="top", fontsize=8)
    axes.title.set_fontsize(10)
    axes.legend(fontsize=8)
    return save(figure, folder, name)


def final_diameters_chart(runs, folder):
    figure, axes = new_chart("Diameter distribution in the last output year", stems_axis_label(runs),
                             xlabel="DBH class (cm, %g-cm classes)" % DIAMETER_CLASS_CM)
    edges = diameter_classes(*[run.final_diameters_cm for run in runs])
    for index, run in enumerate(runs):
        colour = RUN_COLOURS[index % len(RUN_COLOURS)]
        style = dict(histtype="bar", color=colour, edgecolor="#333333") if len(runs) == 1 else \
            dict(histtype="step", color=colour, linewidth=2, linestyle=LINE_STYLES[index % len(LINE_STYLES)])
        axes.hist(run.final_diameters_cm, bins=edges, weights=per_ha(run, run.final_diameters_cm),
                  label="%s, age %g (%d trees)" % (run.label, run.final_output_age, len(run.final_diameters_cm)),
                  **style)
    axes.legend(fontsize=8)
    return save(figure, folder, "diameter_distribution_final.png")


def slug(text):
    return re.sub(r"[^A-Za-z0-9]+", "-", text).strip("-") or "run"


def thinning_charts(runs, folder):
    """One chart per thinning of each run: (run, distribution, file name)."""
    charts = []
    for run in runs:
        for distribution in run.distributions:
            name = "diameter_distribution_age_%g.png" % distribution.thinning.age
            if len(runs) > 1:
                name = "diameter_distribution_%s_age_%g.png" % (slug(run.label), distribution.thinning.age)
            charts.append((run, distribution, thinning_chart(run, distribution, folder, name)))
    return charts


# --- all of them ----------------------------------------------------------------------------------------------------

OVER_AGE_CHARTS = (
    ("Stems per hectare", stems_chart),
    ("Basal area", basal_area_chart),
    ("Dg, Hg and top height", diameter_height_chart),
    ("Standing volume and total production", volume_chart),
    ("Volume increments (CAI, MAI)", increments_chart),
    ("Mortality by cause", mortality_chart),
)


def draw_all(runs, folder):
    """Every chart into `folder`; returns ([(title, file)] over age, final distribution file, thinning charts)."""
    over_age = [(title, draw(runs, folder)) for title, draw in OVER_AGE_CHARTS]
    return over_age, final_diameters_chart(runs, folder), thinning_charts(runs, folder)
