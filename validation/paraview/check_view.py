"""Check the standard view (heliostand_view.py) draws the whole stand (run with pvbatch; see run_pvbatch.sh).

    pvbatch check_view.py STAND_PVD TREES_CSV OUT.png [AGE]

Draws the macro's picture of one year (default: the last) into OUT.png, prints its path (run_pvbatch.sh then checks
the picture: not blank, several colours), and checks against trees.csv and the year's multiblock:
- every block of the year is drawn, except those the view leaves out on purpose (`trees`, `soil`, and
  `crown_envelope` when `branches` is drawn, `leaf_balls` when `foliage` is), and each is visible;
- each drawn block shows the year asked for (the data its display rendered carries that time);
- the trees the drawn blocks show (distinct `tree_id`) are the trees trees.csv lists at that age: the stem or
  branches of every one of them, the foliage of every living tree with leaf balls, and nothing of another tree;
- the legend of each block coloured by a data array names that array: its title is the array's name, alone or
  followed by a gloss in brackets ("light (of the open sky)"), so that a legend cannot name one quantity while the
  colours show another.
Exit status 1 with a message when something is missing.
"""
import csv
import os
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import heliostand_view  # noqa: E402

from paraview import servermanager  # noqa: E402
from paraview.simple import Delete, GetColorTransferFunction, GetDisplayProperties, GetScalarBar  # noqa: E402

NOT_DRAWN = {"trees", "soil"}
WOOD = {"branches", "stem"}        # every tree of the year
FOLIAGE = {"leaf_balls", "foliage", "crown_envelope", "crown_cone"}  # at least every living tree with leaf balls


def trees_at(trees_csv, age):
    """{tree_id: (status, leaf balls)} of trees.csv's rows at stand age `age`."""
    with open(trees_csv, newline="") as f:
        return {int(row["tree_id"]): (row["status"], int(row["leaf_balls"]))
                for row in csv.DictReader(f) if abs(float(row["stand_age"]) - age) < 1e-6}


def blocks_in_year(pvd, age):
    """The names of the blocks of the year's multiblock file."""
    for dataset in ElementTree.parse(pvd).getroot().iter("DataSet"):
        if abs(float(dataset.get("timestep")) - age) < 1e-6:
            vtm = os.path.join(os.path.dirname(pvd), dataset.get("file"))
            return {b.get("name") for b in ElementTree.parse(vtm).getroot().iter() if b.get("name")}
    return set()


def tree_ids_shown(source, age):
    """Distinct tree_id values of what `source` draws at `age` (cell data, else point data)."""
    source.UpdatePipeline(age)
    data = servermanager.Fetch(source)
    ids = set()
    iterator = data.NewIterator() if data.IsA("vtkCompositeDataSet") else None
    pieces = []
    if iterator is None:
        pieces.append(data)
    else:
        iterator.InitTraversal()
        while not iterator.IsDoneWithTraversal():
            pieces.append(iterator.GetCurrentDataObject())
            iterator.GoToNextItem()
    for piece in pieces:
        array = piece.GetCellData().GetArray("tree_id") or piece.GetPointData().GetArray("tree_id")
        if array is not None:
            ids.update(int(array.GetTuple1(i)) for i in range(array.GetNumberOfTuples()))
    return ids


def drawn_age(display):
    """The stand age of the data `display` draws (what the render used, not what the checks below update), or
    None when the data carries no time."""
    information = display.GetRepresentedDataInformation()  # a vtkPVDataInformation
    return information.GetTime() if information.GetHasTime() else None


def legend_problem(name, display, view):
    """A message when the block is coloured by an array whose legend is missing or names something else."""
    association, array = display.ColorArrayName
    if not array:
        return None  # one solid colour: no legend
    if not display.IsScalarBarVisible(view):
        return "block %s is coloured by %s %s without its legend" % (name, association.lower(), array)
    title = GetScalarBar(GetColorTransferFunction(array), view).Title
    if title.split(" (")[0] != array:
        return "block %s is coloured by %s but its legend is titled %r" % (name, array, title)
    return None


def problems_of(pvd, trees_csv, shown, age, view):
    expected = blocks_in_year(pvd, age) - NOT_DRAWN
    if "branches" in expected:
        expected.discard("crown_envelope")
    if "foliage" in expected:
        expected.discard("leaf_balls")
    problems = ["block %s is in the year but not drawn" % b for b in sorted(expected - set(shown))]
    trees = trees_at(trees_csv, age)
    if not trees:
        problems.append("trees.csv has no tree at stand age %g" % age)
    leafy = {t for t, (status, balls) in trees.items() if status == "alive" and balls > 0}
    visible = set()
    for name, source in sorted(shown.items()):
        display = GetDisplayProperties(source)
        if not display.Visibility:
            problems.append("block %s is hidden" % name)
        legend = legend_problem(name, display, view)
        if legend:
            problems.append(legend)
        drawn_at = drawn_age(display)
        if drawn_at is None or abs(drawn_at - age) > 1e-6:
            problems.append("block %s is drawn at stand age %s, not %g" % (name, drawn_at, age))
        ids = tree_ids_shown(source, age)
        visible |= ids
        print("%s: %d trees drawn" % (name, len(ids)))
        if ids - set(trees):
            problems.append("%s draws trees trees.csv does not list at %g: %s" % (name, age, sorted(ids - set(trees))))
        if name in WOOD and ids != set(trees):
            problems.append("%s draws %d trees, trees.csv lists %d" % (name, len(ids), len(trees)))
        if name in FOLIAGE and not leafy <= ids:
            problems.append("%s misses the foliage of trees %s" % (name, sorted(leafy - ids)))
    print("trees visible at stand age %g: %d (trees.csv: %d)" % (age, len(visible), len(trees)))
    if visible != set(trees):
        problems.append("%d trees visible, trees.csv lists %d" % (len(visible), len(trees)))
    return problems


def main(argv):
    if len(argv) not in (4, 5):
        sys.stderr.write("usage: pvbatch check_view.py STAND_PVD TREES_CSV OUT.png [AGE]\n")
        return 2
    pvd, trees_csv, png = argv[1:4]
    age = float(argv[4]) if len(argv) == 5 else None
    view, shown, age = heliostand_view.picture(pvd, png, age)
    problems = problems_of(pvd, trees_csv, shown, age, view)
    print(png)
    Delete(view)  # release the render window while the X display still exists (see render_stand.py)
    for problem in problems:
        sys.stderr.write("error: %s\n" % problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
