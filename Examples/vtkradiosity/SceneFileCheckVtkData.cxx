// The POINT_DATA / CELL_DATA sections of a legacy .vtk file: FIELD arrays
// and attributes (SCALARS, VECTORS, NORMALS, ...), walked as
// vtkDataReader::ReadPointData / ReadCellData read them (SceneFileCheckVtk.cxx).
#include "SceneFileCheckVtkWalker.h"

namespace radiosity
{
namespace cli
{
namespace legacy
{
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
} // namespace legacy
} // namespace cli
} // namespace radiosity
