// The legacy .vtk walker of SceneFileCheckVtk.cxx, shared with
// SceneFileCheckVtkData.cxx (the POINT_DATA / CELL_DATA sections): internal
// to the scene file checks, not an interface.
#ifndef vtkradiosity_SceneFileCheckVtkWalker_h
#define vtkradiosity_SceneFileCheckVtkWalker_h

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
namespace legacy
{
inline std::string Upper(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

inline std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// A word of the file for a message: at most 40 characters, control bytes as '?'.
inline std::string Shown(const std::string& text)
{
  std::string out;
  for (unsigned char c : text.substr(0, 40))
  {
    out += (c < 0x20 || c >= 0x7F) ? '?' : static_cast<char>(c);
  }
  return text.size() > 40 ? out + "..." : out;
}

inline std::string Number(double v)
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

inline bool FindLegacyType(const std::string& word, LegacyType& type)
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


inline bool Count(const std::vector<std::string>& w, std::size_t i, double& value)
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
} // namespace legacy
} // namespace cli
} // namespace radiosity

#endif
