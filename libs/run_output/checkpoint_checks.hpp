// A checkpoint is checked whole before any of it is used: every dataset the solver state and
// the outputs read back is present, of the shape the scene implies, finite, and every index
// within the table it points into (bodies, particles, buckets, runs). A corrupted but
// well-formed file (a few rows short, an index out of range, a NaN time) is refused with one
// InputError naming the dataset, instead of crashing the run or continuing it wrongly.
// Uses core/checked_read.hpp; the layout is Simulation::save_state's (libs/mpm) and
// SolveRun's /output group.
#pragma once
#include <cstddef>

namespace latmpm {

class Hdf5File;

struct CheckpointShape {
  size_t particles = 0;     // points of the scene
  size_t bodies = 0;        // scene bodies
  size_t rigid_bodies = 0;  // [rigid_bodies]
};

void check_checkpoint(const Hdf5File& file, const CheckpointShape& shape);

}  // namespace latmpm
