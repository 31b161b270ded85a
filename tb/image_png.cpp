#include "tb/image_png.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

namespace cube4::tb {
namespace {

// libpng reports through longjmp; the message is kept for the caller.
struct ErrorSink {
  std::string message;
};

void on_error(png_structp png, png_const_charp msg) {
  static_cast<ErrorSink*>(png_get_error_ptr(png))->message = msg;
  png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

struct File {
  std::FILE* f = nullptr;
  ~File() {
    if (f) std::fclose(f);
  }
};

}  // namespace

std::string write_png(const std::string& file, const std::string& shown, const ImagePixels& px) {
  const bool wide = px.format == ImagePixels::Format::U16;
  if ((!wide && px.format != ImagePixels::Format::U8) || px.channels < 1 || px.channels > 4)
    return "cannot write '" + shown + "': PNG takes 8- or 16-bit images of 1 to 4 channels";
  static const int kColour[5] = {0, PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                 PNG_COLOR_TYPE_RGB_ALPHA};
  File out;
  out.f = std::fopen(file.c_str(), "wb");
  if (!out.f) return "cannot write '" + shown + "': " + std::strerror(errno);
  ErrorSink sink;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return "cannot write '" + shown + "': libpng could not start";
  }
  // Rows in PNG's byte order (16-bit values big-endian), built before the
  // setjmp: between it and a longjmp only libpng's C frames run, so no
  // destructor is skipped.
  const size_t row_bytes = static_cast<size_t>(px.width) * px.channels * (wide ? 2 : 1);
  std::vector<png_byte> bytes(row_bytes * static_cast<size_t>(px.height));
  if (wide) {
    const uint16_t* v = static_cast<const uint16_t*>(px.data);
    for (size_t i = 0; i < bytes.size() / 2; ++i) {
      bytes[2 * i] = static_cast<png_byte>(v[i] >> 8);
      bytes[2 * i + 1] = static_cast<png_byte>(v[i]);
    }
  } else {
    std::memcpy(bytes.data(), px.data, bytes.size());
  }
  std::vector<png_bytep> rows(static_cast<size_t>(px.height));
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = bytes.data() + y * row_bytes;
  const std::string bits = std::to_string(px.channel_bits);
  png_text text{};
  text.compression = PNG_TEXT_COMPRESSION_NONE;
  text.key = const_cast<char*>("cube4:channel_bits");
  text.text = const_cast<char*>(bits.c_str());
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return "cannot write '" + shown + "': " + sink.message;
  }
  png_init_io(png, out.f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(px.width), static_cast<png_uint_32>(px.height), wide ? 16 : 8,
               kColour[px.channels], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (px.channel_bits > 0) png_set_text(png, info, &text, 1);
  png_set_rows(png, info, rows.data());
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  // A full disk shows only when the buffered bytes reach it.
  const bool flushed = std::fflush(out.f) == 0 && !std::ferror(out.f);
  const int saved = errno;
  const bool closed = std::fclose(out.f) == 0;
  out.f = nullptr;
  if (!flushed || !closed) return "cannot write '" + shown + "': " + std::strerror(flushed ? errno : saved);
  return {};
}

}  // namespace cube4::tb
