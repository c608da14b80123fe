"""Pieces shared by the pvbatch scripts (render_stand.py, heliotropism/render_sweeps.py, hollows/render_hollows.py).

Scripts in other folders import it after putting this folder on sys.path:

    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "paraview"))
    from pvbatch_common import new_view, radius_tubes
"""
from paraview.simple import Calculator, CreateView, Show, Tube


def new_view(size, background, axes=True):
    """A render view of `size` pixels on a plain background (not ParaView's colour palette)."""
    view = CreateView("RenderView")
    view.ViewSize = size
    view.OrientationAxesVisibility = 1 if axes else 0
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:  # older ParaView: the palette does not override Background
        pass
    view.Background = background
    return view


def radius_tubes(source, view, colour, floor, sides):
    """Lines as tubes of their `radius` point data, at least `floor` so the thinnest stay visible, in one colour.
    Returns the tube filter."""
    floored = Calculator(Input=source)
    floored.AttributeType = "Point Data"
    floored.ResultArrayName = "tube_radius"
    floored.Function = "max(radius, %g)" % floor
    tubes = Tube(Input=floored)
    tubes.Scalars = ["POINTS", "tube_radius"]
    tubes.VaryRadius = "By Absolute Scalar"
    tubes.NumberofSides = sides
    display = Show(tubes, view)
    display.ColorArrayName = ["POINTS", ""]
    display.AmbientColor = colour
    display.DiffuseColor = colour
    return tubes
