// Whitespace trimming shared by the text readers of the command line.
#ifndef vtkradiosity_TextTrim_h
#define vtkradiosity_TextTrim_h

#include <string>

namespace radiosity
{
namespace cli
{
/// `text` without leading and trailing blanks, tabs and carriage returns.
inline std::string Trim(const std::string& text)
{
  const auto begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos)
  {
    return {};
  }
  const auto end = text.find_last_not_of(" \t\r");
  return text.substr(begin, end - begin + 1);
}
}
}

#endif
