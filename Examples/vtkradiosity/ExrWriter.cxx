#include "ExrWriter.h"

#include <ImfRgba.h>
#include <ImfRgbaFile.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <sstream>
#include <vector>

#include <unistd.h>

namespace radiosity
{
namespace cli
{
namespace
{
// Largest finite half; anything above it would be stored as +Inf.
constexpr float HalfMax = 65504.0f;

// Same directory as the target, so that the final rename cannot cross file
// systems and is atomic; the pid keeps concurrent runs apart.
std::string TemporarySibling(const std::string& file)
{
  return file + ".part" + std::to_string(static_cast<long>(::getpid()));
}

// The first pixel that cannot be stored faithfully, as a message; empty if none.
std::string CheckPixels(const RadianceImage& image)
{
  static const char* channel[3] = { "R", "G", "B" };
  for (std::size_t i = 0; i < image.RGB.size(); ++i)
  {
    const float v = image.RGB[i];
    if (std::isfinite(v) && std::fabs(v) <= HalfMax)
    {
      continue;
    }
    const std::size_t pixel = i / 3;
    std::ostringstream s;
    s << "pixel (x " << pixel % static_cast<std::size_t>(image.Width) << ", y "
      << pixel / static_cast<std::size_t>(image.Width) << ") channel " << channel[i % 3]
      << " is " << v
      << (std::isfinite(v) ? " (beyond the half-float range 65504)" : " (not a finite number)");
    return s.str();
  }
  return {};
}
} // namespace

bool WriteExrHalf(const std::string& file, const RadianceImage& image, std::string& error)
{
  const std::string prefix = "cannot write OpenEXR file '" + file + "': ";
  if (image.Width <= 0 || image.Height <= 0)
  {
    error = prefix + "empty image (" + std::to_string(image.Width) + " x " +
      std::to_string(image.Height) + ")";
    return false;
  }
  const std::size_t count =
    static_cast<std::size_t>(image.Width) * static_cast<std::size_t>(image.Height);
  if (image.RGB.size() != 3 * count)
  {
    error = prefix + "image has " + std::to_string(image.RGB.size()) + " values, expected " +
      std::to_string(3 * count);
    return false;
  }
  // Checked before anything touches the disk: a refused image leaves no file.
  const std::string bad = CheckPixels(image);
  if (!bad.empty())
  {
    error = prefix + bad;
    return false;
  }

  std::vector<Imf::Rgba> pixels(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    pixels[i] = Imf::Rgba(image.RGB[3 * i], image.RGB[3 * i + 1], image.RGB[3 * i + 2], 1.0f);
  }

  const std::string temporary = TemporarySibling(file);
  try
  {
    // Scope: the file is complete and closed only when the object is destroyed.
    Imf::RgbaOutputFile out(temporary.c_str(), image.Width, image.Height, Imf::WRITE_RGB);
    out.setFrameBuffer(pixels.data(), 1, static_cast<std::size_t>(image.Width));
    out.writePixels(image.Height);
  }
  catch (const std::exception& e)
  {
    std::remove(temporary.c_str());
    error = prefix + e.what();
    return false;
  }
  if (std::rename(temporary.c_str(), file.c_str()) != 0)
  {
    const int code = errno;
    std::remove(temporary.c_str());
    error = prefix + "rename from '" + temporary + "' failed: " + std::strerror(code);
    return false;
  }
  return true;
}
} // namespace cli
} // namespace radiosity
