// SPDX-License-Identifier: BSD-3-Clause
// shadinglab-gui: the artifact explorer. Interactive by default; with
// --screenshot or --profile it renders the scene, writes the files and exits
// (tests, documentation).
#include "MainWindow.h"

#include "ComparisonWidget.h"
#include "ShadingPanel.h"

#include "MeshIO.h"
#include "shadinglab/Version.h"
#include "shadinglab/render/Settings.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <X11/Xlib.h>

#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{

const char* kUsage =
  "usage: shadinglab-gui [--scene NAME] [INPUT] [--backend gpu|cpu|auto] [--size WxH]\n"
  "                      [--variant corrugated|isosurface] [--rotation DEG] [--distance R]\n"
  "                      [--polarizer DEG] [--light-polarizer DEG]\n"
  "                      [--screenshot FILE.png] [--profile FILE.csv] [--color-by ARRAY]\n"
  "                      [--nonlinear-subdivision N] [--time T | --time-step N]\n"
  "       shadinglab-gui --list-scenes | --version\n"
  "\n"
  "The ShadingLab explorer: the lecture's interpolation artifacts side by side.\n"
  "INPUT is any file the CLI reads (see shadinglab render --help).\n"
  "With --screenshot and/or --profile the window is rendered, the files are\n"
  "written (the profile or study numbers as CSV) and the program exits.\n"
  "Needs an X display (e.g. xvfb-run); without one it exits with status 2.\n";

/// Window size limits: below 400 x 300 the controls do not fit; 8192 is
/// beyond any screen and keeps a grab under 256 MB.
constexpr int kMinWindowSide = 300;
constexpr int kMaxWindowSide = 8192;

int Fail(const std::string& message)
{
  std::cerr << "shadinglab-gui: " << message << "\n";
  return 2;
}

bool ParseSize(const std::string& text, int& w, int& h)
{
  char x = 0;
  char rest = 0;
  return std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) == 3 && (x == 'x' || x == 'X');
}

/// What the command line asks for.
struct Request
{
  std::string scene = "modes", input, screenshot, profile, colorBy, sizeText = "1600x1000";
  shadinglab::gui::SceneOptions options;
  int width = 0, height = 0;
  /// INPUT, read: options.input points at it, so it lives as long.
  vtkSmartPointer<vtkPolyData> mesh;
};

/// Parses the command line into `request`: -1 to go on, else the exit
/// status (0 after --help, --version or --list-scenes; 2 after an error).
/// --time T or --time-step N into `reading` (the CLI's ReadOptions; the
/// reader refuses a step the file does not have). "" or a one-line error.
std::string SetTimeStep(const std::string& flag, const std::string& v, shadinglab::ReadOptions& reading)
{
  char* end = nullptr;
  const double number = std::strtod(v.c_str(), &end);
  if (v.empty() || *end || !std::isfinite(number) ||
    (flag == "--time-step" && (number < 0 || number != std::floor(number) || number > 1e9)))
  {
    return flag + " must be " + (flag == "--time" ? "a finite time" : "a step 0, 1, ...") +
      " (got '" + v + "')";
  }
  if (flag == "--time")
  {
    reading.time = number;
  }
  else
  {
    reading.timeStep = static_cast<int>(number);
  }
  return "";
}

int ParseArguments(int argc, char** argv, Request& request)
{
  using namespace shadinglab;
  std::string& scene = request.scene;
  std::string& input = request.input;
  std::string& screenshot = request.screenshot;
  std::string& profile = request.profile;
  std::string& colorBy = request.colorBy;
  std::string& sizeText = request.sizeText;
  gui::SceneOptions& options = request.options;
  std::vector<std::string> args(argv + 1, argv + argc);
  for (size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= args.size())
      {
        throw std::invalid_argument(std::string(name) + " needs a value");
      }
      return args[++i];
    };
    try
    {
      if (a == "--help" || a == "-h")
      {
        std::cout << kUsage;
        return 0;
      }
      if (a == "--version")
      {
        std::cout << "shadinglab-gui " << SHADINGLAB_VERSION << "\n";
        return 0;
      }
      if (a == "--list-scenes")
      {
        for (const gui::SceneInfo& info : gui::SceneList())
        {
          std::cout << info.name << "\t" << info.summary << "\n";
        }
        return 0;
      }
      if (a == "--scene")
        scene = value("--scene");
      else if (a == "--screenshot")
        screenshot = value("--screenshot");
      else if (a == "--profile")
        profile = value("--profile");
      else if (a == "--size")
        sizeText = value("--size");
      else if (a == "--color-by")
        colorBy = value("--color-by");
      else if (a == "--nonlinear-subdivision")
      {
        // Range and message from the settings table, as the CLI's.
        render::Settings settings;
        const std::string problem =
          render::ApplySettingText(settings, "nonlinear-subdivision", value("--nonlinear-subdivision"), "--");
        if (!problem.empty())
        {
          return Fail(problem);
        }
        options.reading.nonlinearSubdivisionLevel = settings.input.nonlinearSubdivisionLevel;
      }
      else if (a == "--time" || a == "--time-step")
      {
        const std::string problem = SetTimeStep(a, value(a.c_str()), options.reading);
        if (!problem.empty())
        {
          return Fail(problem);
        }
      }
      else if (a == "--variant")
        options.variant = value("--variant");
      else if (a == "--distance")
      {
        const std::string v = value("--distance");
        char* end = nullptr;
        options.distance = std::strtod(v.c_str(), &end);
        if (*end || !(options.distance >= gui::kMinConditionsDistance &&
              options.distance <= gui::kMaxConditionsDistance))
        {
          return Fail("--distance must be a number of radii in [1.5, 10000] (got '" + v + "')");
        }
      }
      else if (a == "--polarizer" || a == "--light-polarizer")
      {
        // Range and message from the settings table, as the CLI's.
        render::Settings settings;
        const std::string key = a.substr(2);
        const std::string problem = render::ApplySettingText(settings, key, value(a.c_str()), "--");
        if (!problem.empty())
        {
          return Fail(problem);
        }
        if (key == "light-polarizer")
        {
          options.lightPolarizer = settings.render.lightPolarizer;
        }
        else if (settings.render.polarizer < 0)
        {
          return Fail("--polarizer -1 (none): the polarization scene turns a polarizer in front of "
                      "the camera; give its angle in [0, 180] degrees");
        }
        else
        {
          options.polarizer = settings.render.polarizer;
        }
      }
      else if (a == "--rotation")
      {
        const std::string v = value("--rotation");
        char* end = nullptr;
        options.rotation = std::strtod(v.c_str(), &end);
        if (*end || !(options.rotation >= 0 && options.rotation <= 90))
        {
          return Fail("--rotation must be a number of degrees in [0, 90] (got '" + v + "')");
        }
      }
      else if (a == "--backend")
      {
        const std::string problem = render::ParseBackend(value("--backend"), options.backend);
        if (!problem.empty())
        {
          return Fail(problem);
        }
      }
      else if (!a.empty() && a[0] == '-')
        return Fail("unknown option " + a + " (see --help)");
      else if (input.empty())
        input = a;
      else
        return Fail("more than one INPUT given ('" + input + "' and '" + a + "')");
    }
    catch (const std::invalid_argument& e)
    {
      return Fail(e.what());
    }
  }
  int& width = request.width;
  int& height = request.height;
  if (!ParseSize(sizeText, width, height) || width < kMinWindowSide || height < kMinWindowSide ||
    width > kMaxWindowSide || height > kMaxWindowSide)
  {
    return Fail("--size must be WxH with sides in [300, 8192] (got '" + sizeText + "')");
  }
  return -1;
}

/// Reads INPUT and checks the X display, the two things that make Qt and
/// VTK abort: "" or the one-line error.
std::string ReadInputAndCheckDisplay(Request& request)
{
  using namespace shadinglab;
  const std::string& input = request.input;
  gui::SceneOptions& options = request.options;
  vtkSmartPointer<vtkPolyData>& mesh = request.mesh;
  if (!input.empty())
  {
    try
    {
      mesh.TakeReference(ReadMesh(input, options.reading));
    }
    catch (const std::exception& e)
    {
      return input + ": " + e.what();
    }
  }
  // Qt and VTK abort without an X display: say so first.
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    return "no X display (DISPLAY is not set); run it under X or xvfb-run";
  }
  if (Display* dpy = XOpenDisplay(nullptr))
  {
    XCloseDisplay(dpy);
  }
  else
  {
    return std::string("cannot open X display '") + display + "'";
  }
  options.input = mesh;
  return "";
}

} // namespace

int main(int argc, char** argv)
{
  using namespace shadinglab;
  Request request;
  const int status = ParseArguments(argc, argv, request);
  if (status >= 0)
  {
    return status;
  }
  const std::string problem = ReadInputAndCheckDisplay(request);
  if (!problem.empty())
  {
    return Fail(problem);
  }
  const std::string& scene = request.scene;
  const std::string& screenshot = request.screenshot;
  const std::string& profile = request.profile;
  const std::string& colorBy = request.colorBy;
  const gui::SceneOptions& options = request.options;
  const int width = request.width, height = request.height;

  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  gui::MainWindow window(options);
  window.resize(width, height);
  window.show();
  QApplication::processEvents();
  std::string error;
  if (!window.LoadScene(scene, error))
  {
    return Fail(error);
  }
  if (!colorBy.empty())
  {
    // As the Array box spells it: a point array, or CELLS:name.
    const std::string spelled = colorBy.rfind("CELLS:", 0) == 0 || colorBy.rfind("POINTS:", 0) == 0
      ? colorBy
      : "POINTS:" + colorBy;
    error = window.ApplyColorBy(spelled);
    if (!error.empty())
    {
      return Fail("--color-by: " + error);
    }
  }
  if (screenshot.empty() && profile.empty())
  {
    return app.exec();
  }
  window.RefreshNow();
  // What was drawn, for scripts: one line per panel with its backend.
  for (int i = 0; i < window.Comparison()->PanelCount(); ++i)
  {
    std::cout << "panel " << i + 1 << ": "
              << window.Comparison()->Panel(i)->Title().toStdString() << "\n";
  }
  if (!profile.empty())
  {
    std::ofstream out(profile);
    out << window.PlotCsv();
    if (!out)
    {
      return Fail("cannot write " + profile);
    }
  }
  if (!screenshot.empty() && !window.grab().save(QString::fromStdString(screenshot)))
  {
    return Fail("cannot write " + screenshot);
  }
  return 0;
}
