#include "hilight/io/image_io.hpp"

#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"

#include <ImfArray.h>
#include <ImfRgbaFile.h>
#include <ImfStdIO.h>
#include <algorithm>
#include <stdexcept>
#include <cmath>
#include <cstdio>
#include <png.h>

namespace hilight {

namespace fs = std::filesystem;

namespace {

float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

float srgb_encode(float linear) {
  linear = std::clamp(linear, 0.f, 1.f);
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.f / 2.4f) - 0.055f;
}

} // namespace

float auto_exposure(const Image& image) {
  std::vector<float> lum;
  for (size_t i = 0; i < image.pixels.size(); ++i)
    if (image.covered[i]) lum.push_back(luminance(image.pixels[i]));
  if (lum.empty()) return 1.f;
  auto quantile = [&](double q) {
    const size_t k = std::min(lum.size() - 1, size_t(q * double(lum.size())));
    std::nth_element(lum.begin(), lum.begin() + std::ptrdiff_t(k), lum.end());
    return lum[k];
  };
  const float top = quantile(0.99), high = quantile(0.95), median = quantile(0.5);
  if (!(top > 0.f)) return 1.f;
  float exposure = 0.9f / top;
  // A bright few (the ceiling over a lamp) must not leave the room black.
  if (median > 0.f && median * exposure < 0.1f) exposure = std::max(exposure, std::min(0.1f / median, 1.f / high));
  return exposure;
}

std::vector<unsigned char> encode_png(const Image& image, float exposure) {
  if (exposure <= 0.f) exposure = auto_exposure(image);
  std::vector<unsigned char> rgb(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    Rgb c = image.covered[i] ? image.pixels[i] * exposure : Rgb(0.12f); // background: dark grey, untouched by exposure
    for (int k = 0; k < 3; ++k) rgb[3 * i + k] = (unsigned char)std::lround(255.f * srgb_encode(c[k]));
  }
  std::vector<unsigned char> bytes;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("PNG encoding failed");
  }
  png_set_write_fn(
      png, &bytes,
      [](png_structp p, png_bytep data, png_size_t length) {
        auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(p));
        out->insert(out->end(), data, data + length);
      },
      nullptr);
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) png_write_row(png, &rgb[size_t(y) * image.width * 3]);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return bytes;
}

namespace {

/// The EXR's bytes, made in memory so that the file is written like every
/// other output (and an error names the target, not a temporary).
std::string encode_exr(const fs::path& path, const Image& image) {
  std::vector<Imf::Rgba> px(image.pixels.size());
  for (size_t i = 0; i < px.size(); ++i) {
    const Rgb& c = image.pixels[i];
    px[i] = Imf::Rgba(c.r, c.g, c.b, image.covered[i] ? 1.f : 0.f);
  }
  try {
    Imf::StdOSStream stream;
    {
      Imf::RgbaOutputFile file(stream, Imf::Header(image.width, image.height), Imf::WRITE_RGBA);
      file.setFrameBuffer(px.data(), 1, size_t(image.width));
      file.writePixels(image.height);
    }  // the file's destructor writes the last of it
    return stream.str();
  } catch (const std::exception& e) {
    throw InputError(path.string(), std::string("OpenEXR: ") + e.what());
  }
}

} // namespace

void write_image(const fs::path& path, const Image& image, float exposure) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (ext != ".png" && ext != ".exr") throw InputError(path.string(), "unknown image type (use .png or .exr)");
  if (ext == ".png") {
    const std::vector<unsigned char> bytes = encode_png(image, exposure);
    write_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  } else {
    write_atomically(path, encode_exr(path, image));
  }
}

PngPixels read_png(const fs::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) throw InputError(path.string(), std::string("cannot read PNG: ") + image.message);
  image.format = PNG_FORMAT_RGB;
  PngPixels out;
  out.width = int(image.width);
  out.height = int(image.height);
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr)) {
    png_image_free(&image);
    throw InputError(path.string(), std::string("cannot read PNG: ") + image.message);
  }
  return out;
}

Image read_exr(const fs::path& path) {
  try {
    Imf::RgbaInputFile file(path.c_str());
    Imath::Box2i dw = file.dataWindow();
    int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    Imf::Array2D<Imf::Rgba> px(h, w);
    file.setFrameBuffer(&px[0][0] - dw.min.x - dw.min.y * w, 1, size_t(w));
    file.readPixels(dw.min.y, dw.max.y);
    Image image(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Imf::Rgba& p = px[y][x];
        image.at(x, y) = Rgb(float(p.r), float(p.g), float(p.b));
        image.covered[size_t(y) * w + x] = float(p.a) > 0.5f;
      }
    return image;
  } catch (const std::exception& e) {
    throw InputError(path.string(), std::string("cannot read OpenEXR: ") + e.what());
  }
}

} // namespace hilight
