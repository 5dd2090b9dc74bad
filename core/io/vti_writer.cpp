#include "core/io/vti_writer.h"

#include <vtkCharArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_progress.h"
#include "core/util/error.h"

namespace sandstorm {

VtiCompression vtiCompressionNamed(const std::string& name, const std::string& where) {
  if (name == "zlib") return VtiCompression::ZLib;
  if (name == "lz4") return VtiCompression::LZ4;
  if (name == "none") return VtiCompression::None;
  throw Error(concat(where, ": '", name, "': expected zlib, lz4 or none"));
}

void writeVti(const std::filesystem::path& path, const VectorField& field,
              const std::string& arrayName, VtiCompression compression) {
  if (field.empty()) throw Error(concat(path.string(), ": cannot write an empty field"));
  const glm::ivec3 dims = field.dims();
  const glm::vec3 spacing = field.spacing();
  vtkNew<vtkImageData> image;
  image->SetDimensions(dims.x, dims.y, dims.z);
  image->SetOrigin(field.bounds().min.x, field.bounds().min.y, field.bounds().min.z);
  image->SetSpacing(dims.x > 1 ? spacing.x : 1.0, dims.y > 1 ? spacing.y : 1.0,
                    dims.z > 1 ? spacing.z : 1.0);
  vtkNew<vtkFloatArray> values;
  values->SetName(arrayName.c_str());
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(vtkIdType(field.pointCount()));
  const auto v = field.values();
  for (std::size_t i = 0; i < v.size(); ++i)
    values->SetTypedTuple(vtkIdType(i), &v[i].x);
  image->GetPointData()->SetVectors(values);
  if (field.hasValidity()) {
    // As VTK marks resampled points: vtkValidPointMask, 1 where there is data.
    vtkNew<vtkCharArray> mask;
    mask->SetName("vtkValidPointMask");
    mask->SetNumberOfTuples(vtkIdType(field.pointCount()));
    const auto valid = field.validity();
    for (std::size_t i = 0; i < valid.size(); ++i)
      mask->SetValue(vtkIdType(i), char(valid[i]));
    image->GetPointData()->AddArray(mask);
  }

  for (const VectorField::Scalars& a : field.scalars()) {
    vtkNew<vtkFloatArray> scalar;
    scalar->SetName(a.name.c_str());
    scalar->SetNumberOfTuples(vtkIdType(a.values.size()));
    for (std::size_t i = 0; i < a.values.size(); ++i)
      scalar->SetValue(vtkIdType(i), a.values[i]);
    image->GetPointData()->AddArray(scalar);
  }

  VtkMessageTrap trap(path);
  vtkNew<vtkXMLImageDataWriter> writer;
  trap.watch(writer);
  writer->SetInputData(image);
  writer->SetFileName(path.string().c_str());
  // Raw appended data (as ParaView writes it), not base64: a third smaller,
  // and read back without decoding text. 64-bit header words: a grid's bytes
  // may pass 4 GiB.
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetHeaderTypeToUInt64();
  switch (compression) {
    case VtiCompression::ZLib:
      writer->SetCompressorTypeToZLib();
      break;
    case VtiCompression::LZ4:
      writer->SetCompressorTypeToLZ4();
      break;
    case VtiCompression::None:
      writer->SetCompressorTypeToNone();
      break;
  }
  // The writer reports its share done; the bytes are the arrays it writes.
  VtkProgress progress(writer, "writing " + path.filename().string(),
                       double(field.pointCount()) * (12.0 + (field.hasValidity() ? 1.0 : 0.0) +
                                                     4.0 * field.scalars().size()));
  const int ok = writer->Write();
  progress.finish();
  trap.throwIfFailed("writing VTK XML image data");
  if (!ok) throw Error(concat(path.string(), ": VTK could not write the file"));
}

}  // namespace sandstorm
