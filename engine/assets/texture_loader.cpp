#include "assets/texture_loader.h"

#include <cstring>

#include "assets/block_model.h"
#include "assets/labpbr.h"
#include "core/error.h"

namespace terrasol {
namespace {

std::string text(const std::vector<std::uint8_t>& bytes) {
  return {bytes.begin(), bytes.end()};
}

Image solid(int w, int h, const std::uint8_t rgba[4]) {
  Image image(w, h);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) std::memcpy(&image.rgba[i], rgba, 4);
  return image;
}

std::vector<Image> splitFrames(const Image& strip, int frameHeight) {
  std::vector<Image> frames;
  for (int top = 0; top + frameHeight <= strip.height; top += frameHeight) {
    Image f(strip.width, frameHeight);
    std::memcpy(f.rgba.data(), strip.pixel(0, top), f.rgba.size());
    frames.push_back(std::move(f));
  }
  return frames;
}

// Filtered for normal maps, nearest for specular data (no new metal ids or emission values may appear
// between texels).
Image resample(const Image& src, int w, int h, bool filtered) {
  return resizeImage(src, w, h, filtered);
}

struct Companion {
  std::vector<Image> frames;
  bool present = false;
};

// A companion map (_n or _s) of `base` from the same pack: a strip with the same frames, or one frame
// used for all of them; resampled when its frame size differs.
Companion loadCompanion(const ResourcePack& pack, const std::string& file, const LoadedTexture& base,
                        bool filtered, std::vector<PackProblem>& problems) {
  Companion c;
  const auto path = pack.blockTexture(file);
  if (!path) return c;
  const std::string shown = pack.files().displayName(*path);
  try {
    const Image image = decodeImage(pack.files().require(*path), shown, kTextureLimits);
    const int frames = static_cast<int>(base.albedo.size());
    const int fw = base.albedo[0].width, fh = base.albedo[0].height;
    std::vector<Image> split;
    std::optional<Animation> own;
    if (const auto meta = pack.blockTexture(file + ".mcmeta")) {
      own = parseAnimation(text(pack.files().require(*meta)), image.width, image.height,
                           pack.files().displayName(*meta));
    }
    if (own) {
      // Its own strip layout; frame i of the texture uses frame i of the map when the counts match.
      split = splitFrames(image, own->frameHeight);
      if (static_cast<int>(split.size()) != frames) split.resize(1);
    } else if (frames > 1 && image.height % frames == 0 && image.height / frames * fw == image.width * fh) {
      split = splitFrames(image, image.height / frames);
    } else {
      split.push_back(image);
      if (frames > 1 && image.width != image.height * fw / fh) {
        problems.push_back(
            {PackProblem::Severity::Warning,
             shown + ": not one frame or a strip of " + std::to_string(frames) + "; used as one frame"});
      }
    }
    for (auto& f : split) {
      if (f.width != fw || f.height != fh) f = resample(f, fw, fh, filtered);
    }
    while (static_cast<int>(split.size()) < frames) split.push_back(split[0]);
    c.frames = std::move(split);
    c.present = true;
  } catch (const Error& e) {
    problems.push_back({PackProblem::Severity::Error, e.what()});
  }
  return c;
}

}  // namespace

Image missingTexture(int size) {
  Image image(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const bool magenta = ((x * 2 / size) + (y * 2 / size)) % 2 == 0;
      std::uint8_t* p = image.pixel(x, y);
      p[0] = magenta ? 248 : 0, p[1] = 0, p[2] = magenta ? 248 : 0, p[3] = 255;
    }
  return image;
}

LoadedTexture loadBlockTexture(const PackStack& packs, const std::vector<std::string>& candidates,
                               std::vector<PackProblem>& problems) {
  LoadedTexture t;
  t.name = candidates.empty() ? "" : candidates[0];
  std::optional<PackStack::Found> found;
  std::string used;
  if (const auto named = packs.findBlockTextureNamed(candidates)) {
    found = named->found;
    used = named->name;
  }
  if (found) {
    const ResourcePack& pack = *found->pack;
    t.source = pack.files().displayName(found->path);
    t.openGlNormals = pack.info().openGlNormals;
    try {
      const Image image = decodeImage(pack.files().require(found->path), t.source, kTextureLimits);
      if (const auto meta = pack.blockTexture(used + ".png.mcmeta")) {
        t.animation = parseAnimation(text(pack.files().require(*meta)), image.width, image.height,
                                     pack.files().displayName(*meta));
      }
      if (t.animation) {
        t.albedo = splitFrames(image, t.animation->frameHeight);
      } else if (image.width != image.height) {
        throw Error(t.source + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                    " is not square and has no .mcmeta animation");
      } else {
        t.albedo.push_back(image);
      }
    } catch (const Error& e) {
      problems.push_back({PackProblem::Severity::Error, e.what()});
      t.albedo.clear();
      t.animation.reset();
    }
    if (!t.albedo.empty()) {
      Companion n = loadCompanion(pack, used + "_n.png", t, true, problems);
      Companion s = loadCompanion(pack, used + "_s.png", t, false, problems);
      t.hasNormalMap = n.present;
      t.hasSpecularMap = s.present;
      t.normal = std::move(n.frames);
      t.specular = std::move(s.frames);
    }
  } else if (candidates != std::vector<std::string>{kMissingTexture}) {  // asked for on purpose: no warning
    std::string tried;
    for (const auto& name : candidates) tried += (tried.empty() ? "" : ", ") + name + ".png";
    problems.push_back(
        {PackProblem::Severity::Warning, "missing texture '" + t.name + "' (no pack has " + tried + ")"});
  }
  if (t.albedo.empty()) {
    t.missing = true;
    t.albedo.push_back(missingTexture());
  }
  const int w = t.albedo[0].width, h = t.albedo[0].height;
  if (t.normal.empty()) t.normal.assign(t.albedo.size(), solid(w, h, labpbr::kDefaultNormal));
  if (t.specular.empty()) t.specular.assign(t.albedo.size(), solid(w, h, labpbr::kDefaultSpecular));
  return t;
}

}  // namespace terrasol
