// SceneFileCheck.h for VTK XML files (.vtp, .vtu, .vtm...).
//
// Two passes. First the counts of the Piece and DataArray tags against the
// file's size (a count past the file would be allocated by the reader before
// it notices). Then the XML itself, parsed with vtkXMLParser (VTK's expat) up
// to <AppendedData>, as vtkXMLDataParser does: the Points array must have 3
// components (any other count leaks in vtkXMLReader::ReadArrayValues), and
// every inline ASCII DataArray of Points, PointData, CellData, Verts, Lines,
// Strips, Polys and Cells must hold numbers of its type, as many as the
// piece's counts need (a value that does not parse ends in a null
// dereference in vtkXMLDataReader::ReadPieceData); cell offsets increase up
// to the connectivity's size and connectivity ids are below NumberOfPoints.
// Inline binary (base64, maybe compressed) and appended data are not decoded
// here: they would need a second decoder, and no known input crashes the
// reader through them (the counts are still checked against the file size).
#include "SceneFileCheck.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkXMLParser.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
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

bool ParseCount(const std::string& text, long long& value)
{
  if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos)
    return false;
  value = std::stoll(text);
  return true;
}

// Walks the elements of a VTK XML file; the first problem found is Error.
class XmlChecker : public vtkXMLParser
{
public:
  static XmlChecker* New();
  vtkTypeMacro(XmlChecker, vtkXMLParser);

  const std::string* Bytes = nullptr;
  std::string Error;
  bool SyntaxError = false;
  long long SyntaxAt = 0;

  // The piece counts, and what was seen of the cell section being read.
  long long Points = 0, Cells = 0;
  std::map<std::string, long long> SectionCells; // Verts, Lines, Strips, Polys, Cells
  bool PointsArray = false;
  struct Section
  {
    bool Connectivity = false, Offsets = false; // present (any format)
    bool ConnectivityRead = false, OffsetsRead = false; // ASCII, walked
    long long ConnectivityCount = 0, LastOffset = 0;
  } Current;

  // The DataArray being read.
  bool InArray = false, Ascii = false;
  std::string Parent, Name, Type, Text;
  long long Components = 1, Tuples = -1;
  int ArrayLine = 0;

protected:
  int Line()
  {
    const auto at = static_cast<std::size_t>(std::max<long long>(0, this->GetXMLByteIndex()));
    return 1 +
      static_cast<int>(std::count(this->Bytes->begin(),
        this->Bytes->begin() + static_cast<std::ptrdiff_t>(std::min(at, this->Bytes->size())), '\n'));
  }
  bool Fail(const std::string& message)
  {
    if (this->Error.empty())
      this->Error = message;
    return false;
  }
  static const char* Find(const char** atts, const char* name)
  {
    for (int i = 0; atts && atts[i]; i += 2)
    {
      if (std::string(atts[i]) == name)
        return atts[i + 1];
    }
    return nullptr;
  }

  void StartElement(const char* name, const char** atts) override
  {
    if (!this->Error.empty())
      return;
    const std::string element = name;
    this->Stack.push_back(element);
    if (element == "Piece")
    {
      this->Points = this->Cells = 0;
      this->SectionCells.clear();
      this->PointsArray = false;
      long long n = 0;
      for (const char* key : { "NumberOfPoints", "NumberOfVerts", "NumberOfLines",
             "NumberOfStrips", "NumberOfPolys", "NumberOfCells" })
      {
        const char* value = Find(atts, key);
        if (value && ParseCount(value, n))
        {
          const std::string k = key;
          if (k == "NumberOfPoints")
            this->Points = n;
          else
          {
            this->Cells += n;
            this->SectionCells[k == "NumberOfCells" ? "Cells" : k.substr(8)] = n;
          }
        }
      }
      return;
    }
    if (element == "Verts" || element == "Lines" || element == "Strips" || element == "Polys" ||
      element == "Cells")
    {
      this->Current = Section();
      return;
    }
    if (element != "DataArray")
      return;
    this->InArray = true;
    this->Parent = this->Stack.size() >= 2 ? this->Stack[this->Stack.size() - 2] : "";
    const char* arrayName = Find(atts, "Name");
    const char* type = Find(atts, "type");
    const char* components = Find(atts, "NumberOfComponents");
    const char* tuples = Find(atts, "NumberOfTuples");
    const char* format = Find(atts, "format");
    this->Name = arrayName ? arrayName : "";
    this->Type = type ? type : "";
    this->Ascii = format && std::string(format) == "ascii";
    this->Text.clear();
    this->ArrayLine = this->Line();
    this->Components = 1;
    this->Tuples = -1;
    const std::string where = "line " + std::to_string(this->ArrayLine) + ": " + this->What();
    if (components && (!ParseCount(components, this->Components) || this->Components < 1))
    {
      this->Fail(where + " has NumberOfComponents=\"" + Shown(components) + "\", not a count of 1 or more");
      return;
    }
    // vtkXMLDataReader reads an array only in a format it knows; another (or
    // none) leaves the array unread and then dereferenced (found by fuzzing).
    const std::string formatName = format ? format : "";
    if (formatName != "ascii" && formatName != "binary" && formatName != "appended")
    {
      this->Fail(where + (format ? " has format=\"" + Shown(formatName) + "\"" : std::string(" has no format")) +
        ", not ascii, binary or appended");
      return;
    }
    if (formatName == "appended" && !Find(atts, "offset"))
    {
      this->Fail(where + " is appended but has no offset");
      return;
    }
    if (tuples && !ParseCount(tuples, this->Tuples))
    {
      this->Fail(where + " has NumberOfTuples=\"" + Shown(tuples) + "\", not a count");
      return;
    }
    if (this->Parent == "Points")
    {
      this->PointsArray = true;
      if (this->Components != 3)
      {
        this->Fail(where + " has " + std::to_string(this->Components) + " component" +
          (this->Components == 1 ? "" : "s") + (components ? "" : " (no NumberOfComponents)") +
          "; points have NumberOfComponents=\"3\"");
      }
    }
  }

  void CharacterDataHandler(const char* data, int length) override
  {
    if (this->InArray && this->Ascii && this->Error.empty())
      this->Text.append(data, static_cast<std::size_t>(length));
  }

  void EndElement(const char* name) override
  {
    if (!this->Error.empty())
      return;
    const std::string element = name;
    if (!this->Stack.empty())
      this->Stack.pop_back();
    if (element == "DataArray" && this->InArray)
    {
      this->InArray = false;
      this->CheckArray();
    }
    else if (this->SectionCells.count(element) && this->SectionCells[element] > 0)
    {
      const long long cells = this->SectionCells[element];
      const std::string where = "line " + std::to_string(this->Line()) + ": " + element + " (" +
        std::to_string(cells) + " cells)";
      if (!this->Current.Connectivity || !this->Current.Offsets)
        this->Fail(where + " has no '" + (this->Current.Connectivity ? "offsets" : "connectivity") +
          "' DataArray");
      else if (this->Current.ConnectivityRead && this->Current.OffsetsRead &&
        this->Current.LastOffset != this->Current.ConnectivityCount)
        this->Fail(where + ": the last offset is " + std::to_string(this->Current.LastOffset) +
          " but the connectivity holds " + std::to_string(this->Current.ConnectivityCount) + " ids");
    }
    else if (element == "Piece" && this->Points > 0 && !this->PointsArray)
    {
      this->Fail("line " + std::to_string(this->Line()) + ": a Piece of " +
        std::to_string(this->Points) + " points has no Points DataArray");
    }
  }

  void ReportXmlParseError() override
  {
    if (!this->SyntaxError)
    {
      this->SyntaxError = true;
      this->SyntaxAt = this->GetXMLByteIndex();
    }
  }

private:
  std::vector<std::string> Stack;

  std::string What() const
  {
    return this->Parent + " DataArray" + (this->Name.empty() ? "" : " '" + Shown(this->Name) + "'");
  }

  void CheckArray()
  {
    const bool cellSection = this->SectionCells.count(this->Parent) > 0 ||
      this->Parent == "Verts" || this->Parent == "Lines" || this->Parent == "Strips" ||
      this->Parent == "Polys" || this->Parent == "Cells";
    if (cellSection && this->Name == "connectivity")
      this->Current.Connectivity = true;
    if (cellSection && this->Name == "offsets")
      this->Current.Offsets = true;
    if (!this->Ascii)
      return; // binary or appended: see the comment at the top
    static const std::map<std::string, bool> numeric = { { "Int8", true }, { "UInt8", true },
      { "Int16", true }, { "UInt16", true }, { "Int32", true }, { "UInt32", true },
      { "Int64", true }, { "UInt64", true }, { "Float32", false }, { "Float64", false } };
    const auto type = numeric.find(this->Type);
    const std::string where = "line " + std::to_string(this->ArrayLine) + ": " + this->What();
    if (type == numeric.end())
    {
      if (this->Type != "String")
        this->Fail(where + " has the type '" + Shown(this->Type) +
          "', not one of VTK's (Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, "
          "Float32, Float64, String)");
      return;
    }
    const bool integer = type->second;
    long long sectionCells = cellSection ? this->SectionCells[this->Parent] : 0;
    // What the piece needs: the values the reader will take from this array.
    long long expected = -1;
    std::string need;
    if (this->Parent == "Points" || this->Parent == "PointData")
    {
      expected = this->Points * this->Components;
      need = std::to_string(this->Points) + " points x " + std::to_string(this->Components);
    }
    else if (this->Parent == "CellData")
    {
      expected = this->Cells * this->Components;
      need = std::to_string(this->Cells) + " cells x " + std::to_string(this->Components);
    }
    else if (cellSection && (this->Name == "offsets" || this->Name == "types"))
    {
      expected = sectionCells;
      need = std::to_string(sectionCells) + " cells";
    }
    else if (!cellSection && this->Tuples >= 0)
    {
      expected = this->Tuples * this->Components;
      need = std::to_string(this->Tuples) + " tuples x " + std::to_string(this->Components);
    }
    const bool connectivity = cellSection && this->Name == "connectivity";
    const bool offsets = cellSection && this->Name == "offsets";
    std::istringstream values(this->Text);
    std::string token;
    long long count = 0, previous = 0;
    while (values >> token)
    {
      ++count;
      const std::string value = "value " + std::to_string(count) + ", '" + Shown(token) + "',";
      if (!IsAsciiNumber(token, integer))
      {
        this->Fail(where + ": " + value + " is not " + (integer ? "an integer" : "a number") +
          " (" + this->Type + ")");
        return;
      }
      if (!connectivity && !offsets)
        continue;
      errno = 0;
      const long long v = std::strtoll(token.c_str(), nullptr, 10);
      if (errno == ERANGE || v < 0 || (connectivity && v >= this->Points))
      {
        this->Fail(where + ": " + value + " is out of range (" +
          (connectivity ? std::to_string(this->Points) + " points)" : "an offset)"));
        return;
      }
      if (offsets && v <= previous)
      {
        this->Fail(where + ": " + value + " is not above the offset before it (" +
          std::to_string(previous) + ")");
        return;
      }
      previous = v;
    }
    if (expected >= 0 && count != expected)
    {
      this->Fail(where + " holds " + std::to_string(count) + " values but " + need + " need " +
        std::to_string(expected));
      return;
    }
    if (connectivity)
    {
      this->Current.ConnectivityCount = count;
      this->Current.ConnectivityRead = true;
    }
    if (offsets)
    {
      this->Current.LastOffset = previous;
      this->Current.OffsetsRead = true;
    }
  }
};
vtkStandardNewMacro(XmlChecker);

// The structure pass (see the top of the file) on one file's bytes.
bool CheckXmlStructure(const std::string& file, const std::string& bytes, std::string& error)
{
  vtkNew<XmlChecker> checker;
  checker->Bytes = &bytes;
  const std::size_t appended = bytes.find("<AppendedData");
  const std::size_t end = std::min(appended, bytes.size());
  std::size_t start = bytes.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  checker->InitializeParser();
  // vtkXMLParser takes an unsigned int length: feed it in chunks.
  for (std::size_t at = start; at < end && !checker->SyntaxError;)
  {
    const std::size_t n = std::min<std::size_t>(end - at, 1u << 30);
    checker->ParseChunk(bytes.data() + at, static_cast<unsigned int>(n));
    at += n;
  }
  const bool truncated = appended != std::string::npos;
  const bool syntaxBefore = checker->SyntaxError;
  checker->CleanupParser(); // reports a truncated document: expected before <AppendedData>
  if (!checker->Error.empty())
  {
    error = file + ": " + checker->Error;
    return false;
  }
  if (syntaxBefore || (checker->SyntaxError && !truncated))
  {
    const auto at = static_cast<std::size_t>(std::max<long long>(0, checker->SyntaxAt));
    error = file + ": not well-formed XML at byte " + std::to_string(at) + " (line " +
      std::to_string(1 + std::count(bytes.begin(),
                           bytes.begin() + static_cast<std::ptrdiff_t>(std::min(at, bytes.size())), '\n')) +
      ")";
    return false;
  }
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
  if (!CheckXmlStructure(file, bytes, error))
  {
    return false;
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
