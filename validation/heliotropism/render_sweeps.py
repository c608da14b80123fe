"""Draw the seed-000 validation sweeps like the paper's figure panels (run with pvbatch, through
validation/paraview/run_pvbatch.sh).

    pvbatch render_sweeps.py TREES_DIR OUT_DIR

TREES_DIR is the `trees` folder `heliotropism_validation validate OUT` writes: index.csv lists, per sweep and in
panel order, a label and the first seed's tree (NAME.vtp: living branches as lines with a pipe-model `radius`;
NAME_tips.vtp: the living tips, i.e. the leaf-ball centres). One PNG per sweep, its trees side by side from the
side (looking north), every panel at the same scale so sizes compare; Fig. 10 also from above, as in the paper,
whose top views show the spread of the tips. Leaf balls are drawn as small dots at the tips (the paper shows them
as circles; at their true radius R = 2 they would hide the branches).
"""
import csv
import os
import sys
from collections import OrderedDict

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "paraview"))
from pvbatch_common import new_view as common_view, radius_tubes  # noqa: E402

from paraview.simple import (CreateLayout, Delete, ExtractSurface, Glyph, RemoveLayout,
                             Render, SaveScreenshot, Show, Text, Threshold, XMLPolyDataReader)

PANEL_SIZE = [420, 560]  # pixels of one panel (side view); top views are square
BARK = [0.40, 0.26, 0.14]
SECOND_TREE = [0.15, 0.30, 0.60]  # Fig. 11's left tree, so the two crowns can be told apart
LEAF = [0.20, 0.62, 0.20]
BACKGROUND = [1.0, 1.0, 1.0]
INK = [0.1, 0.1, 0.1]
TIP_DOT_RADIUS = 0.3  # branch lengths
MARGIN = 1.15  # the largest tree fills the panel but for this factor (room for the labels)


def read_index(path):
    """Sweeps in file order, each a (title, [(label, branches file, tips file), ...])."""
    sweeps = OrderedDict()
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            title, panels = sweeps.setdefault(row["sweep"], (row["title"], []))
            panels.append((row["label"], row["branches"], row["tips"]))
    return sweeps


def bounds_of(source):
    source.UpdatePipeline()
    b = source.GetDataInformation().GetBounds()
    if b[0] > b[1]:  # no living branch left
        return None
    return b


def show_tubes(source, view, colour, floor):
    """Branches as tubes of their pipe-model radius, at least `floor` so the thinnest stay visible."""
    radius_tubes(source, view, colour, floor, sides=8)


def show_tree(branches, tips, view, two_trees, floor):
    if two_trees:  # group 1 is the right tree (the one that regrows), group 0 the left
        for group, colour in ((0, SECOND_TREE), (1, BARK)):
            part = Threshold(Input=branches, Scalars=["CELLS", "group"], LowerThreshold=group,
                             UpperThreshold=group)
            # Threshold gives an unstructured grid; Tube wants polylines.
            show_tubes(ExtractSurface(Input=part), view, colour, floor)
    else:
        show_tubes(branches, view, BARK, floor)
    dots = Glyph(Input=tips, GlyphType="Sphere")
    dots.ScaleArray = ["POINTS", "No scale array"]
    dots.ScaleFactor = 2.0 * TIP_DOT_RADIUS  # the glyph sphere has radius 0.5
    dots.OrientationArray = ["POINTS", "No orientation array"]
    dots.GlyphMode = "All Points"
    dots.GlyphType.ThetaResolution = 8
    dots.GlyphType.PhiResolution = 6
    display = Show(dots, view)
    display.ColorArrayName = ["POINTS", ""]
    display.AmbientColor = LEAF
    display.DiffuseColor = LEAF


def label(view, text, location, size):
    source = Text(Text=text)
    display = Show(source, view)
    display.WindowLocation = location
    display.FontSize = size
    display.Color = INK


def new_view(size):
    view = common_view(size, BACKGROUND, axes=False)
    view.CameraParallelProjection = 1
    return view


def place_camera(view, centre, direction, up, scale):
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[i] - 1000.0 * direction[i] for i in range(3)]
    view.CameraViewUp = up
    view.CameraParallelScale = scale


def render_sweep(trees_dir, out_path, title, panels, top_view):
    """One image: the panels side by side in a layout, same parallel scale in all of them."""
    size = [PANEL_SIZE[0], PANEL_SIZE[0]] if top_view else PANEL_SIZE
    aspect = size[0] / size[1]
    two_trees = any("left cut" in p[0] for p in panels)
    sources = []
    for text, branches_file, tips_file in panels:
        branches = XMLPolyDataReader(FileName=[os.path.join(trees_dir, branches_file)])
        tips = XMLPolyDataReader(FileName=[os.path.join(trees_dir, tips_file)])
        sources.append((text, branches, tips, bounds_of(branches)))
    present = [b for _, _, _, b in sources if b is not None]
    if not present:
        raise RuntimeError("%s: every tree is empty" % title)
    # Half the visible height in world units, fitted to the largest tree (x extent over the panel's aspect).
    if top_view:
        extent = max(max(b[1] - b[0], b[3] - b[2]) for b in present)
        scale = 0.5 * MARGIN * extent + TIP_DOT_RADIUS
    else:
        scale = 0.5 * MARGIN * max(max(b[5] for b in present) - min(b[4] for b in present),
                                   max(b[1] - b[0] for b in present) / aspect)
        scale += TIP_DOT_RADIUS
    floor = 1.0 * scale / size[1]  # about one pixel wide at the least
    low, high = min(b[4] for b in present), max(b[5] for b in present)

    layout = CreateLayout(title)
    location = 0
    views = []
    for i, (text, branches, tips, b) in enumerate(sources):
        view = new_view(size)
        if i < len(sources) - 1:  # split off an equal share for this panel, the rest stays on the right
            location = layout.SplitHorizontal(location, 1.0 / (len(sources) - i))
            layout.AssignView(location, view)
            location += 1
        else:
            layout.AssignView(location, view)
        views.append(view)
        show_tree(branches, tips, view, two_trees, floor)
        label(view, text, "Upper Center", 15)
        if i == 0:
            label(view, title + (" (top view)" if top_view else ""), "Lower Left Corner", 12)
        if b is None:
            b = present[0]
        # Each tree centred across, all panels at one height so the trees stand on one ground line.
        centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (low + high) / 2]
        if top_view:
            place_camera(view, centre, [0.0, 0.0, -1.0], [0.0, 1.0, 0.0], scale)
        else:
            place_camera(view, centre, [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], scale)
        Render(view)
    layout.SetSize(size[0] * len(sources), size[1])
    SaveScreenshot(out_path, layout, SaveAllViews=1, ImageResolution=[size[0] * len(sources), size[1]],
                   SeparatorWidth=2, SeparatorColor=[0.6, 0.6, 0.6])
    # Release the render windows while the X display still exists (see render_stand.py).
    for view in views:
        Delete(view)
    RemoveLayout(layout)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: pvbatch render_sweeps.py TREES_DIR OUT_DIR\n")
        return 2
    trees_dir, out_dir = argv[1], argv[2]
    index = os.path.join(trees_dir, "index.csv")
    if not os.path.isfile(index):
        sys.stderr.write("error: %s: no such file (run heliotropism_validation validate first)\n" % index)
        return 2
    os.makedirs(out_dir, exist_ok=True)
    written = []
    for sweep, (title, panels) in read_index(index).items():
        name = os.path.join(out_dir, "%s_side.png" % sweep)
        render_sweep(trees_dir, name, title, panels, top_view=False)
        written.append(name)
        if sweep == "fig10":  # the paper's Fig. 10 adds top views: the spread of the tips
            name = os.path.join(out_dir, "%s_top.png" % sweep)
            render_sweep(trees_dir, name, title, panels, top_view=True)
            written.append(name)
    for name in written:
        print(name)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
