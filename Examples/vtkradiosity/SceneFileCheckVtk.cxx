// SceneFileCheck.h for legacy .vtk files (XML: SceneFileCheckXml.cxx).
//
// vtkDataSetReader trusts what it reads: a FIELD line without its name and
// count, a cell whose point count runs past its section, a point id past the
// points, a POINTS type that is no number type (a leak) all end in a crash
// inside VTK. So the file is walked here as VTK's legacy reader will read it,
// DATASET POLYDATA only (SPEC: scenes are polygonal data), and every count,
// size, type and id is checked before the reader sees the file. This is a
// validator, not a second reader: nothing is allocated for a declared count,
// and counts are checked against the bytes left before they are walked.
#include "SceneFileCheckVtkWalker.h"

namespace radiosity
{
namespace cli
{
bool IsAsciiNumber(const std::string& t, bool integer)
{
  std::size_t i = (!t.empty() && (t[0] == '+' || t[0] == '-')) ? 1 : 0;
  std::size_t digits = 0;
  while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])))
  {
    ++i, ++digits;
  }
  if (!integer && i < t.size() && t[i] == '.')
  {
    for (++i; i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); ++i)
    {
      ++digits;
    }
  }
  if (digits == 0)
  {
    return false;
  }
  if (!integer && i < t.size() && (t[i] == 'e' || t[i] == 'E'))
  {
    ++i;
    i += (i < t.size() && (t[i] == '+' || t[i] == '-')) ? 1 : 0;
    std::size_t exponent = 0;
    for (; i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); ++i)
    {
      ++exponent;
    }
    if (exponent == 0)
    {
      return false;
    }
  }
  return i == t.size();
}

namespace legacy
{

bool LegacyWalker::Points_(const std::vector<std::string>& w)
{
  double n = 0;
  LegacyType type;
  if (w.size() != 3 || !Count(w, 1, n))
  {
    return this->Fail(this->At() + ": a POINTS line is 'POINTS N TYPE'");
  }
  if (this->Points >= 0)
  {
    return this->Fail(this->At() + ": a second POINTS section");
  }
  if (!this->Type(w[2], "POINTS", type, false))
  {
    return false;
  }
  if (type.Bit)
  {
    return this->Fail(this->At() + ": POINTS of type bit (coordinates are float or double)");
  }
  this->Points = n;
  return this->Values(3 * n, type, Number(n) + " points");
}

bool LegacyWalker::CellSection(const std::vector<std::string>& w)
{
  const std::string key = Upper(w[0]);
  double n = 0, size = 0;
  if (w.size() != 3 || !Count(w, 1, n) || !Count(w, 2, size))
  {
    return this->Fail(this->At() + ": a " + key + " line is '" + key + " N SIZE'");
  }
  if (std::find(this->Sections.begin(), this->Sections.end(), key) != this->Sections.end())
  {
    return this->Fail(this->At() + ": a second " + key + " section");
  }
  this->Sections.push_back(key);
  if (this->Points < 0)
  {
    return this->Fail(this->At() + ": " + key + " before POINTS (the cells' point ids need them)");
  }
  return this->Major >= 5 ? this->OffsetCells(key, n, size, this->Line)
                          : this->LegacyCells(key, n, size, this->Line);
}

// "POLYGONS n size" then `size` ints: per cell its point count and the ids.
// vtkCellArray::ImportLegacyFormat walks them without bounds.
bool LegacyWalker::LegacyCells(const std::string& key, double n, double size, int line)
{
  LegacyType type;
  FindLegacyType("int", type);
  double cell = 0, next = 0;
  const std::string header = "line " + std::to_string(line) + ": " + key;
  const auto each = [&](double k, long long v)
  {
    const std::string where = this->ValueAt() + ": " + key;
    if (k == next) // a cell's point count
    {
      if (cell == n)
      {
        return this->Fail(where + " declares " + Number(n) + " cells but its size " +
          Number(size) + " holds more (value " + Number(k + 1) + " starts cell " +
          Number(cell + 1) + ")");
      }
      if (v < 1 || static_cast<double>(v) > size - k - 1)
      {
        return this->Fail(where + " cell " + Number(cell) + " has " + std::to_string(v) +
          " points but the declared size " + Number(size) + " leaves room for " +
          Number(size - k - 1) + (v < 1 ? " (a cell has at least 1 point)" : ""));
      }
      next = k + 1 + static_cast<double>(v);
      ++cell;
      return true;
    }
    if (v < 0 || static_cast<double>(v) >= this->Points)
    {
      return this->Fail(where + " cell " + Number(cell - 1) + " has the point id " +
        std::to_string(v) + ", out of range (" + Number(this->Points) + " points)");
    }
    return true;
  };
  if (!this->Values(size, type, Number(n) + " " + key + " (" + Number(size) + " ids)", each))
  {
    return false;
  }
  if (cell != n)
  {
    return this->Fail(header + " declares " + Number(n) + " cells but its size " +
      Number(size) + " holds " + Number(cell));
  }
  this->Cells += n;
  return true;
}

// VTK 5.1: "POLYGONS offsets connectivity", then OFFSETS and CONNECTIVITY arrays.
bool LegacyWalker::OffsetCells(const std::string& key, double n, double size, int line)
{
  if (n < 1)
  {
    return true; // vtkDataReader::ReadCells reads nothing more: an empty cell array
  }
  const std::string where = "line " + std::to_string(line) + ": " + key;
  std::vector<std::string> w;
  LegacyType offsets, connectivity;
  const auto at = [this, &key]() { return this->ValueAt() + ": " + key; };
  if (!this->NextLine(w) || Upper(w[0]) != "OFFSETS" || w.size() != 2)
  {
    return this->Fail(where + " (VTK 5 cells) is not followed by an 'OFFSETS TYPE' line");
  }
  if (!this->ShortWords(w) || !this->Type(w[1], key + " OFFSETS", offsets, true))
  {
    return false;
  }
  long long previous = 0;
  const auto offset = [&](double k, long long v)
  {
    if ((k == 0 && v != 0) || (k > 0 && v <= previous) || static_cast<double>(v) > size)
    {
      return this->Fail(at() + " offset " + Number(k) + " is " + std::to_string(v) +
        (k == 0 ? " (the first offset is 0)"
                : v <= previous ? ", not above the one before (" + std::to_string(previous) + ")"
                                : ", beyond the " + Number(size) + " connectivity ids"));
    }
    previous = v;
    return true;
  };
  if (!this->Values(n, offsets, Number(n) + " " + key + " offsets", offset))
  {
    return false;
  }
  if (static_cast<double>(previous) != size)
  {
    return this->Fail(where + " declares " + Number(size) + " connectivity ids but its last "
      "offset is " + std::to_string(previous));
  }
  if (!this->NextLine(w) || Upper(w[0]) != "CONNECTIVITY" || w.size() != 2)
  {
    return this->Fail(where + " OFFSETS are not followed by a 'CONNECTIVITY TYPE' line");
  }
  if (!this->ShortWords(w) || !this->Type(w[1], key + " CONNECTIVITY", connectivity, true))
  {
    return false;
  }
  if (Lower(connectivity.Name) != Lower(offsets.Name))
  {
    return this->Fail(this->At() + ": " + key + " CONNECTIVITY of type " + connectivity.Name +
      " but OFFSETS of type " + offsets.Name + " (VTK needs one type for both)");
  }
  const auto id = [&](double k, long long v)
  {
    if (v < 0 || static_cast<double>(v) >= this->Points)
    {
      return this->Fail(at() + " connectivity id " + Number(k) + " is " + std::to_string(v) +
        ", out of range (" + Number(this->Points) + " points)");
    }
    return true;
  };
  if (!this->Values(size, connectivity, Number(size) + " connectivity ids", id))
  {
    return false;
  }
  this->Cells += n - 1;
  return true;
}


bool LegacyWalker::Walk()
{
  std::vector<std::string> w;
  if (!this->NextLine(w))
  {
    return this->Fail("the file ends after its header (no DATASET POLYDATA)");
  }
  if (!this->ShortWords(w))
  {
    return false;
  }
  if (Upper(w[0]) != "DATASET")
  {
    return this->Fail(this->At() + ": '" + Shown(w[0]) + "' where DATASET POLYDATA is expected "
                                                         "(the loader reads polygonal data)");
  }
  if (w.size() != 2 || Upper(w[1]) != "POLYDATA")
  {
    return this->Fail(this->At() + ": DATASET " + Shown(w.size() > 1 ? w[1] : "") +
      " is not polygonal data (the loader reads DATASET POLYDATA; convert with "
      "vtkGeometryFilter)");
  }
  // Geometry: FIELD, POINTS and the cell sections, up to the attributes.
  std::string section;
  while (this->NextLine(w))
  {
    if (!this->ShortWords(w))
    {
      return false;
    }
    const std::string key = Upper(w[0]);
    if (key == "POINT_DATA" || key == "CELL_DATA")
    {
      section = key;
      break;
    }
    bool ok = true;
    if (key == "METADATA")
    {
      this->SkipMetadata();
    }
    else if (key == "FIELD")
    {
      ok = this->Field(w, -1, "");
    }
    else if (key == "POINTS")
    {
      ok = this->Points_(w);
    }
    else if (key == "VERTICES" || key == "LINES" || key == "POLYGONS" || key == "TRIANGLE_STRIPS")
    {
      ok = this->CellSection(w);
    }
    else
    {
      return this->Fail(this->At() + ": unknown keyword '" + Shown(w[0]) +
        "' in DATASET POLYDATA (VTK's legacy reader takes FIELD, POINTS, VERTICES, LINES, "
        "POLYGONS, TRIANGLE_STRIPS, POINT_DATA and CELL_DATA)");
    }
    if (!ok)
    {
      return false;
    }
  }
  // Attributes: POINT_DATA n / CELL_DATA n sections up to the end of the file.
  double tuples = 0;
  while (!section.empty())
  {
    double n = 0;
    const double expected = section == "POINT_DATA" ? std::max(this->Points, 0.0) : this->Cells;
    if (w.size() != 2 || !Count(w, 1, n))
    {
      return this->Fail(this->At() + ": a " + section + " line is '" + section + " N'");
    }
    if (n != expected)
    {
      return this->Fail(this->At() + ": " + section + " " + Number(n) + " but the data set has " +
        Number(expected) + (section == "POINT_DATA" ? " points" : " cells"));
    }
    tuples = n;
    std::string next;
    while (next.empty() && this->NextLine(w))
    {
      if (!this->ShortWords(w))
      {
        return false;
      }
      const std::string key = Upper(w[0]);
      bool handled = false;
      if (key == "POINT_DATA" || key == "CELL_DATA")
      {
        next = key;
      }
      else if (key == "METADATA")
      {
        this->SkipMetadata();
      }
      else if (!this->Attribute(w, section, tuples, handled))
      {
        return false;
      }
      else if (!handled)
      {
        return this->Fail(this->At() + ": unknown keyword '" + Shown(w[0]) + "' in " + section +
          " (VTK's legacy reader takes SCALARS, COLOR_SCALARS, LOOKUP_TABLE, VECTORS, NORMALS, "
          "TEXTURE_COORDINATES, TENSORS, TENSORS6, GLOBAL_IDS, PEDIGREE_IDS, " +
          (section == "POINT_DATA" ? "EDGE_FLAGS, " : "") + "FIELD, POINT_DATA and CELL_DATA)");
      }
    }
    section = next;
  }
  return true;
}
} // namespace legacy

using namespace legacy; // the walker and its helpers (SceneFileCheckVtkWalker.h)


bool CheckLegacyVtk(const std::string& file, const std::string& bytes, std::string& error)
{
  const std::string magic = "# vtk DataFile Version";
  if (bytes.compare(0, magic.size(), magic) != 0)
  {
    const std::size_t end = std::min(bytes.find('\n'), std::size_t(40));
    error = file + ": not a legacy VTK file (the first line is '" +
      Shown(bytes.substr(0, std::min(end, bytes.size()))) + "', not '" + magic + " N.N')";
    return false;
  }
  // VTK reads the version with sscanf("%d.%d"); without one it reads legacy cells.
  int major = 0, minor = 0;
  const std::string first = bytes.substr(magic.size(), 64);
  if (std::sscanf(first.c_str(), "%d.%d", &major, &minor) != 2)
  {
    major = 0;
  }
  // Line 1 the magic, line 2 a title (anything, possibly empty), line 3 the format.
  std::size_t pos = 0;
  for (int line = 0; line < 2; ++line)
  {
    const std::size_t end = bytes.find('\n', pos);
    if (end == std::string::npos)
    {
      error = file + ": the legacy header ends on line " + std::to_string(line + 1);
      return false;
    }
    pos = end + 1;
  }
  std::istringstream format(bytes.substr(pos, bytes.find('\n', pos) - pos));
  std::string word;
  format >> word;
  if (Upper(word) != "ASCII" && Upper(word) != "BINARY")
  {
    error = file + ": line 3 of a legacy VTK file must be ASCII or BINARY, not '" + Shown(word) +
      "'";
    return false;
  }
  const std::size_t end = bytes.find('\n', pos);
  LegacyWalker walk(bytes, Upper(word) == "BINARY", major);
  walk.Pos = end == std::string::npos ? bytes.size() : end + 1;
  walk.Line = 3;
  if (!walk.Walk())
  {
    error = file + ": " + walk.Error;
    return false;
  }
  return true;
}
} // namespace cli
} // namespace radiosity
