// Text helpers of the scene file checks (SceneFileCheck*.cxx): words and
// lines as VTK's PLY reader splits them, counts, and bytes shown in messages.
// Internal to the checks, not an interface.
#ifndef vtkradiosity_SceneFileCheckText_h
#define vtkradiosity_SceneFileCheckText_h

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace radiosity
{
namespace cli
{
namespace text
{
// A byte shown as the user would look it up in a hex dump.
inline std::string Hex(unsigned char c)
{
  char text[8];
  std::snprintf(text, sizeof text, "0x%02X", c);
  return text;
}

// Text of a header line for a message: at most 60 characters, no control bytes.
inline std::string Shown(const std::string& text)
{
  std::string out;
  for (unsigned char c : text.substr(0, 60))
  {
    out += (c < 0x20 || c >= 0x7F) ? '?' : static_cast<char>(c);
  }
  return text.size() > 60 ? out + "..." : out;
}

inline std::vector<std::string> Words(const std::string& line)
{
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
    {
      ++i;
    }
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r')
    {
      ++i;
    }
    if (i > start)
    {
      words.push_back(line.substr(start, i - start));
    }
  }
  return words;
}

// A non-negative decimal count, the whole token; false for anything else.
inline bool ParseCount(const std::string& token, unsigned long long& value)
{
  if (token.empty() || token.size() > 19 ||
    token.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  value = std::strtoull(token.c_str(), nullptr, 10);
  return true;
}

// Reads lines of `bytes` from `pos`: the line without its '\n'; false at the end.
inline bool NextLine(const std::string& bytes, std::size_t& pos, std::string& line, bool& ended)
{
  if (pos >= bytes.size())
  {
    return false;
  }
  const std::size_t end = bytes.find('\n', pos);
  ended = end != std::string::npos;
  line = bytes.substr(pos, (ended ? end : bytes.size()) - pos);
  pos = ended ? end + 1 : bytes.size();
  return true;
}

} // namespace text
} // namespace cli
} // namespace radiosity

#endif
