// SceneFileCheck.h for VTK's own formats: legacy .vtk and XML (.vtp, .vtm...).
#include "SceneFileCheck.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

namespace radiosity
{
namespace cli
{
namespace
{
std::string Upper(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

// Bytes per value of a legacy data type; 0 for types of variable length.
int LegacyTypeSize(const std::string& type)
{
  static const std::map<std::string, int> sizes = { { "bit", 1 }, { "unsigned_char", 1 },
    { "char", 1 }, { "signed_char", 1 }, { "unsigned_short", 2 }, { "short", 2 },
    { "unsigned_int", 4 }, { "int", 4 }, { "unsigned_long", 8 }, { "long", 8 },
    { "vtktypeint64", 8 }, { "vtktypeuint64", 8 }, { "vtkidtype", 8 }, { "float", 4 },
    { "double", 8 } };
  std::string lower = type;
  std::transform(lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) { return std::tolower(c); });
  const auto found = sizes.find(lower);
  return found == sizes.end() ? 0 : found->second;
}

// Walks a legacy file: header lines (keywords) and the data blocks they
// declare, skipping each block by its declared size; a count larger than what
// is left is the error. Stops quietly at anything it does not know (the VTK
// reader reports that itself).
class LegacyWalker
{
public:
  LegacyWalker(const std::string& bytes, bool binary)
    : Bytes(bytes)
    , Binary(binary)
  {
  }
  std::size_t Pos = 0;
  int Line = 0;

  bool NextLine(std::vector<std::string>& words)
  {
    words.clear();
    while (words.empty())
    {
      if (this->Pos >= this->Bytes.size())
      {
        return false;
      }
      std::size_t end = this->Bytes.find('\n', this->Pos);
      end = end == std::string::npos ? this->Bytes.size() : end;
      std::istringstream s(this->Bytes.substr(this->Pos, end - this->Pos));
      this->Pos = std::min(end + 1, this->Bytes.size());
      ++this->Line;
      std::string w;
      while (s >> w)
      {
        words.push_back(w);
      }
    }
    return true;
  }

  // Skips `values` values of `type` declared by the header line just read.
  bool Skip(double values, const std::string& type, const std::string& what, std::string& error)
  {
    const int size = LegacyTypeSize(type);
    if (size == 0)
    {
      this->Stop = true; // strings and the like: variable length
      return true;
    }
    const double left = static_cast<double>(this->Bytes.size() - this->Pos);
    const double need = this->Binary
      ? (Upper(type) == "BIT" ? values / 8.0 : values * size)
      : values * 2.0 - 1.0; // "0 0 0": two characters a value, the last one's line end aside
    if (need > left)
    {
      std::ostringstream s;
      s << std::fixed << std::setprecision(0) << "line " << this->Line << " declares " << what << " (" << values << " "
        << type << " values, " << (this->Binary ? "" : "at least ") << ByteSize(need)
        << ") but the file holds " << ByteSize(left) << " after it";
      error = s.str();
      return false;
    }
    if (this->Binary)
    {
      this->Pos += static_cast<std::size_t>(std::ceil(need));
      if (this->Pos < this->Bytes.size() && this->Bytes[this->Pos] == '\n')
      {
        ++this->Pos; // the line end after the block is not a line of its own
      }
      return true;
    }
    // ASCII: skip whitespace-separated values (they may span lines).
    for (double k = 0; k < values; ++k)
    {
      while (this->Pos < this->Bytes.size() && std::isspace(static_cast<unsigned char>(this->Bytes[this->Pos])))
      {
        this->Line += this->Bytes[this->Pos] == '\n';
        ++this->Pos;
      }
      if (this->Pos >= this->Bytes.size())
      {
        std::ostringstream s;
        s << std::fixed << std::setprecision(0) << "the file ends after " << k << " of the " << values << " values of " << what;
        error = s.str();
        return false;
      }
      while (this->Pos < this->Bytes.size() && !std::isspace(static_cast<unsigned char>(this->Bytes[this->Pos])))
      {
        ++this->Pos;
      }
    }
    return true;
  }
  bool Stop = false;
  bool IsBinary() const { return this->Binary; }

private:
  const std::string& Bytes;
  bool Binary;
};

bool Count(const std::vector<std::string>& w, std::size_t i, double& value)
{
  if (i >= w.size() || w[i].find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  value = std::stod(w[i]);
  return true;
}

bool WalkLegacy(LegacyWalker& walk, std::string& error)
{
  std::vector<std::string> w;
  double attributes = 0; // tuples of the current POINT_DATA / CELL_DATA section
  double points = 0, cells = 0;
  bool pointsKnown = false; // a POINTS line (structured data sets have DIMENSIONS)
  bool cellsKnown = false; // POLYDATA and UNSTRUCTURED_GRID list their cells
  while (!walk.Stop && walk.NextLine(w))
  {
    const std::string key = Upper(w[0]);
    double n = 0, m = 0;
    std::ostringstream what;
    what << std::fixed << std::setprecision(0);
    if (key == "DATASET")
    {
      cellsKnown = w.size() >= 2 && (Upper(w[1]) == "POLYDATA" || Upper(w[1]) == "UNSTRUCTURED_GRID");
      continue;
    }
    if (key == "DIMENSIONS" || key == "ORIGIN" || key == "SPACING" ||
      key == "ASPECT_RATIO")
    {
      continue;
    }
    if (key == "POINTS" && Count(w, 1, n) && w.size() >= 3)
    {
      points = n;
      pointsKnown = true;
      what << n << " points";
      if (!walk.Skip(3 * n, w[2], what.str(), error))
        return false;
    }
    else if ((key == "X_COORDINATES" || key == "Y_COORDINATES" || key == "Z_COORDINATES") &&
      Count(w, 1, n) && w.size() >= 3)
    {
      what << n << " " << w[0];
      if (!walk.Skip(n, w[2], what.str(), error))
        return false;
    }
    else if ((key == "VERTICES" || key == "LINES" || key == "POLYGONS" ||
               key == "TRIANGLE_STRIPS" || key == "CELLS") &&
      Count(w, 1, n) && Count(w, 2, m))
    {
      cells = key == "CELLS" ? n : cells + n;
      // Version 5: "POLYGONS offsets connectivity" then OFFSETS and CONNECTIVITY blocks.
      const std::size_t keep = walk.Pos;
      const int line = walk.Line;
      std::vector<std::string> next;
      if (walk.NextLine(next) && Upper(next[0]) == "OFFSETS" && next.size() >= 2)
      {
        what << n << " " << w[0] << " offsets";
        if (!walk.Skip(n, next[1], what.str(), error))
          return false;
        if (!walk.NextLine(next) || Upper(next[0]) != "CONNECTIVITY" || next.size() < 2)
          return true; // the reader says what is wrong
        if (!walk.Skip(m, next[1], std::to_string(static_cast<long long>(m)) + " connectivity ids",
              error))
          return false;
        continue;
      }
      walk.Pos = keep;
      walk.Line = line;
      what << n << " " << w[0] << " (" << m << " ids)";
      if (!walk.Skip(m, "int", what.str(), error))
        return false;
    }
    else if (key == "CELL_TYPES" && Count(w, 1, n))
    {
      what << n << " cell types";
      if (!walk.Skip(n, "int", what.str(), error))
        return false;
    }
    else if ((key == "POINT_DATA" || key == "CELL_DATA") && Count(w, 1, n))
    {
      const double limit = key == "POINT_DATA" ? points : cells;
      if (n > limit && (key == "POINT_DATA" ? pointsKnown : cellsKnown))
      {
        std::ostringstream s;
        s << std::fixed << std::setprecision(0) << "line " << walk.Line << ": " << w[0] << " " << n << " but the data set has " << limit
          << (key == "POINT_DATA" ? " points" : " cells");
        error = s.str();
        return false;
      }
      attributes = n;
    }
    else if (key == "SCALARS" && w.size() >= 3)
    {
      double components = 1;
      if (w.size() >= 4 && !Count(w, 3, components))
        return true;
      std::vector<std::string> next;
      const std::size_t keep = walk.Pos;
      const int line = walk.Line;
      if (!walk.NextLine(next) || Upper(next[0]) != "LOOKUP_TABLE")
      {
        walk.Pos = keep; // LOOKUP_TABLE is optional
        walk.Line = line;
      }
      what << "SCALARS " << w[1] << ": " << attributes << " tuples of " << components;
      if (!walk.Skip(attributes * components, w[2], what.str(), error))
        return false;
    }
    else if (key == "LOOKUP_TABLE" && Count(w, 2, n))
    {
      what << "LOOKUP_TABLE " << w[1] << " of " << n << " colours";
      if (!walk.Skip(4 * n, walk.IsBinary() ? "unsigned_char" : "float", what.str(), error))
        return false;
    }
    else if (key == "COLOR_SCALARS" && Count(w, 2, n))
    {
      what << "COLOR_SCALARS " << w[1] << ": " << attributes << " tuples of " << n;
      if (!walk.Skip(attributes * n, walk.IsBinary() ? "unsigned_char" : "float", what.str(), error))
        return false;
    }
    else if ((key == "VECTORS" || key == "NORMALS" || key == "TENSORS" || key == "TENSORS6") &&
      w.size() >= 3)
    {
      const double components = key == "TENSORS" ? 9 : key == "TENSORS6" ? 6 : 3;
      what << w[0] << " " << w[1] << ": " << attributes << " tuples";
      if (!walk.Skip(attributes * components, w[2], what.str(), error))
        return false;
    }
    else if ((key == "TEXTURE_COORDINATES" || key == "TCOORDS") && Count(w, 2, n) &&
      w.size() >= 4)
    {
      what << w[0] << " " << w[1] << ": " << attributes << " tuples of " << n;
      if (!walk.Skip(attributes * n, w[3], what.str(), error))
        return false;
    }
    else if ((key == "GLOBAL_IDS" || key == "PEDIGREE_IDS") && w.size() >= 3)
    {
      what << w[0] << " " << w[1] << ": " << attributes << " ids";
      if (!walk.Skip(attributes, w[2], what.str(), error))
        return false;
    }
    else if (key == "FIELD" && Count(w, 2, n))
    {
      for (double a = 0; a < n && !walk.Stop; ++a)
      {
        std::vector<std::string> array;
        double components = 0, tuples = 0;
        if (!walk.NextLine(array))
          return true;
        if (Upper(array[0]) == "METADATA")
        {
          --a;
          continue;
        }
        if (!Count(array, 1, components) || !Count(array, 2, tuples) || array.size() < 4)
          return true;
        std::ostringstream array_what;
        array_what << std::fixed << std::setprecision(0);
        array_what << "field array " << array[0] << ": " << tuples << " tuples of " << components;
        if (!walk.Skip(components * tuples, array[3], array_what.str(), error))
          return false;
      }
    }
    else if (key == "METADATA" || key == "INFORMATION" || key == "NAME" || key == "DATA" ||
      key == "COMPONENT_NAMES")
    {
      continue; // metadata lines: no counts that allocate
    }
    else
    {
      return true; // unknown to this check: the reader will say
    }
  }
  return true;
}
} // namespace

bool CheckLegacyVtk(const std::string& file, const std::string& bytes, std::string& error)
{
  LegacyWalker header(bytes, false);
  std::vector<std::string> w;
  const std::string magic = "# vtk DataFile Version";
  if (bytes.compare(0, magic.size(), magic) != 0)
  {
    const std::size_t end = std::min(bytes.find('\n'), std::size_t(40));
    error = file + ": not a legacy VTK file (the first line is '" +
      bytes.substr(0, std::min(end, bytes.size())) + "', not '" + magic + " N.N')";
    return false;
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
  header.Pos = pos;
  header.Line = 2;
  if (!header.NextLine(w) || (Upper(w[0]) != "ASCII" && Upper(w[0]) != "BINARY"))
  {
    error = file + ": line 3 of a legacy VTK file must be ASCII or BINARY, not '" +
      (w.empty() ? std::string() : w[0]) + "'";
    return false;
  }
  LegacyWalker walk(bytes, Upper(w[0]) == "BINARY");
  walk.Pos = header.Pos;
  walk.Line = header.Line;
  std::string why;
  if (!WalkLegacy(walk, why))
  {
    error = file + ": " + why;
    return false;
  }
  return true;
}
namespace
{
// The value of attribute `name` in the tag that starts at `tag` (up to its '>').
bool Attribute(const std::string& bytes, std::size_t tag, const std::string& name,
  std::string& value)
{
  const std::size_t close = bytes.find('>', tag);
  std::size_t at = bytes.find(" " + name + "=", tag);
  if (at == std::string::npos || at > close)
  {
    at = bytes.find("\t" + name + "=", tag);
    if (at == std::string::npos || at > close)
      return false;
  }
  at += name.size() + 2;
  if (at >= bytes.size() || (bytes[at] != '"' && bytes[at] != '\''))
    return false;
  const std::size_t end = bytes.find(bytes[at], at + 1);
  if (end == std::string::npos)
    return false;
  value = bytes.substr(at + 1, end - at - 1);
  return true;
}

bool CheckXml(const std::string& file, const std::string& bytes, int depth, std::string& error)
{
  std::size_t start = 0;
  if (bytes.compare(0, 3, "\xEF\xBB\xBF") == 0)
    start = 3;
  start = bytes.find_first_not_of(" \t\r\n", start);
  if (start == std::string::npos || bytes[start] != '<')
  {
    error = file + ": not an XML file (it does not start with '<')";
    return false;
  }
  // The data may be compressed: a count can then exceed the file's bytes by
  // the compressor's best ratio (runs of one value), and no more.
  const std::size_t root = bytes.find("<VTKFile");
  double ratio = 1;
  std::string compressor;
  if (root != std::string::npos && Attribute(bytes, root, "compressor", compressor))
  {
    ratio = compressor.find("LZ4") != std::string::npos ? 255
      : compressor.find("LZMA") != std::string::npos   ? 7000
                                                        : 1032;
  }
  // Raw appended data is binary: attributes are only looked for before it.
  const std::size_t end = std::min(bytes.find("<AppendedData"), bytes.size());
  const double limit = ratio * static_cast<double>(bytes.size());
  for (const char* name : { "NumberOfPoints", "NumberOfCells", "NumberOfVerts", "NumberOfLines",
         "NumberOfStrips", "NumberOfPolys", "NumberOfTuples" })
  {
    const std::string key = std::string(" ") + name + "=";
    for (std::size_t at = bytes.find(key); at < end; at = bytes.find(key, at + 1))
    {
      std::string value;
      const std::size_t tag = bytes.rfind('<', at);
      if (!Attribute(bytes, tag, name, value))
        continue;
      const double per = std::string(name) == "NumberOfPoints" ? 3 : 1;
      char* stop = nullptr;
      const double n = std::strtod(value.c_str(), &stop);
      if (*stop != '\0' || !(n >= 0))
      {
        error = file + ": " + name + "=\"" + value + "\" (byte " + std::to_string(at + 1) +
          ") is not a count";
        return false;
      }
      if (n * per > limit)
      {
        std::ostringstream s;
        s << file << ": " << name << "=\"" << value << "\" (byte " << at + 1 << ") needs at least "
          << ByteSize(n * per / ratio) << (ratio > 1 ? " compressed (" + compressor + ")" : "")
          << " but the file holds " << bytes.size() << " bytes";
        error = s.str();
        return false;
      }
    }
  }
  // A multiblock file names its pieces: they are checked too.
  const std::string dir = file.find('/') == std::string::npos ? ""
                                                              : file.substr(0, file.rfind('/') + 1);
  for (std::size_t at = bytes.find("<DataSet"); at < end; at = bytes.find("<DataSet", at + 1))
  {
    std::string piece;
    if (!Attribute(bytes, at, "file", piece) || piece.empty())
      continue;
    const std::string path = piece[0] == '/' ? piece : dir + piece;
    std::string pieceBytes;
    if (depth > 8)
    {
      error = file + ": data sets nested deeper than 8 files";
      return false;
    }
    if (!ReadFileBytes(path, pieceBytes, error) || !CheckXml(path, pieceBytes, depth + 1, error))
    {
      error = file + ": block file '" + piece + "': " + error;
      return false;
    }
  }
  return true;
}
} // namespace

bool CheckXmlVtk(const std::string& file, const std::string& bytes, std::string& error)
{
  return CheckXml(file, bytes, 0, error);
}
} // namespace cli
} // namespace radiosity
