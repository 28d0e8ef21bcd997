#include "optimize/design_export.hpp"

#include <openvdb/openvdb.h>

#include <cmath>

#include "core/file_transfer.hpp"
#include "core/hdf5_file.hpp"
#include "levelset/level_set_mesh.hpp"
#include "levelset/level_set_units.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/stl_file.hpp"
#include "points/point_set.hpp"

namespace latmpm::optimize {
namespace {

// Lattice layers through the thickness of a planar design (at least one).
int extrusion_layers(const DesignGrid& grid) {
  return grid.planar ? std::max(1, int(std::lround(grid.thickness / grid.spacing()))) : 1;
}

// The lattice coordinates of point l and its mirror images through `mirror`.
std::vector<Index3> images(const DesignGrid& grid, const Index3& l, const std::vector<SymmetryPlane>& mirror) {
  std::vector<Index3> out{l};
  const Index3 n = grid.lattice();
  for (const SymmetryPlane& plane : mirror) {
    const size_t count = out.size();
    for (size_t i = 0; i < count; ++i) {
      Index3 m = out[i];
      m[plane.axis] = plane.far_face ? 2 * n[plane.axis] - 1 - m[plane.axis] : -1 - m[plane.axis];
      out.push_back(m);
    }
  }
  return out;
}

}  // namespace

ExportReport export_design(const DesignGrid& grid, const std::vector<Real>& binary,
                           const std::vector<SymmetryPlane>& mirror, const std::string& points_path,
                           const std::string& stl_path, const Provenance& provenance) {
  ExportReport report;
  const Real s = grid.spacing();
  const int layers = extrusion_layers(grid);
  openvdb::initialize();
  openvdb::BoolGrid::Ptr solid = openvdb::BoolGrid::create(false);
  auto accessor = solid->getAccessor();
  PointSet points;
  points.body_names = {"part"};
  points.cell_size = grid.cell_size;
  points.ppc = grid.per_cell;
  for (size_t q = 0; q < grid.point_count(); ++q) {
    if (!(binary[q] > 0.5)) continue;
    for (const Index3& l : images(grid, grid.lattice_coord(q), mirror))
      for (int layer = 0; layer < layers; ++layer) {
        const Index3 v(l[0], l[1], grid.planar ? layer : l[2]);
        accessor.setValueOn(openvdb::Coord(v[0], v[1], v[2]), true);
        points.position.push_back((v.cast<Real>().array() + 0.5).matrix() * s);
        points.volume.push_back(s * s * s);
        points.half_size.push_back(Vec3::Constant(s / 2));
        points.body.push_back(0);
      }
  }
  report.points = points.size();
  report.solid_volume = Real(points.size()) * s * s * s;

  if (!points_path.empty()) {
    OutputFile out(points_path, "--output");
    {
      Hdf5File file(out.temp_path(), Hdf5File::Mode::create);
      write_provenance(file, provenance);
      write_point_set(file, points);
    }
    out.commit();
  }
  if (!stl_path.empty() && report.points > 0) {
    // A signed field on the voxel centres, −s/2 in solid voxels and +s/2 in their void
    // neighbours (world units: mm, level_set_units.hpp): its zero iso-surface lies on the
    // faces between solid and void, so the surface encloses the solid voxels exactly
    // (a level set made from the voxel topology would pass through the boundary voxels'
    // centres and lose half a voxel per side, most of a one-voxel strut).
    // The field lives on sub-voxels of s/4, so that marching cubes' bevel along the edges
    // of the voxel staircase costs little of a one-voxel strut's volume.
    const int sub = 4;
    const float half = float(0.5 * s / sub * grid_units_per_metre);
    openvdb::FloatGrid::Ptr sdf = openvdb::FloatGrid::create(half);
    sdf->setGridClass(openvdb::GRID_LEVEL_SET);
    auto transform = level_set_transform(s / sub);  // sub-voxel i's centre at (i + ½) s/sub
    transform->postTranslate(openvdb::Vec3d(half, half, half));
    sdf->setTransform(transform);
    auto field = sdf->getAccessor();
    auto solid_at = [&](const openvdb::Coord& v) {  // sub-voxel v inside a solid voxel?
      auto down = [&](int a) { return a >= 0 ? a / sub : -((-a + sub - 1) / sub); };
      return accessor.isValueOn(openvdb::Coord(down(v.x()), down(v.y()), down(v.z())));
    };
    for (auto it = solid->cbeginValueOn(); it; ++it) {
      const openvdb::Coord c = it.getCoord();
      for (int dz = -1; dz <= sub; ++dz)
        for (int dy = -1; dy <= sub; ++dy)
          for (int dx = -1; dx <= sub; ++dx) {
            const openvdb::Coord n(sub * c.x() + dx, sub * c.y() + dy, sub * c.z() + dz);
            if (!field.isValueOn(n)) field.setValue(n, solid_at(n) ? -half : half);
          }
    }
    const TriangleMesh mesh = level_set_to_mesh(*sdf);
    report.triangles = mesh.triangles.size();
    const MeshReport checked = check_mesh(mesh, false);
    report.surface_volume = checked.volume;
    report.closed = checked.encloses_volume() && checked.outward;
    OutputFile out(stl_path, "--output");
    write_stl(mesh, out.temp_path(), 1e-3);
    out.commit();
  }
  return report;
}

}  // namespace latmpm::optimize
