#include "core/io/vdb_writer.h"

#include <openvdb/io/File.h>
#include <openvdb/math/Maps.h>

#include "core/io/openvdb_grids.h"
#include "core/io/vdb_reader.h"
#include "core/util/error.h"

namespace sandstorm {

void writeVdb(const std::filesystem::path& path, const VectorField& field,
              const std::string& gridName) {
  if (field.empty()) throw Error(concat(path.string(), ": cannot write an empty field"));
  initializeOpenVdb();
  const glm::ivec3 dims = field.dims();
  const glm::vec3 s = field.spacing();
  const glm::vec3 m = field.bounds().min;
  const openvdb::Vec3d scale(dims.x > 1 ? s.x : 1.0, dims.y > 1 ? s.y : 1.0,
                             dims.z > 1 ? s.z : 1.0);
  auto map =
      std::make_shared<openvdb::math::ScaleTranslateMap>(scale, openvdb::Vec3d(m.x, m.y, m.z));
  auto grid = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
  grid->setTransform(std::make_shared<openvdb::math::Transform>(map));
  grid->setName(gridName);
  grid->insertMeta("sandstorm_axes", openvdb::StringMetadata("z-up, right-handed, metres"));
  auto acc = grid->getAccessor();
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const glm::vec3& v = field.at(i, j, k);
        acc.setValueOn(openvdb::Coord(i, j, k), openvdb::Vec3s(v.x, v.y, v.z));
      }
  // Scalar arrays as float grids on the same transform, every point active.
  openvdb::GridPtrVec grids{grid};
  for (const VectorField::Scalars& a : field.scalars()) {
    auto scalar = openvdb::FloatGrid::create(0.0f);
    scalar->setTransform(grid->transform().copy());
    scalar->setName(a.name);
    auto sa = scalar->getAccessor();
    for (int k = 0; k < dims.z; ++k)
      for (int j = 0; j < dims.y; ++j)
        for (int i = 0; i < dims.x; ++i)
          sa.setValueOn(openvdb::Coord(i, j, k), a.values[field.index(i, j, k)]);
    grids.push_back(scalar);
  }
  try {
    openvdb::io::File out(path.string());
    out.write(grids);
    out.close();
  } catch (const std::exception& e) {
    throw Error(concat(path.string(), ": OpenVDB could not write the file: ", e.what()));
  }
}

}  // namespace sandstorm
