"""The README's pictures of a stand series, in the standard view (stand_view.py). Run with pvbatch:

    validation/paraview/run_pvbatch.sh validation/paraview/readme_pictures.py LOG_DIR OUT/stand.pvd IMAGE_DIR

Writes into IMAGE_DIR (names after the stand folder's name, e.g. `sobetsu`):
- NAME-age-A.png: the first output year (the survey) and the last year; NAME-age-A-thinned.png: each thinning
  year after the thinning (the removed trees left out);
- NAME-crown.png: a close-up of the crown of the tallest tree in the last year;
- NAME-top-view.png: the plot from above in the last year, with a red marker where a tree was removed by a
  thinning (the events.csv next to stand.pvd) and the year's trees.
Each is 1000 x 650 pixels; prints their paths (run_pvbatch.sh checks them).
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pvbatch_common import new_view  # noqa: E402
from stand_view import LIVING, SKY, last_year_first, standard_view, time_steps  # noqa: E402

from paraview.simple import Delete, Disk, PVDReader, Render, SaveScreenshot, Show  # noqa: E402

SIZE = [1000, 650]
MARK = [0.85, 0.1, 0.1]


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def save(view, path, written):
    Render(view)
    SaveScreenshot(path, view, ImageResolution=SIZE)
    written.append(path)


def stand_pictures(pvd, out, name, thinning_ages, written):
    """The first year, each thinning year after it and the last year, one camera for all."""
    for living_only, ages in ((False, None), (True, thinning_ages)):
        reader = PVDReader(FileName=pvd)
        times = time_steps(reader)
        view = new_view(SIZE, SKY)
        standard_view(reader, pvd, view, LIVING if living_only else None)
        for age in last_year_first(ages if ages is not None else {times[0], times[-1]}):
            view.ViewTime = age
            suffix = "-thinned" if living_only else ""
            save(view, os.path.join(out, "%s-age-%d%s.png" % (name, age, suffix)), written)
        Delete(view)


def crown_picture(pvd, out, name, last_trees, written):
    """The tallest tree of the last year alone, close."""
    tallest = max(last_trees, key=lambda t: float(t["height_m"]))
    x, y, height = float(tallest["x_m"]), float(tallest["y_m"]), float(tallest["height_m"])
    base = float(tallest["crown_base_m"])
    tree_id = int(tallest["tree_id"])
    reader = PVDReader(FileName=pvd)
    view = new_view(SIZE, SKY, axes=False)
    standard_view(reader, pvd, view, ("tree_id", tree_id, tree_id))
    view.ViewTime = time_steps(reader)[-1]
    centre = [x, y, (base + height) / 2]
    reach = 1.6 * (height - base)
    view.CameraFocalPoint = centre
    view.CameraPosition = [x + 0.6 * reach, y - reach, centre[2] + 0.3 * reach]
    view.CameraViewUp = [0, 0, 1]
    save(view, os.path.join(out, "%s-crown.png" % name), written)
    Delete(view)


def top_view(pvd, out, name, removed, tallest_m, written):
    """From above, a red disc (above the canopy) at every tree a thinning removed."""
    reader = PVDReader(FileName=pvd)
    view = new_view(SIZE, SKY, axes=False)
    standard_view(reader, pvd, view)
    view.ViewTime = time_steps(reader)[-1]
    top = tallest_m + 1.0
    for tree in removed:
        disc = Disk(InnerRadius=0.0, OuterRadius=0.35, CircumferentialResolution=24)
        shown = Show(disc, view)
        shown.Position = [float(tree["x_m"]), float(tree["y_m"]), top]
        shown.AmbientColor = MARK
        shown.DiffuseColor = MARK
    bounds = reader.GetDataInformation().GetBounds()
    cx, cy = (bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2
    view.CameraFocalPoint = [cx, cy, 0]
    view.CameraPosition = [cx, cy, 100]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1  # a map: the markers above the canopy stand over their trees
    view.ResetCamera(False)
    view.CameraParallelScale = 0.55 * max(bounds[3] - bounds[2], (bounds[1] - bounds[0]) * SIZE[1] / SIZE[0])
    save(view, os.path.join(out, "%s-top-view.png" % name), written)
    Delete(view)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: pvbatch readme_pictures.py STAND_PVD IMAGE_DIR\n")
        return 2
    pvd, out = argv[1], argv[2]
    run = os.path.dirname(os.path.abspath(pvd))
    name = os.path.basename(run)
    os.makedirs(out, exist_ok=True)
    events = rows(os.path.join(run, "events.csv"))
    trees = rows(os.path.join(run, "trees.csv"))
    thinned = [e for e in events if e["cause"] == "thinning"]
    thinning_ages = sorted({int(e["stand_age"]) for e in thinned})
    last_age = max(int(t["stand_age"]) for t in trees)
    # Positions of the removed trees: their row in the year they were written as removed.
    removed = [t for t in trees if t["status"] == "removed"]
    written = []
    stand_pictures(pvd, out, name, thinning_ages, written)
    crown_picture(pvd, out, name, [t for t in trees if int(t["stand_age"]) == last_age and t["status"] == "alive"],
                  written)
    top_view(pvd, out, name, removed, max(float(t["height_m"]) for t in trees), written)
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
