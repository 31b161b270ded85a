// Image files through OpenImageIO. Final images: premultiplied RGBA as PNG
// (8 bit) or EXR (float). Base planes: PNG with 16-bit channels holding the
// hardware's values bit-replicated (v12 -> v16 = v<<4 | v>>8, so v16>>4 gives
// them back exactly), or EXR as value / (2^bits - 1). The writers write the
// file named (tb/output_files.hpp gives them a temporary) and throw
// InputError, naming `shown_as` (default: the file), unless it reads back
// whole.
#pragma once
#include <string>

#include "golden/renderers.hpp"

namespace cube4::tb {

void write_image(const std::string& path, const golden::ImageF& img, const std::string& shown_as = "");
void write_baseplane(const std::string& path, const golden::BasePlane& bp, const std::string& shown_as = "");
// The float renderer's.
void write_baseplane(const std::string& path, const golden::ImageF& bp, const std::string& shown_as = "");
golden::ImageF read_image(const std::string& path);
// Reads a base plane written by write_baseplane (PNG) back to its integer values.
golden::BasePlane read_baseplane_png(const std::string& path, int bits);

}  // namespace cube4::tb
