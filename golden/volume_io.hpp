// Volume loaders and synthetic volumes. Every loader quantises to the
// pipeline's voxel width with the mapping of docs/volumes.md, and reports a
// bad or truncated file as an InputError naming the file and the fault.
#pragma once
#include <string>

#include "golden/scene.hpp"
#include "golden/volume.hpp"

namespace cube4::golden {

// Loads or generates the volume a scene names. `scene_dir` resolves relative
// paths. `voxel_bits` is the pipeline's voxel width.
Volume load_volume(const VolumeSource& src, int voxel_bits, const std::string& scene_dir);

Volume load_den(const std::string& path, const Quantisation& q, int voxel_bits);
Volume load_raw(const VolumeSource& src, const std::string& path, int voxel_bits);
Volume load_nifti(const std::string& path, const Quantisation& q, int voxel_bits);
Volume make_synthetic(const VolumeSource& src, int voxel_bits);

// Where Debian's libvolpack1-dev puts the MRI head (the default scene's volume).
std::string default_brainsmall_path();

}  // namespace cube4::golden
