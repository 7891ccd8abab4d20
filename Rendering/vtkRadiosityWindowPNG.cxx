#include "vtkRadiosityWindowPNG.h"

#include "vtkErrorCode.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkWindowToImageFilter.h"

bool vtkRadiosityWriteWindowPNG(vtkRenderWindow* window, const char* fileName, std::string& error)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(fileName);
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    error = std::string("Could not write PNG image '") + fileName +
      "': " + vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode());
    return false;
  }
  return true;
}
