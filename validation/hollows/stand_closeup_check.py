"""Check render_hollows.py's stand mode on a small stand-like multiblock (run with pvbatch).

    pvbatch stand_closeup_check.py VTP_DIR OUT_DIR

Builds OUT_DIR/mini_stand/STAND_AGE_0001.vtm the way the stand output lays out stems: a block `trunk`
(vtkPolyData, all trees' stems in stand coordinates, point data `part` and `tree_id`) next to other blocks.
Tree 3 is the two-hollow stem of FigureMeshes (beyond_two_hollows.vtp) standing at (2, 1); tree 7, another
stem, stands 0.9 m in front of its upper hollow, where it would hide the wound. Then renders a close-up of the
upper hollow from a focus point on it (what `render_hollows.py --stand FILE --focus X Y Z --out PNG` does) and
prints the PNG path.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import render_hollows  # noqa: E402  (needs the path above)
from vtkmodules.vtkCommonCore import vtkIntArray  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkMultiBlockDataSet, vtkPolyData  # noqa: E402
from vtkmodules.vtkCommonTransforms import vtkTransform  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkAppendPolyData  # noqa: E402
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter, vtkXMLPolyDataReader  # noqa: E402

# The upper hollow of beyond_two_hollows.vtp (figure_meshes_test.cpp): centre 1.9 m up, facing 40 degrees.
UPPER_HOLLOW_HEIGHT, UPPER_HOLLOW_AZIMUTH = 1.9, 40.0
STEM_RADIUS_THERE = 0.24  # about (seed 001 taper of the 30 m test tree); the script finds the stem itself


def tree(vtp, tree_id, x, y):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(vtp)
    transform = vtkTransform()
    transform.Translate(x, y, 0.0)
    moved = vtkTransformPolyDataFilter()
    moved.SetInputConnection(reader.GetOutputPort())
    moved.SetTransform(transform)
    moved.Update()
    stem = vtkPolyData()
    stem.DeepCopy(moved.GetOutput())
    ids = vtkIntArray()
    ids.SetName("tree_id")
    ids.SetNumberOfValues(stem.GetNumberOfPoints())
    ids.Fill(tree_id)
    stem.GetPointData().AddArray(ids)
    return stem


def write_mini_stand(vtp_dir, out_dir):
    a = math.radians(UPPER_HOLLOW_AZIMUTH)
    append = vtkAppendPolyData()
    append.AddInputData(tree(os.path.join(vtp_dir, "beyond_two_hollows.vtp"), 3, 2.0, 1.0))
    append.AddInputData(tree(os.path.join(vtp_dir, "stem_without_hollow.vtp"), 7,
                             2.0 + 0.9 * math.cos(a), 1.0 + 0.9 * math.sin(a)))
    append.Update()
    stand = vtkMultiBlockDataSet()
    stand.SetNumberOfBlocks(2)
    stand.SetBlock(0, append.GetOutput())
    stand.GetMetaData(0).Set(vtkCompositeDataSet.NAME(), "trunk")
    stand.SetBlock(1, vtkPolyData())
    stand.GetMetaData(1).Set(vtkCompositeDataSet.NAME(), "branches")
    folder = os.path.join(out_dir, "mini_stand")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "STAND_AGE_0001.vtm")
    writer = vtkXMLMultiBlockDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(stand)
    if writer.Write() != 1:
        raise OSError("%s: could not write" % path)
    return path


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: pvbatch stand_closeup_check.py VTP_DIR OUT_DIR\n")
        return 2
    vtp_dir, out_dir = argv[1], argv[2]
    vtm = write_mini_stand(vtp_dir, out_dir)
    a = math.radians(UPPER_HOLLOW_AZIMUTH)
    focus = [2.0 + STEM_RADIUS_THERE * math.cos(a), 1.0 + STEM_RADIUS_THERE * math.sin(a), UPPER_HOLLOW_HEIGHT]
    png = render_hollows.render_mesh(vtm, os.path.join(out_dir, "stand_closeup.png"), focus=focus,
                                     title="Stand output: close-up of tree 3's upper hollow")
    print(png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
