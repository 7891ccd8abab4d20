// SceneFileCheck.h for .ply files: the header parsed, the layout vtkPLYReader
// assumes checked, the ASCII or binary body walked, and the header handed to
// the reader written anew from what was checked.
#include "SceneFileCheck.h"
#include <vtksys/SystemTools.hxx>
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <sys/stat.h>
#include <vector>
#include "SceneFileCheckText.h"

namespace radiosity
{
namespace cli
{
namespace
{
using namespace text;

// ------------------------------------------------------------------ PLY
enum class Kind
{
  Int,
  UInt,
  Float
};
struct PlyType
{
  int Size;
  Kind K;
};
// vtkPLY's type names (VTK 9.2, case sensitive); int64 and the like are not among them.
const std::map<std::string, PlyType>& PlyTypes()
{
  static const std::map<std::string, PlyType> types = { { "char", { 1, Kind::Int } },
    { "int8", { 1, Kind::Int } }, { "uchar", { 1, Kind::UInt } }, { "uint8", { 1, Kind::UInt } },
    { "short", { 2, Kind::Int } }, { "int16", { 2, Kind::Int } },
    { "ushort", { 2, Kind::UInt } }, { "uint16", { 2, Kind::UInt } },
    { "int", { 4, Kind::Int } }, { "int32", { 4, Kind::Int } }, { "uint", { 4, Kind::UInt } },
    { "uint32", { 4, Kind::UInt } }, { "float", { 4, Kind::Float } },
    { "float32", { 4, Kind::Float } }, { "double", { 8, Kind::Float } },
    { "float64", { 8, Kind::Float } } };
  return types;
}

struct PlyProperty
{
  std::string Name;
  PlyType Type;
  bool List = false;
  PlyType Count{ 0, Kind::UInt };
  std::string TypeName, CountName; ///< as the header spells them
};
struct PlyElement
{
  std::string Name;
  unsigned long long Count = 0;
  int Line = 0;
  std::vector<PlyProperty> Properties;
  const PlyProperty* Find(const std::string& name) const
  {
    for (const PlyProperty& p : this->Properties)
    {
      if (p.Name == name)
      {
        return &p;
      }
    }
    return nullptr;
  }
};

// VTK's PLY lines are read into 4096-character buffers.
constexpr std::size_t PlyLineLength = 4095;

// The plural the messages use for an element ("vertices", "faces", "edges").
std::string Plural(const std::string& element)
{
  return element == "vertex" ? "vertices" : element + "s";
}

// One binary value of `type` at `p` (endianness `big`), as a double.
double BinaryValue(const char* p, const PlyType& type, bool big)
{
  unsigned char b[8];
  for (int i = 0; i < type.Size; ++i)
  {
    b[i] = static_cast<unsigned char>(p[big ? type.Size - 1 - i : i]);
  }
  switch (type.Size)
  {
    case 1:
      return type.K == Kind::Int ? static_cast<double>(static_cast<std::int8_t>(b[0])) : b[0];
    case 2:
    {
      std::uint16_t u;
      std::memcpy(&u, b, 2);
      return type.K == Kind::Int ? static_cast<double>(static_cast<std::int16_t>(u)) : u;
    }
    case 4:
    {
      std::uint32_t u;
      std::memcpy(&u, b, 4);
      if (type.K == Kind::Float)
      {
        float f;
        std::memcpy(&f, b, 4);
        return f;
      }
      return type.K == Kind::Int ? static_cast<double>(static_cast<std::int32_t>(u)) : u;
    }
    default:
    {
      double d;
      std::memcpy(&d, b, 8);
      return d;
    }
  }
}

// A list's count or a face's vertex index must be a whole number; VTK's
// buffers limit a list to 255 entries (its count is stored in an unsigned char).
bool CheckListCount(double count, const std::string& what, std::string& error)
{
  if (!(count >= 0 && count <= 255 && count == std::floor(count)))
  {
    std::ostringstream s;
    s << what << " has a list of " << count << " entries (VTK's PLY reader takes 0 to 255)";
    error = s.str();
    return false;
  }
  return true;
}

bool CheckIndex(double index, unsigned long long vertices, const std::string& what,
  std::string& error)
{
  // Compared as doubles: an index that overflows to infinity (31e308) must
  // not be converted to an integer (undefined behaviour).
  if (!(index >= 0 && index < static_cast<double>(vertices) && index == std::floor(index)))
  {
    std::ostringstream s;
    s << what << " has the vertex index " << index << ", out of range (" << vertices
      << " vertices)";
    error = s.str();
    return false;
  }
  return true;
}

bool ParsePlyHeader(const std::string& bytes, std::size_t& pos, bool& ascii, bool& big,
  std::vector<PlyElement>& elements, std::string& error)
{
  std::string line;
  bool ended = false;
  int number = 0;
  bool format = false;
  while (NextLine(bytes, pos, line, ended))
  {
    ++number;
    const std::string where = "header line " + std::to_string(number);
    if (line.size() > PlyLineLength)
    {
      error = where + " is " + std::to_string(line.size()) + " characters long (at most " +
        std::to_string(PlyLineLength) + ")";
      return false;
    }
    // vtkPLY renames vertex_index to vertex_indices in every line it reads.
    const auto alias = line.find("vertex_index");
    if (alias != std::string::npos && line.compare(alias, 14, "vertex_indices") != 0)
    {
      line.replace(alias, 12, "vertex_indices");
    }
    const std::vector<std::string> w = Words(line);
    if (number == 1)
    {
      if (w.empty() || w[0] != "ply")
      {
        error = "not a PLY file: the first line is '" + Shown(line) + "', not 'ply'";
        return false;
      }
      continue;
    }
    if (w.empty())
    {
      continue;
    }
    const std::string& key = w[0];
    if (key == "comment" || key == "obj_info")
    {
      continue;
    }
    if (key == "end_header")
    {
      if (!format)
      {
        error = "the header has no format line";
        return false;
      }
      if (elements.empty())
      {
        error = "the header declares no element";
        return false;
      }
      if (!ended)
      {
        error = "the file ends with end_header: no data";
        return false;
      }
      return true;
    }
    if (key == "format")
    {
      if (format || w.size() != 3 ||
        (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
      {
        error = where + ": bad format line '" + Shown(line) +
          "' (one of 'format ascii|binary_little_endian|binary_big_endian 1.0')";
        return false;
      }
      format = true;
      ascii = w[1] == "ascii";
      big = w[1] == "binary_big_endian";
      continue;
    }
    if (key == "element")
    {
      PlyElement e;
      if (w.size() != 3 || !ParseCount(w[2], e.Count))
      {
        error = where + ": bad element line '" + Shown(line) + "' (element NAME COUNT)";
        return false;
      }
      e.Name = w[1];
      e.Line = number;
      elements.push_back(e);
      continue;
    }
    if (key == "property")
    {
      if (elements.empty())
      {
        error = where + ": property before any element: '" + Shown(line) + "'";
        return false;
      }
      const auto& types = PlyTypes();
      PlyProperty p;
      const bool list = w.size() >= 2 && w[1] == "list";
      if (w.size() != (list ? 5u : 3u))
      {
        error = where + ": bad property line '" + Shown(line) +
          "' (property TYPE NAME or property list COUNTTYPE TYPE NAME)";
        return false;
      }
      const std::string& typeName = w[list ? 3 : 1];
      const auto type = types.find(typeName);
      if (type == types.end())
      {
        error = where + ": unknown property type '" + Shown(typeName) +
          "' (VTK reads char, uchar, short, ushort, int, uint, float, double and their sized "
          "names int8...float64)";
        return false;
      }
      p.Type = type->second;
      p.TypeName = typeName;
      p.List = list;
      if (list)
      {
        const auto count = types.find(w[2]);
        if (count == types.end() || count->second.K == Kind::Float)
        {
          error = where + ": the list count type '" + Shown(w[2]) + "' is not an integer type";
          return false;
        }
        p.Count = count->second;
        p.CountName = w[2];
      }
      p.Name = w[list ? 4 : 2];
      elements.back().Properties.push_back(p);
      continue;
    }
    // Anything else VTK skips (exporters write stray text lines into the header).
  }
  error = "the header has no end_header line";
  return false;
}

// What vtkPLYReader assumes of the elements it reads (checked before it reads them).
bool CheckPlyLayout(const std::vector<PlyElement>& elements, std::size_t& last,
  std::string& error)
{
  int vertex = -1, face = -1;
  for (std::size_t i = 0; i < elements.size(); ++i)
  {
    const PlyElement& e = elements[i];
    if (e.Properties.empty())
    {
      // vtkPLY's ply_close frees the property table of every element: one
      // without properties has none, and the free crashes (found by fuzzing).
      error = "header line " + std::to_string(e.Line) + ": element '" + Shown(e.Name) +
        "' has no property";
      return false;
    }
    for (std::size_t a = 0; a < e.Properties.size(); ++a)
    {
      for (std::size_t b = a + 1; b < e.Properties.size(); ++b)
      {
        if (e.Properties[a].Name == e.Properties[b].Name)
        {
          error = "header line " + std::to_string(e.Line) + "+: element '" + Shown(e.Name) +
            "' declares the property '" + Shown(e.Properties[a].Name) + "' twice";
          return false;
        }
      }
    }
    int& seen = e.Name == "vertex" ? vertex : face;
    if (e.Name == "vertex" || e.Name == "face")
    {
      if (seen >= 0)
      {
        error = "header line " + std::to_string(e.Line) + ": a second '" + e.Name + "' element";
        return false;
      }
      seen = static_cast<int>(i);
    }
    for (const PlyProperty& p : e.Properties)
    {
      static const char* scalars[] = { "x", "y", "z", "u", "v", "texture_u", "texture_v", "s",
        "t", "nx", "ny", "nz", "red", "green", "blue", "alpha", "intensity" };
      const bool wantList = e.Name == "face" && (p.Name == "vertex_indices" || p.Name == "texcoord");
      const bool wantScalar = (e.Name == "vertex" || e.Name == "face") &&
        std::find(std::begin(scalars), std::end(scalars), p.Name) != std::end(scalars);
      if ((wantList && !p.List) || (wantScalar && p.List))
      {
        error = "header line " + std::to_string(e.Line) + "+: property '" + p.Name +
          "' of element '" + e.Name + "' must be " + (wantList ? "a list" : "a scalar");
        return false;
      }
    }
  }
  if (vertex < 0 || !elements[vertex].Find("x") || !elements[vertex].Find("y") ||
    !elements[vertex].Find("z"))
  {
    error = "no 'vertex' element with properties x, y and z";
    return false;
  }
  if (face >= 0 && face < vertex)
  {
    error = "the 'face' element comes before the 'vertex' element (VTK's PLY reader needs the "
            "vertices first)";
    return false;
  }
  if (face >= 0 && !elements[face].Find("vertex_indices"))
  {
    error = "the 'face' element has no vertex_indices (or vertex_index) list";
    return false;
  }
  last = static_cast<std::size_t>(std::max(vertex, face));
  for (std::size_t i = 0; i < last; ++i)
  {
    if (elements[i].Name != "vertex" && elements[i].Name != "face")
    {
      error = "header line " + std::to_string(elements[i].Line) + ": element '" +
        Shown(elements[i].Name) +
        "' comes before the vertices or faces (VTK's PLY reader does not skip it)";
      return false;
    }
  }
  return true;
}

bool WalkAsciiPly(std::string& bytes, std::size_t pos, const std::vector<PlyElement>& elements,
  std::size_t last, int headerLines, std::string& error)
{
  // A quick count first: one line per element at least.
  unsigned long long declared = 0;
  for (std::size_t i = 0; i <= last; ++i)
  {
    declared += elements[i].Count;
  }
  const auto lines = static_cast<unsigned long long>(
    std::count(bytes.begin() + static_cast<std::ptrdiff_t>(pos), bytes.end(), '\n') + 1);
  if (declared > lines)
  {
    std::string counts;
    for (std::size_t i = 0; i <= last; ++i)
    {
      counts += (i ? ", " : "") + std::to_string(elements[i].Count) + " " + Plural(elements[i].Name);
    }
    error = "the header declares " + std::to_string(declared) + " element lines (" + counts +
      ") but the file holds only " + std::to_string(lines) + " lines after the header";
    return false;
  }
  const unsigned long long vertices = elements[0].Name == "vertex" ? elements[0].Count
    : elements[1].Count;
  std::string line;
  bool ended = true;
  int number = headerLines;
  for (std::size_t i = 0; i <= last; ++i)
  {
    const PlyElement& e = elements[i];
    for (unsigned long long k = 0; k < e.Count; ++k)
    {
      const std::string item = e.Name + " " + std::to_string(k) + " of " + std::to_string(e.Count);
      if (!NextLine(bytes, pos, line, ended))
      {
        error = "the header declares " + std::to_string(e.Count) + " " + Plural(e.Name) +
          " but the file ends after " + std::to_string(k) + " of them (line " +
          std::to_string(number) + ")";
        return false;
      }
      ++number;
      const std::string where = "line " + std::to_string(number) + " (" + item + ")";
      if (line.size() > PlyLineLength)
      {
        error = where + " is " + std::to_string(line.size()) + " characters long (VTK reads " +
          std::to_string(PlyLineLength) + ")";
        return false;
      }
      const std::vector<std::string> w = Words(line);
      std::size_t at = 0;
      for (const PlyProperty& p : e.Properties)
      {
        std::size_t n = 1;
        if (p.List)
        {
          double count = 0;
          if (at < w.size())
          {
            char* end = nullptr;
            count = std::strtod(w[at].c_str(), &end);
            if (*end != '\0')
            {
              count = -1;
            }
          }
          if (at >= w.size() || !CheckListCount(count, where + ": list " + p.Name, error))
          {
            if (at >= w.size())
            {
              error = where + " holds " + std::to_string(w.size()) +
                " values; the header declares more (property " + p.Name + ")";
            }
            return false;
          }
          ++at;
          n = static_cast<std::size_t>(count);
        }
        if (at + n > w.size())
        {
          error = where + " holds " + std::to_string(w.size()) +
            " values; the header declares more (property " + p.Name + ")";
          return false;
        }
        for (std::size_t j = 0; j < n; ++j, ++at)
        {
          char* end = nullptr;
          const double value = std::strtod(w[at].c_str(), &end);
          if (*end != '\0')
          {
            error = where + ": '" + Shown(w[at]) + "' is not a number (property " + p.Name + ")";
            return false;
          }
          if (e.Name == "face" && p.Name == "vertex_indices" &&
            !CheckIndex(value, vertices, where, error))
          {
            return false;
          }
        }
      }
      if (at != w.size())
      {
        error = where + " holds " + std::to_string(w.size()) + " values but the header declares " +
          std::to_string(at);
        return false;
      }
    }
  }
  if (!ended)
  {
    bytes += '\n'; // VTK drops a last line without its line end (and then frees a stale pointer)
  }
  return true;
}

bool WalkBinaryPly(const std::string& bytes, std::size_t pos, bool big,
  const std::vector<PlyElement>& elements, std::size_t last, std::string& error)
{
  const std::size_t body = bytes.size() - pos;
  // The fewest bytes the declared elements take (lists empty): refuses a count
  // the file cannot hold before anything is walked or allocated.
  double least = 0;
  for (std::size_t i = 0; i <= last; ++i)
  {
    double item = 0;
    for (const PlyProperty& p : elements[i].Properties)
    {
      item += p.List ? p.Count.Size : p.Type.Size;
    }
    least += item * static_cast<double>(elements[i].Count);
    if (least > static_cast<double>(body))
    {
      std::string need = ByteSize(least), have = ByteSize(static_cast<double>(body));
      if (need == have) // a file cut short by a little: the exact counts tell
      {
        need = std::to_string(static_cast<long long>(least)) + " bytes";
        have = std::to_string(body) + " bytes";
      }
      std::ostringstream s;
      s << "header line " << elements[i].Line << " declares " << elements[i].Count << " "
        << Plural(elements[i].Name) << " of " << item << " bytes"
        << (i > 0 ? " (with the elements before, " : " (") << need << ") but the file holds "
        << have << " after the header";
      error = s.str();
      return false;
    }
  }
  const unsigned long long vertices = elements[0].Name == "vertex" ? elements[0].Count
    : elements[1].Count;
  for (std::size_t i = 0; i <= last; ++i)
  {
    const PlyElement& e = elements[i];
    bool lists = false;
    std::size_t stride = 0;
    for (const PlyProperty& p : e.Properties)
    {
      lists = lists || p.List;
      stride += p.Type.Size;
    }
    if (!lists)
    {
      pos += stride * e.Count; // checked above
      continue;
    }
    for (unsigned long long k = 0; k < e.Count; ++k)
    {
      const std::string where =
        e.Name + " " + std::to_string(k) + " of " + std::to_string(e.Count) + " (byte " +
        std::to_string(pos) + ")";
      for (const PlyProperty& p : e.Properties)
      {
        std::size_t n = 1;
        if (p.List)
        {
          if (bytes.size() - pos < static_cast<std::size_t>(p.Count.Size))
          {
            error = "the file ends inside " + where;
            return false;
          }
          const double count = BinaryValue(bytes.data() + pos, p.Count, big);
          if (!CheckListCount(count, where + ": list " + p.Name, error))
          {
            return false;
          }
          pos += p.Count.Size;
          n = static_cast<std::size_t>(count);
        }
        if (bytes.size() - pos < n * p.Type.Size)
        {
          error = "the file ends inside " + where;
          return false;
        }
        if (e.Name == "face" && p.Name == "vertex_indices")
        {
          for (std::size_t j = 0; j < n; ++j)
          {
            if (!CheckIndex(BinaryValue(bytes.data() + pos + j * p.Type.Size, p.Type, big),
                  vertices, where, error))
            {
              return false;
            }
          }
        }
        pos += n * p.Type.Size;
      }
    }
  }
  return true;
}
} // namespace

bool CheckPly(const std::string& file, std::string& bytes, std::string& error)
{
  std::size_t pos = 0;
  bool ascii = true, big = false;
  std::vector<PlyElement> elements;
  std::size_t last = 0;
  std::string why;
  if (!ParsePlyHeader(bytes, pos, ascii, big, elements, why) ||
    !CheckPlyLayout(elements, last, why))
  {
    error = file + ": " + why;
    return false;
  }
  const int headerLines =
    static_cast<int>(std::count(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
  // vtkPLY reads text lines as C strings: a NUL byte ends the line early and
  // the line then holds fewer values than were checked (a strtod(NULL) crash).
  const std::size_t nul = bytes.find('\0');
  if (nul < (ascii ? bytes.size() : pos))
  {
    const auto line = 1 + std::count(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(nul), '\n');
    error = file + ": a NUL byte at offset " + std::to_string(nul) + " (line " +
      std::to_string(line) + ") in the " + (nul < pos ? "header" : "ASCII body") +
      " (VTK's PLY reader would end the line there)";
    return false;
  }
  // vtkPLY also renames vertex_index to vertex_indices in every body line it
  // reads (strcpy in place: two bytes more than the line held).
  if (ascii && bytes.find("vertex_index", pos) != std::string::npos)
  {
    error = file + ": the ASCII body holds the text 'vertex_index' (line " +
      std::to_string(1 + std::count(bytes.begin(),
                           bytes.begin() + static_cast<std::ptrdiff_t>(bytes.find("vertex_index", pos)), '\n')) +
      "), not a number";
    return false;
  }
  const bool ok = ascii ? WalkAsciiPly(bytes, pos, elements, last, headerLines, why)
                        : WalkBinaryPly(bytes, pos, big, elements, last, why);
  if (!ok)
  {
    error = file + ": " + why;
    return false;
  }
  // Only now (the file holds them): counts past VTK's int.
  for (std::size_t i = 0; i <= last; ++i)
  {
    if (elements[i].Count > static_cast<unsigned long long>(INT_MAX))
    {
      why = "header line " + std::to_string(elements[i].Line) + " declares " +
        std::to_string(elements[i].Count) + " " + Plural(elements[i].Name) +
        ", more than VTK's PLY reader can count (" + std::to_string(INT_MAX) + ")";
      error = file + ": " + why;
      return false;
    }
  }
  // vtkPLYReader reads lists of the face element only; a list elsewhere is
  // walked by vtkPLY into storage it never set up (found by fuzzing). Checked
  // after the body, whose messages say more about a file that is short.
  for (const PlyElement& e : elements)
  {
    for (const PlyProperty& p : e.Properties)
    {
      if (p.List && e.Name != "face")
      {
        error = file + ": header line " + std::to_string(e.Line) + "+: property '" + Shown(p.Name) +
          "' of element '" + Shown(e.Name) + "' is a list (only the face element may hold lists)";
        return false;
      }
    }
  }
  // The reader gets the header as it was understood here, written anew: no
  // comment, stray line or spacing of the original can make vtkPLY parse it
  // otherwise than it was checked (its header parser and this one differ on
  // malformed lines, and a difference is a crash: found by fuzzing).
  std::string header = std::string("ply\nformat ") +
    (ascii ? "ascii" : big ? "binary_big_endian" : "binary_little_endian") + " 1.0\n";
  for (const PlyElement& e : elements)
  {
    header += "element " + e.Name + " " + std::to_string(e.Count) + "\n";
    for (const PlyProperty& p : e.Properties)
    {
      header += p.List ? "property list " + p.CountName + " " + p.TypeName + " " + p.Name + "\n"
                       : "property " + p.TypeName + " " + p.Name + "\n";
    }
  }
  header += "end_header\n";
  bytes = header + bytes.substr(pos);
  return true;
}

} // namespace cli
} // namespace radiosity
