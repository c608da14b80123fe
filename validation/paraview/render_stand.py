"""Render a heliostand output series with ParaView (run with pvbatch; see render.sh).

    pvbatch render_stand.py STAND_PVD OUT_DIR [AGE ...]

Draws what the series' level of detail wrote (run.detail, docs/formats.md): at `full`, branches become tubes
whose radius is the wood radius written as point data (Tube filter, "Vary Radius: By Absolute Scalar") and leaf
balls spheres of their own radius coloured by their relative light; at `envelope`, the stem as tubes and each
tree's crown envelope coloured by the tree's light; at `cone`, each tree's crown cone coloured by its light. Roots (a `roots` block, written when the scenario has roots on) become tubes of
their own radius below a half-transparent ground. One PNG for the first and one for the last time step, both framed on the
stand as it is at the last time step so the two images compare directly. Given AGEs (stand ages), one PNG
per listed age instead (e.g. the years before and after a thinning).
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pvbatch_common import new_view, radius_tubes  # noqa: E402

from paraview.simple import (ColorBy, Delete, ExtractBlock, GetColorTransferFunction,
                             GetScalarBar, Glyph, Plane, PVDReader, Render, SaveScreenshot, Show, Tube)

IMAGE_SIZE = [1200, 800]
BARK = [0.45, 0.30, 0.18]
DEAD_WOOD = [0.60, 0.58, 0.55]
GROUND = [0.55, 0.62, 0.45]
SKY = [0.86, 0.91, 0.97]
INK = [0.1, 0.1, 0.1]
ROOT = [0.78, 0.62, 0.42]


def time_steps(reader):
    values = reader.TimestepValues
    if values is None:
        return [0.0]
    try:
        return list(values)
    except TypeError:  # a single time step comes back as a bare number
        return [values]


def block(reader, name):
    """One named block of the yearly multiblock (empty if absent that year). It stays a multiblock of
    polydata, which Tube and Glyph accept; MergeBlocks would turn it into an unstructured grid."""
    extract = ExtractBlock(Input=reader)
    extract.Selectors = ["/Root/" + name]
    return extract


def show_branches(reader, view):
    tubes = Tube(Input=block(reader, "branches"))
    tubes.Scalars = ["POINTS", "radius"]
    tubes.VaryRadius = "By Absolute Scalar"
    tubes.NumberofSides = 10
    tubes.Capping = 1
    display = Show(tubes, view)
    display.ColorArrayName = ["POINTS", ""]  # solid bark colour, not a data array
    display.AmbientColor = BARK
    display.DiffuseColor = BARK
    return tubes


def show_leaf_balls(reader, view):
    spheres = Glyph(Input=block(reader, "leaf_balls"), GlyphType="Sphere")
    spheres.ScaleArray = ["POINTS", "radius"]
    spheres.ScaleFactor = 2.0  # the glyph sphere has radius 0.5: scale by 2 r to get radius r
    spheres.OrientationArray = ["POINTS", "No orientation array"]
    spheres.GlyphMode = "All Points"
    spheres.GlyphType.ThetaResolution = 12
    spheres.GlyphType.PhiResolution = 8
    colour_by_light(Show(spheres, view), "POINTS", view)
    return spheres


def colour_by_light(display, association, view):
    """Colour by `light` on the one fixed 0..1 scale of every block and year, with its legend."""
    ColorBy(display, (association, "light"))
    light = GetColorTransferFunction("light")
    light.ApplyPreset("Viridis (matplotlib)", True)
    light.RescaleTransferFunction(0.0, 1.0)  # relative light: a fixed scale keeps years comparable
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(light, view)
    bar.Title = "relative light"
    bar.ComponentTitle = ""
    bar.TitleColor = INK
    bar.LabelColor = INK


def show_stem(reader, view):
    """The stem axis (detail `envelope`) as tubes of its wood radius."""
    return radius_tubes(block(reader, "stem"), view, BARK, floor=0.01, sides=10)


def show_crowns(reader, view, name):
    """Crown envelopes or cones (details `envelope`, `cone`), coloured by their tree's light (cell data)."""
    crowns = block(reader, name)
    colour_by_light(Show(crowns, view), "CELLS", view)
    return crowns


def has_block(pvd, name):
    """True if the last year's multiblock file of the series names a block `name`."""
    try:
        datasets = ElementTree.parse(pvd).getroot().iter("DataSet")
        files = [d.get("file") for d in datasets if d.get("file")]
        if not files:
            return False
        vtm = os.path.join(os.path.dirname(pvd), files[-1])
        return any(b.get("name") == name for b in ElementTree.parse(vtm).getroot().iter())
    except (OSError, ElementTree.ParseError):
        return False


def show_roots(reader, view):
    """Root segments as tubes of their own radius (fine roots are sub-millimetre: a floor keeps them
    visible at stand scale without changing the coarse roots)."""
    return radius_tubes(block(reader, "roots"), view, ROOT, floor=0.004, sides=6)


def show_ground(bounds, view, opacity=1.0, surface_z=None):
    """The ground plane at the soil surface (z = 0 where stems stand when the soil block is in the
    bounds), else at the bottom of the data."""
    x0, x1, y0, y1, z0, _ = bounds
    if surface_z is not None:
        z0 = surface_z
    margin = 0.05 * max(x1 - x0, y1 - y0, 1.0)
    ground = Plane(Origin=[x0 - margin, y0 - margin, z0], Point1=[x1 + margin, y0 - margin, z0],
                   Point2=[x0 - margin, y1 + margin, z0])
    display = Show(ground, view)
    display.AmbientColor = GROUND
    display.DiffuseColor = GROUND
    display.Opacity = opacity


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


def main(argv):
    if len(argv) < 3:
        sys.stderr.write("usage: pvbatch render_stand.py STAND_PVD OUT_DIR [AGE ...]\n")
        return 2
    pvd, out_dir = argv[1], argv[2]
    try:
        ages = [float(age) for age in argv[3:]]
    except ValueError:
        sys.stderr.write("error: ages must be numbers: %s\n" % " ".join(argv[3:]))
        return 2
    if not os.path.isfile(pvd):
        sys.stderr.write("error: %s: no such file\n" % pvd)
        return 2
    os.makedirs(out_dir, exist_ok=True)

    reader = PVDReader(FileName=pvd)
    times = time_steps(reader)
    view = new_view(IMAGE_SIZE, SKY)

    if has_block(pvd, "branches"):
        show_branches(reader, view)
        show_leaf_balls(reader, view)
    if has_block(pvd, "stem"):
        show_stem(reader, view)
    # At `full` the envelopes would hide the shoots and leaf balls they enclose: those are drawn instead.
    for crowns in ("crown_envelope", "crown_cone"):
        if has_block(pvd, crowns) and not has_block(pvd, "branches"):
            show_crowns(reader, view, crowns)
    roots = has_block(pvd, "roots")
    if roots:
        show_roots(reader, view)

    # Frame on the last (largest) year so both images share one camera.
    view.ViewTime = times[-1]
    reader.UpdatePipeline(times[-1])
    bounds = reader.GetDataInformation().GetBounds()
    show_ground(bounds, view, opacity=0.35 if roots else 1.0, surface_z=0.0 if roots else None)
    frame_stand(view, bounds)

    missing = [age for age in ages if not any(abs(age - t) < 1e-6 for t in times)]
    if missing:
        sys.stderr.write("error: no output year at stand age %s (have %s)\n" %
                         (", ".join("%g" % a for a in missing), ", ".join("%g" % t for t in times)))
        return 2
    written = []
    for t in sorted(set(ages) if ages else {times[0], times[-1]}):
        view.ViewTime = t
        Render(view)
        name = os.path.join(out_dir, "stand_age_%04d.png" % int(round(t)))
        SaveScreenshot(name, view, ImageResolution=IMAGE_SIZE)
        written.append(name)
    for name in written:
        print(name)
    # Release the render window while the X display still exists: left to interpreter teardown,
    # pvbatch 5.11 under xvfb-run fails with GLXBadContext and exit status 1 after the images are saved.
    Delete(view)
    del view
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
