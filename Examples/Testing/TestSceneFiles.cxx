// The scene loader's content checks (SceneFileCheck*.cxx) and readers on
// small hand-made files: every refusal names the file, what, where and the
// value, before a VTK reader that could crash sees the file.
#include "CliTestSupport.h"
#include "ObjMtlReader.h"
#include "SceneFileCheck.h"
#include "SceneLoader.h"

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
#include <limits>

using namespace radiosity;
using namespace radiosity::cli;
using clitest::TempDir;
using clitest::Tuple3;

// ------------------------------------------------------- scene files checks

using SceneFiles = TempDir;

namespace
{
// Loads `file`, expecting a refusal whose message contains every one of `parts`.
void ExpectRefused(const std::string& file, std::initializer_list<const char*> parts)
{
  std::string error;
  std::vector<std::string> warnings;
  EXPECT_FALSE(LoadScene(file, error, warnings)) << file;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_EQ(error.rfind(file, 0), 0u) << "the message starts with the file: " << error;
  for (const char* part : parts)
  {
    EXPECT_NE(error.find(part), std::string::npos) << "'" << part << "' not in: " << error;
  }
}

vtkDataArray* CellArray(vtkDataObject* data, const char* name)
{
  auto* pd = vtkPolyData::SafeDownCast(data);
  return pd ? pd->GetCellData()->GetArray(name) : nullptr;
}

std::string Joined(const std::vector<std::string>& lines)
{
  std::string all;
  for (const std::string& l : lines)
  {
    all += l + "\n";
  }
  return all;
}

const char* TwoTrianglesPly = "ply\nformat ascii 1.0\nelement vertex 4\n"
                              "property float x\nproperty float y\nproperty float z\n"
                              "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                              "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3";

std::string LittleEndian32(std::uint32_t v)
{
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i)
  {
    s[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
  }
  return s;
}
} // namespace

// vtkDataSetReader keeps only the first SCALARS array unless told to read them all.
TEST_F(SceneFiles, LegacyVtkKeepsEveryCellArrayAndNamesThem)
{
  const std::string file = this->Write("two.vtk",
    "# vtk DataFile Version 3.0\ntwo arrays\nASCII\nDATASET POLYDATA\n"
    "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\nPOLYGONS 2 8\n3 0 1 2\n3 0 2 3\n"
    "CELL_DATA 2\nSCALARS Reflectance double 3\nLOOKUP_TABLE default\n0.5 0.5 0.5 0.5 0.5 0.5\n"
    "SCALARS Emission double 3\nLOOKUP_TABLE default\n1 1 1 0 0 0\n"
    "SCALARS Reflectence double 1\nLOOKUP_TABLE default\n0 0\n");
  std::string error;
  std::vector<std::string> warnings, notes;
  vtkSmartPointer<vtkDataObject> data = LoadScene(file, error, warnings, notes, LoadOptions());
  ASSERT_TRUE(data) << error;
  ASSERT_TRUE(CellArray(data, "Reflectance"));
  ASSERT_TRUE(CellArray(data, "Emission"));
  EXPECT_EQ(CellArray(data, "Emission")->GetComponent(0, 1), 1.0);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("read " + file + ": 4 points, 2 polygons; cell arrays: Reflectance (3), "
                          "Emission (3), Reflectence (1)"),
    std::string::npos)
    << notes[0];
  // The typo is named in a warning; the known arrays are not.
  const std::string all = Joined(warnings);
  EXPECT_NE(all.find("'Reflectence' is not a scene array"), std::string::npos) << all;
  EXPECT_EQ(all.find("'Emission'"), std::string::npos) << all;
}

// A Reflectance array is physical: the loader leaves 1.0 as it is (the scene check refuses it).
TEST_F(SceneFiles, ReflectanceArrayIsNotClamped)
{
  const std::string file = this->Write("one.vtk",
    "# vtk DataFile Version 3.0\nwhite\nASCII\nDATASET POLYDATA\n"
    "POINTS 3 float\n0 0 0 1 0 0 1 1 0\nPOLYGONS 1 4\n3 0 1 2\n"
    "CELL_DATA 1\nSCALARS Reflectance double 3\nLOOKUP_TABLE default\n1 1 1\n");
  std::string error;
  std::vector<std::string> warnings;
  vtkSmartPointer<vtkDataObject> data = LoadScene(file, error, warnings);
  ASSERT_TRUE(data) << error;
  EXPECT_EQ(CellArray(data, "Reflectance")->GetComponent(0, 0), 1.0);
}

// .mtl Kd are display colours: white is clamped to --max-reflectance, one warning.
TEST_F(SceneFiles, WhiteKdClampedWithOneWarning)
{
  this->Write("w.mtl", "newmtl white\nKd 1 1 1\nnewmtl paper\nKd 0.97 0.5 0.2\n"
                       "newmtl grey\nKd 0.5 0.5 0.5\nnewmtl bad\nKd 1.2 0 0\n");
  const std::string obj = this->Write("w.obj",
    "mtllib w.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl white\nf 1 2 3\nusemtl paper\nf 1 2 3\n"
    "usemtl grey\nf 1 2 3\nusemtl bad\nf 1 2 3\n");
  std::string error;
  std::vector<std::string> warnings;
  LoadOptions options;
  options.MaxReflectance = 0.9;
  vtkSmartPointer<vtkDataObject> data = LoadScene(obj, error, warnings, options);
  ASSERT_TRUE(data) << error;
  vtkDataArray* kd = CellArray(data, "Reflectance");
  ASSERT_TRUE(kd);
  EXPECT_EQ(Tuple3(kd, 0), (std::array<double, 3>{ 0.9, 0.9, 0.9 }));
  EXPECT_EQ(Tuple3(kd, 1), (std::array<double, 3>{ 0.9, 0.5, 0.2 }));
  EXPECT_EQ(Tuple3(kd, 2), (std::array<double, 3>{ 0.5, 0.5, 0.5 }));
  EXPECT_EQ(kd->GetComponent(3, 0), 1.2); // no display colour: left for the scene check to refuse
  const std::string all = Joined(warnings);
  std::size_t clampWarnings = 0;
  for (const std::string& w : warnings)
  {
    clampWarnings += w.find("clamped to 0.9") != std::string::npos;
  }
  EXPECT_EQ(clampWarnings, 1u) << all;
  EXPECT_NE(all.find("2 material(s)"), std::string::npos) << all;
  // The default limit is 0.95.
  data = LoadScene(obj, error, warnings);
  ASSERT_TRUE(data) << error;
  EXPECT_EQ(CellArray(data, "Reflectance")->GetComponent(0, 0), 0.95);
}

// assimp's PLY/issue623.ply: a list property in the vertex element that the
// lines do not hold. vtkPLYReader indexes past the line's words (a segfault).
TEST_F(SceneFiles, PlyLinesShorterThanTheHeaderRefused)
{
  const std::string ply = this->Write("issue623.ply",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
    "property list uchar uint vertex_indices\nend_header\n"
    "0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n");
  ExpectRefused(ply, { "line 12", "vertex 0 of 3", "holds 6 values" });
}

TEST_F(SceneFiles, PlyReadsTwoTrianglesWithoutAFinalLineEnd)
{
  const std::string ply = this->Write("square.ply", TwoTrianglesPly);
  std::string error;
  std::vector<std::string> warnings;
  vtkSmartPointer<vtkDataObject> data = LoadScene(ply, error, warnings);
  ASSERT_TRUE(data) << error;
  EXPECT_EQ(vtkPolyData::SafeDownCast(data)->GetNumberOfPolys(), 2);
}

TEST_F(SceneFiles, PlyBadHeadersAndIndicesRefused)
{
  const std::string good = TwoTrianglesPly;
  const auto variant = [&](const std::string& name, const std::string& from, const std::string& to)
  {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return this->Write(name, text);
  };
  ExpectRefused(variant("type.ply", "property float z", "property float128 z"),
    { "header line 6", "unknown property type 'float128'" });
  ExpectRefused(variant("format.ply", "format ascii 1.0", "format utf8 1.0"), { "bad format line" });
  ExpectRefused(variant("noz.ply", "property float z\n", ""), { "x, y and z" });
  ExpectRefused(variant("index.ply", "3 0 2 3", "3 0 2 7"),
    { "face 1 of 2", "vertex index 7, out of range (4 vertices)" });
  ExpectRefused(variant("short.ply", "element face 2", "element face 3"),
    { "declares 7 element lines (4 vertices, 3 faces) but the file holds only 6 lines" });
  ExpectRefused(variant("blank.ply", "3 0 1 2\n", "\n3 0 1 2\n"), { "holds 0 values" });
  ExpectRefused(variant("order.ply", "element vertex 4", "element edge 1\nproperty int a\nelement vertex 4"),
    { "element 'edge' comes before" });
  ExpectRefused(variant("orphan.ply", "format ascii 1.0\n", "format ascii 1.0\nproperty int q\n"),
    { "property before any element" });
}

// A binary PLY that claims four billion vertices (it used to end in
// "internal error: vector::_M_default_append").
TEST_F(SceneFiles, PlyCountBeyondTheFileRefusedBeforeReading)
{
  const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 4294967295\n"
                             "property float x\nproperty float y\nproperty float z\nend_header\n";
  const std::string ply = this->Write("huge.ply", header + std::string(1234, '\0'));
  ExpectRefused(ply, { "header line 3 declares 4294967295 vertices of 12 bytes (51.5 GB)",
                       "the file holds 1234 bytes after the header" });
  // A count that fits in the file but not in VTK's int.
  const std::string ok = "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
                         "property float x\nproperty float y\nproperty float z\n"
                         "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  std::string body(12, '\0');
  body += '\x03' + LittleEndian32(0) + LittleEndian32(0) + LittleEndian32(5);
  ExpectRefused(this->Write("binindex.ply", ok + body), { "face 0 of 1", "vertex index 5" });
}

TEST_F(SceneFiles, LegacyVtkCountBeyondTheFileRefused)
{
  ExpectRefused(this->Write("billion.vtk",
                  "# vtk DataFile Version 3.0\nbig\nASCII\nDATASET POLYDATA\n"
                  "POINTS 1000000000 float\n0 0 0 1 0 0 1 1 0\n"),
    { "line 5 declares 1000000000 points", "but the file holds" });
  ExpectRefused(this->Write("cells.vtk",
                  "# vtk DataFile Version 3.0\nbig\nBINARY\nDATASET POLYDATA\n"
                  "POINTS 1 float\n" + std::string(12, '\0') + "\nPOLYGONS 500000000 2000000000\n"),
    { "line 6 declares 500000000 POLYGONS (2000000000 ids) (2000000000 int values, 8 GB) but the "
      "file holds 0 bytes after it" });
  ExpectRefused(this->Write("attr.vtk",
                  "# vtk DataFile Version 3.0\nbig\nASCII\nDATASET POLYDATA\n"
                  "POINTS 1 float\n0 0 0\nCELL_DATA 900000000\nSCALARS Emission float 3\n0 0 0\n"),
    { "CELL_DATA 900000000 but the data set has" });
  ExpectRefused(this->Write("magic.vtk", "solid x\n"), { "not a legacy VTK file" });
}

TEST_F(SceneFiles, BinaryStlCountMustMatchTheSize)
{
  std::string stl(80, '\0');
  stl += LittleEndian32(1000000) + std::string(50, '\x01');
  ExpectRefused(this->Write("count.stl", stl),
    { "declares 1000000 triangles", "the file holds 134 bytes (1 triangles)" });
  std::string exact(80, '\0');
  exact += LittleEndian32(1);
  const float facet[12] = { 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0 }; // normal, 3 vertices
  exact += std::string(reinterpret_cast<const char*>(facet), sizeof facet) + std::string(2, '\0');
  std::string error;
  std::vector<std::string> warnings;
  EXPECT_TRUE(LoadScene(this->Write("one.stl", exact), error, warnings)) << error;
}

// assimp's OBJ/box_UTF16BE.obj used to exit 2 with warnings and no error line.
TEST_F(SceneFiles, ObjThatIsNotEightBitTextRefused)
{
  std::string utf16 = "\xFE\xFF";
  for (char c : std::string("v 0 0 0\n"))
  {
    utf16 += std::string(1, '\0') + c;
  }
  ExpectRefused(this->Write("box_UTF16BE.obj", utf16), { "UTF-16", "FE 0xFF at offset 0" });
  ExpectRefused(this->Write("nobom.obj", utf16.substr(2)), { "UTF-16", "offset 0" });
  ExpectRefused(this->Write("binary.obj", std::string("v 0 0 0\n\x01\x02", 10)),
    { "binary content", "0x01 at offset 8" });
}

TEST_F(SceneFiles, XmlCountBeyondTheFileAndUnknownTypesRefused)
{
  ExpectRefused(this->Write("big.vtp",
                  "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\">"
                  "<PolyData><Piece NumberOfPoints=\"2000000000\" NumberOfPolys=\"1\">"
                  "</Piece></PolyData></VTKFile>\n"),
    { "NumberOfPoints=\"2000000000\"", "the file holds" });
  ExpectRefused(this->Write("text.vtp", "solid\n"), { "not an XML file" });
  ExpectRefused(this->Write("box.gltf", "{}"), { "unknown scene file type '.gltf'", "glTF" });
  ExpectRefused(this->Write("box.glb", "glTF"), { "unknown scene file type '.glb'" });
  std::string error;
  std::vector<std::string> warnings;
  EXPECT_FALSE(LoadScene((this->Dir / "missing.ply").string(), error, warnings));
  EXPECT_NE(error.find("missing.ply: cannot be opened"), std::string::npos) << error;
}

namespace
{
// The fuzzer's legacy findings (Testing/Fuzz/regressions/vtk-*): the loader
// reads DATASET POLYDATA only, and walks it as vtkPolyDataReader will.
const char* LegacyHeader = "# vtk DataFile Version 3.0\nt\nASCII\n";

std::string BigEndian32(std::int32_t v)
{
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i)
  {
    s[i] = static_cast<char>((static_cast<std::uint32_t>(v) >> (24 - 8 * i)) & 0xFF);
  }
  return s;
}
} // namespace

TEST_F(SceneFiles, LegacyVtkOtherThanPolyDataRefused)
{
  const std::string h = LegacyHeader;
  ExpectRefused(this->Write("grid.vtk", h + "DATASET STRUCTURED_GRID\nDIMENSIONS 2 2 1\n"),
    { "line 4: DATASET STRUCTURED_GRID is not polygonal data (the loader reads DATASET "
      "POLYDATA; convert with vtkGeometryFilter)" });
  ExpectRefused(this->Write("ugrid.vtk",
                  h + "DATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n"
                      "CELLS 1 1\n4 0 1 2 3\n"),
    { "line 4: DATASET UNSTRUCTURED_GRID is not polygonal data" });
  ExpectRefused(this->Write("field.vtk", h + "FIELD f 1\na 1 2 float\n1 2\n"),
    { "line 4: 'FIELD' where DATASET POLYDATA is expected" });
}

TEST_F(SceneFiles, LegacyVtkCellsMustFitTheirSizeAndPoints)
{
  const std::string h = std::string(LegacyHeader) +
    "DATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n";
  ExpectRefused(this->Write("size.vtk", h + "POLYGONS 1 4\n100000 0 1 2\n"),
    { "line 8: POLYGONS cell 0 has 100000 points but the declared size 4 leaves room for 3" });
  ExpectRefused(this->Write("index.vtk", h + "POLYGONS 1 5\n4 0 1 2 100000000\n"),
    { "line 8: POLYGONS cell 0 has the point id 100000000, out of range (3 points)" });
  ExpectRefused(this->Write("count.vtk", h + "POLYGONS 2 4\n3 0 1 2\n"),
    { "line 7: POLYGONS declares 2 cells but its size 4 holds 1" });
  ExpectRefused(this->Write("cells.vtk", h + "CELL_DATA 1\nSCALARS a float\nLOOKUP_TABLE default\n1\n"),
    { "line 7: CELL_DATA 1 but the data set has 0 cells" });
  // Binary: big-endian ints.
  const std::string binary = "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET POLYDATA\n"
                             "POINTS 3 float\n" + std::string(36, '\0') + "\nPOLYGONS 1 4\n";
  ExpectRefused(this->Write("binary.vtk",
                  binary + BigEndian32(3) + BigEndian32(0) + BigEndian32(1) + BigEndian32(7) + "\n"),
    { "POLYGONS cell 0 has the point id 7, out of range (3 points)" });
  ExpectRefused(this->Write("negative.vtk",
                  binary + BigEndian32(-5) + BigEndian32(0) + BigEndian32(1) + BigEndian32(2) + "\n"),
    { "POLYGONS cell 0 has -5 points" });
  std::string error;
  std::vector<std::string> warnings;
  EXPECT_TRUE(LoadScene(this->Write("good.vtk", binary + BigEndian32(3) + BigEndian32(0) +
                                       BigEndian32(1) + BigEndian32(2) + "\n"),
    error, warnings))
    << error;
  // VTK 5.1: OFFSETS and CONNECTIVITY.
  const std::string v5 = "# vtk DataFile Version 5.1\nt\nASCII\nDATASET POLYDATA\n"
                         "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 2 3\n";
  EXPECT_TRUE(LoadScene(this->Write("v5.vtk", v5 + "OFFSETS vtktypeint64\n0 3\n"
                                                   "CONNECTIVITY vtktypeint64\n0 1 2\n"),
    error, warnings))
    << error;
  ExpectRefused(this->Write("v5off.vtk", v5 + "OFFSETS vtktypeint64\n0 4\nCONNECTIVITY "
                                              "vtktypeint64\n0 1 2\n"),
    { "line 9: POLYGONS offset 1 is 4, beyond the 3 connectivity ids" });
  ExpectRefused(this->Write("v5id.vtk", v5 + "OFFSETS vtktypeint64\n0 3\nCONNECTIVITY "
                                             "vtktypeint64\n0 1 3\n"),
    { "line 11: POLYGONS connectivity id 2 is 3, out of range (3 points)" });
  ExpectRefused(this->Write("v5type.vtk", v5 + "OFFSETS float\n0 3\n"),
    { "line 8: POLYGONS OFFSETS has the data type 'float', not an integer type" });
}

TEST_F(SceneFiles, LegacyVtkTypesFieldsAndKeywordsChecked)
{
  const std::string h = std::string(LegacyHeader) + "DATASET POLYDATA\n";
  const std::string tri = h + "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\n";
  ExpectRefused(this->Write("variant.vtk", h + "POINTS 1 variant\n0 0 0\n"),
    { "line 5: POINTS has the data type 'variant', not a number type" });
  ExpectRefused(this->Write("field.vtk", h + "FIELD\n"),
    { "line 5: a FIELD line is 'FIELD NAME N'", "'FIELD' alone" });
  ExpectRefused(this->Write("arrays.vtk", h + "FIELD f 1\n"),
    { "FIELD f of 1 arrays but the file holds 0 bytes after it" });
  ExpectRefused(this->Write("noarray.vtk", h + "FIELD f 2\na 1 1 float\n1\n\n\n"),
    { "the file ends before array 2 of the 2 of FIELD f" });
  ExpectRefused(this->Write("tuples.vtk", tri + "CELL_DATA 1\nFIELD f 1\nEmission 3 2 float\n1 1 1 1 1 1\n"),
    { "line 11: FIELD f array Emission has 2 tuples but CELL_DATA 1 declares 1" });
  ExpectRefused(this->Write("lut.vtk", tri + "CELL_DATA 1\nSCALARS Emission float 3\n1 1 1\n"),
    { "line 10: SCALARS Emission is not followed by 'LOOKUP_TABLE NAME'" });
  ExpectRefused(this->Write("keyword.vtk", tri + "XYZ\n"),
    { "line 9: unknown keyword 'XYZ' in DATASET POLYDATA" });
  ExpectRefused(this->Write("attribute.vtk", tri + "CELL_DATA 1\nCOLORS c float\n"),
    { "line 10: unknown keyword 'COLORS' in CELL_DATA" });
  ExpectRefused(this->Write("points.vtk", tri + "POINT_DATA 2\n"),
    { "line 9: POINT_DATA 2 but the data set has 3 points" });
  ExpectRefused(this->Write("nan.vtk", h + "POINTS 1 float\n0 nan 0\n"),
    { "line 6: 1 points: value 2, 'nan', is not a number (float)" });
  ExpectRefused(this->Write("value.vtk", tri + "CELL_DATA 1\nVECTORS v double\n1 2 3F3\n"),
    { "line 11: VECTORS v: 1 tuples of 3: value 3, '3F3', is not a number (double)" });
}

// vtkPLY reads ASCII lines as C strings: a NUL ends a line early.
TEST_F(SceneFiles, PlyNulByteRefused)
{
  std::string ply = TwoTrianglesPly;
  ply[ply.find("1 0 0")] = '\0';
  ExpectRefused(this->Write("nul.ply", ply), { "a NUL byte at offset", "(line 11) in the ASCII body" });
}

// vtkPLY's ply_close frees the property table of every element, and one
// declared without properties crashes it (Testing/Fuzz/regressions/
// ply-binary-element-without-properties-bad-free).
TEST_F(SceneFiles, PlyElementWithoutPropertiesRefused)
{
  std::string ply = TwoTrianglesPly;
  ply.insert(ply.find("end_header"), "element material 1\n");
  ExpectRefused(this->Write("bare.ply", ply), { "bare.ply: header line 9: element 'material' has no property" });
}

// A list on an element other than face, with lines that hold its values,
// crashed vtkPLY (Testing/Fuzz/regressions/ply-list-property-outside-face).
TEST_F(SceneFiles, PlyListOutsideTheFaceElementRefused)
{
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                          "property float y\nproperty float z\nproperty list uchar int extra\n"
                          "end_header\n0 0 0 1 7\n1 0 0 1 7\n0 1 0 1 7\n";
  ExpectRefused(this->Write("list.ply", ply),
    { "list.ply: header line 3+: property 'extra' of element 'vertex' is a list" });
}

// vtkXMLPolyDataReader crashes on ASCII values that do not parse and leaks
// on Points without 3 components (Testing/Fuzz/regressions/vtp-*).
TEST_F(SceneFiles, XmlArraysCheckedAgainstThePiece)
{
  const auto vtp = [](const std::string& points, const std::string& cellData,
                     const std::string& connectivity, const std::string& offsets)
  {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\">\n"
           "<PolyData><Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\">\n<Points>" +
      points + "</Points>\n<CellData>" + cellData + "</CellData>\n<Polys>\n" +
      "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" + connectivity +
      "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" + offsets +
      "</DataArray>\n</Polys></Piece></PolyData></VTKFile>\n";
  };
  const std::string points =
    "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray>";
  const std::string emission =
    "<DataArray type=\"Float64\" Name=\"Emission\" NumberOfComponents=\"3\" format=\"ascii\">";
  std::string error;
  std::vector<std::string> warnings;
  EXPECT_TRUE(LoadScene(this->Write("good.vtp", vtp(points, emission + "1 1 1</DataArray>", "0 1 2", "3")),
    error, warnings))
    << error;
  ExpectRefused(this->Write("value.vtp", vtp(points, emission + "3 3F3</DataArray>", "0 1 2", "3")),
    { "line 5: CellData DataArray 'Emission': value 2, '3F3', is not a number (Float64)" });
  ExpectRefused(this->Write("few.vtp", vtp(points, emission + "1 1</DataArray>", "0 1 2", "3")),
    { "line 5: CellData DataArray 'Emission' holds 2 values but 1 cells x 3 need 3" });
  ExpectRefused(this->Write("one.vtp",
                  vtp("<DataArray type=\"Float64\" format=\"ascii\">0 0 0</DataArray>", "", "0 1 2", "3")),
    { "line 4: Points DataArray has 1 component (no NumberOfComponents); points have "
      "NumberOfComponents=\"3\"" });
  ExpectRefused(this->Write("id.vtp", vtp(points, "", "0 1 5", "3")),
    { "Polys DataArray 'connectivity': value 3, '5', is out of range (3 points)" });
  ExpectRefused(this->Write("offset.vtp", vtp(points, "", "0 1 2", "4")),
    { "Polys (1 cells): the last offset is 4 but the connectivity holds 3 ids" });
  ExpectRefused(this->Write("broken.vtp", "<VTKFile><PolyData></VTKFile>\n"),
    { "not well-formed XML at byte" });
  // An array in no format VTK knows is left unread, then dereferenced
  // (Testing/Fuzz/regressions/vtp-array-of-unknown-format).
  ExpectRefused(this->Write("format.vtp",
                  vtp(points,
                    "<DataArray type=\"Float64\" Name=\"Emission\" NumberOfComponents=\"3\" "
                    "format=\"asci\">1 1 1</DataArray>",
                    "0 1 2", "3")),
    { "line 5: CellData DataArray 'Emission' has format=\"asci\", not ascii, binary or appended" });
}
