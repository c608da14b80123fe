"""Render a heliostand output series with ParaView (run with pvbatch; see render.sh).

    pvbatch render_stand.py STAND_PVD OUT_DIR [AGE ...]

Draws the standard view of the series (stand_view.py: what the level of detail wrote, stems and branches as tubes
of their wood radius, foliage coloured by light, roots below a half-transparent ground, the stand age). One PNG
for the first and one for the last time step, both framed on the stand as it is at the last time step so the two
images compare directly. Given AGEs (stand ages), one PNG
per listed age instead (e.g. the years before and after a thinning).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pvbatch_common import new_view  # noqa: E402
from stand_view import SKY, last_year_first, standard_view, time_steps  # noqa: E402

from paraview.simple import Delete, PVDReader, Render, SaveScreenshot  # noqa: E402

IMAGE_SIZE = [1200, 800]


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
    standard_view(reader, pvd, view)  # framed on the last year, so every image shares one camera

    missing = [age for age in ages if not any(abs(age - t) < 1e-6 for t in times)]
    if missing:
        sys.stderr.write("error: no output year at stand age %s (have %s)\n" %
                         (", ".join("%g" % a for a in missing), ", ".join("%g" % t for t in times)))
        return 2
    written = []
    for t in last_year_first(set(ages) if ages else {times[0], times[-1]}):
        view.ViewTime = t
        Render(view)
        name = os.path.join(out_dir, "stand_age_%04d.png" % int(round(t)))
        SaveScreenshot(name, view, ImageResolution=IMAGE_SIZE)
        written.append(name)
    for name in sorted(written):
        print(name)
    # Release the render window while the X display still exists: left to interpreter teardown,
    # pvbatch 5.11 under xvfb-run fails with GLXBadContext and exit status 1 after the images are saved.
    Delete(view)
    del view
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
