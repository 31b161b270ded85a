// Volume loaders and synthetic volumes. Every loader quantises to the
// pipeline's voxel width with the mapping of docs/volumes.md, and reports a
// bad or truncated file as an InputError naming the file and the fault.
#pragma once
#include <string>

#include "golden/scene.hpp"
#include "golden/volume.hpp"

namespace cube4::golden {

// Loads or generates the volume a scene names. `scene_dir` resolves relative
// paths. `voxel_bits` is the pipeline's voxel width. With `header_only` a
// loader stops once the header is read and checked (its memory check
// included) and returns the volume without voxels: its dimensions, spacing,
// width and source, all a run's limits depend on.
Volume load_volume(const VolumeSource& src, int voxel_bits, const std::string& scene_dir, bool header_only = false);

Volume load_den(const std::string& path, const Quantisation& q, int voxel_bits, bool header_only = false);
Volume load_raw(const VolumeSource& src, const std::string& path, int voxel_bits, bool header_only = false);
Volume load_nifti(const std::string& path, const Quantisation& q, int voxel_bits, bool header_only = false);
Volume make_synthetic(const VolumeSource& src, int voxel_bits, bool header_only = false);

// The volume's tags from the scene's "tags" (file, then labelling rules in
// order): none (v.tags empty, every tag 0) when precision.tag_bits is 0 or
// the scene gives no source. A tag above 2^tag_bits - 1 is an InputError
// naming the file, the voxel and the tag.
void load_tags(const Scene& s, Volume& v, const std::string& scene_dir);

// Where Debian's libvolpack1-dev puts the MRI head (the default scene's volume).
std::string default_brainsmall_path();

}  // namespace cube4::golden
