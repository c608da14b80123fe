"""A close-up of one crown's needle foliage, for docs/formats.md's block `foliage`. Run with pvbatch:

    validation/paraview/run_pvbatch.sh validation/paraview/foliage_closeup.py LOG_DIR OUT/stand.pvd PNG [TREE]

Needs a series written at `detail = "full"` (blocks `foliage` and `branches`; the example's own scenario
stands/sobetsu/scenario.toml writes it). Writes PNG, 1000 x 650 pixels: the upper crown of one tree in the last
output year, alone, its needle sprays (`foliage`) coloured by point `light` on the fixed 0..1 scale with its legend
and its shoots (`branches`) as tubes of their wood radius. The tree: TREE (trees.csv's `tree_id` or `label`), by
default the tallest living tree of the last year (as readme_pictures.py's crown picture). Prints the PNG's path
(run_pvbatch.sh checks it).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pvbatch_common import new_view  # noqa: E402
from readme_pictures import SIZE, rows, save  # noqa: E402
from stand_view import (SKY, block, series_blocks, show_age, show_branches, show_foliage,  # noqa: E402
                        time_steps)

from paraview.simple import Delete, PVDReader, Render  # noqa: E402

NEEDS = ("foliage", "branches")
# The camera, in the tree's crown lengths: it looks at a point this far below the top, from this far away (the top
# fifth of the crown in the picture, each shoot's spray a few dozen pixels wide).
FOCUS_BELOW_TOP = 0.1
DISTANCE = 0.38


def pick_tree(last_trees, wanted):
    """The tree named by `wanted` (tree_id or label), else the tallest."""
    if wanted is None:
        return max(last_trees, key=lambda t: float(t["height_m"]))
    for tree in last_trees:
        if wanted in (tree["tree_id"], tree["label"]):
            return tree
    return None


def aim(view, tree):
    """Look at the crown's top from the south-south-east, a little from above, as crown_picture does but closer."""
    x, y, height = float(tree["x_m"]), float(tree["y_m"]), float(tree["height_m"])
    crown = height - float(tree["crown_base_m"])
    centre = [x, y, height - FOCUS_BELOW_TOP * crown]
    reach = DISTANCE * crown
    view.CameraFocalPoint = centre
    view.CameraPosition = [x + 0.5 * reach, y - reach, centre[2] + 0.25 * reach]
    view.CameraViewUp = [0, 0, 1]


def closeup(pvd, png, tree):
    """The tree's shoots and foliage alone (its cells by tree_id), at the last output year."""
    tree_id = int(tree["tree_id"])
    only = ("tree_id", tree_id, tree_id)
    reader = PVDReader(FileName=pvd)
    view = new_view(SIZE, SKY, axes=False)
    view.ViewTime = time_steps(reader)[-1]  # before Show, which builds the tubes at the view's time
    show_branches(block(reader, "branches", only), view)
    show_foliage(block(reader, "foliage", only), view)
    show_age(reader, view)
    # paraview.simple resets the camera at a script's first Render() to what is drawn: render once before aiming.
    Render(view)
    aim(view, tree)
    save(view, png, [])
    Delete(view)  # while the X display still exists (render_stand.py says why)


def main(argv):
    if len(argv) not in (3, 4):
        sys.stderr.write("usage: pvbatch foliage_closeup.py STAND_PVD PNG [TREE_ID|LABEL]\n")
        return 2
    pvd, png = argv[1], argv[2]
    if not os.path.isfile(pvd):
        sys.stderr.write("error: %s: no such file\n" % pvd)
        return 2
    missing = [name for name in NEEDS if name not in series_blocks(pvd)]
    if missing:
        sys.stderr.write("error: %s has no block %s: write the series with [run] detail = \"full\"\n"
                         % (pvd, ", ".join(missing)))
        return 2
    trees = rows(os.path.join(os.path.dirname(os.path.abspath(pvd)), "trees.csv"))
    last_age = max(int(t["stand_age"]) for t in trees)
    last_trees = [t for t in trees if int(t["stand_age"]) == last_age and t["status"] == "alive"]
    tree = pick_tree(last_trees, argv[3] if len(argv) == 4 else None)
    if tree is None:
        sys.stderr.write("error: no living tree %s at stand age %d\n" % (argv[3], last_age))
        return 2
    if os.path.dirname(png):
        os.makedirs(os.path.dirname(png), exist_ok=True)
    closeup(pvd, png, tree)
    print(png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
