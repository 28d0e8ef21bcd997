// The run's time series: one row every N steps, written as RUN_DIR/series.csv (flushed row by
// row, so a run that stops — or is watched while it goes — leaves every row so far readable)
// and RUN_DIR/series.h5 (the same columns, one dataset each, with provenance; replaced
// atomically on every save(), so it is always a complete file).
// Column headers carry their unit: "time[s]", "load_driven[N]".
#pragma once
#include <fstream>
#include <string>
#include <vector>

#include "core/provenance.hpp"

namespace latmpm {

struct SeriesColumn {
  std::string name;         // "time": also the HDF5 dataset name /series/time
  std::string unit;         // "s", "N", "J", "1" for counts
  std::string description;  // stored as the dataset's attribute "description"
  std::string header() const { return name + "[" + unit + "]"; }
};

// Reads a series CSV back: its header cells and rows (exact: written with 17 digits).
// Throws InputError naming the file for a missing file or a malformed row.
std::vector<std::vector<double>> read_series_csv(const std::string& path, std::vector<std::string>* header);

class SeriesWriter {
 public:
  // Creates (truncates) csv_path now and writes the header line.
  SeriesWriter(std::string csv_path, std::string hdf5_path, std::vector<SeriesColumn> columns,
               Provenance provenance);
  // The same, starting with rows of an earlier run (a resumed run: they are written again
  // first, so the CSV holds them and then the new rows).
  SeriesWriter(std::string csv_path, std::string hdf5_path, std::vector<SeriesColumn> columns,
               Provenance provenance, const std::vector<std::vector<double>>& earlier_rows);
  const std::vector<SeriesColumn>& columns() const { return columns_; }
  // One value per column; written to the CSV and flushed at once.
  void append(const std::vector<double>& row);
  size_t rows() const { return rows_; }
  // Writes series.h5 with every row so far (temporary name, then rename).
  void save() const;

 private:
  std::string csv_path_, hdf5_path_;
  std::vector<SeriesColumn> columns_;
  Provenance provenance_;
  std::ofstream csv_;
  std::vector<std::vector<double>> values_;  // per column
  size_t rows_ = 0;
};

}  // namespace latmpm
