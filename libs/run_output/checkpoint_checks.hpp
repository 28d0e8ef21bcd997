// A checkpoint is checked whole before any of it is used: every dataset the solver state and
// the outputs read back is present, of the shape the scene implies, finite, and every index
// within the table it points into (bodies, particles, buckets, runs). A corrupted but
// well-formed file (a few rows short, an index out of range, a NaN time) is refused with one
// InputError naming the dataset, instead of crashing the run or continuing it wrongly.
// Uses core/checked_read.hpp over the layout of Simulation::save_state (named datasets,
// libs/mpm/checkpoint_io.hpp; the particle fields from the registry, particle_fields.hpp)
// and SolveRun's /output group. The format version is checked by mpm's CheckpointReader.
#pragma once

namespace latmpm {

class Hdf5File;
namespace mpm {
class Simulation;
}

// `simulation` is the scene's, set up and not yet stepped: it gives the counts and fields.
void check_checkpoint(const Hdf5File& file, const mpm::Simulation& simulation);

}  // namespace latmpm
