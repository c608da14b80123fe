"""Open a heliostand series (stand.pvd) in ParaView with the standard view, in one step.

The standard view (stand_view.py): stems and branches as tubes of their wood radius, trunks, foliage (needle sprays,
crown envelopes or cones) coloured by light on one fixed 0..1 scale with its legend, roots below a
half-transparent ground, the stand age in a corner. Play the time steps to see the stand grow.

ParaView GUI, as a macro: Macros > Import new macro... > this file (once). Then open stand.pvd (File > Open, Apply)
and click the `heliostand_view` macro: it draws the series you opened. With no stand.pvd open it opens
$HELIOSTAND_PVD, else stand.pvd in ParaView's working directory. ParaView copies an imported macro into its own
Macros folder: set HELIOSTAND_PARAVIEW_DIR to this folder (validation/paraview) so the macro finds
stand_view.py. Or from a shell, in one command:

    HELIOSTAND_PVD=out/sobetsu/stand.pvd paraview --script=validation/paraview/heliostand_view.py

pvbatch (headless; validation/paraview/run_pvbatch.sh runs it under Xvfb and checks the picture):

    pvbatch heliostand_view.py STAND_PVD [--png OUT.png] [--age AGE] [--living]

draws the same view and saves it as a PNG (default: the last year), printing the PNG's path; --living leaves out
the trees that died or were removed since the previous output year (the stand after that year's thinning).
"""
import argparse
import os
import sys


def _shared_modules_folder():
    """Where stand_view.py is: next to this file, or (for a macro ParaView copied into its Macros folder)
    $HELIOSTAND_PARAVIEW_DIR, the project's validation/paraview."""
    candidates = [os.environ.get("HELIOSTAND_PARAVIEW_DIR", "")]
    if "__file__" in globals():
        candidates.insert(0, os.path.dirname(os.path.abspath(__file__)))
    for folder in candidates:
        if folder and os.path.isfile(os.path.join(folder, "stand_view.py")):
            return folder
    raise SystemExit("heliostand_view: stand_view.py not found: set HELIOSTAND_PARAVIEW_DIR to the project's "
                     "validation/paraview folder")


sys.path.insert(0, _shared_modules_folder())
from pvbatch_common import new_view  # noqa: E402
from stand_view import LIVING, SKY, standard_view, time_steps  # noqa: E402

from paraview import servermanager  # noqa: E402
from paraview.simple import (Delete, GetActiveSource, GetActiveViewOrCreate, GetAnimationScene, PVDReader,  # noqa: E402
                             Render, SaveScreenshot)

IMAGE_SIZE = [1200, 800]


def series_to_open(argv):
    """The stand.pvd to draw in the GUI: the one already open, else the argument, $HELIOSTAND_PVD, ./stand.pvd.
    Returns (reader, path)."""
    active = GetActiveSource()
    if active is not None and active.GetXMLName() == "PVDReader":
        return active, active.FileName
    path = argv[1] if len(argv) > 1 and argv[1] else os.environ.get("HELIOSTAND_PVD", "stand.pvd")
    if not os.path.isfile(path):
        raise SystemExit("heliostand_view: %s: no such file (open stand.pvd first, or set HELIOSTAND_PVD)" % path)
    return PVDReader(FileName=path), path


def in_gui(argv):
    """The macro in the ParaView GUI: the standard view on the current render view, at the last year."""
    reader, path = series_to_open(argv)
    view = GetActiveViewOrCreate("RenderView")
    view.Background = SKY
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:  # older ParaView: the palette does not override Background
        pass
    standard_view(reader, path, view)
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = time_steps(reader)[-1]
    Render(view)


def picture(pvd, png, age=None, living_only=False):
    """pvbatch: the standard view of `pvd` at stand age `age` (default: the last year) saved to `png`. Returns
    (view, {block: shown source}, the age drawn)."""
    reader = PVDReader(FileName=pvd)
    times = time_steps(reader)
    if age is None:
        age = times[-1]
    if not any(abs(age - t) < 1e-6 for t in times):
        raise SystemExit("error: %s: no output year at stand age %g (have %s)" %
                         (pvd, age, ", ".join("%g" % t for t in times)))
    view = new_view(IMAGE_SIZE, SKY)
    shown = standard_view(reader, pvd, view, LIVING if living_only else None)
    view.ViewTime = age
    Render(view)
    SaveScreenshot(png, view, ImageResolution=IMAGE_SIZE)
    return view, shown, age


def batch(argv):
    parser = argparse.ArgumentParser(prog="pvbatch heliostand_view.py")
    parser.add_argument("pvd")
    parser.add_argument("--png", default="heliostand_view.png")
    parser.add_argument("--age", type=float)
    parser.add_argument("--living", action="store_true",
                        help="only the living trees: the stand after the year's thinning")
    args = parser.parse_args(argv[1:])
    if not os.path.isfile(args.pvd):
        sys.stderr.write("error: %s: no such file\n" % args.pvd)
        return 2
    view, _, _ = picture(args.pvd, args.png, args.age, args.living)
    print(args.png)
    Delete(view)  # release the render window while the X display still exists (see render_stand.py)
    return 0


if __name__ == "__main__":
    if servermanager.vtkProcessModule.GetProcessType() == servermanager.vtkProcessModule.PROCESS_BATCH:
        sys.exit(batch(sys.argv))
    in_gui(getattr(sys, "argv", [""]))  # the GUI's macro, or paraview --script
