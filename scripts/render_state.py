"""Render one state of a slideline run (its .xdmf) coloured by a cell field, to a PNG.

    pvbatch scripts/render_state.py out/sslide3p.xdmf picture.png [--state -1] [--field von_mises]
        [--magnify 100] [--size 1000 650] [--check]

Without a display, run it under `xvfb-run -a pvbatch ...` (Debian's ParaView needs an X server;
a ParaView built with EGL or OSMesa takes `pvbatch --force-offscreen-rendering`).
With --check the script reads the PNG back and exits 1 when it is blank (fewer than 16 colours)
and 2 when the stress tensor did not arrive as 6 components (docs/output.md, "ParaView").
"""
import argparse
import sys

from paraview.simple import (ColorBy, GetActiveCamera, GetActiveViewOrCreate, GetScalarBar,
                             OpenDataFile, SaveScreenshot, Show, UpdatePipeline, WarpByVector)
from paraview import servermanager


def parse():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("xdmf")
    p.add_argument("png")
    p.add_argument("--state", type=int, default=-1, help="state index (default: the last)")
    p.add_argument("--field", default="von_mises", help="cell field to colour by")
    p.add_argument("--size", type=int, nargs=2, default=[1000, 650])
    p.add_argument("--magnify", type=float, default=1.0,
                   help="draw the displacements this many times larger (1: as computed)")
    p.add_argument("--check", action="store_true", help="fail on a blank picture or a bad tensor")
    return p.parse_args()


def tensor_components(reader):
    """Number of components of the cell array `stress` in the first leaf that has it."""
    data = servermanager.Fetch(reader)
    leaves = [data]
    if data.IsA("vtkCompositeDataSet"):
        leaves = []
        it = data.NewIterator()
        it.InitTraversal()
        while not it.IsDoneWithTraversal():
            leaves.append(it.GetCurrentDataObject())
            it.GoToNextItem()
    for b in leaves:
        if b is not None and b.GetCellData().GetArray("stress") is not None:
            return b.GetCellData().GetArray("stress").GetNumberOfComponents()
    return 0


def distinct_colours(png):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    img = r.GetOutput()
    pixels = vtk_to_numpy(img.GetPointData().GetScalars())
    return len({tuple(p) for p in pixels[::7]})


def main():
    a = parse()
    reader = OpenDataFile(a.xdmf)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) or [0.0]
    t = times[a.state]
    UpdatePipeline(time=t, proxy=reader)
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = a.size
    view.ViewTime = t
    view.Background = [1.0, 1.0, 1.0]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    shown_source = reader
    if a.magnify != 1.0:
        # The geometry already holds u once: add (magnify - 1) u.
        shown_source = WarpByVector(Input=reader, Vectors=["POINTS", "displacement"],
                                    ScaleFactor=a.magnify - 1.0)
    shown = Show(shown_source, view)
    shown.SetRepresentationType("Surface With Edges")
    ColorBy(shown, ("CELLS", a.field))
    shown.RescaleTransferFunctionToDataRange(True, False)
    shown.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(shown.LookupTable, view)
    bar.Title = a.field
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.WindowLocation = "Upper Right Corner"
    view.CameraPosition = [1.0, 1.0, 3.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera()
    GetActiveCamera().Dolly(1.35)
    SaveScreenshot(a.png, view, ImageResolution=a.size)
    print(f"{a.png}: state {a.state} of {len(times)} (t = {t}), coloured by {a.field}")
    if a.check:
        n = distinct_colours(a.png)
        comps = tensor_components(reader)
        print(f"distinct colours {n}, stress components {comps}")
        if n < 16:
            sys.exit(1)
        if comps != 6:
            sys.exit(2)


if __name__ == "__main__":
    main()
