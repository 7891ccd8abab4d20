"""What the plugin's pvbatch tests share: the failure list, screenshots
compared with their baselines, pixel statistics and the capture of VTK's
error output."""
import os
import sys

from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkImagingCore import vtkImageDifference  # noqa: F401
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def finish():
    if failures:
        print("%d failure(s)" % len(failures))
        sys.stdout.flush()
        # pvbatch crashes in its teardown after sys.exit(1) (ParaView 5.11,
        # with or without the plugin); the status is what the test says.
        os._exit(1)
    print("all checks passed")


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[:, :, :3].astype(float)


def compare_with_baseline(image, baseline, threshold=0.15):
    """vtkImageDifference's thresholded error of `image` against `baseline`
    (a missing baseline fails, naming the image to look at and commit)."""
    if not os.path.exists(baseline):
        check(False, "no baseline %s: look at %s and commit it" % (baseline, image))
        return
    readers = [vtkPNGReader(), vtkPNGReader()]
    readers[0].SetFileName(baseline)
    readers[1].SetFileName(image)
    difference = vtkImageDifference()
    difference.SetInputConnection(readers[1].GetOutputPort())
    difference.SetImageConnection(readers[0].GetOutputPort())
    difference.Update()
    error = difference.GetThresholdedError()
    print("%s: image difference %.3f" % (os.path.basename(image), error))
    check(error <= threshold, "%s differs from its baseline: %.3f" % (os.path.basename(image), error))


class CapturedMessages:
    """VTK's warnings and errors while in the `with` block, as text."""

    def __enter__(self):
        self.window = vtkStringOutputWindow()
        vtkOutputWindow.SetInstance(self.window)
        return self

    def __exit__(self, *args):
        self.text = self.window.GetOutput()
        vtkOutputWindow.SetInstance(None)


def cornell_view_screenshot(source, image, remote_rendering=False):
    """`source` (a Cornell box) in a Radiosity Render View solved by
    progressive radiosity (tolerance 0.01), seen from the box's open side, its
    300 x 300 screenshot written to `image`; `remote_rendering`: rendered on
    the servers of a client-server session. Returns the view."""
    from paraview.simple import CreateView, Render, SaveScreenshot, Show

    view = CreateView("RadiosityRenderView")
    view.ViewSize = [300, 300]
    view.OrientationAxesVisibility = 0
    view.Method = "Progressive"
    view.Tolerance = 0.01
    if remote_rendering:
        view.RemoteRenderThreshold = 0
    Show(source, view)
    Render(view)  # paraview.simple resets the camera at a view's first render
    view.CameraPosition = [0.278, 0.273, -0.8]
    view.CameraFocalPoint = [0.278, 0.273, 0.28]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    Render(view)
    SaveScreenshot(image, view, ImageResolution=[300, 300])
    return view
