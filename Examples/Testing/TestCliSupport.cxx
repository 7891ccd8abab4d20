// Tests of the command-line program's file formats and progress display.
#include "ExrWriter.h"
#include "ObjMtlReader.h"
#include "ProbeIO.h"
#include "ProgressBar.h"
#include "SceneLoader.h"
#include "CliTestSupport.h"

#include <ImfRgba.h>
#include <ImfRgbaFile.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <thread>

namespace fs = std::filesystem;
using namespace radiosity;
using namespace radiosity::cli;
using clitest::TempDir;
using clitest::Tuple3;

namespace
{
std::string ReadAll(std::FILE* f)
{
  std::string text;
  std::rewind(f);
  char buffer[512];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof(buffer), f)) > 0)
  {
    text.append(buffer, n);
  }
  return text;
}
} // namespace

// ---------------------------------------------------------------------- OBJ

using ObjMtl = TempDir;

TEST_F(ObjMtl, MaterialsObjectsAndFaceForms)
{
  this->Write("room.mtl",
    "# comment\n"
    "newmtl white\n"
    "Kd 0.7 0.7 0.7\n"
    "Ks 0.1 0.2 0.3\n"
    "Ns 25\n"
    "illum 2\n"
    "newmtl lamp\r\n" // CRLF tolerated
    "Kd 0.2\r\n"      // one value means grey
    "Ke 10 9 8\r\n");
  const std::string obj = this->Write("room.obj",
    "mtllib room.mtl\n"
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n"
    "vt 0 0\n"
    "vn 0 0 1\n"
    "o floor\n"
    "usemtl white\n"
    "f 1 2 3 4\n"                 // quad: two triangles
    "g light\n"
    "usemtl lamp\n"
    "f 1/1 2/1 3/1\n"             // v/vt
    "f 1//1 3//1 \\\n 4//1\n"     // v//vn, continued line
    "f -4/1/1 -3/1/1 -2/1/1\n"    // negative indices, v/vt/vn
    "o floor\n"                   // same name: same object
    "usemtl ghost\n"
    "f 2 3 4\n"
    "l 1 2\n"
    "p 3\n");
  std::string error;
  std::vector<std::string> warnings;
  auto poly = ReadObjWithMaterials(obj, error, warnings);
  ASSERT_TRUE(poly) << error;
  EXPECT_EQ(poly->GetNumberOfPoints(), 4);
  EXPECT_EQ(poly->GetPoints()->GetDataType(), VTK_DOUBLE);
  ASSERT_EQ(poly->GetNumberOfCells(), 6);

  auto* cd = poly->GetCellData();
  auto* kd = cd->GetArray("Reflectance");
  auto* ke = cd->GetArray("Emission");
  auto* ks = cd->GetArray("Specular");
  auto* ns = cd->GetArray("Shininess");
  auto* id = cd->GetArray("ObjectId");
  ASSERT_TRUE(kd && ke && ks && ns && id);
  EXPECT_EQ(kd->GetNumberOfComponents(), 3);
  EXPECT_EQ(kd->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(ke->GetNumberOfComponents(), 3);
  EXPECT_EQ(ks->GetNumberOfComponents(), 3);
  EXPECT_EQ(ns->GetNumberOfComponents(), 1);
  EXPECT_EQ(id->GetDataType(), VTK_INT);

  using C = std::array<double, 3>;
  for (vtkIdType t : { 0, 1 })
  {
    EXPECT_EQ(Tuple3(kd, t), (C{ 0.7, 0.7, 0.7 }));
    EXPECT_EQ(Tuple3(ks, t), (C{ 0.1, 0.2, 0.3 }));
    EXPECT_EQ(Tuple3(ke, t), (C{ 0, 0, 0 }));
    EXPECT_EQ(ns->GetComponent(t, 0), 25.0);
    EXPECT_EQ(id->GetComponent(t, 0), 0);
  }
  for (vtkIdType t : { 2, 3, 4 })
  {
    EXPECT_EQ(Tuple3(kd, t), (C{ 0.2, 0.2, 0.2 }));
    EXPECT_EQ(Tuple3(ke, t), (C{ 10, 9, 8 }));
    EXPECT_EQ(id->GetComponent(t, 0), 1);
  }
  // Undefined material: SPEC default.
  EXPECT_EQ(Tuple3(kd, 5), (C{ 0.5, 0.5, 0.5 }));
  EXPECT_EQ(Tuple3(ke, 5), (C{ 0, 0, 0 }));
  EXPECT_EQ(id->GetComponent(5, 0), 0);

  // Fan triangulation and index forms.
  auto ids = vtkSmartPointer<vtkIdList>::New();
  const std::vector<std::array<vtkIdType, 3>> expected = { { 0, 1, 2 }, { 0, 2, 3 },
    { 0, 1, 2 }, { 0, 2, 3 }, { 0, 1, 2 }, { 1, 2, 3 } };
  for (vtkIdType t = 0; t < 6; ++t)
  {
    poly->GetCellPoints(t, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 3);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(ids->GetId(k), expected[t][k]) << "triangle " << t;
    }
  }

  auto* names = vtkStringArray::SafeDownCast(poly->GetFieldData()->GetAbstractArray("ObjectNames"));
  ASSERT_TRUE(names);
  ASSERT_EQ(names->GetNumberOfValues(), 2);
  EXPECT_EQ(names->GetValue(0), "floor");
  EXPECT_EQ(names->GetValue(1), "light");

  // One warning for the undefined material, one for l/p.
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("ghost"), std::string::npos);
  EXPECT_NE(warnings[1].find("2 line/point"), std::string::npos);
}

TEST_F(ObjMtl, MissingMtlAndNoUsemtlWarn)
{
  const std::string obj = this->Write("a.obj",
    "mtllib nothere.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    "f 1 2 3\n");
  std::string error;
  std::vector<std::string> warnings;
  auto poly = ReadObjWithMaterials(obj, error, warnings);
  ASSERT_TRUE(poly) << error;
  ASSERT_EQ(poly->GetNumberOfCells(), 1);
  EXPECT_EQ(poly->GetCellData()->GetArray("Reflectance")->GetComponent(0, 1), 0.5);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("nothere.mtl"), std::string::npos);
  EXPECT_NE(warnings[1].find("no material"), std::string::npos);
  // Faces before any o/g: one object named after the file.
  auto* names = vtkStringArray::SafeDownCast(poly->GetFieldData()->GetAbstractArray("ObjectNames"));
  ASSERT_TRUE(names);
  ASSERT_EQ(names->GetNumberOfValues(), 1);
  EXPECT_EQ(names->GetValue(0), "a");
}

TEST_F(ObjMtl, MalformedLinesNameFileLineAndText)
{
  struct Case
  {
    std::string Body;
    std::string Line;
  };
  const std::vector<Case> cases = {
    { "v 0 0 0\nv 1 x 0\n", ":2:" },
    { "v 0 0 0\nv 1 0 nan\n", ":2:" },
    { "v 0 0\n", ":1:" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n", ":5:" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", ":4:" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 2 3\n", ":4:" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", ":4:" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n", ":4:" }, // no vt defined
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3a\n", ":4:" },
  };
  for (const Case& c : cases)
  {
    const std::string obj = this->Write("bad.obj", c.Body);
    std::string error;
    std::vector<std::string> warnings;
    EXPECT_FALSE(ReadObjWithMaterials(obj, error, warnings)) << c.Body;
    EXPECT_NE(error.find("bad.obj" + c.Line), std::string::npos) << error;
    const std::string lastLine = c.Body.substr(c.Body.rfind('\n', c.Body.size() - 2) + 1);
    EXPECT_NE(error.find(lastLine.substr(0, lastLine.size() - 1)), std::string::npos) << error;
  }

  // A malformed .mtl is an error too, naming the .mtl.
  this->Write("m.mtl", "newmtl a\nKd 0.5 0.5\n");
  const std::string obj = this->Write("m.obj", "mtllib m.mtl\n");
  std::string error;
  std::vector<std::string> warnings;
  EXPECT_FALSE(ReadObjWithMaterials(obj, error, warnings));
  EXPECT_NE(error.find("m.mtl:2:"), std::string::npos) << error;

  EXPECT_FALSE(ReadObjWithMaterials((this->Dir / "none.obj").string(), error, warnings));
  EXPECT_NE(error.find("none.obj"), std::string::npos) << error;
}

// ---------------------------------------------------------------------- EXR

using Exr = TempDir;

TEST_F(Exr, RoundTripWithinHalfPrecision)
{
  RadianceImage image;
  image.Width = 5;
  image.Height = 3;
  for (int i = 0; i < image.Width * image.Height * 3; ++i)
  {
    image.RGB.push_back(0.001f * static_cast<float>(i * i) + (i % 3 == 0 ? 1000.0f : 0.0f));
  }
  const std::string file = (this->Dir / "out.exr").string();
  std::string error;
  ASSERT_TRUE(WriteExrHalf(file, image, error)) << error;
  EXPECT_EQ(this->FileCount(), 1u); // no temporary left

  Imf::RgbaInputFile in(file.c_str());
  const auto window = in.dataWindow();
  const int w = window.max.x - window.min.x + 1;
  const int h = window.max.y - window.min.y + 1;
  ASSERT_EQ(w, 5);
  ASSERT_EQ(h, 3);
  EXPECT_EQ(in.channels() & Imf::WRITE_RGB, Imf::WRITE_RGB);
  std::vector<Imf::Rgba> pixels(static_cast<std::size_t>(w * h));
  in.setFrameBuffer(pixels.data() - window.min.x - window.min.y * w, 1, w);
  in.readPixels(window.min.y, window.max.y);
  for (int p = 0; p < w * h; ++p)
  {
    const float expected[3] = { image.RGB[3 * p], image.RGB[3 * p + 1], image.RGB[3 * p + 2] };
    const float actual[3] = { pixels[p].r, pixels[p].g, pixels[p].b };
    for (int c = 0; c < 3; ++c)
    {
      // half: 11 significant bits, relative error <= 2^-11; tiny values are subnormal.
      EXPECT_NEAR(actual[c], expected[c], std::fabs(expected[c]) * 4.9e-4f + 6e-8f)
        << "pixel " << p << " channel " << c;
    }
  }
}

TEST_F(Exr, NonFiniteAndOutOfRangeRefusedNothingLeft)
{
  RadianceImage image;
  image.Width = 2;
  image.Height = 2;
  image.RGB.assign(12, 0.5f);
  const std::string file = (this->Dir / "bad.exr").string();
  for (float bad : { std::numeric_limits<float>::quiet_NaN(),
         std::numeric_limits<float>::infinity(), 1.0e6f })
  {
    image.RGB[7] = bad; // pixel (x 0, y 1), channel G
    std::string error;
    EXPECT_FALSE(WriteExrHalf(file, image, error));
    EXPECT_NE(error.find("bad.exr"), std::string::npos) << error;
    EXPECT_NE(error.find("x 0, y 1"), std::string::npos) << error;
    EXPECT_EQ(this->FileCount(), 0u);
  }

  image.RGB.resize(11);
  std::string error;
  EXPECT_FALSE(WriteExrHalf(file, image, error));
  EXPECT_EQ(this->FileCount(), 0u);

  // Unwritable place: error names the file, nothing left.
  image.RGB.assign(12, 0.5f);
  const std::string nowhere = (this->Dir / "no" / "such" / "dir.exr").string();
  EXPECT_FALSE(WriteExrHalf(nowhere, image, error));
  EXPECT_NE(error.find(nowhere), std::string::npos) << error;
  EXPECT_EQ(this->FileCount(), 0u);
}

// ------------------------------------------------------------------- probes

using Probes = TempDir;

TEST_F(Probes, ReadWriteRoundTrip)
{
  const std::string in = this->Write("probes.csv",
    "\xEF\xBB\xBF x , y,z,nx,ny ,nz\r\n"
    "0.1,0.2,0.3,0,0,2\r\n"
    "\n"
    "-1e-3, 4.5 ,+6,1,1,0\n");
  std::vector<Probe> probes;
  std::string error;
  ASSERT_TRUE(ReadProbes(in, probes, error)) << error;
  ASSERT_EQ(probes.size(), 2u);
  EXPECT_EQ(probes[0].Position, Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(probes[0].Normal, Vec3(0, 0, 1)); // normalized
  EXPECT_EQ(probes[1].Position, Vec3(-1e-3, 4.5, 6));
  EXPECT_NEAR(probes[1].Normal.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(probes[1].Normal.y, std::sqrt(0.5), 1e-15);

  const std::vector<RGB> values = { RGB(1.0 / 3.0, 2e-300, 123456.789), RGB(0.1, 0.2, 0.7) };
  const std::string out = (this->Dir / "values.csv").string();
  ASSERT_TRUE(WriteProbeValues(out, probes, values, error)) << error;
  EXPECT_EQ(this->FileCount(), 2u); // no temporary left

  std::ifstream back(out);
  std::string line;
  std::getline(back, line);
  EXPECT_EQ(line, "x,y,z,E_r,E_g,E_b");
  for (std::size_t i = 0; i < 2; ++i)
  {
    ASSERT_TRUE(std::getline(back, line));
    double v[6];
    char* p = line.data();
    for (double& x : v)
    {
      x = std::strtod(p, &p);
      if (*p == ',')
      {
        ++p;
      }
    }
    EXPECT_EQ(*p, '\0');
    // Full precision: the exact doubles come back.
    EXPECT_EQ(Vec3(v[0], v[1], v[2]), probes[i].Position);
    EXPECT_EQ(RGB(v[3], v[4], v[5]), values[i]);
  }
  EXPECT_FALSE(std::getline(back, line));

  // Refused output leaves nothing.
  const std::string refused = (this->Dir / "refused.csv").string();
  EXPECT_FALSE(WriteProbeValues(refused, probes, { values[0] }, error));
  EXPECT_FALSE(WriteProbeValues(
    refused, probes, { values[0], RGB(std::numeric_limits<double>::quiet_NaN()) }, error));
  EXPECT_NE(error.find("refused.csv"), std::string::npos) << error;
  EXPECT_EQ(this->FileCount(), 2u);
}

TEST_F(Probes, DaylightFactorColumnWithASky)
{
  // SPEC "Lights and sky": DF = luminance(E) / luminance(E_unobstructed),
  // luminance 0.2126 R + 0.7152 G + 0.0722 B.
  const RGB sky(100.0, 50.0, 25.0);
  const double skyLuminance = 0.2126 * 100.0 + 0.7152 * 50.0 + 0.0722 * 25.0;
  EXPECT_DOUBLE_EQ(DaylightFactor(RGB(10.0, 0.0, 0.0), sky), 2.126 / skyLuminance);
  EXPECT_DOUBLE_EQ(DaylightFactor(sky, sky), 1.0);
  EXPECT_EQ(DaylightFactor(sky, RGB(0.0)), 0.0);
  const std::vector<Probe> probes = { Probe{ Vec3(0.0), Vec3(0, 0, 1) }, Probe{ Vec3(1.0), Vec3(0, 0, 1) } };
  const std::vector<RGB> values = { RGB(50.0, 25.0, 12.5), RGB(0.0, 7.0, 0.0) };
  const std::string out = (this->Dir / "df.csv").string();
  std::string error;
  ASSERT_TRUE(WriteProbeValues(out, probes, values, error, &sky)) << error;
  std::ifstream back(out);
  std::string line;
  std::getline(back, line);
  EXPECT_EQ(line, "x,y,z,E_r,E_g,E_b,DF");
  for (std::size_t i = 0; i < 2; ++i)
  {
    ASSERT_TRUE(std::getline(back, line));
    const double df = std::strtod(line.substr(line.rfind(',') + 1).c_str(), nullptr);
    EXPECT_DOUBLE_EQ(df, DaylightFactor(values[i], sky)) << line;
  }
  EXPECT_DOUBLE_EQ(DaylightFactor(values[0], sky), 0.5);
  // The file reads back as a reference (--reference FILE), DF ignored.
  std::vector<RGB> back2;
  ASSERT_TRUE(ReadProbeValues(out, probes, back2, error)) << error;
  ASSERT_EQ(back2.size(), 2u);
  EXPECT_EQ(back2[0], values[0]);
  EXPECT_EQ(back2[1], values[1]);
  // A seventh column of another name, or a DF that is not a number, is refused.
  const std::string other = this->Write("other.csv", "x,y,z,E_r,E_g,E_b,UDI\n0,0,0,1,1,1,0.5\n1,1,1,1,1,1,0.5\n");
  EXPECT_FALSE(ReadProbeValues(other, probes, back2, error));
  EXPECT_NE(error.find(":1:"), std::string::npos) << error;
  const std::string nan = this->Write("nan.csv", "x,y,z,E_r,E_g,E_b,DF\n0,0,0,1,1,1,nan\n1,1,1,1,1,1,0.5\n");
  EXPECT_FALSE(ReadProbeValues(nan, probes, back2, error));
  EXPECT_NE(error.find("DF"), std::string::npos) << error;
}

TEST_F(Probes, ErrorsNameTheLine)
{
  struct Case
  {
    std::string Body;
    std::string Where;
  };
  const std::vector<Case> cases = {
    { "x,y,z,nx,ny\n0,0,0,0,0\n", ":1:" },
    { "x,y,z,nz,ny,nx\n", ":1:" },
    { "x;y;z;nx;ny;nz\n", ":1:" },
    { "x,y,z,nx,ny,nz\n0,0,0,0,0,1\n0,0,0,0,1\n", ":3:" },
    { "x,y,z,nx,ny,nz\n0,0,0,0,0,1\n0,0,0,0,1,1,1\n", ":3:" },
    { "x,y,z,nx,ny,nz\n0,0,abc,0,0,1\n", ":2:" },
    { "x,y,z,nx,ny,nz\n0,0,,0,0,1\n", ":2:" },
    { "x,y,z,nx,ny,nz\n0,0,1e999,0,0,1\n", ":2:" },
    { "x,y,z,nx,ny,nz\n0,0,nan,0,0,1\n", ":2:" },
    { "x,y,z,nx,ny,nz\n\n1,2,3,0,0,0\n", ":3:" },
  };
  for (const Case& c : cases)
  {
    const std::string file = this->Write("p.csv", c.Body);
    std::vector<Probe> probes;
    std::string error;
    EXPECT_FALSE(ReadProbes(file, probes, error)) << c.Body;
    EXPECT_TRUE(probes.empty());
    EXPECT_NE(error.find("p.csv" + c.Where), std::string::npos) << c.Body << " -> " << error;
  }
  std::vector<Probe> probes;
  std::string error;
  EXPECT_FALSE(ReadProbes(this->Write("empty.csv", ""), probes, error));
  EXPECT_NE(error.find("empty.csv"), std::string::npos) << error;
  EXPECT_FALSE(ReadProbes((this->Dir / "missing.csv").string(), probes, error));
  EXPECT_NE(error.find("missing.csv"), std::string::npos) << error;
}

// ------------------------------------------------------------- progress bar

TEST(ProgressBarTest, PlainLinesRateLimited)
{
  std::FILE* f = std::tmpfile();
  ASSERT_TRUE(f);
  {
    ProgressBar bar(f); // a file is not a terminal
    ProgressStatus s;
    s.Phase = "shooting";
    for (int i = 0; i < 1000; ++i)
    {
      s.Iteration = i;
      s.Fraction = i / 1000.0;
      s.Residual = 1.0 / (i + 1);
      EXPECT_TRUE(bar.Update(s));
    }
    bar.Finish("done");
  }
  const std::string text = ReadAll(f);
  std::fclose(f);
  // First, last and the message; a fast loop gets no more.
  EXPECT_EQ(text,
    "  0% shooting  it 0  residual 1.0e+00\n"
    " 99% shooting  it 999  residual 1.0e-03\n"
    "done\n");
}

TEST(ProgressBarTest, PlainLinePerPhaseAndAfterASecond)
{
  std::FILE* f = std::tmpfile();
  ASSERT_TRUE(f);
  ProgressBar bar(f, false);
  ProgressStatus s;
  s.Phase = "preprocessing";
  bar.Update(s);
  s.Phase = "shooting";
  bar.Update(s);
  std::this_thread::sleep_for(std::chrono::milliseconds(1050));
  s.Iteration = 7;
  bar.Update(s);
  bar.Finish("");
  const std::string text = ReadAll(f);
  std::fclose(f);
  EXPECT_EQ(text,
    "  0% preprocessing  it 0  residual 0.0e+00\n"
    "  0% shooting  it 0  residual 0.0e+00\n"
    "  0% shooting  it 7  residual 0.0e+00\n");
}

TEST(ProgressBarTest, TerminalBarRedrawsInPlace)
{
  std::FILE* f = std::tmpfile();
  ASSERT_TRUE(f);
  ProgressBar bar(f, true);
  ProgressStatus s;
  s.Phase = "preprocessing-long-name";
  s.Fraction = 0.0;
  bar.Update(s);
  s.Phase = "shooting";
  s.Iteration = 1234;
  s.Residual = 2.3e-3;
  s.Fraction = 0.43;
  bar.Update(s);
  const ProgressCallback callback = std::ref(bar); // usable as the solver's callback
  EXPECT_TRUE(callback(s));
  bar.Finish("converged");
  const std::string text = ReadAll(f);
  std::fclose(f);
  const std::string first = "[....................]   0% preprocessing-long-name  it 0  residual 0.0e+00";
  const std::string second = "[########............]  43% shooting  it 1234  residual 2.3e-03";
  // The third update came within 0.1 s: shown only by Finish, as the last state.
  const std::string expected = "\r" + first + "\r" + second +
    std::string(first.size() - second.size(), ' ') + "\r" + second + "\nconverged\n";
  EXPECT_EQ(text, expected);
}
