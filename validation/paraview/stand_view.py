"""The standard view of a heliostand series (stand.pvd), shared by the macro heliostand_view.py (the ParaView GUI
and pvbatch) and render_stand.py (the README's pictures): stems and branches as tubes of their wood radius, trunks,
foliage coloured by light on one fixed 0..1 scale with its legend, roots below a half-transparent ground, and the
stand age written in a corner.

Each block the writer can write is drawn by one function of BLOCK_DISPLAYS (block name -> function(block, view)
returning the source it shows); a new block is drawn by adding one function there. Blocks not listed (`trees`,
`soil`) are not drawn: `trees` is one point per tree (its attributes are on every block's cells), `soil` a grid.
"""
import os
import xml.etree.ElementTree as ElementTree

from pvbatch_common import radius_tubes

from paraview.simple import (AnnotateTimeFilter, ColorBy, ExtractBlock, ExtractSurface, GetColorTransferFunction,
                             GetScalarBar, Glyph, PassArrays, Plane, Show, Threshold, Tube)

BARK = [0.45, 0.30, 0.18]
GROUND = [0.55, 0.62, 0.45]
SKY = [0.86, 0.91, 0.97]
INK = [0.1, 0.1, 0.1]
ROOT = [0.78, 0.62, 0.42]
LIGHT_PRESET = "Viridis (matplotlib)"
# The legend names the array it colours by: `light`, the share of the open sky's light a leaf ball receives, its own
# crown's shade included (docs/formats.md). Not the growth rules' `relative_light` (stand / the tree alone), which
# is near 1 at the top of a dominant's crown where `light` may read 0.2.
LIGHT_TITLE = "light (of the open sky)"
ROOT_LINE_PIXELS = 2.0


# Cell filters for `only`: (tree attribute, lowest, highest value kept).
LIVING = ("status", 0, 0)  # the living trees: the stand after the year's thinning


def block(reader, name, only=None):
    """One named block of the yearly multiblock (empty if absent that year). It stays a multiblock of
    polydata, which Tube and Glyph accept; MergeBlocks would turn it into an unstructured grid. `only`: keep the
    cells whose tree attribute is in a range, e.g. LIVING or ("tree_id", 7, 7)."""
    extract = ExtractBlock(Input=reader)
    extract.Selectors = ["/Root/" + name]
    if only is None:
        return extract
    array, low, high = only
    kept = Threshold(Input=extract, Scalars=["CELLS", array], LowerThreshold=low, UpperThreshold=high)
    return ExtractSurface(Input=kept)  # Threshold gives unstructured grids; Tube and Glyph want polydata


def colour_by_light(display, association, view):
    """Colour by `light` on the one fixed 0..1 scale shared by every block and year, with its legend."""
    ColorBy(display, (association, "light"))
    light = GetColorTransferFunction("light")
    light.ApplyPreset(LIGHT_PRESET, True)
    light.AutomaticRescaleRangeMode = "Never"  # ParaView would otherwise stretch it to each year's values
    light.RescaleTransferFunction(0.0, 1.0)  # a fixed scale keeps blocks and years comparable
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(light, view)
    bar.Title = LIGHT_TITLE
    bar.ComponentTitle = ""
    bar.TitleColor = INK
    bar.LabelColor = INK


def solid(display, colour):
    display.ColorArrayName = ["POINTS", ""]  # one colour, not a data array
    display.AmbientColor = colour
    display.DiffuseColor = colour


def show_branches(source, view):
    """Every shoot (detail `full`) as a tube of its wood radius (Tube, Vary Radius: By Absolute Scalar), carrying
    only the arrays the view uses: `radius`, and `tree_id`, whose branches they are. Each shoot becomes a dozen tube
    cells (the example's half million shoots, six million), and copying the shoots' other ten cell arrays to every
    one of them took 30 % of the tubes' time (docs/performance.md, "Both trees built by Ninja, and the branch
    tubes' arrays")."""
    kept = PassArrays(Input=source)
    kept.PointDataArrays = ["radius"]
    kept.CellDataArrays = ["tree_id"]
    tubes = Tube(Input=kept)
    tubes.Scalars = ["POINTS", "radius"]
    tubes.VaryRadius = "By Absolute Scalar"
    tubes.NumberofSides = 10
    tubes.Capping = 1
    solid(Show(tubes, view), BARK)
    return tubes


def show_stem(source, view):
    """The stem axis (detail `envelope`) as tubes of its wood radius."""
    return radius_tubes(source, view, BARK, floor=0.01, sides=10)


def show_trunk(source, view):
    """Every stem surface (detail `full`), hollows included."""
    solid(Show(source, view), BARK)
    return source


def show_leaf_balls(source, view):
    """Each leaf ball as a sphere of its own radius coloured by the light it receives."""
    spheres = Glyph(Input=source, GlyphType="Sphere")
    spheres.ScaleArray = ["POINTS", "radius"]
    spheres.ScaleFactor = 2.0  # the glyph sphere has radius 0.5: scale by 2 r to get radius r
    spheres.OrientationArray = ["POINTS", "No orientation array"]
    spheres.GlyphMode = "All Points"
    spheres.GlyphType.ThetaResolution = 12
    spheres.GlyphType.PhiResolution = 8
    colour_by_light(Show(spheres, view), "POINTS", view)
    return spheres


def show_foliage(source, view):
    """Needle sprays (detail `full`): one piece around each living foliage-year shoot, as wide as the leaf ball it
    stands for, coloured by that ball's light (point data)."""
    colour_by_light(Show(source, view), "POINTS", view)
    return source


def show_crowns(source, view):
    """Crown cones, coloured by their tree's mean light (cell data)."""
    colour_by_light(Show(source, view), "CELLS", view)
    return source


def show_envelopes(source, view):
    """Crown envelopes, coloured by the light at each corner (point data: the nearest leaf ball's), so a crown
    shows its lit top and shaded base; series written before the envelopes had it: their tree's mean (cell data)."""
    source.UpdatePipeline(view.ViewTime)  # at the view's time (the last year): without a time, the first
    corners = "light" in source.PointData.keys()
    colour_by_light(Show(source, view), "POINTS" if corners else "CELLS", view)
    return source


def show_roots(source, view):
    """Root segments as lines drawn as shaded tubes a few pixels wide (Render Lines As Tubes), not as Tube filter
    geometry: the example's roots are 290 000 segments a year, and tubes of them took 2.3 million polygons, 0.6 GB
    and most of a picture's time (docs/formats.md, "Rendering with ParaView")."""
    display = Show(source, view)
    solid(display, ROOT)
    display.RenderLinesAsTubes = 1
    display.LineWidth = ROOT_LINE_PIXELS
    return source


# Block name -> how it is drawn, in drawing order.
BLOCK_DISPLAYS = [
    ("branches", show_branches),
    ("stem", show_stem),
    ("trunk", show_trunk),
    ("leaf_balls", show_leaf_balls),
    ("foliage", show_foliage),
    ("crown_envelope", show_envelopes),
    ("crown_cone", show_crowns),
    ("roots", show_roots),
]


def series_blocks(pvd):
    """The names of the blocks the series' years hold (all years: roots may be written only every few years)."""
    names = set()
    try:
        folder = os.path.dirname(pvd)
        for dataset in ElementTree.parse(pvd).getroot().iter("DataSet"):
            if dataset.get("file"):
                vtm = os.path.join(folder, dataset.get("file"))
                names.update(b.get("name") for b in ElementTree.parse(vtm).getroot().iter() if b.get("name"))
    except (OSError, ElementTree.ParseError):
        pass
    return names


def blocks_to_draw(pvd):
    """The blocks of BLOCK_DISPLAYS the series holds. At `full` the crown envelopes would hide the shoots and
    leaf balls they enclose: those are drawn instead; and the leaf balls would hide the needle foliage that stands
    for them (they stay in the files as the model's own view: draw the block `leaf_balls` to see them)."""
    present = series_blocks(pvd)
    if "branches" in present:
        present.discard("crown_envelope")
    if "foliage" in present:
        present.discard("leaf_balls")
    return [(name, show) for name, show in BLOCK_DISPLAYS if name in present]


def show_stand(reader, pvd, view, only=None):
    """Draws every block of the series the standard way and the stand age. Returns {block name: shown source}."""
    shown = {name: show(block(reader, name, only), view) for name, show in blocks_to_draw(pvd)}
    show_age(reader, view)
    return shown


def show_age(reader, view):
    """The stand age (the series' time) in the upper left corner."""
    age = AnnotateTimeFilter(Input=reader)
    age.Format = "stand age {time:.0f} years"
    display = Show(age, view)
    display.WindowLocation = "Upper Left Corner"
    display.Color = INK
    display.FontSize = 22


def show_ground(bounds, view, below_roots):
    """The ground plane, half transparent over roots (at z = 0 where stems stand), else opaque at the bottom of
    the data."""
    x0, x1, y0, y1, z0, _ = bounds
    if below_roots:
        z0 = 0.0
    margin = 0.05 * max(x1 - x0, y1 - y0, 1.0)
    ground = Plane(Origin=[x0 - margin, y0 - margin, z0], Point1=[x1 + margin, y0 - margin, z0],
                   Point2=[x0 - margin, y1 + margin, z0])
    display = Show(ground, view)
    display.AmbientColor = GROUND
    display.DiffuseColor = GROUND
    display.Opacity = 0.35 if below_roots else 1.0
    return ground


def frame_stand(view, bounds):
    """Look at the stand from the south-east and above, then zoom so everything is in view."""
    x0, x1, y0, y1, z0, z1 = bounds
    centre = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2]
    size = max(x1 - x0, y1 - y0, z1 - z0, 1.0)
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0] + 1.2 * size, centre[1] - 1.8 * size, centre[2] + 1.0 * size]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera(False)
    view.GetActiveCamera().Dolly(1.25)  # ResetCamera fits the bounding sphere, which leaves wide margins
    # In pvbatch, paraview.simple's first Render() resets the camera once more, to what it draws, without the dolly:
    # the scripts draw the last year first, so that is the last year's frame.


def time_steps(reader):
    values = reader.TimestepValues
    if values is None:
        return [0.0]
    try:
        return list(values)
    except TypeError:  # a single time step comes back as a bare number
        return [values]


def last_year_first(ages):
    """`ages` in the order to draw them after standard_view: newest first, so that the last year, whose geometry it
    left built, is drawn before any other when it is among them (the camera stays the first picture's)."""
    return sorted(ages, reverse=True)


def standard_view(reader, pvd, view, only=None):
    """The whole standard view on `view`, framed on the last (largest) year, which it leaves the view at. Returns
    {block: shown source}. `only`: the cells to keep (block()), e.g. LIVING leaves out the trees that died or were
    removed since the previous output year."""
    last = time_steps(reader)[-1]
    # The view's time is set before the blocks are shown: Show builds each block's geometry (tubes, glyphs) at the
    # view's time, and left at its default it would build the first year's, to be built again for the picture of
    # the last (docs/formats.md, "Each block shown at the last year first"). Callers draw in last_year_first's order.
    view.ViewTime = last
    shown = show_stand(reader, pvd, view, only)
    reader.UpdatePipeline(last)
    bounds = reader.GetDataInformation().GetBounds()
    show_ground(bounds, view, below_roots="roots" in shown)
    frame_stand(view, bounds)
    return shown
