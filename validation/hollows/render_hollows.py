"""Render hollow meshes with ParaView (run with pvbatch, e.g. through validation/paraview/run_pvbatch.sh).

    pvbatch render_hollows.py --figures VTP_DIR OUT_DIR
        the seed-like figures written by FigureMeshes.WriteSeedLikeFiguresAsVtp (<build>/validation/hollows/),
        one PNG each, a close-up of the wound coloured to make the figure's point (see FIGURES)
    pvbatch render_hollows.py --mesh FILE.vtp|.vtu|.vtm --out PNG [--focus X Y Z] [--colour ARRAY]
                              [--azimuth DEG] [--elevation DEG] [--distance M] [--title TEXT] [--all-trees]
        one close-up of a hollow in any mesh file. In a multiblock (.vtm, e.g. the stand output STAND_AGE_NNNN.vtm)
        only the block named `trunk` is shown. --stand is a synonym of --mesh.

Colours: `part` (0 stem, 1 bark, 2 callus: the default), `callus_thickness_m` (the roll by its corner radius,
the rest by part), `bark_shift_m` (the bark by how far its lines were pushed sideways, grid edges drawn:
the bark lines), `bark_lift_m` (the bark by its rise onto the roll, the roll by its thickness).

Framing: the camera looks at the focus point (default: the centre of the callus nearest to it, or of all
callus) horizontally from outside the stem (the direction from the stem axis, found as the centre of the
stem's cross-section at the focus height, to the focus), raised by --elevation (default 15 degrees), from
a distance that fits the wound (--distance overrides it). If the points carry `tree_id` (stand output),
only the tree nearest to the focus is shown unless --all-trees is given, so that no other stem hides the
wound. Prints the path of every PNG written (run_pvbatch.sh checks them).
"""
import argparse
import math
import os
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "paraview"))
from pvbatch_common import new_view  # noqa: E402

from paraview import servermanager
from paraview.simple import (ColorBy, Contour, Delete, ExtractBlock, GetColorTransferFunction,
                             GetScalarBar, MergeBlocks, OpenDataFile, PointDatatoCellData, Render, SaveScreenshot,
                             Show, Text, Threshold)

IMAGE_SIZE = [1200, 900]
BACKGROUND = [0.93, 0.94, 0.96]
INK = [0.1, 0.1, 0.1]
PART_NAMES = ["stem", "bark", "callus"]
PART_COLOURS = [[0.62, 0.56, 0.48], [0.42, 0.27, 0.16], [0.93, 0.76, 0.50]]

# (file stem, colouring, elevation degrees, zoom-out factor, title): the seed's Figs. 4.1-4.4 and ours beyond.
FIGURES = [
    ("fig4_1_tall_narrow", "callus_thickness_m", 15, 1.0,
     "Fig. 4.1 analogue: tall narrow wound (W 6 cm, H 30 cm), callus thickest along the vertical rim"),
    ("fig4_1_round", "callus_thickness_m", 15, 1.0,
     "Fig. 4.1 analogue: round wound (W = H = 16 cm), callus by thickness"),
    ("fig4_1_wide_flat", "callus_thickness_m", 15, 1.0,
     "Fig. 4.1 analogue: wide flat wound (W 30 cm, H 8 cm), thin roll on the flat top and bottom"),
    ("fig4_2_bark_detour", "bark_shift_m", 10, 1.2,
     "Fig. 4.2 analogue: bark lines (grid columns) pushed around the wound, by sideways shift"),
    ("fig4_3_thick_roll", "bark_lift_m", 25, 1.0,
     "Fig. 4.3 analogue: bark rising onto a thick roll (bark by lift, roll by thickness)"),
    ("fig4_4_seed_tangent_plane", "part", 15, 2.5,
     "Fig. 4.4 analogue: hollow on a stem, seed's tangent-plane placement"),
    ("fig4_4_wide_wrapping", "part", 15, 1.3, "Beyond the seed: a wound wrapping 63 % of the stem"),
    ("fig4_4_root_collar", "part", 20, 1.5, "Beyond the seed: a hollow on a flaring root collar"),
    ("beyond_broken_stem_ring", "part", 40, 1.2, "Beyond the seed: callus all around a broken stem"),
    ("beyond_two_hollows", "part", 15, 1.0, "Beyond the seed: two hollows on one stem (stacked bands)"),
]


# ---------------------------------------------------------------------------------------------------------
# Reading and measuring (the fetched data is walked point by point: pvbatch here has no numpy).

def has_block(vtm, name):
    try:
        return any(b.get("name") == name for b in ElementTree.parse(vtm).getroot().iter())
    except (OSError, ElementTree.ParseError):
        return False


def open_mesh(path):
    """The mesh as a pipeline source: a .vtm is reduced to its `trunk` block (when it has one), merged."""
    reader = OpenDataFile(path)
    if reader is None:
        raise ValueError("%s: ParaView cannot read this file" % path)
    if path.endswith(".vtm"):
        if has_block(path, "trunk"):
            extract = ExtractBlock(Input=reader)
            extract.Selectors = ["//trunk"]  # at any depth of the multiblock
            reader = extract
        return MergeBlocks(Input=reader)
    return reader


def point_array(data, name):
    array = data.GetPointData().GetArray(name)
    return array


def bbox(points):
    xs, ys, zs = zip(*points)
    return [min(xs), max(xs), min(ys), max(ys), min(zs), max(zs)]


def centre_of(box):
    return [(box[0] + box[1]) / 2, (box[2] + box[3]) / 2, (box[4] + box[5]) / 2]


def wound_frame(data, focus=None):
    """(focus, outward unit vector (x, y), wound size, tree id or None) measured on the fetched mesh."""
    n = data.GetNumberOfPoints()
    if n == 0:
        raise ValueError("the mesh has no points")
    part = point_array(data, "part")
    tree = point_array(data, "tree_id")
    point = data.GetPoint
    tree_of = (lambda i: int(tree.GetTuple1(i))) if tree is not None else (lambda i: None)

    chosen_tree = None
    if focus is not None:
        nearest = min(range(n), key=lambda i: sum((a - b) ** 2 for a, b in zip(point(i), focus)))
        chosen_tree = tree_of(nearest)
    callus = []
    if part is not None:
        for i in range(n):
            if int(round(part.GetTuple1(i))) != 2 or (chosen_tree is not None and tree_of(i) != chosen_tree):
                continue
            p = point(i)
            if focus is None or sum((a - b) ** 2 for a, b in zip(p, focus)) < 1.0:
                callus.append(p)
    if callus:
        box = bbox(callus)
        size = max(box[1] - box[0], box[3] - box[2], box[5] - box[4])
        centre = centre_of(box)
    else:
        size = 0.4
        centre = list(focus) if focus is not None else centre_of(data.GetBounds())
    if focus is not None:
        centre = list(focus)

    # The stem axis at the focus height: the centre of the tree's cross-section there (a bounding box of a
    # ring is centred on its axis, however unevenly the ring is sampled).
    near = [p for p in (point(i) for i in range(n)
                        if chosen_tree is None or tree_of(i) == chosen_tree) if abs(p[2] - centre[2]) < 0.3]
    ring = []
    for slab in (0.01, 0.03, 0.1, 0.3):
        ring = [p for p in near if abs(p[2] - centre[2]) < slab]
        if len(ring) >= 8:
            break
    outward = [1.0, 0.0]
    if ring:
        box = bbox(ring)
        axis = centre_of(box)
        dx, dy = centre[0] - axis[0], centre[1] - axis[1]
        length = math.hypot(dx, dy)
        if length > 0.05 * max(box[1] - box[0], box[3] - box[2]):
            outward = [dx / length, dy / length]
    return centre, outward, size, chosen_tree


# ---------------------------------------------------------------------------------------------------------
# Colouring

def part_lookup_table():
    lut = GetColorTransferFunction("part")
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = sum([[str(i), name] for i, name in enumerate(PART_NAMES)], [])
    lut.IndexedColors = sum(PART_COLOURS, [])
    return lut


def style_bar(lut, view, title, position=None):
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = INK
    bar.LabelColor = INK
    bar.TitleFontSize = 18
    bar.LabelFontSize = 16
    bar.ScalarBarLength = 0.35
    if position is not None:
        bar.WindowLocation = "Any Location"
        bar.Position = position
    return bar


def colour_by_part(display, view, legend=True):
    ColorBy(display, ("POINTS", "part"))
    lut = part_lookup_table()
    display.LookupTable = lut
    if legend:
        display.SetScalarBarVisibility(view, True)
        style_bar(lut, view, "part", [0.88, 0.05])


def colour_by_range(display, source, view, array, preset, title, position, symmetric=False):
    """Colours by a point array over its range; `preset` is a ParaView preset name or a list of RGB
    colours spread evenly over the range."""
    ColorBy(display, ("POINTS", array))
    lut = GetColorTransferFunction(array)
    source.UpdatePipeline()
    low, high = source.PointData[array].GetRange()
    if symmetric:
        low, high = -max(abs(low), abs(high), 1e-6), max(abs(low), abs(high), 1e-6)
    high = max(high, low + 1e-6)
    if isinstance(preset, str):
        lut.ApplyPreset(preset, True)
    else:
        lut.RGBPoints = sum([[low + (high - low) * k / (len(preset) - 1)] + list(rgb)
                             for k, rgb in enumerate(preset)], [])
    lut.RescaleTransferFunction(low, high)
    lut.AutomaticRescaleRangeMode = "Never"
    display.SetScalarBarVisibility(view, True)
    style_bar(lut, view, title, position)


def show_bark_lines(cells, view):
    """The grain as lines: contours of the stem-grid column index `bark_line` half-way between neighbouring
    columns, on the bark patch only (cells whose corners are all bark), so they bend round the wound as the
    bark lines do."""
    bark = Threshold(Input=cells, Scalars=["CELLS", "part"], LowerThreshold=0.99, UpperThreshold=1.01)
    bark.UpdatePipeline()
    low, high = bark.PointData["bark_line"].GetRange()
    lines = Contour(Input=bark, ContourBy=["POINTS", "bark_line"], ComputeScalars=0,
                    Isosurfaces=[c + 0.5 for c in range(int(low), int(high))])
    display = Show(lines, view)
    display.ColorArrayName = ["POINTS", ""]
    display.DiffuseColor = [0.1, 0.1, 0.1]
    display.AmbientColor = [0.1, 0.1, 0.1]
    display.LineWidth = 1.5


def show_coloured(source, view, colour):
    """Shows the mesh; for the thickness/shift/lift colourings the roll and the rest are shown as separate
    pieces (cells whose corners are all callus, and the others), each coloured by what it carries."""
    if colour == "part":
        colour_by_part(Show(source, view), view)
        return
    cells = PointDatatoCellData(Input=source)
    cells.PassPointData = 1
    roll = Threshold(Input=cells, Scalars=["CELLS", "part"], LowerThreshold=1.99, UpperThreshold=2.01)
    rest = Threshold(Input=cells, Scalars=["CELLS", "part"], LowerThreshold=-1.0, UpperThreshold=1.99)
    roll_display, rest_display = Show(roll, view), Show(rest, view)
    if colour == "callus_thickness_m":
        colour_by_range(roll_display, roll, view, "callus_thickness_m", "Inferno (matplotlib)",
                        "callus thickness (m)", [0.88, 0.50])
        colour_by_part(rest_display, view)
    elif colour == "bark_shift_m":
        colour_by_range(rest_display, rest, view, "bark_shift_m", "Cool to Warm", "bark line shift (m)",
                        [0.88, 0.50], symmetric=True)
        show_bark_lines(cells, view)
        roll_display.ColorArrayName = ["POINTS", ""]
        roll_display.DiffuseColor = PART_COLOURS[2]
        roll_display.AmbientColor = PART_COLOURS[2]
    elif colour == "bark_lift_m":
        colour_by_range(rest_display, rest, view, "bark_lift_m", [PART_COLOURS[0], [0.35, 0.62, 0.35], [0.05, 0.35, 0.15]],
                        "bark lift (m)", [0.88, 0.05])
        colour_by_range(roll_display, roll, view, "callus_thickness_m", "Inferno (matplotlib)",
                        "callus thickness (m)", [0.88, 0.50])
    else:
        raise ValueError("unknown colouring %r (part, callus_thickness_m, bark_shift_m, bark_lift_m)" % colour)


# ---------------------------------------------------------------------------------------------------------

def render_mesh(path, out_png, focus=None, colour="part", azimuth=None, elevation=15.0, distance=None,
                zoom_out=1.0, title=None, all_trees=False):
    """One close-up PNG of the hollow in `path` (see the module documentation); returns the PNG's path."""
    source = open_mesh(path)
    source.UpdatePipeline()
    data = servermanager.Fetch(source)
    centre, outward, size, tree = wound_frame(data, focus)
    if tree is not None and not all_trees:
        source = Threshold(Input=source, Scalars=["POINTS", "tree_id"], LowerThreshold=tree - 0.5,
                           UpperThreshold=tree + 0.5)
    if azimuth is not None:
        outward = [math.cos(math.radians(azimuth)), math.sin(math.radians(azimuth))]

    view = new_view(IMAGE_SIZE, BACKGROUND)
    show_coloured(source, view, colour)
    if title:
        caption = Text(Text=title)
        caption_display = Show(caption, view)
        caption_display.WindowLocation = "Upper Center"
        caption_display.FontSize = 20
        caption_display.Color = INK
        try:  # a light box keeps the caption readable over dark bark
            caption_display.ShowBorder = "Always"
            caption_display.BackgroundColor = [1.0, 1.0, 1.0, 0.85]
            caption_display.BorderColor = [1.0, 1.0, 1.0]
        except (AttributeError, ValueError, TypeError):
            pass

    # The view angle is 30 degrees: at 3.2 sizes away the wound fills about 60 % of the image height.
    Render(view)  # the first render resets the camera to the whole data set: set ours after it
    d = distance if distance is not None else 3.2 * max(size, 0.05) * zoom_out
    e = math.radians(elevation)
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0] + d * math.cos(e) * outward[0], centre[1] + d * math.cos(e) * outward[1],
                           centre[2] + d * math.sin(e)]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    Render(view)
    out_dir = os.path.dirname(out_png)
    if out_dir:
        os.makedirs(out_dir, exist_ok=True)
    SaveScreenshot(out_png, view, ImageResolution=IMAGE_SIZE)
    # Release the render window while the X display still exists (see render_stand.py).
    Delete(view)
    del view
    return out_png


def render_figures(vtp_dir, out_dir):
    written = []
    for name, colour, elevation, zoom_out, title in FIGURES:
        path = os.path.join(vtp_dir, name + ".vtp")
        if not os.path.isfile(path):
            raise FileNotFoundError("%s: no such file (run FigureMeshes.WriteSeedLikeFiguresAsVtp first)" % path)
        written.append(render_mesh(path, os.path.join(out_dir, name + ".png"), colour=colour, elevation=elevation,
                                   zoom_out=zoom_out, title=title))
    return written


def main(argv):
    parser = argparse.ArgumentParser(prog="render_hollows.py", description=__doc__.split("\n\n")[0])
    parser.add_argument("--figures", nargs=2, metavar=("VTP_DIR", "OUT_DIR"))
    parser.add_argument("--mesh", "--stand", dest="mesh", metavar="FILE")
    parser.add_argument("--out", metavar="PNG")
    parser.add_argument("--focus", nargs=3, type=float, metavar=("X", "Y", "Z"))
    parser.add_argument("--colour", "--color", default="part",
                        choices=["part", "callus_thickness_m", "bark_shift_m", "bark_lift_m"])
    parser.add_argument("--azimuth", type=float, help="direction (degrees from +x) the camera looks from")
    parser.add_argument("--elevation", type=float, default=15.0)
    parser.add_argument("--distance", type=float, help="camera distance from the focus (m)")
    parser.add_argument("--title")
    parser.add_argument("--all-trees", action="store_true")
    args = parser.parse_args(argv[1:])
    if bool(args.figures) == bool(args.mesh) or (args.mesh and not args.out):
        parser.print_usage(sys.stderr)
        sys.stderr.write("error: give either --figures VTP_DIR OUT_DIR or --mesh FILE --out PNG\n")
        return 2
    try:
        if args.figures:
            written = render_figures(*args.figures)
        else:
            if not os.path.isfile(args.mesh):
                raise FileNotFoundError("%s: no such file" % args.mesh)
            written = [render_mesh(args.mesh, args.out, args.focus, args.colour, args.azimuth, args.elevation,
                                   args.distance, title=args.title, all_trees=args.all_trees)]
    except (OSError, ValueError) as error:
        sys.stderr.write("error: %s\n" % error)
        return 2
    for name in written:
        print(name)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
