#include "tiny_column.hpp"

#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"

namespace latmpm::test {

PointSet tiny_column(const TinyColumn& s) {
  PointSet p;
  p.body_names = {"column", "bottom_plate", "top_plate"};
  p.cell_size = s.cell;
  p.ppc = s.ppc;
  const double spacing = s.cell / s.ppc;
  const int across = s.width_cells * s.ppc, plate = s.plate_cells * s.ppc;
  const int column = s.height_cells * s.ppc;
  for (int k = 0; k < 2 * plate + column; ++k)
    for (int j = 0; j < across; ++j)
      for (int i = 0; i < across; ++i) {
        p.position.emplace_back((i + 0.5) * spacing, (j + 0.5) * spacing, (k + 0.5) * spacing);
        p.volume.push_back(spacing * spacing * spacing);
        p.half_size.emplace_back(spacing / 2, spacing / 2, spacing / 2);
        p.body.push_back(k < plate ? 1 : k < plate + column ? 0 : 2);
        p.tags["record"].push_back(k == plate);
      }
  return p;
}

void write_points(const PointSet& points, const std::string& path) {
  Hdf5File f(path, Hdf5File::Mode::create);
  write_point_set(f, points);
  write_provenance(f, Provenance{"tiny_column", "test", "tiny_column()", {}, "2024-01-01T00:00:00Z", {}});
}

}  // namespace latmpm::test
