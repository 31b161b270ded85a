// PNG files written through libpng, in the cube4 process itself: the one
// format every render writes (the final image, the bit-exact base plane),
// so that a render need not open OpenImageIO's module and the some 260
// libraries behind it (tb/image_plugin.hpp; docs/performance.md,
// "Start-up"). Reading and EXR stay with OpenImageIO.
#pragma once
#include <string>

#include "tb/image_plugin.hpp"

namespace cube4::tb {

// Writes px (U8 or U16, 1 to 4 channels; the values as they are, which PNG
// calls unassociated alpha) to `file`; "" or why not, naming `shown`. A
// short write (a full disk, a file size limit) is an error, not a
// truncated file reported as written.
std::string write_png(const std::string& file, const std::string& shown, const ImagePixels& px);

}  // namespace cube4::tb
