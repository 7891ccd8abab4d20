#include "ObjMtlReader.h"

#include "TextTrim.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace radiosity
{
namespace cli
{
namespace
{
using Color = std::array<double, 3>;

struct Material
{
  Color Kd{ 0.5, 0.5, 0.5 }; // SPEC default reflectance
  Color Ke{ 0.0, 0.0, 0.0 };
  Color Ks{ 0.0, 0.0, 0.0 };
  double Ns = 0.0;
};

// Thrown by the line parsers; the caller adds file and line (one place formats
// every message the same way).
struct LineError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Reads logical lines: strips '\r' (files from Windows) and joins lines that end
// in a backslash, as the OBJ format allows. `number` is the first physical line.
class LineReader
{
public:
  explicit LineReader(std::istream& in)
    : In(in)
  {
  }
  bool Next(std::string& line, int& number)
  {
    line.clear();
    std::string part;
    bool any = false;
    while (std::getline(this->In, part))
    {
      ++this->Physical;
      if (!any)
      {
        number = this->Physical;
      }
      any = true;
      if (!part.empty() && part.back() == '\r')
      {
        part.pop_back();
      }
      if (!part.empty() && part.back() == '\\')
      {
        part.back() = ' ';
        line += part;
        continue;
      }
      line += part;
      return true;
    }
    return any;
  }

private:
  std::istream& In;
  int Physical = 0;
};

std::vector<std::string> Split(const std::string& text)
{
  std::vector<std::string> tokens;
  std::istringstream s(text);
  std::string t;
  while (s >> t)
  {
    tokens.push_back(t);
  }
  return tokens;
}


// Everything after the keyword: names (materials, objects, files) may contain spaces.
std::string RestOfLine(const std::string& line, const std::string& keyword)
{
  const auto at = line.find(keyword);
  return Trim(line.substr(at + keyword.size()));
}

// from_chars: locale independent (a VTK application may have set a locale
// with a decimal comma) and it rejects trailing garbage.
double ParseNumber(const std::string& token, const char* what)
{
  double value = 0.0;
  const char* begin = token.data();
  const char* end = begin + token.size();
  if (*begin == '+')
  {
    ++begin; // from_chars refuses a leading '+', which some exporters write
  }
  const auto result = std::from_chars(begin, end, value);
  if (result.ec != std::errc() || result.ptr != end)
  {
    throw LineError(std::string("bad number '") + token + "' for " + what);
  }
  if (!std::isfinite(value))
  {
    throw LineError(std::string("non-finite number '") + token + "' for " + what);
  }
  return value;
}

long ParseIndex(const std::string& token, const std::string& vertex)
{
  long value = 0;
  const char* begin = token.data();
  const char* end = begin + token.size();
  const auto result = std::from_chars(begin, end, value);
  if (token.empty() || result.ec != std::errc() || result.ptr != end)
  {
    throw LineError("bad index in face vertex '" + vertex + "'");
  }
  return value;
}

// OBJ indices are 1-based; negative ones count back from the last element read.
std::size_t ResolveIndex(long index, std::size_t count, const char* what, const std::string& vertex)
{
  long resolved = index > 0 ? index - 1 : static_cast<long>(count) + index;
  if (index == 0 || resolved < 0 || resolved >= static_cast<long>(count))
  {
    throw LineError(std::string(what) + " index " + std::to_string(index) + " out of range (" +
      std::to_string(count) + " defined so far) in face vertex '" + vertex + "'");
  }
  return static_cast<std::size_t>(resolved);
}

// One of "v", "v/vt", "v//vn", "v/vt/vn". Texture coordinates and normals are
// not used (surfaces are one-sided by winding, SPEC), but their indices are
// checked: an index past the end means the file is damaged.
std::size_t ParseFaceVertex(
  const std::string& token, std::size_t vertices, std::size_t texcoords, std::size_t normals)
{
  std::array<std::string, 3> parts;
  std::size_t n = 0;
  std::size_t start = 0;
  while (true)
  {
    const auto slash = token.find('/', start);
    if (n == 3)
    {
      throw LineError("too many '/' in face vertex '" + token + "'");
    }
    parts[n++] = token.substr(start, slash == std::string::npos ? slash : slash - start);
    if (slash == std::string::npos)
    {
      break;
    }
    start = slash + 1;
  }
  const std::size_t v = ResolveIndex(ParseIndex(parts[0], token), vertices, "vertex", token);
  if (n >= 2 && !parts[1].empty())
  {
    ResolveIndex(ParseIndex(parts[1], token), texcoords, "texture coordinate", token);
  }
  if (n == 3)
  {
    ResolveIndex(ParseIndex(parts[2], token), normals, "normal", token);
  }
  else if (n == 2 && parts[1].empty())
  {
    throw LineError("empty texture coordinate index in face vertex '" + token + "'");
  }
  return v;
}

// "Kd r g b", or "Kd r" meaning grey (the MTL format's rule).
Color ParseColor(const std::vector<std::string>& tokens)
{
  if (tokens.size() != 2 && tokens.size() != 4)
  {
    throw LineError(tokens[0] + " expects 1 or 3 numbers (spectral and xyz forms are not supported)");
  }
  const double r = ParseNumber(tokens[1], tokens[0].c_str());
  if (tokens.size() == 2)
  {
    return { r, r, r };
  }
  return { r, ParseNumber(tokens[2], tokens[0].c_str()),
    ParseNumber(tokens[3], tokens[0].c_str()) };
}

std::string Directory(const std::string& file)
{
  const auto slash = file.find_last_of('/');
  return slash == std::string::npos ? std::string() : file.substr(0, slash + 1);
}

std::string Stem(const std::string& file)
{
  const auto slash = file.find_last_of('/');
  std::string name = slash == std::string::npos ? file : file.substr(slash + 1);
  const auto dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

std::string Where(const std::string& file, int line)
{
  return file + ":" + std::to_string(line) + ": ";
}

// Adds the materials of one .mtl file to `materials`. A later definition of the
// same name replaces an earlier one, as in most readers.
bool ReadMtl(const std::string& file, std::map<std::string, Material>& materials,
  std::string& error, std::vector<std::string>& warnings)
{
  std::ifstream in(file);
  if (!in)
  {
    warnings.push_back("material library '" + file +
      "' cannot be read: its materials get the default reflectance 0.5");
    return true;
  }
  LineReader reader(in);
  std::string line;
  int number = 0;
  Material* current = nullptr;
  std::string currentName;
  std::set<std::string> withoutKd; // SPEC: the default reflectance comes with a warning
  while (reader.Next(line, number))
  {
    const std::vector<std::string> tokens = Split(line);
    if (tokens.empty() || tokens[0][0] == '#')
    {
      continue;
    }
    try
    {
      const std::string& key = tokens[0];
      if (key == "newmtl")
      {
        const std::string name = RestOfLine(line, "newmtl");
        if (name.empty())
        {
          throw LineError("newmtl without a name");
        }
        materials[name] = Material();
        current = &materials[name];
        currentName = name;
        withoutKd.insert(name);
        continue;
      }
      const bool known = key == "Kd" || key == "Ke" || key == "Ks" || key == "Ns";
      if (!known)
      {
        continue; // Ka, d, Tr, illum, Ni, map_*...: nothing radiosity uses
      }
      if (current == nullptr)
      {
        throw LineError(key + " before any newmtl");
      }
      if (key == "Kd")
      {
        current->Kd = ParseColor(tokens);
        withoutKd.erase(currentName);
      }
      else if (key == "Ke")
      {
        current->Ke = ParseColor(tokens);
      }
      else if (key == "Ks")
      {
        current->Ks = ParseColor(tokens);
      }
      else
      {
        if (tokens.size() != 2)
        {
          throw LineError("Ns expects 1 number");
        }
        current->Ns = ParseNumber(tokens[1], "Ns");
      }
    }
    catch (const LineError& e)
    {
      error = Where(file, number) + e.what() + ": '" + line + "'";
      return false;
    }
  }
  for (const std::string& name : withoutKd)
  {
    warnings.push_back("material '" + name + "' in '" + file + "' has no Kd: reflectance 0.5 grey");
  }
  return true;
}
} // namespace

vtkSmartPointer<vtkPolyData> ReadObjWithMaterials(const std::string& objFile, std::string& error,
  std::vector<std::string>& warnings, double maxReflectance)
{
  std::ifstream in(objFile);
  if (!in)
  {
    error = "cannot read OBJ file '" + objFile + "'";
    return nullptr;
  }
  const std::string directory = Directory(objFile);

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  std::size_t texcoords = 0, normals = 0;

  // Materials are looked up after the whole file is read: a usemtl may precede
  // the mtllib that defines it.
  std::map<std::string, Material> materials;
  std::set<std::string> libraries;
  std::vector<std::string> materialNames; // index -> name, "" for no usemtl
  std::map<std::string, int> materialIndex{ { "", 0 } };
  materialNames.push_back("");
  int currentMaterial = 0;
  std::vector<int> triangleMaterial;

  std::vector<std::string> objectNames;
  std::map<std::string, int> objectIndex;
  std::string currentObject = Stem(objFile);
  std::vector<int> triangleObject;

  std::size_t ignoredElements = 0; // l, p
  std::map<std::string, std::size_t> unknown;

  LineReader reader(in);
  std::string line;
  int number = 0;
  while (reader.Next(line, number))
  {
    const std::vector<std::string> tokens = Split(line);
    if (tokens.empty() || tokens[0][0] == '#')
    {
      continue;
    }
    const std::string& key = tokens[0];
    try
    {
      if (key == "v")
      {
        // "v x y z [w]" or "v x y z r g b" (vertex colours): only xyz matter.
        if (tokens.size() < 4)
        {
          throw LineError("a vertex needs 3 coordinates");
        }
        points->InsertNextPoint(ParseNumber(tokens[1], "x"), ParseNumber(tokens[2], "y"),
          ParseNumber(tokens[3], "z"));
      }
      else if (key == "vt")
      {
        ++texcoords;
      }
      else if (key == "vn")
      {
        ++normals;
      }
      else if (key == "f")
      {
        if (tokens.size() < 4)
        {
          throw LineError("a face needs at least 3 vertices");
        }
        std::vector<vtkIdType> ids;
        const std::size_t vertices = static_cast<std::size_t>(points->GetNumberOfPoints());
        for (std::size_t i = 1; i < tokens.size(); ++i)
        {
          ids.push_back(
            static_cast<vtkIdType>(ParseFaceVertex(tokens[i], vertices, texcoords, normals)));
        }
        auto object = objectIndex.find(currentObject);
        if (object == objectIndex.end())
        {
          object = objectIndex.emplace(currentObject, static_cast<int>(objectNames.size())).first;
          objectNames.push_back(currentObject);
        }
        // Fan triangulation: exact for the convex polygons exporters write.
        for (std::size_t i = 1; i + 1 < ids.size(); ++i)
        {
          const vtkIdType triangle[3] = { ids[0], ids[i], ids[i + 1] };
          triangles->InsertNextCell(3, triangle);
          triangleMaterial.push_back(currentMaterial);
          triangleObject.push_back(object->second);
        }
      }
      else if (key == "usemtl")
      {
        const std::string name = RestOfLine(line, "usemtl");
        auto found = materialIndex.find(name);
        if (found == materialIndex.end())
        {
          found = materialIndex.emplace(name, static_cast<int>(materialNames.size())).first;
          materialNames.push_back(name);
        }
        currentMaterial = found->second;
      }
      else if (key == "mtllib")
      {
        // The whole rest of the line if that names a file (names with spaces),
        // otherwise the whitespace-separated list the format defines.
        const std::string rest = RestOfLine(line, "mtllib");
        std::vector<std::string> files;
        if (std::ifstream(directory + rest).good())
        {
          files.push_back(rest);
        }
        else
        {
          files.assign(tokens.begin() + 1, tokens.end());
        }
        for (const std::string& name : files)
        {
          if (libraries.insert(name).second &&
            !ReadMtl(directory + name, materials, error, warnings))
          {
            return nullptr;
          }
        }
      }
      else if (key == "o" || key == "g")
      {
        const std::string name = RestOfLine(line, key);
        currentObject = name.empty() ? Stem(objFile) : name;
      }
      else if (key == "l" || key == "p")
      {
        ++ignoredElements;
      }
      else if (key != "s" && key != "vp")
      {
        ++unknown[key]; // curves, surfaces, display attributes: not a scene for radiosity
      }
    }
    catch (const LineError& e)
    {
      error = Where(objFile, number) + e.what() + ": '" + line + "'";
      return nullptr;
    }
  }

  const vtkIdType count = triangles->GetNumberOfCells();
  auto reflectance = vtkSmartPointer<vtkDoubleArray>::New();
  auto emission = vtkSmartPointer<vtkDoubleArray>::New();
  auto specular = vtkSmartPointer<vtkDoubleArray>::New();
  auto shininess = vtkSmartPointer<vtkDoubleArray>::New();
  auto objectId = vtkSmartPointer<vtkIntArray>::New();
  reflectance->SetName("Reflectance");
  emission->SetName("Emission");
  specular->SetName("Specular");
  shininess->SetName("Shininess");
  objectId->SetName("ObjectId");
  for (vtkDoubleArray* a : { reflectance.Get(), emission.Get(), specular.Get() })
  {
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(count);
  }
  shininess->SetNumberOfTuples(count);
  objectId->SetNumberOfTuples(count);

  // Resolve each used material once; undefined ones get the default, warned once.
  std::vector<Material> resolved(materialNames.size());
  std::vector<std::size_t> uses(materialNames.size(), 0);
  for (int m : triangleMaterial)
  {
    ++uses[static_cast<std::size_t>(m)];
  }
  for (std::size_t m = 0; m < materialNames.size(); ++m)
  {
    if (uses[m] == 0)
    {
      continue;
    }
    const auto found = materials.find(materialNames[m]);
    if (found != materials.end())
    {
      resolved[m] = found->second;
    }
    else if (materialNames[m].empty())
    {
      warnings.push_back(std::to_string(uses[m]) + " triangle(s) of '" + objFile +
        "' have no material (no usemtl): reflectance 0.5 grey");
    }
    else
    {
      warnings.push_back(std::to_string(uses[m]) + " triangle(s) of '" + objFile +
        "' use the undefined material '" + materialNames[m] + "': reflectance 0.5 grey");
    }
  }
  // Display colours at or above the limit (white is common) are clamped; above
  // 1 they are no display colour and are left for the scene check to refuse.
  std::vector<std::string> clamped;
  for (std::size_t m = 0; m < materialNames.size() && maxReflectance < 1.0; ++m)
  {
    bool any = false;
    for (double& c : resolved[m].Kd)
    {
      if (uses[m] > 0 && c >= maxReflectance && c <= 1.0)
      {
        c = maxReflectance;
        any = true;
      }
    }
    if (any)
    {
      clamped.push_back(materialNames[m]);
    }
  }
  if (!clamped.empty())
  {
    std::ostringstream s;
    s << clamped.size() << " material(s) of '" << objFile
      << "' have a Kd component at or above --max-reflectance " << maxReflectance << " ('"
      << clamped[0] << "'" << (clamped.size() > 1 ? ", ..." : "")
      << "): display colours, clamped to " << maxReflectance;
    warnings.push_back(s.str());
  }
  for (vtkIdType t = 0; t < count; ++t)
  {
    const Material& m = resolved[static_cast<std::size_t>(triangleMaterial[t])];
    reflectance->SetTypedTuple(t, m.Kd.data());
    emission->SetTypedTuple(t, m.Ke.data());
    specular->SetTypedTuple(t, m.Ks.data());
    shininess->SetValue(t, m.Ns);
    objectId->SetValue(t, triangleObject[t]);
  }

  if (ignoredElements > 0)
  {
    warnings.push_back(std::to_string(ignoredElements) + " line/point element(s) (l, p) in '" +
      objFile + "' ignored: only faces are surfaces");
  }
  for (const auto& [key, n] : unknown)
  {
    warnings.push_back(std::to_string(n) + " '" + key + "' statement(s) in '" + objFile +
      "' ignored (not supported)");
  }
  if (count == 0)
  {
    warnings.push_back("'" + objFile + "' has no faces");
  }

  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName("ObjectNames");
  for (const std::string& name : objectNames)
  {
    names->InsertNextValue(name);
  }

  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->SetPoints(points);
  output->SetPolys(triangles);
  output->GetCellData()->AddArray(reflectance);
  output->GetCellData()->AddArray(emission);
  output->GetCellData()->AddArray(specular);
  output->GetCellData()->AddArray(shininess);
  output->GetCellData()->AddArray(objectId);
  output->GetFieldData()->AddArray(names);
  return output;
}
} // namespace cli
} // namespace radiosity
