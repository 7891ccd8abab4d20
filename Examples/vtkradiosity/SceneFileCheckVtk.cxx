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
#include "SceneFileCheck.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iomanip>
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

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// A word of the file for a message: at most 40 characters, control bytes as '?'.
std::string Shown(const std::string& text)
{
  std::string out;
  for (unsigned char c : text.substr(0, 40))
  {
    out += (c < 0x20 || c >= 0x7F) ? '?' : static_cast<char>(c);
  }
  return text.size() > 40 ? out + "..." : out;
}

std::string Number(double v)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(0) << v;
  return s.str();
}

// A number type of VTK's legacy reader (vtkDataReader::ReadArray): bytes per
// binary value (vtkidtype is written as a 4-byte int), integer or not.
struct LegacyType
{
  std::string Name;
  int Size = 0;
  bool Integer = false;
  bool Bit = false;
};

bool FindLegacyType(const std::string& word, LegacyType& type)
{
  struct Entry
  {
    const char* Name;
    int Size;
    bool Integer;
  };
  static const Entry types[] = { { "bit", 1, true }, { "unsigned_char", 1, true },
    { "char", 1, true }, { "signed_char", 1, true }, { "unsigned_short", 2, true },
    { "short", 2, true }, { "unsigned_int", 4, true }, { "int", 4, true },
    { "unsigned_long", 8, true }, { "long", 8, true }, { "vtktypeint64", 8, true },
    { "vtktypeuint64", 8, true }, { "vtkidtype", 4, true }, { "float", 4, false },
    { "double", 8, false } };
  const std::string lower = Lower(word);
  for (const Entry& e : types)
  {
    if (lower == e.Name)
    {
      type.Name = word;
      type.Size = e.Size;
      type.Integer = e.Integer;
      type.Bit = lower == "bit";
      return true;
    }
  }
  return false;
}

} // namespace

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

namespace
{
bool Count(const std::vector<std::string>& w, std::size_t i, double& value)
{
  if (i >= w.size() || w[i].empty() || w[i].size() > 18 ||
    w[i].find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  value = std::stod(w[i]);
  return true;
}

// Walks a legacy file the way vtkPolyDataReader reads it (keywords, then the
// data blocks they declare). Every refusal is one sentence in Error.
class LegacyWalker
{
public:
  LegacyWalker(const std::string& bytes, bool binary, int major)
    : Bytes(bytes)
    , Binary(binary)
    , Major(major)
  {
  }
  std::size_t Pos = 0;
  int Line = 0;
  std::string Error;

  bool Walk();

private:
  const std::string& Bytes;
  bool Binary;
  int Major;
  double Points = -1; // -1 until POINTS
  double Cells = 0;
  std::vector<std::string> Sections; // cell sections seen

  bool Fail(const std::string& message)
  {
    this->Error = message;
    return false;
  }
  std::string At() const { return "line " + std::to_string(this->Line); }
  // Inside an ASCII data block Line counts the lines before the value's: the
  // header line was read whole and the line ends walked past since.
  std::string ValueAt() const
  {
    return "line " + std::to_string(this->Line + (this->Binary ? 0 : 1));
  }

  // The next line, without its '\n'; false at the end of the file.
  bool RawLine(std::string& line)
  {
    if (this->Pos >= this->Bytes.size())
    {
      return false;
    }
    std::size_t end = this->Bytes.find('\n', this->Pos);
    end = end == std::string::npos ? this->Bytes.size() : end;
    line = this->Bytes.substr(this->Pos, end - this->Pos);
    this->Pos = std::min(end + 1, this->Bytes.size());
    ++this->Line;
    return true;
  }

  // The words of the next line that has any; false at the end of the file.
  bool NextLine(std::vector<std::string>& words)
  {
    words.clear();
    std::string line;
    while (words.empty())
    {
      if (!this->RawLine(line))
      {
        return false;
      }
      std::istringstream s(line);
      std::string w;
      while (s >> w)
      {
        words.push_back(w);
      }
    }
    return true;
  }

  // Words of a keyword line: VTK reads them into 256-byte buffers.
  bool ShortWords(const std::vector<std::string>& w)
  {
    for (const std::string& word : w)
    {
      if (word.size() > 255)
      {
        return this->Fail(this->At() + ": a word of " + std::to_string(word.size()) +
          " characters ('" + Shown(word) + "'; VTK's legacy reader takes at most 255)");
      }
    }
    return true;
  }

  bool Type(const std::string& word, const std::string& what, LegacyType& type, bool integer)
  {
    if (!FindLegacyType(word, type))
    {
      return this->Fail(this->At() + ": " + what + " has the data type '" + Shown(word) +
        "', not a number type VTK's legacy reader takes (bit, char, unsigned_char, short, "
        "unsigned_short, int, unsigned_int, long, unsigned_long, vtktypeint64, vtktypeuint64, "
        "vtkidtype, float, double)");
    }
    if (integer && (!type.Integer || type.Bit))
    {
      return this->Fail(this->At() + ": " + what + " has the data type '" + Shown(word) +
        "', not an integer type (int, vtktypeint64 or vtkidtype)");
    }
    return true;
  }

  /// Walks `count` values of `type` declared by the line just read: their
  /// bytes must be in the file, ASCII ones must be numbers of the type, and
  /// `each` (when given) sees every integer value by its index.
  bool Values(double count, const LegacyType& type, const std::string& what,
    const std::function<bool(double, long long)>& each = nullptr)
  {
    const double left = static_cast<double>(this->Bytes.size() - this->Pos);
    const double need = this->Binary ? (type.Bit ? std::ceil(count / 8.0) : count * type.Size)
                                     : count * 2.0 - 1.0; // "0 0 0": a value and a blank each
    if (need > left)
    {
      std::ostringstream s;
      s << this->At() << " declares " << what << " (" << Number(count) << " " << type.Name
        << " values, " << (this->Binary ? "" : "at least ") << ByteSize(need)
        << ") but the file holds " << ByteSize(left) << " after it";
      return this->Fail(s.str());
    }
    if (this->Binary)
    {
      const std::size_t start = this->Pos;
      if (each)
      {
        for (double k = 0; k < count; ++k)
        {
          const char* p = this->Bytes.data() + start + static_cast<std::size_t>(k) * type.Size;
          unsigned long long u = 0;
          for (int b = 0; b < type.Size; ++b) // big-endian
          {
            u = (u << 8) | static_cast<unsigned char>(p[b]);
          }
          long long v = static_cast<long long>(u);
          if (type.Size == 4 && type.Name != "unsigned_int")
          {
            v = static_cast<long long>(static_cast<std::int32_t>(static_cast<std::uint32_t>(u)));
          }
          if (!each(k, v))
          {
            return false;
          }
        }
      }
      // Line numbers count the text lines only (keywords), not binary blocks.
      this->Pos += static_cast<std::size_t>(need);
      if (this->Pos < this->Bytes.size() && this->Bytes[this->Pos] == '\n')
      {
        ++this->Pos; // the line end after the block is not a line of its own
      }
      return true;
    }
    // ASCII: whitespace-separated values (they may span lines).
    const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    std::string token;
    for (double k = 0; k < count; ++k)
    {
      while (this->Pos < this->Bytes.size() && space(this->Bytes[this->Pos]))
      {
        this->Line += this->Bytes[this->Pos] == '\n';
        ++this->Pos;
      }
      if (this->Pos >= this->Bytes.size())
      {
        return this->Fail("the file ends after " + Number(k) + " of the " + Number(count) +
          " values of " + what);
      }
      const std::size_t start = this->Pos;
      while (this->Pos < this->Bytes.size() && !space(this->Bytes[this->Pos]))
      {
        ++this->Pos;
      }
      token.assign(this->Bytes, start, this->Pos - start);
      if (!IsAsciiNumber(token, type.Integer))
      {
        return this->Fail(this->ValueAt() + ": " + what + ": value " + Number(k + 1) + ", '" +
          Shown(token) + "', is not " + (type.Integer ? "an integer" : "a number") + " (" +
          type.Name + ")");
      }
      if (each)
      {
        errno = 0;
        const long long v = std::strtoll(token.c_str(), nullptr, 10);
        if (errno == ERANGE || !each(k, v))
        {
          return this->Error.empty()
            ? this->Fail(this->ValueAt() + ": " + what + ": value " + Number(k + 1) + ", '" +
                Shown(token) + "', is out of range")
            : false;
        }
      }
    }
    return true;
  }

  // "METADATA" after an array: lines up to a blank one (component names, information keys).
  void SkipMetadata()
  {
    std::string line;
    while (this->RawLine(line) && line.find_first_not_of(" \t\r") != std::string::npos)
    {
    }
  }

  bool Points_(const std::vector<std::string>& w);
  bool CellSection(const std::vector<std::string>& w);
  bool LegacyCells(const std::string& key, double n, double size, int line);
  bool OffsetCells(const std::string& key, double n, double size, int line);
  bool Field(const std::vector<std::string>& w, double tuples, const std::string& section);
  bool Attribute(const std::vector<std::string>& w, const std::string& section, double tuples,
    bool& handled);
};

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

// "FIELD name n" and its n arrays ("NAME components tuples type" or NULL_ARRAY);
// `tuples` >= 0: the POINT_DATA / CELL_DATA count every array must have.
bool LegacyWalker::Field(
  const std::vector<std::string>& w, double tuples, const std::string& section)
{
  double n = 0;
  if (w.size() != 3 || !Count(w, 2, n))
  {
    return this->Fail(this->At() + ": a FIELD line is 'FIELD NAME N' (a name and the number of "
                                   "arrays), not '" + Shown(w.size() > 1 ? w[1] : w[0]) +
      (w.size() > 1 ? "...'" : "' alone"));
  }
  const std::string field = "FIELD " + w[1];
  // vtkFieldData::AllocateArrays(n) comes first: an array takes a line at least.
  const double left = static_cast<double>(this->Bytes.size() - this->Pos);
  if (n * 2 > left)
  {
    return this->Fail(this->At() + " declares " + field + " of " + Number(n) +
      " arrays but the file holds " + ByteSize(left) + " after it");
  }
  for (double a = 0; a < n; ++a)
  {
    std::vector<std::string> array;
    if (!this->NextLine(array))
    {
      return this->Fail("the file ends before array " + Number(a + 1) + " of the " + Number(n) +
        " of " + field);
    }
    if (!this->ShortWords(array))
    {
      return false;
    }
    if (Upper(array[0]) == "METADATA")
    {
      this->SkipMetadata();
      --a;
      continue;
    }
    if (array[0] == "NULL_ARRAY" && array.size() == 1)
    {
      continue;
    }
    double components = 0, count = 0;
    LegacyType type;
    const std::string what = field + " array " + Shown(array[0]);
    if (array.size() != 4 || !Count(array, 1, components) || !Count(array, 2, count))
    {
      return this->Fail(this->At() + ": array " + Number(a + 1) + " of " + Number(n) + " of " +
        field + " is not 'NAME COMPONENTS TUPLES TYPE'");
    }
    if (components < 1)
    {
      return this->Fail(this->At() + ": " + what + " has 0 components");
    }
    if (tuples >= 0 && count != tuples)
    {
      return this->Fail(this->At() + ": " + what + " has " + Number(count) + " tuples but " +
        section + " declares " + Number(tuples));
    }
    if (!this->Type(array[3], what, type, false) ||
      !this->Values(components * count, type,
        what + " (" + Number(count) + " tuples of " + Number(components) + ")"))
    {
      return false;
    }
  }
  return true;
}

// One attribute of a POINT_DATA / CELL_DATA section (vtkDataReader::ReadPointData).
bool LegacyWalker::Attribute(
  const std::vector<std::string>& w, const std::string& section, double tuples, bool& handled)
{
  const std::string key = Upper(w[0]);
  handled = true;
  LegacyType type;
  double components = 0;
  std::string what = key + (w.size() > 1 ? " " + Shown(w[1]) : std::string());
  if (key == "SCALARS")
  {
    components = 1;
    if ((w.size() != 3 && w.size() != 4) || (w.size() == 4 && !Count(w, 3, components)) ||
      components < 1)
    {
      return this->Fail(this->At() + ": a SCALARS line is 'SCALARS NAME TYPE [COMPONENTS]'");
    }
    if (!this->Type(w[2], what, type, false))
    {
      return false;
    }
    std::vector<std::string> table;
    const std::string at = this->At();
    if (!this->NextLine(table) || Upper(table[0]) != "LOOKUP_TABLE" || table.size() != 2 ||
      !this->ShortWords(table))
    {
      return this->Fail(at + ": " + what + " is not followed by 'LOOKUP_TABLE NAME' "
                                                   "(VTK needs one; 'LOOKUP_TABLE default')");
    }
  }
  else if (key == "VECTORS" || key == "NORMALS" || key == "TENSORS" || key == "TENSORS6" ||
    key == "GLOBAL_IDS" || key == "PEDIGREE_IDS" || (key == "EDGE_FLAGS" && section == "POINT_DATA"))
  {
    components = key == "TENSORS" ? 9 : key == "TENSORS6" ? 6 : key == "VECTORS" || key == "NORMALS" ? 3 : 1;
    if (w.size() != 3)
    {
      return this->Fail(this->At() + ": a " + key + " line is '" + key + " NAME TYPE'");
    }
    if (!this->Type(w[2], what, type, false))
    {
      return false;
    }
  }
  else if (key == "TEXTURE_COORDINATES")
  {
    if (w.size() != 4 || !Count(w, 2, components) || components < 1 || components > 3)
    {
      return this->Fail(this->At() + ": a TEXTURE_COORDINATES line is 'TEXTURE_COORDINATES NAME "
                                     "DIMENSION TYPE' with a dimension of 1 to 3");
    }
    if (!this->Type(w[3], what, type, false))
    {
      return false;
    }
  }
  else if (key == "COLOR_SCALARS" || key == "LOOKUP_TABLE")
  {
    double n = 0;
    if (w.size() != 3 || !Count(w, 2, n) || (key == "COLOR_SCALARS" && n < 1))
    {
      return this->Fail(this->At() + ": a " + key + " line is '" + key + " NAME " +
        (key == "LOOKUP_TABLE" ? "SIZE'" : "COMPONENTS'"));
    }
    FindLegacyType(this->Binary ? "unsigned_char" : "float", type);
    // A lookup table is `n` RGBA colours, whatever the section's count.
    components = key == "LOOKUP_TABLE" ? 4 : n;
    if (key == "LOOKUP_TABLE")
    {
      return this->Values(4 * n, type, what + " of " + Number(n) + " colours");
    }
  }
  else if (key == "FIELD")
  {
    return this->Field(w, tuples, section + " " + Number(tuples));
  }
  else
  {
    handled = false;
    return true;
  }
  return this->Values(tuples * components, type,
    what + ": " + Number(tuples) + " tuples of " + Number(components));
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
} // namespace

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
