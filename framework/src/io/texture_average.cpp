#include "texture_average.hpp"
#include "confined_path.hpp"

#include <assimp/material.h>
#include <assimp/scene.h>
#include <algorithm>
#include <cmath>
#include <memory>
#include <stb/stb_image.h>
#include <vector>

namespace hilight {

namespace {

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

/// Mean of RGBA8 texels (4 bytes each), in linear light, weighted by alpha.
std::optional<Rgb> mean_rgba8(const unsigned char* texels, size_t count) {
  double sum[3] = {0, 0, 0}, weight = 0;
  for (size_t i = 0; i < count; ++i) {
    const unsigned char* t = texels + 4 * i;
    double a = t[3] / 255.0;
    for (int c = 0; c < 3; ++c) sum[c] += a * srgb_to_linear(t[c] / 255.0);
    weight += a;
  }
  if (!(weight > 0)) return std::nullopt;
  return Rgb(float(sum[0] / weight), float(sum[1] / weight), float(sum[2] / weight));
}

struct StbFree {
  void operator()(unsigned char* p) const { stbi_image_free(p); }
};

} // namespace

std::optional<Rgb> average_texture(const aiScene& scene, const aiMaterial& material, const std::filesystem::path& folder,
                                   std::string& problem) {
  std::string outside;
  aiString path;
  if (material.GetTexture(aiTextureType_BASE_COLOR, 0, &path) != AI_SUCCESS &&
      material.GetTexture(aiTextureType_DIFFUSE, 0, &path) != AI_SUCCESS)
    return std::nullopt;
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<unsigned char, StbFree> pixels;
  if (const aiTexture* embedded = scene.GetEmbeddedTexture(path.C_Str())) {
    if (embedded->mHeight == 0) {  // compressed (PNG, JPEG...) in memory
      pixels.reset(stbi_load_from_memory(reinterpret_cast<const unsigned char*>(embedded->pcData), int(embedded->mWidth), &w, &h,
                                         &channels, 4));
    } else {  // raw BGRA texels
      const size_t count = size_t(embedded->mWidth) * embedded->mHeight;
      std::vector<unsigned char> rgba(4 * count);
      for (size_t i = 0; i < count; ++i) {
        const aiTexel& t = embedded->pcData[i];
        rgba[4 * i] = t.r, rgba[4 * i + 1] = t.g, rgba[4 * i + 2] = t.b, rgba[4 * i + 3] = t.a;
      }
      return mean_rgba8(rgba.data(), count);
    }
  } else {
    // Files from Windows tools name textures with backslashes; some name
    // folders that were not shipped: try the path, then the bare file name.
    std::string name = path.C_Str();
    std::replace(name.begin(), name.end(), '\\', '/');
    for (const auto& file : {folder / name, folder / std::filesystem::path(name).filename()}) {
      if (!inside_folder(folder, file)) {  // not read (issue 35); the bare name in the folder may still be it
        outside = named_from(folder, file);
        continue;
      }
      pixels.reset(stbi_load(file.c_str(), &w, &h, &channels, 4));
      if (pixels) break;
    }
  }
  if (!pixels && !outside.empty()) {
    problem = "texture " + outside + " lies outside the scene's folder, so it is not read";
    return std::nullopt;
  }
  if (!pixels) {
    problem = std::string("texture ") + path.C_Str() + " cannot be read (" + (stbi_failure_reason() ? stbi_failure_reason() : "?") + ")";
    return std::nullopt;
  }
  return mean_rgba8(pixels.get(), size_t(w) * size_t(h));
}

} // namespace hilight
