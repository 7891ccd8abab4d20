// libFuzzer target for scene loading and validation: the path a scene file
// takes in `vtkradiosity solve SCENE` before any solver sees it.
//
//   radiosity::cli::LoadScene(file)           Examples/vtkradiosity/SceneLoader.cxx
//     (.vtk vtkDataSetReader, .ply vtkPLYReader, .stl vtkSTLReader,
//      .vtp vtkXMLGenericDataObjectReader, .obj + .mtl ObjMtlReader.cxx)
//   vtkRadiositySceneConverter::ToScene(data)  Filters/
//   radiosity::ValidateScene(scene)            Modules/Radiosity/Common/Scene.cxx
//   radiosity::DropDegenerateTriangles(scene)
//
// Input layout: the first byte picks the format, the rest is the file.
//
//   'v' legacy .vtk    'p' .ply    's' .stl    'x' .vtp (VTK XML)
//   'o' .obj, optionally followed by "\n%%mtl\n" and the contents of the
//       .mtl, written beside the .obj as `scene.mtl` (so `mtllib scene.mtl`
//       in the .obj finds it; without the separator there is no .mtl file)
//   'l' reserved for LIGHTS.json (--lights): not fuzzed yet, see LoadLights
//   any other byte: byte % 5 picks one of v, o, p, s, x (so no input is wasted)
//
// The bytes are written to a file with that extension in a temporary
// directory of this process, and the file goes through the path above.
// Normal outcomes: a scene, LoadScene's null with an error string, a
// ToScene refusal, a radiosity::SceneError from validation. Anything else is
// a finding: a crash, an ASan/UBSan report, any other exception (it escapes
// and aborts), an allocation over -malloc_limit_mb, a run over -timeout.
//
// Build (Testing/Fuzz/README.md) and run by hand:
//   FuzzSceneLoading -dict=Testing/Fuzz/scene.dict -rss_limit_mb=2048 \
//     -malloc_limit_mb=2048 -timeout=10 WORK_CORPUS Testing/Fuzz/corpus
//   FuzzSceneLoading Testing/Fuzz/regressions/*     # replay, once each
// Set FUZZ_SCENE_VERBOSE=1 to see VTK's error output and the outcome.
#include "SceneLoader.h"

#include "vtkRadiositySceneConverter.h"

#include "vtkDataObject.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include "Radiosity/Common/Scene.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{
std::string TempDir;
bool Verbose = false;

const char* const MtlSeparator = "\n%%mtl\n";

enum class Format
{
  Vtk,
  Obj,
  Ply,
  Stl,
  Vtp,
  Lights
};

Format Pick(std::uint8_t byte)
{
  switch (byte)
  {
    case 'v':
      return Format::Vtk;
    case 'o':
      return Format::Obj;
    case 'p':
      return Format::Ply;
    case 's':
      return Format::Stl;
    case 'x':
      return Format::Vtp;
    case 'l':
      return Format::Lights;
    default:
    {
      static const Format cycle[] = { Format::Vtk, Format::Obj, Format::Ply, Format::Stl,
        Format::Vtp };
      return cycle[byte % 5];
    }
  }
}

const char* ExtensionOf(Format f)
{
  switch (f)
  {
    case Format::Vtk:
      return "vtk";
    case Format::Obj:
      return "obj";
    case Format::Ply:
      return "ply";
    case Format::Stl:
      return "stl";
    case Format::Vtp:
      return "vtp";
    case Format::Lights:
      return "json";
  }
  return "bin";
}

/// A property of the code under test that every input must keep: a finding
/// (printed, then abort, which libFuzzer reports as a crash) when it fails.
#define CHECK(condition, message)                                                                  \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::cerr << "FuzzSceneLoading: " << (message) << "\n";                                      \
      std::abort();                                                                                \
    }                                                                                              \
  } while (false)

void WriteFile(const std::string& path, const char* data, std::size_t size)
{
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f)
  {
    std::perror(path.c_str());
    std::abort(); // the harness itself failed: not the code under test
  }
  if (size > 0 && std::fwrite(data, 1, size, f) != size)
  {
    std::perror(path.c_str());
    std::abort();
  }
  std::fclose(f);
}

void RemoveTempDir()
{
  if (TempDir.empty())
  {
    return;
  }
  for (const char* name : { "scene.vtk", "scene.obj", "scene.mtl", "scene.ply", "scene.stl",
         "scene.vtp", "scene.json" })
  {
    std::remove((TempDir + "/" + name).c_str());
  }
  rmdir(TempDir.c_str());
}

/// The place for --lights LIGHTS.json once its reader exists: load the lights
/// from `path` and validate them, treating a refusal (error string or
/// SceneError) as a normal outcome, as for scenes below.
void LoadLights(const std::string& /*path*/) {}

/// Swallows VTK's messages (every malformed file makes a reader complain).
/// Warnings stay enabled globally: the loader listens to the readers' errors
/// through an output window of its own, as it does in vtkradiosity.
class SilentOutputWindow : public vtkOutputWindow
{
public:
  static SilentOutputWindow* New();
  vtkTypeMacro(SilentOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
};
vtkStandardNewMacro(SilentOutputWindow);

void Report(const char* outcome, const std::string& what)
{
  if (Verbose)
  {
    std::cerr << "FuzzSceneLoading: " << outcome << (what.empty() ? "" : ": ") << what << "\n";
  }
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/)
{
  Verbose = std::getenv("FUZZ_SCENE_VERBOSE") != nullptr;
  if (!Verbose)
  {
    vtkNew<SilentOutputWindow> silent;
    vtkOutputWindow::SetInstance(silent);
  }
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/fuzz-scene-XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (!mkdtemp(buffer.data()))
  {
    std::perror("mkdtemp");
    std::abort();
  }
  TempDir = buffer.data();
  std::atexit(RemoveTempDir);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  const Format format = Pick(data[0]);
  const char* body = reinterpret_cast<const char*>(data + 1);
  std::size_t bodySize = size - 1;
  const std::string file = TempDir + "/scene." + ExtensionOf(format);

  if (format == Format::Lights)
  {
    WriteFile(file, body, bodySize);
    LoadLights(file);
    return 0;
  }

  if (format == Format::Obj)
  {
    const std::string mtl = TempDir + "/scene.mtl";
    const std::string whole(body, bodySize);
    const auto at = whole.find(MtlSeparator);
    if (at == std::string::npos)
    {
      std::remove(mtl.c_str()); // no .mtl this time: the reader warns
    }
    else
    {
      const std::size_t mtlStart = at + std::strlen(MtlSeparator);
      WriteFile(mtl, body + mtlStart, bodySize - mtlStart);
      bodySize = at;
    }
  }
  WriteFile(file, body, bodySize);

  std::string error;
  std::vector<std::string> warnings;
  vtkSmartPointer<vtkDataObject> input = radiosity::cli::LoadScene(file, error, warnings);
  if (!input)
  {
    // The contract: null comes with a reason (SceneLoader.h).
    CHECK(!error.empty(), "LoadScene returned null without an error message");
    Report("refused by LoadScene", error);
    return 0;
  }

  radiosity::Scene scene;
  error.clear();
  if (!vtkRadiositySceneConverter::ToScene(input, scene, error, warnings))
  {
    Report("refused by ToScene", error);
    return 0;
  }
  try
  {
    radiosity::ValidateScene(scene);
  }
  catch (const radiosity::SceneError& e)
  {
    Report("refused by ValidateScene", e.what());
    return 0;
  }
  const radiosity::SceneCleanupReport cleanup = radiosity::DropDegenerateTriangles(scene);
  Report("accepted", std::to_string(scene.NumberOfTriangles()) + " triangles, " +
      std::to_string(cleanup.DegenerateTrianglesDropped) + " degenerate dropped");
  return 0;
}
