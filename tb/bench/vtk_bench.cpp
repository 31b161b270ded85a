// vtk_bench: times VTK's software fixed-point ray caster,
// vtkFixedPointVolumeRayCastMapper, on a volume cube4 reads, as a speed
// reference for the golden renderer (scripts/perf_golden.sh). Needs an X
// display (the mapper draws its image through OpenGL): run it under
// `xvfb-run -a`.
//
// Usage:
//   vtk_bench --volume PATH.den [--size 256] [--rotate RX RY RZ]
//             [--frames N] [--warmup K] [--threads T] [--image FILE.png]
//
// Scene: scenes/default.json's classification and lighting as VTK states
// them: opacity ramp over the value range {0, 0.094, 0.16, 1} ->
// {0, 0, 0.6, 0.8}, white, shaded (ambient 0.15, diffuse 0.85, specular
// 0.35, power 20) by one white directional light (0.3, 0.3, 1) in camera
// space, trilinear interpolation, one sample per voxel along the ray
// (sample distance 1, automatic adjustment off), parallel projection, the
// volume's diagonal across the image, the model rotated about x, then y,
// then z (cube4's `view.rotate`). What VTK computes beyond that (its own
// gradient estimate and shading tables, its early ray termination at
// opacity 1 - 1/255 and space leaping over its min-max blocks) is its own.
//
// Timing: CLOCK_MONOTONIC around vtkRenderWindow::Render() of a modified
// volume, per frame, N frames after K warm-up frames, T threads for the
// mapper (default 1). Output: one JSON object: volume, dim, size, threads,
// frames, ms {median, min, mean, max}, voxels_per_frame, nonzero_pixels.
#include <vtkCamera.h>
#include <vtkColorTransferFunction.h>
#include <vtkFixedPointVolumeRayCastMapper.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTransform.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

#include "golden/volume_io.hpp"

namespace {

struct Args {
  std::string volume, image;
  int size = 256, frames = 10, warmup = 2, threads = 1;
  double rotate[3] = {20, 60, 180};
};

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr, "vtk_bench: %s\nusage: vtk_bench --volume PATH.den [--size N] [--rotate RX RY RZ] "
               "[--frames N] [--warmup K] [--threads T] [--image FILE.png]\n", why.c_str());
  std::exit(2);
}

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) usage(k + " needs a value");
      return argv[++i];
    };
    if (k == "--volume") a.volume = next();
    else if (k == "--image") a.image = next();
    else if (k == "--size") a.size = std::stoi(next());
    else if (k == "--frames") a.frames = std::stoi(next());
    else if (k == "--warmup") a.warmup = std::stoi(next());
    else if (k == "--threads") a.threads = std::stoi(next());
    else if (k == "--rotate") for (double& r : a.rotate) r = std::stod(next());
    else usage("unknown option " + k);
  }
  if (a.volume.empty()) usage("--volume is required");
  if (a.size < 1 || a.frames < 1 || a.warmup < 0 || a.threads < 1) usage("sizes, frames and threads must be positive");
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = parse(argc, argv);
  cube4::golden::VolumeSource src;
  src.kind = "den";
  src.path = a.volume;
  const cube4::golden::Volume vol = cube4::golden::load_volume(src, 8, ".");
  const int nx = vol.dim[0], ny = vol.dim[1], nz = vol.dim[2];

  vtkNew<vtkImageData> image;
  image->SetDimensions(nx, ny, nz);
  image->AllocateScalars(VTK_UNSIGNED_SHORT, 1);
  std::copy(vol.data.begin(), vol.data.end(), static_cast<uint16_t*>(image->GetScalarPointer()));
  const double top = vol.max_value();

  vtkNew<vtkPiecewiseFunction> opacity;
  const double points[4][2] = {{0, 0}, {0.094, 0}, {0.16, 0.6}, {1, 0.8}};
  for (const auto& p : points) opacity->AddPoint(p[0] * top, p[1]);
  vtkNew<vtkColorTransferFunction> colour;
  colour->AddRGBPoint(0, 1, 1, 1);
  colour->AddRGBPoint(top, 1, 1, 1);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(colour);
  property->SetInterpolationTypeToLinear();
  property->ShadeOn();
  property->SetAmbient(0.15);
  property->SetDiffuse(0.85);
  property->SetSpecular(0.35);
  property->SetSpecularPower(20);

  vtkNew<vtkFixedPointVolumeRayCastMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetNumberOfThreads(a.threads);
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(1.0);
  mapper->SetImageSampleDistance(1.0);

  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  // The model matrix Rz·Ry·Rx about the volume's centre.
  vtkNew<vtkTransform> model;
  model->PostMultiply();
  model->Translate(-(nx - 1) / 2.0, -(ny - 1) / 2.0, -(nz - 1) / 2.0);
  model->RotateX(a.rotate[0]);
  model->RotateY(a.rotate[1]);
  model->RotateZ(a.rotate[2]);
  volume->SetUserTransform(model);

  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(0, 0, 0);
  renderer->RemoveAllLights();
  vtkNew<vtkLight> light;
  light->SetLightTypeToCameraLight();
  light->SetPosition(0.3, 0.3, 1);
  light->SetFocalPoint(0, 0, 0);
  light->SetIntensity(1);
  renderer->AddLight(light);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0, 0, 0);
  const double diagonal = std::sqrt(double(nx) * nx + double(ny) * ny + double(nz) * nz);
  camera->SetPosition(0, 0, 2 * diagonal);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(diagonal / 2);
  camera->SetClippingRange(diagonal / 2, 3 * diagonal);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(a.size, a.size);
  window->AddRenderer(renderer);

  std::vector<double> ms;
  for (int f = 0; f < a.warmup + a.frames; ++f) {
    volume->Modified();
    mapper->Modified();
    const auto t0 = std::chrono::steady_clock::now();
    window->Render();
    const double t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (f >= a.warmup) ms.push_back(t);
  }

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();
  vtkUnsignedCharArray* px = vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  long nonzero = 0;
  const int comps = px ? px->GetNumberOfComponents() : 0;
  for (vtkIdType i = 0; px && i < px->GetNumberOfTuples(); ++i) {
    bool any = false;
    for (int c = 0; c < std::min(comps, 3); ++c) any |= px->GetValue(i * comps + c) != 0;
    nonzero += any;
  }
  if (!a.image.empty()) {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(a.image.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
  }

  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double mean = std::accumulate(ms.begin(), ms.end(), 0.0) / ms.size();
  std::printf("{\"volume\": \"%s\", \"dim\": [%d, %d, %d], \"size\": %d, \"threads\": %d, \"frames\": %d, "
              "\"ms\": {\"median\": %.3f, \"min\": %.3f, \"mean\": %.3f, \"max\": %.3f}, \"voxels_per_frame\": %lld, "
              "\"nonzero_pixels\": %ld}\n",
              a.volume.c_str(), nx, ny, nz, a.size, a.threads, a.frames, median, sorted.front(), mean, sorted.back(),
              static_cast<long long>(nx) * ny * nz, nonzero);
  return nonzero > 0 ? 0 : 1;
}
