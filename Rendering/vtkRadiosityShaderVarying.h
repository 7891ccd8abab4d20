// A varying added to vtkOpenGLPolyDataMapper's shaders: declared and set in
// the vertex shader, passed through the geometry shader VTK adds for surface
// edges or wide lines (if any), declared in the fragment shader. The //VTK::
// TCoord tags carry it and are kept for the superclass's own replacements;
// with a geometry shader the shader cache renames <name>VSOutput to
// <name>GSOutput in the fragment shader. Shared by the radiosity mappers.
#ifndef vtkRadiosityShaderVarying_h
#define vtkRadiosityShaderVarying_h

#include "vtkShader.h"
#include "vtkShaderProgram.h"

#include <map>
#include <string>

/**
 * Adds `<type> <name>VSOutput` = `value` (a vertex shader expression, after
 * `vertexDeclarations`) and declares `fragmentDeclarations` with it in the
 * fragment shader.
 */
inline void vtkRadiosityAddVarying(std::map<vtkShader::Type, vtkShader*>& shaders,
  const std::string& type, const std::string& name, const std::string& vertexDeclarations,
  const std::string& value, const std::string& fragmentDeclarations)
{
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string gs = shaders[vtkShader::Geometry]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  const std::string vsOut = name + "VSOutput";
  vtkShaderProgram::Substitute(vs, "//VTK::TCoord::Dec",
    "//VTK::TCoord::Dec\n" + vertexDeclarations + "out " + type + " " + vsOut + ";\n");
  vtkShaderProgram::Substitute(
    vs, "//VTK::TCoord::Impl", "//VTK::TCoord::Impl\n  " + vsOut + " = " + value + ";\n");
  if (!gs.empty())
  {
    const std::string gsOut = name + "GSOutput";
    vtkShaderProgram::Substitute(gs, "//VTK::TCoord::Dec",
      "//VTK::TCoord::Dec\nin " + type + " " + vsOut + "[];\nout " + type + " " + gsOut + ";\n");
    vtkShaderProgram::Substitute(
      gs, "//VTK::TCoord::Impl", "//VTK::TCoord::Impl\n    " + gsOut + " = " + vsOut + "[i];\n");
  }
  vtkShaderProgram::Substitute(fs, "//VTK::TCoord::Dec",
    "//VTK::TCoord::Dec\nin " + type + " " + vsOut + ";\n" + fragmentDeclarations);
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Geometry]->SetSource(gs);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

#endif
