// What the command-line program's unit tests share.
#ifndef vtkradiosity_CliTestSupport_h
#define vtkradiosity_CliTestSupport_h

#include <vtkDataArray.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace clitest
{
namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards.
class TempDir : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::string pattern = (fs::temp_directory_path() / "cli_support_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    this->Dir = pattern;
  }
  void TearDown() override
  {
    std::error_code ignored;
    fs::remove_all(this->Dir, ignored);
  }
  std::string Write(const std::string& name, const std::string& text)
  {
    const fs::path path = this->Dir / name;
    std::ofstream(path) << text;
    return path.string();
  }
  std::size_t FileCount() const
  {
    return static_cast<std::size_t>(
      std::distance(fs::directory_iterator(this->Dir), fs::directory_iterator()));
  }
  fs::path Dir;
};

/// Tuple i of a 3-component array.
inline std::array<double, 3> Tuple3(vtkDataArray* a, vtkIdType i)
{
  return { a->GetComponent(i, 0), a->GetComponent(i, 1), a->GetComponent(i, 2) };
}
} // namespace clitest

#endif
